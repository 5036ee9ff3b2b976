//! Faults as actions (section 4): reading and checking them.

use super::*;
use schemars::JsonSchema;

impl Fracta {
    /// The working unit on a cell named by an action.
    pub(super) fn working_unit_at(&self, cell: u64) -> Result<u32> {
        let u = self.occ[cell as usize];
        if u == NO_UNIT || self.units[u as usize].status != Status::Working {
            return Err(Error::field(
                "cells",
                format!("cell {cell} holds no working unit"),
            ));
        }
        Ok(u)
    }
}

pub(super) enum Fault {
    Cells(Vec<u64>),
    Unit(u32),
}

/// A fault (section 4): `{"kind": "fault", "unit": 3}` cuts the power of unit 3 (units are
/// numbered in reading order of the start shape); `{"kind": "fault", "cells": [i]}` of the unit
/// on lattice cell i (the click tool).
#[derive(Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase", deny_unknown_fields)]
#[schemars(tag = "kind")]
#[schemars(rename = "FractaDisturbance")]
pub(super) enum FaultAction {
    /// Cuts the power of a unit, named by `unit` (its number in reading order of the start
    /// shape) or by the lattice cell it is on (`cells`).
    Fault {
        #[serde(default)]
        cells: Option<Vec<u64>>,
        #[serde(default)]
        unit: Option<u64>,
    },
}

/// Reads a fault action. Only what holds at any step is checked here (the kind, cells inside
/// the lattice, an existing unit number), since a scheduled fault is checked against the
/// starting state; whether a working unit is there is checked when it is applied.
pub(super) fn parse_fault(action: &Action, cells_in_lattice: usize, units: usize) -> Result<Fault> {
    let FaultAction::Fault { cells, unit } = kumiki_model::error::from_action(action)?;
    match (cells, unit) {
        (Some(cells), None) => {
            if cells.is_empty() {
                return Err(Error::field("cells", "name at least one cell"));
            }
            if let Some(c) = cells.iter().find(|&&c| c >= cells_in_lattice as u64) {
                return Err(Error::field(
                    "cells",
                    format!("cell {c} is outside the lattice"),
                ));
            }
            Ok(Fault::Cells(cells))
        }
        (None, Some(u)) => {
            if u >= units as u64 {
                return Err(Error::field(
                    "unit",
                    format!(
                        "there is no unit {u}; units are numbered 0 to {} in reading order of the start shape",
                        units - 1
                    ),
                ));
            }
            Ok(Fault::Unit(u as u32))
        }
        _ => Err(Error::field(
            "",
            "give either cells (lattice cell indices) or unit (a unit number)",
        )),
    }
}
