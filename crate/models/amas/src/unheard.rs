//! Section 5.5 with footnote 3: which broken neighbours a module never heard. "Every module holds
//! the values of the gradient field its neighbors have", and a module whose communication broke
//! "cannot exchange potential values": the neighbours it had when it broke keep its last value,
//! but a module placed beside it later was never sent one and holds none. Such links are few
//! (only around broken modules), so they are kept apart from the lattice, and the field's row
//! kernels are corrected at the few cells that have any (`field.rs`).

use std::collections::BTreeMap;

/// Bits of a module's mask: its neighbour to the left, right, above and below (the order in
/// which the field's row kernels read them).
pub const LEFT: u8 = 1;
pub const RIGHT: u8 = 2;
pub const UP: u8 = 4;
pub const DOWN: u8 = 8;

/// For each module that has any, the neighbours it never heard (a mask of [`LEFT`], [`RIGHT`],
/// [`UP`], [`DOWN`]), by cell.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Unheard {
    masks: BTreeMap<u32, u8>,
}

impl Unheard {
    /// The neighbours module `i` never heard.
    #[inline]
    pub fn mask(&self, i: usize) -> u8 {
        match self.masks.is_empty() {
            true => 0,
            false => self.masks.get(&(i as u32)).copied().unwrap_or(0),
        }
    }

    /// Whether module `i` hears its neighbour `j` (on a lattice `w` cells wide).
    #[inline]
    pub fn hears(&self, i: usize, j: usize, w: usize) -> bool {
        self.mask(i) & bit(i, j, w) == 0
    }

    /// A module appears at `t`: it never heard the broken modules beside it (`broken(j)`), and
    /// its neighbours, which may have been deaf to a broken module removed from `t`, hear the
    /// new one.
    pub fn placed(&mut self, t: usize, w: usize, around: &[usize], broken: impl Fn(usize) -> bool) {
        let mut mask = 0;
        for &j in around {
            if broken(j) {
                mask |= bit(t, j, w);
            }
            if let Some(m) = self.masks.get_mut(&(j as u32)) {
                *m &= !bit(j, t, w);
                if *m == 0 {
                    self.masks.remove(&(j as u32));
                }
            }
        }
        match mask {
            0 => self.masks.remove(&(t as u32)),
            m => self.masks.insert(t as u32, m),
        };
    }

    /// The module at `t` is gone: nothing it heard matters any more.
    pub fn gone(&mut self, t: usize) {
        self.masks.remove(&(t as u32));
    }

    /// The modules of row `y` (on a lattice `w` cells wide) that miss a neighbour, with their
    /// column and mask, in order.
    pub fn in_row(&self, y: usize, w: usize) -> impl Iterator<Item = (usize, u8)> + '_ {
        let start = (y * w) as u32;
        self.masks
            .range(start..start + w as u32)
            .map(move |(&i, &m)| (i as usize - y * w, m))
    }

    /// Every module that misses a neighbour, and which, in cell order (for the state hash).
    pub fn iter(&self) -> impl Iterator<Item = (u32, u8)> + '_ {
        self.masks.iter().map(|(&i, &m)| (i, m))
    }
}

/// The bit of module `i`'s mask that stands for its neighbour `j`.
#[inline]
fn bit(i: usize, j: usize, w: usize) -> u8 {
    if j + 1 == i {
        LEFT
    } else if j == i + 1 {
        RIGHT
    } else if j + w == i {
        UP
    } else {
        DOWN
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_module_placed_beside_a_broken_one_never_hears_it() {
        // A 3-wide lattice: cell 4 is the centre, 3 its left, 5 its right, 1 above, 7 below.
        let mut u = Unheard::default();
        u.placed(4, 3, &[5, 1, 3, 7], |j| j == 1 || j == 3);
        assert_eq!(u.mask(4), UP | LEFT);
        assert!(!u.hears(4, 1, 3) && !u.hears(4, 3, 3));
        assert!(u.hears(4, 5, 3) && u.hears(4, 7, 3));
        assert_eq!(u.in_row(1, 3).collect::<Vec<_>>(), vec![(1, UP | LEFT)]);
        // The broken module above is removed and a working one placed there: cell 4 hears it.
        u.placed(1, 3, &[2, 0, 4], |_| false);
        assert_eq!(u.mask(4), LEFT);
        u.gone(4);
        assert_eq!(u.iter().count(), 0);
    }
}
