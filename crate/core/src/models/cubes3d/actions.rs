//! Disturbances and clicks: removing, adding and holding units, and switching the target.

use serde::Deserialize;
use serde_json::Value;

use super::{Cubes, HELD_USER};
use crate::error::{Error, Result};
use crate::models::Action;

/// A disturbance or click: `{"kind": "remove" | "add" | "hold", "cells": [i]}` removes a unit
/// (if the rest stays connected), adds one next to the structure, or toggles whether a unit is
/// held in place; `{"kind": "switch"}` moves to the next target now.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ActionSpec {
    kind: String,
    #[serde(default)]
    cells: Vec<u32>,
}

fn parse_action(action: &Action) -> Result<ActionSpec> {
    let a: ActionSpec = crate::error::from_value(Value::Object(action.clone()))?;
    match a.kind.as_str() {
        "remove" | "add" | "hold" => {
            if a.cells.len() != 1 {
                return Err(Error::field("cells", "give exactly one cell, like [42]"));
            }
        }
        "switch" => {}
        other => {
            return Err(Error::field(
                "kind",
                format!("unknown action '{other}'; known: remove, add, hold, switch"),
            ))
        }
    }
    Ok(a)
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
    if a.kind == "switch" && targets < 2 {
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
        match a.kind.as_str() {
            "switch" => {
                let next = (self.main_target() + 1) % self.targets.len();
                for k in 0..self.units.len() {
                    self.switch_unit(self.units[k] as usize, next);
                }
                Ok(())
            }
            kind => {
                let c = a.cells[0] as usize;
                match kind {
                    "remove" => self.remove_unit(c),
                    "add" => self.add_unit(c),
                    _ => {
                        if !self.st.occupied(c) {
                            return Err(Error::field("cells", format!("cell {c} holds no unit")));
                        }
                        self.flags[c] ^= HELD_USER;
                        self.refresh(c);
                        Ok(())
                    }
                }
            }
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
        self.st.add(i);
        self.after_change(&[i]);
        Ok(())
    }
}
