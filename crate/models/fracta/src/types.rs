//! Connection types (section 3.1): the bond patterns of a hexagonal unit, their classes under
//! rotation and reflection, which of them can move, and the distances between them.
//!
//! Everything here is computed from the geometry of the hexagonal lattice:
//! - a bond pattern is a 6-bit mask, bit `d` set when the neighbour in direction `d` is present
//!   (directions as in [`kumiki_model::lattice::Hex`]: counter-clockwise, so `(d + 1) % 6` turns 60°);
//! - the classes are the orbits of the 64 masks under the 12 symmetries of the hexagon; the
//!   empty mask is its own class, called `none` (a missing neighbour), the other 63 masks fall
//!   into the 12 connection types of the paper;
//! - a unit moves by rolling 60° about a neighbour (`roll_ok`, with the masks' symmetries in
//!   `pattern.rs`); the types whose units can roll are the movable ones;
//! - two types are linked when one motion of a neighbouring unit turns a unit of one type into
//!   the other ([`derive_links`], in `links.rs`), and their distance is the length of the
//!   shortest chain of links.
//!
//! Only the names are written by hand, attached to each class through its canonical (smallest)
//! mask; the test suite checks that the names cover exactly the computed classes.

use std::collections::BTreeSet;
use std::sync::OnceLock;

use super::links::derive_links;
use super::pattern::{can_roll, canonical};

/// Number of connection classes including `none`.
pub const CLASSES: usize = 13;
/// The class of the empty pattern: no unit there.
pub const NONE: u8 = 0;

/// Names of the classes, attached through their canonical masks. `paper` marks the letters the
/// paper's text fixes; the others are ours, chosen like the paper's after the shape the bonds
/// draw from the centre of the hexagon.
struct Naming {
    canonical: u8,
    name: &'static str,
    ascii: &'static str,
    aliases: &'static [&'static str],
    paper: bool,
    color: &'static str,
    description: &'static str,
}

const NAMING: [Naming; CLASSES] = [
    Naming {
        canonical: 0,
        name: "none",
        ascii: "none",
        aliases: &[],
        paper: false,
        color: "#ffffff",
        description: "no unit (pads a shorter neighbour list)",
    },
    Naming {
        canonical: 0b000001,
        name: "e",
        ascii: "e",
        aliases: &[],
        paper: true,
        color: "#e4572e",
        description: "one bond: an end, unstable",
    },
    Naming {
        canonical: 0b000011,
        name: "o",
        ascii: "o",
        aliases: &[],
        paper: true,
        color: "#f29e4c",
        description: "two bonds side by side: a corner",
    },
    Naming {
        canonical: 0b000101,
        name: "v",
        ascii: "v",
        aliases: &[],
        paper: false,
        color: "#c9a66b",
        description: "two bonds at 120°: a bend",
    },
    Naming {
        canonical: 0b001001,
        name: "i",
        ascii: "i",
        aliases: &[],
        paper: false,
        color: "#a07c5b",
        description: "two opposite bonds: a straight link",
    },
    Naming {
        canonical: 0b000111,
        name: "ε",
        ascii: "eps",
        aliases: &["epsilon"],
        paper: true,
        color: "#f1c453",
        description: "three bonds side by side",
    },
    Naming {
        canonical: 0b001011,
        name: "λ",
        ascii: "lambda",
        aliases: &[],
        paper: false,
        color: "#8fbc8f",
        description: "a straight line with one branch at 60°",
    },
    Naming {
        canonical: 0b010101,
        name: "Y",
        ascii: "y",
        aliases: &[],
        paper: false,
        color: "#5fa8a0",
        description: "three bonds at 120°",
    },
    Naming {
        canonical: 0b001111,
        name: "K",
        ascii: "k",
        aliases: &[],
        paper: true,
        color: "#4d85c5",
        description: "four bonds side by side: a line with two branches on one side",
    },
    Naming {
        canonical: 0b010111,
        name: "ψ",
        ascii: "psi",
        aliases: &[],
        paper: false,
        color: "#6a6fb8",
        description: "three bonds side by side and one opposite the middle one",
    },
    Naming {
        canonical: 0b011011,
        name: "x",
        ascii: "x",
        aliases: &[],
        paper: false,
        color: "#8a5fa8",
        description: "two crossing straight lines",
    },
    Naming {
        canonical: 0b011111,
        name: "c",
        ascii: "c",
        aliases: &[],
        paper: false,
        color: "#3b5b86",
        description: "five bonds: open on one side",
    },
    Naming {
        canonical: 0b111111,
        name: "s",
        ascii: "s",
        aliases: &[],
        paper: true,
        color: "#27323f",
        description: "six bonds: surrounded",
    },
];

/// One connection class.
#[derive(Clone, Debug)]
pub struct TypeInfo {
    /// The display name: the paper's letter where its text fixes one (e, o, ε, K, s).
    pub name: &'static str,
    /// ASCII spelling accepted in statements (`eps` for ε).
    pub ascii: &'static str,
    pub aliases: &'static [&'static str],
    pub paper: bool,
    pub color: &'static str,
    pub description: &'static str,
    /// The smallest mask of the class.
    pub canonical: u8,
    pub bonds: u8,
    /// Every mask of the class can roll somewhere (section 3.1).
    pub movable: bool,
}

/// The classes, the class of every mask, and the distances between classes.
#[derive(Debug)]
pub struct Types {
    /// Class index of each of the 64 masks. Classes are numbered by bond count, then canonical
    /// mask, which is also the order neighbour lists are sorted in (section 3.2.1).
    pub class_of: [u8; 64],
    pub info: Vec<TypeInfo>,
    /// Links of the type graph, as (smaller, larger) class index pairs.
    pub links: BTreeSet<(u8, u8)>,
    pub dist: [[u8; CLASSES]; CLASSES],
}

impl Types {
    fn compute() -> Types {
        let mut reps: Vec<u8> = (0..64u8).map(canonical).collect();
        kumiki_model::sort::sort_by_key(&mut reps, |&m| (m.count_ones(), m));
        reps.dedup();
        assert_eq!(reps.len(), CLASSES, "the hexagon has 13 bond classes");
        let mut class_of = [0u8; 64];
        for m in 0..64u8 {
            class_of[m as usize] = reps.iter().position(|&r| r == canonical(m)).unwrap() as u8;
        }
        let info = reps
            .iter()
            .map(|&rep| {
                let n = NAMING
                    .iter()
                    .find(|n| n.canonical == rep)
                    .expect("every class is named");
                let members = (0..64u8).filter(|&m| canonical(m) == rep);
                let movable = rep != 0 && members.clone().all(can_roll);
                TypeInfo {
                    name: n.name,
                    ascii: n.ascii,
                    aliases: n.aliases,
                    paper: n.paper,
                    color: n.color,
                    description: n.description,
                    canonical: rep,
                    bonds: rep.count_ones() as u8,
                    movable,
                }
            })
            .collect();
        let links: BTreeSet<(u8, u8)> = derive_links()
            .into_iter()
            .map(|(a, b)| {
                let (a, b) = (class_of[a as usize], class_of[b as usize]);
                (a.min(b), a.max(b))
            })
            .filter(|(a, b)| a != b)
            .collect();
        let dist = distances(&links);
        Types {
            class_of,
            info,
            links,
            dist,
        }
    }

    /// The class of a unit whose neighbours are `mask`.
    #[inline]
    pub fn of(&self, mask: u8) -> u8 {
        self.class_of[(mask & 63) as usize]
    }

    pub fn name(&self, class: u8) -> &'static str {
        self.info[class as usize].name
    }

    /// The class a name or alias stands for (ASCII spellings in any case).
    pub fn parse(&self, word: &str) -> Option<u8> {
        let lower = word.to_ascii_lowercase();
        self.info
            .iter()
            .position(|t| {
                t.name != "none"
                    && (t.name == word
                        || t.ascii == lower
                        || t.aliases.iter().any(|&a| a == lower)
                        || (t.name.is_ascii() && t.name.to_ascii_lowercase() == lower))
            })
            .map(|i| i as u8)
    }

    /// "e, o, v, i, ε (eps), ..." for error messages.
    pub fn known(&self) -> String {
        self.info
            .iter()
            .skip(1)
            .map(|t| {
                if t.ascii == t.name.to_ascii_lowercase() {
                    t.name.to_string()
                } else {
                    format!("{} ({})", t.name, t.ascii)
                }
            })
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// Shortest-path lengths in the type graph (breadth-first from every class).
fn distances(links: &BTreeSet<(u8, u8)>) -> [[u8; CLASSES]; CLASSES] {
    let mut dist = [[u8::MAX; CLASSES]; CLASSES];
    for (s, row) in dist.iter_mut().enumerate() {
        row[s] = 0;
        let mut frontier = vec![s as u8];
        let mut d = 0u8;
        while !frontier.is_empty() {
            d += 1;
            let mut next = Vec::new();
            for &u in &frontier {
                for &(a, b) in links {
                    let v = if a == u {
                        b
                    } else if b == u {
                        a
                    } else {
                        continue;
                    };
                    if row[v as usize] == u8::MAX {
                        row[v as usize] = d;
                        next.push(v);
                    }
                }
            }
            frontier = next;
        }
    }
    dist
}

/// The class table, computed once.
pub fn types() -> &'static Types {
    static TYPES: OnceLock<Types> = OnceLock::new();
    TYPES.get_or_init(Types::compute)
}
