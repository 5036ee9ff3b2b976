//! What the page draws and shows: the layout (legends, fields, tools), the cell codes, the
//! field values, the robots, and the inspector's words about a cell.

use std::borrow::Cow;

use serde_json::{json, Map, Value};

use super::field::{Field, FAR};
use super::state::{self, code, MODULE, REMOVE};
use super::{
    Amas, FieldKind, EV_COLLISION, EV_RELAY, LOADED, LOADED_LOST, NONE, UNLOADED, UNLOADED_LOST,
};
use kumiki_model::lattice::LatticeKind;
use kumiki_model::model::{Action, Agent, FieldInfo, Layout, LegendEntry, ToolInfo};

impl Amas {
    pub(super) fn describe_layout(&self) -> Layout {
        let mut fields = match self.p.field {
            FieldKind::Continuous => vec![FieldInfo {
                name: "potential".into(),
                label: "potential (eq. 1): 1 at the growth front, 0 at the supply".into(),
                arrows: true,
            }],
            FieldKind::Discrete => vec![
                FieldInfo {
                    name: "to_front".into(),
                    label: "distance to the growth front (eq. 2)".into(),
                    arrows: true,
                },
                FieldInfo {
                    name: "to_supply".into(),
                    label: "distance to the supply (eq. 2)".into(),
                    arrows: true,
                },
            ],
        };
        fields.push(FieldInfo {
            name: "collisions".into(),
            label: "collisions per cell so far (the cell a robot wanted when it had to wait)"
                .into(),
            arrows: false,
        });
        Layout {
            lattice: LatticeKind::Square,
            dims: [self.w as u32, self.h as u32, 1],
            cells: vec![
                LegendEntry::new(code::VACANT, "target (vacant)", "#dfe6ee"),
                LegendEntry::new(code::SUPPLY, "supply", "#c9a66b"),
                LegendEntry::new(code::SUPPLY_FRONT, "supply at the growth front", "#d9822b"),
                LegendEntry::new(code::MODULE, "module", "#5b7083"),
                LegendEntry::new(code::FRONT, "growth front", "#2b95d6"),
                LegendEntry::new(
                    code::DISASSEMBLY_SUPPLY,
                    "supply (next to a module to remove)",
                    "#a67c52",
                ),
                LegendEntry::new(code::TO_REMOVE, "to be removed", "#c274c2"),
                LegendEntry::new(code::BROKEN, "communication broken", "#30404d"),
            ],
            agents: vec![
                LegendEntry::new(UNLOADED, "robot", "#f2f2f2"),
                LegendEntry::new(LOADED, "robot carrying a module", "#f29d49"),
                LegendEntry::new(UNLOADED_LOST, "robot, no gradient (random move)", "#b8c4ce"),
                LegendEntry::new(
                    LOADED_LOST,
                    "robot carrying, no gradient (random move)",
                    "#c98a4b",
                ),
            ],
            events: vec![
                LegendEntry::new(EV_COLLISION, "collision", "#db3737"),
                LegendEntry::new(EV_RELAY, "module relay", "#0f9960"),
            ],
            fields,
            tools: vec![
                ToolInfo {
                    name: "remove".into(),
                    label: "Remove module (5.4)".into(),
                    action: action(json!({"kind": "remove"})),
                },
                ToolInfo {
                    name: "break".into(),
                    label: "Break communication (5.5)".into(),
                    action: action(json!({"kind": "break"})),
                },
                ToolInfo {
                    name: "dismantle".into(),
                    label: "Mark to be removed (6.2)".into(),
                    action: action(json!({"kind": "dismantle"})),
                },
                ToolInfo {
                    name: "extend".into(),
                    label: "Add target cell".into(),
                    action: action(json!({"kind": "extend"})),
                },
            ],
            cell_labels: false,
            chart: "built".into(),
            goal: true,
        }
    }

    pub(super) fn cell_codes(&self) -> Cow<'_, [u8]> {
        Cow::Borrowed(&self.display)
    }

    pub(super) fn field_values(&self, name: &str) -> Option<Cow<'_, [f32]>> {
        let on = |i: usize| self.state[i] & MODULE != 0;
        if name == "collisions" {
            // Modules show 0 until a collision happens on them; other cells show their count
            // only once a collision happened there (a contested placement site), so the empty
            // air stays undrawn.
            let mut heat: Vec<f32> = (0..self.state.len())
                .map(|i| if on(i) { 0.0 } else { f32::NAN })
                .collect();
            for (&i, &c) in &self.collision_cells {
                heat[i as usize] = c as f32;
            }
            return Some(Cow::Owned(heat));
        }
        match (&self.field, name) {
            (Field::Continuous { p, .. }, "potential") => Some(Cow::Owned(
                p.iter()
                    .enumerate()
                    .map(|(i, &v)| if on(i) { v } else { f32::NAN })
                    .collect(),
            )),
            (
                Field::Discrete {
                    to_supply,
                    to_front,
                    ..
                },
                "to_supply" | "to_front",
            ) => {
                let src = if name == "to_supply" {
                    to_supply
                } else {
                    to_front
                };
                Some(Cow::Owned(
                    src.iter()
                        .enumerate()
                        .map(|(i, &v)| {
                            if on(i) && v != FAR {
                                f32::from(v)
                            } else {
                                f32::NAN
                            }
                        })
                        .collect(),
                ))
            }
            _ => None,
        }
    }

    pub(super) fn agent_list(&self) -> Vec<Agent> {
        self.robots
            .iter()
            .map(|r| Agent {
                cell: r.cell,
                kind: match (r.loaded, r.lost) {
                    (false, false) => UNLOADED,
                    (true, false) => LOADED,
                    (false, true) => UNLOADED_LOST,
                    (true, true) => LOADED_LOST,
                },
            })
            .collect()
    }

    pub(super) fn inspect_cell(&self, i: usize) -> Map<String, Value> {
        let mut m = Map::new();
        if i >= self.state.len() {
            return m;
        }
        let s = self.state[i];
        m.insert("x".into(), (i % self.w).into());
        m.insert("y".into(), (i / self.w).into());
        m.insert("cell".into(), state::describe(s).into());
        let on = s & MODULE != 0;
        match &self.field {
            Field::Continuous { p, .. } => {
                m.insert(
                    "potential".into(),
                    if on { json!(p[i]) } else { Value::Null },
                );
            }
            Field::Discrete {
                to_supply,
                to_front,
                ..
            } => {
                let show = |v: u16| {
                    if on && v != FAR {
                        v.into()
                    } else {
                        Value::Null
                    }
                };
                m.insert("to_supply".into(), show(to_supply[i]));
                m.insert("to_front".into(), show(to_front[i]));
            }
        }
        let collisions = self.collision_cells.get(&(i as u32)).copied().unwrap_or(0);
        m.insert("collisions".into(), collisions.into());
        if s & REMOVE != 0 {
            m.insert("removable".into(), self.removable(i).into());
        }
        if self.occupant[i] != NONE {
            let r = self.occupant[i] as usize;
            m.insert("robot".into(), r.into());
            m.insert("loaded".into(), self.robots[r].loaded.into());
            m.insert("busy".into(), self.robots[r].busy.into());
        }
        m
    }
}

pub(super) fn action(value: Value) -> Action {
    match value {
        Value::Object(m) => m,
        _ => Map::new(),
    }
}
