//! Loads as actions, one cell per click in the page, so loads are recorded in the scenario and
//! replayed by its link:
//! - `{"kind": "load", "cells": [i, ...], "force": N}` puts a downward load of N newtons on the
//!   robot at each cell (0 takes it off);
//! - `{"kind": "unload", "cells": [i, ...]}` takes the loads off those robots;
//! - `{"kind": "move", "cells": [i]}` moves a load in two clicks: the first on a loaded robot
//!   lifts its load, the next on any robot puts it down there.
//!
//! A load stays with its robot as the robot moves.

use schemars::JsonSchema;
use serde::Deserialize;

use super::motion::NONE;
use super::Chobie;
use kumiki_model::error::{Error, Result};
use kumiki_model::model::Action;

/// The largest load, newtons.
pub const MAX_FORCE: f64 = 1e6;

#[derive(Deserialize, JsonSchema)]
#[serde(deny_unknown_fields, rename_all = "lowercase")]
#[schemars(tag = "kind")]
#[schemars(rename = "ChobieDisturbance")]
pub(super) enum LoadAction {
    /// Puts a downward load of `force` newtons on the robot at each cell (0 takes it off).
    Load { cells: Vec<u64>, force: f64 },
    /// Takes the loads off the robots at those cells.
    Unload { cells: Vec<u64> },
    /// Moves a load in two clicks: the first on a loaded robot lifts its load, the next on any
    /// robot puts it down there.
    Move { cells: Vec<u64> },
}

/// The form of a load action, whatever the state.
enum Change {
    Set(f64),
    /// Lifts the named robot's load when none is held, else puts the held load down there.
    Move,
}

/// The cells of a load action and its change, checked for form only (whatever the state):
/// whether the cells hold robots depends on the state when it is applied.
fn parse_form(action: &Action) -> Result<(Vec<u64>, Change)> {
    let (cells, change) = match kumiki_model::error::from_action(action)? {
        LoadAction::Load { cells, force } => {
            if !(force.is_finite() && (0.0..=MAX_FORCE).contains(&force)) {
                return Err(Error::field(
                    "force",
                    format!("must be a number of newtons from 0 to {MAX_FORCE}"),
                ));
            }
            (cells, Change::Set(force))
        }
        LoadAction::Unload { cells } => (cells, Change::Set(0.0)),
        LoadAction::Move { cells } => {
            if cells.len() != 1 {
                return Err(Error::field("cells", "a move names one cell per click"));
            }
            (cells, Change::Move)
        }
    };
    if cells.is_empty() {
        return Err(Error::field("cells", "name at least one cell"));
    }
    Ok((cells, change))
}

/// Checks the form of a load action, whatever the state.
pub(super) fn check_load(action: &Action) -> Result<()> {
    parse_form(action).map(|_| ())
}

impl Chobie {
    /// The robots the action names in the present state, and its change.
    fn parse_load(&self, action: &Action) -> Result<(Vec<u32>, Change)> {
        let (cells, change) = parse_form(action)?;
        let lifts = matches!(change, Change::Move) && self.held <= 0.0;
        let mut robots = Vec::with_capacity(cells.len());
        for (k, &c) in cells.iter().enumerate() {
            let r = usize::try_from(c)
                .ok()
                .and_then(|c| self.body.occ.get(c).copied())
                .unwrap_or(NONE);
            if r == NONE {
                return Err(Error::field(
                    format!("cells[{k}]"),
                    format!("cell {c} holds no robot"),
                ));
            }
            if lifts && self.loads[r as usize] <= 0.0 {
                return Err(Error::field(
                    format!("cells[{k}]"),
                    format!("the robot at cell {c} carries no load to move"),
                ));
            }
            robots.push(r);
        }
        Ok((robots, change))
    }

    pub(super) fn apply_load(&mut self, action: &Action) -> Result<()> {
        let (robots, change) = self.parse_load(action)?;
        for r in robots {
            let load = &mut self.loads[r as usize];
            match change {
                Change::Set(force) => *load = force,
                Change::Move if self.held > 0.0 => {
                    *load += self.held;
                    self.held = 0.0;
                }
                Change::Move => {
                    self.held = *load;
                    *load = 0.0;
                }
            }
        }
        self.solve();
        Ok(())
    }
}
