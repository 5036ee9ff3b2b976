//! Disturbances, scheduled in the scenario or clicked in the page:
//! - `remove`: built modules disappear (section 5.4); their neighbours become growth front.
//! - `break`: communication breakdown (5.5): the module no longer updates the field or talks to
//!   robots.
//! - `dismantle`: the module leaves the target and is to be removed (6.2).
//! - `extend`: an empty cell next to the structure or the target joins the target.
//!
//! Each takes `"count": N` (N cells drawn at random among those that qualify; fewer if fewer
//! qualify) or `"cells": [i, ...]` (those cells, each of which must qualify).

use schemars::JsonSchema;
use serde::Deserialize;

use super::state::{BROKEN, CONVEYOR, MODULE, REMOVE, VACANT};
use super::{Amas, NONE};
use kumiki_model::error::{Error, Result};
use kumiki_model::model::Action;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Remove,
    Break,
    Dismantle,
    Extend,
}

pub struct Checked {
    kind: Kind,
    count: Option<u32>,
    cells: Vec<u32>,
}

/// An action as written: its kind, and which cells (a count drawn at random, or a list).
#[derive(Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase", deny_unknown_fields)]
#[schemars(tag = "kind")]
#[schemars(rename = "AmasDisturbance")]
pub(super) enum Raw {
    /// Built modules disappear (section 5.4); their neighbours become growth front.
    Remove(Which),
    /// Communication breakdown (5.5): the module no longer updates the field or talks to robots.
    Break(Which),
    /// The module leaves the target and is to be removed (6.2).
    Dismantle(Which),
    /// An empty cell next to the structure or the target joins the target.
    Extend(Which),
}

/// Which cells an action takes: `count` of those that qualify, drawn at random, or the `cells`
/// listed (each must qualify).
#[derive(Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
#[schemars(rename = "AmasCells")]
pub(super) struct Which {
    #[serde(default)]
    count: Option<u32>,
    #[serde(default)]
    cells: Option<Vec<u32>>,
}

impl Amas {
    /// Why cell `i` does not qualify for `kind`, if it does not.
    fn unfit(&self, kind: Kind, i: usize) -> Option<String> {
        let Some(&s) = self.state.get(i) else {
            return Some(format!("cell {i} is outside the lattice"));
        };
        let built = s & MODULE != 0 && s & CONVEYOR == 0;
        match kind {
            Kind::Remove if !built => Some(format!("cell {i} holds no built module")),
            Kind::Remove if self.occupant[i] != NONE => Some(format!("a robot stands on cell {i}")),
            Kind::Break if !built => Some(format!("cell {i} holds no built module")),
            Kind::Break if s & BROKEN != 0 => Some(format!("cell {i} is already broken")),
            Kind::Dismantle if !built => Some(format!("cell {i} holds no built module")),
            Kind::Dismantle if s & REMOVE != 0 => {
                Some(format!("cell {i} is already to be removed"))
            }
            Kind::Extend if s & (MODULE | VACANT) != 0 => Some(format!(
                "cell {i} is already part of the structure or target"
            )),
            Kind::Extend => {
                let (nb, k) = self.neighbours(i);
                if nb[..k]
                    .iter()
                    .any(|&j| self.state[j] & (MODULE | VACANT) != 0)
                {
                    None
                } else {
                    Some(format!(
                        "cell {i} touches neither the structure nor the target"
                    ))
                }
            }
            _ => None,
        }
    }

    /// An action that fits the present state: every listed cell suits it.
    pub(super) fn check(&self, action: &Action) -> Result<Checked> {
        let a = parse(action, self.state.len())?;
        for (n, &c) in a.cells.iter().enumerate() {
            if let Some(why) = self.unfit(a.kind, c as usize) {
                return Err(Error::field(format!("cells[{n}]"), why));
            }
        }
        Ok(a)
    }

    pub(super) fn perform(&mut self, a: &Checked) {
        let cells: Vec<usize> = match a.count {
            Some(count) => {
                let candidates: Vec<usize> = (0..self.state.len())
                    .filter(|&i| self.unfit(a.kind, i).is_none())
                    .collect();
                self.disturb_rng
                    .sample_distinct(candidates.len(), count as usize)
                    .into_iter()
                    .map(|k| candidates[k])
                    .collect()
            }
            None => a.cells.iter().map(|&c| c as usize).collect(),
        };
        for i in cells {
            // A cell listed twice qualifies only the first time.
            if self.unfit(a.kind, i).is_some() {
                continue;
            }
            let s = self.state[i];
            match a.kind {
                Kind::Remove => {
                    if s & REMOVE != 0 {
                        self.state[i] = 0;
                        self.to_remove -= 1;
                    } else {
                        self.state[i] = VACANT;
                        self.vacant += 1;
                    }
                    self.removed += 1;
                }
                Kind::Break => {
                    self.state[i] |= BROKEN;
                    self.broken += 1;
                }
                Kind::Dismantle => {
                    self.state[i] |= REMOVE;
                    self.to_remove += 1;
                    self.target_cells -= 1;
                }
                Kind::Extend => {
                    self.state[i] = VACANT;
                    self.vacant += 1;
                    self.target_cells += 1;
                }
            }
            self.dirty = true;
            self.refresh_around(i);
            self.init_value(i);
        }
        self.settle();
    }
}

/// The form of an action: its kind, a count or cells, and cells inside a lattice of
/// `cells_in_lattice` cells. Whether the cells suit the action depends on the state when it is
/// applied (see [`Amas::check`]).
pub(super) fn parse(action: &Action, cells_in_lattice: usize) -> Result<Checked> {
    let (kind, which) = match kumiki_model::error::from_action(action)? {
        Raw::Remove(w) => (Kind::Remove, w),
        Raw::Break(w) => (Kind::Break, w),
        Raw::Dismantle(w) => (Kind::Dismantle, w),
        Raw::Extend(w) => (Kind::Extend, w),
    };
    match (which.count, which.cells) {
        (Some(count), None) => Ok(Checked {
            kind,
            count: Some(count),
            cells: Vec::new(),
        }),
        (None, Some(cells)) => {
            for (n, &c) in cells.iter().enumerate() {
                if c as usize >= cells_in_lattice {
                    return Err(Error::field(
                        format!("cells[{n}]"),
                        format!("cell {c} is outside the lattice"),
                    ));
                }
            }
            Ok(Checked {
                kind,
                count: None,
                cells,
            })
        }
        _ => Err(Error::field("count", "give either count or cells")),
    }
}
