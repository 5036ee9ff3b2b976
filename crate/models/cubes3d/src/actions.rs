//! Disturbances and clicks: removing, adding and holding units, and switching the target.

use schemars::JsonSchema;
use serde::Deserialize;

use super::{Cubes, HELD_USER};
use kumiki_model::error::{Error, Result};
use kumiki_model::model::Action;

/// A disturbance or click: `{"kind": "remove" | "add" | "hold", "cells": [i]}` removes a unit
/// (if the rest stays connected), adds one next to the structure, or toggles whether a unit is
/// held in place; `{"kind": "switch"}` moves to the next target now.
#[derive(Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase", deny_unknown_fields)]
#[schemars(tag = "kind")]
#[schemars(rename = "Cubes3dDisturbance")]
pub(super) enum ActionSpec {
    /// Removes the unit in the one cell listed, if the rest stays connected.
    Remove {
        #[serde(default)]
        cells: Vec<u32>,
    },
    /// Adds a unit in the one empty cell listed, next to the structure.
    Add {
        #[serde(default)]
        cells: Vec<u32>,
    },
    /// Toggles whether the unit in the one cell listed is held in place.
    Hold {
        #[serde(default)]
        cells: Vec<u32>,
    },
    /// Moves to the next target now. A click of the switch tool names the clicked cell too; it
    /// is not used.
    Switch {
        #[serde(default)]
        cells: Vec<u32>,
    },
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Op {
    Remove,
    Add,
    Hold,
    Switch,
}

struct Parsed {
    op: Op,
    cells: Vec<u32>,
}

fn parse_action(action: &Action) -> Result<Parsed> {
    let (op, cells) = match kumiki_model::error::from_action(action)? {
        ActionSpec::Remove { cells } => (Op::Remove, cells),
        ActionSpec::Add { cells } => (Op::Add, cells),
        ActionSpec::Hold { cells } => (Op::Hold, cells),
        ActionSpec::Switch { cells } => (Op::Switch, cells),
    };
    if op != Op::Switch && cells.len() != 1 {
        return Err(Error::field("cells", "give exactly one cell, like [42]"));
    }
    Ok(Parsed { op, cells })
}

/// The form of an action in a space of `cells` cells with `targets` targets, whatever the state.
pub(super) fn check_form(action: &Action, cells: usize, targets: usize) -> Result<()> {
    let a = parse_action(action)?;
    if let Some(&c) = a.cells.iter().find(|&&c| c as usize >= cells) {
        return Err(Error::field(
            "cells",
            format!("cell {c} is outside the lattice"),
        ));
    }
    if a.op == Op::Switch && targets < 2 {
        return Err(Error::field("kind", "switch needs two or more targets"));
    }
    Ok(())
}

impl Cubes {
    pub(super) fn check(&self, action: &Action) -> Result<()> {
        check_form(action, self.st.len(), self.targets.len())
    }

    pub(super) fn perform(&mut self, action: &Action) -> Result<()> {
        self.check(action)?;
        let a = parse_action(action)?;
        let c = a.cells.first().map(|&c| c as usize);
        match (a.op, c) {
            (Op::Switch, _) => {
                let next = (self.main_target() + 1) % self.targets.len();
                for k in 0..self.units.len() {
                    self.switch_unit(self.units[k] as usize, next);
                }
                Ok(())
            }
            (Op::Remove, Some(c)) => self.remove_unit(c),
            (Op::Add, Some(c)) => self.add_unit(c),
            (Op::Hold, Some(c)) => {
                if !self.st.occupied(c) {
                    return Err(Error::field("cells", format!("cell {c} holds no unit")));
                }
                self.flags[c] ^= HELD_USER;
                self.refresh(c);
                Ok(())
            }
            // parse_action has refused this already: every kind but switch names one cell.
            (_, None) => Err(Error::field("cells", "give exactly one cell, like [42]")),
        }
    }

    pub(super) fn remove_unit(&mut self, i: usize) -> Result<()> {
        if !self.st.occupied(i) {
            return Err(Error::field("cells", format!("cell {i} holds no unit")));
        }
        if self.units.len() <= 2 {
            return Err(Error::field("cells", "the last two units stay"));
        }
        let mut s = std::mem::take(&mut self.scratch);
        let ok = self.st.stays_connected(i, None, &mut s);
        self.scratch = s;
        if !ok {
            return Err(Error::field(
                "cells",
                format!("removing the unit in cell {i} would split the structure"),
            ));
        }
        if !self.st.plane_holds(i) {
            return Err(Error::field(
                "cells",
                format!("the unit in cell {i} is the last one the ground plane holds"),
            ));
        }
        self.vacate(i);
        self.st.remove(i);
        self.after_change(&[i]);
        Ok(())
    }

    pub(super) fn add_unit(&mut self, i: usize) -> Result<()> {
        if self.st.wall[i] {
            return Err(Error::field(
                "cells",
                format!("cell {i} is outside the space units may use"),
            ));
        }
        if self.st.occupied(i) {
            return Err(Error::field(
                "cells",
                format!("cell {i} already holds a unit"),
            ));
        }
        if self.st.mask(i) == 0 {
            return Err(Error::field(
                "cells",
                format!("cell {i} touches no unit; a new unit must join the structure"),
            ));
        }
        if self.units.len() >= self.max_units {
            return Err(Error::field(
                "cells",
                format!("at most {} units", self.max_units),
            ));
        }
        self.target[i] = self.main_target() as u8;
        self.upos[i] = self.units.len() as u32;
        self.units.push(i as u32);
        self.diff.push(f64::NAN);
        self.stable.push(0);
        self.took.push(self.steps);
        self.st.add(i);
        self.after_change(&[i]);
        Ok(())
    }
}
