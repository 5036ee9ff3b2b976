//! Loads as actions: `{"kind": "load", "cells": [i, ...], "force": N}` puts a downward load of N
//! newtons on the robot at each cell (0 takes it off). A click in the page sends the same
//! action, so loads are recorded in the scenario and replayed by its link. A load stays with its
//! robot as the robot moves; moving a load is taking it off one robot and putting it on another.

use serde::Deserialize;

use super::motion::NONE;
use super::Chobie;
use crate::error::{from_value, Error, Result};
use crate::models::Action;

/// The largest load, newtons.
pub const MAX_FORCE: f64 = 1e6;

#[derive(Deserialize)]
#[serde(deny_unknown_fields, tag = "kind", rename_all = "lowercase")]
enum Load {
    Load { cells: Vec<u64>, force: f64 },
}

impl Chobie {
    pub(super) fn parse_load(&self, action: &Action) -> Result<(Vec<u64>, f64)> {
        let Load::Load { cells, force } = from_value(serde_json::Value::Object(action.clone()))?;
        if !(force.is_finite() && (0.0..=MAX_FORCE).contains(&force)) {
            return Err(Error::field(
                "force",
                format!("must be a number of newtons from 0 to {MAX_FORCE}"),
            ));
        }
        if cells.is_empty() {
            return Err(Error::field("cells", "name at least one cell"));
        }
        Ok((cells, force))
    }

    pub(super) fn apply_load(&mut self, action: &Action) -> Result<()> {
        let (cells, force) = self.parse_load(action)?;
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
            robots.push(r);
        }
        for r in robots {
            self.loads[r as usize] = force;
        }
        self.solve();
        Ok(())
    }
}
