//! What the page draws and shows: the layout (legends, fields, tools), the scene (ghost, light,
//! ground), the bonds, the metrics, the field values and the inspector's words about a cell.

use std::borrow::Cow;

use serde_json::{json, Map, Value};

use super::connect::Scratch;
use super::motion::DIRS;
use super::spec::Ground;
use super::typelist::TypeList;
use super::types::{CODES, NAMES};
use super::{Cubes, ARRIVED, HELD_LIT, HELD_USER, LEFT};
use kumiki_model::lattice::LatticeKind;
use kumiki_model::model::{FieldInfo, Layout, LegendEntry, Metric, Scene, ToolInfo};

/// Cell colours by connection type, code 1 (C1) to 9 (C6).
const COLOURS: [&str; CODES] = [
    "", "#e15759", "#f28e2b", "#edc948", "#59a14f", "#4e79a7", "#76b7b2", "#b07aa1", "#ff9da7",
    "#9c755f",
];

impl Cubes {
    pub(super) fn describe_layout(&self) -> Layout {
        let tool = |name: &str, label: &str| ToolInfo {
            name: name.into(),
            label: label.into(),
            action: json!({ "kind": name })
                .as_object()
                .cloned()
                .unwrap_or_default(),
        };
        let mut tools = vec![
            tool("remove", "Remove unit"),
            tool("add", "Add unit"),
            tool("hold", "Hold / release unit"),
        ];
        if self.targets.len() > 1 {
            tools.push(tool("switch", "Switch target"));
        }
        let mut fields = vec![
            FieldInfo {
                name: "difference".into(),
                label: "difference D from the target (eq. 4)".into(),
                arrows: false,
            },
            FieldInfo {
                name: "movable".into(),
                label: "may move (1) or not (0)".into(),
                arrows: false,
            },
            FieldInfo {
                name: "reachable".into(),
                label: "number of reachable positions".into(),
                arrows: false,
            },
        ];
        if self.light.is_some() {
            fields.push(FieldInfo {
                name: "lit".into(),
                label: "sees the light (1) or not (0)".into(),
                arrows: false,
            });
        }
        Layout {
            lattice: LatticeKind::Cubic,
            dims: self.st.dims,
            cells: (1..CODES)
                .map(|c| LegendEntry::new(c as u8, NAMES[c], COLOURS[c]))
                .collect(),
            agents: Vec::new(),
            events: vec![
                LegendEntry::new(ARRIVED, "unit arrived", "#2b95d6"),
                LegendEntry::new(LEFT, "unit left", "#db3737"),
            ],
            fields,
            tools,
            cell_labels: true,
            goal: self.stop_at_goal && self.targets.len() == 1,
            chart: if self.light.is_some() {
                "displacement"
            } else {
                "mean_difference"
            }
            .into(),
        }
    }

    pub(super) fn describe_scene(&self) -> Scene {
        Scene {
            ghost: self.targets[self.main_target()].ghost.clone(),
            light: self.light.map(|d| DIRS[d].map(|v| v as f32)),
            ground: (self.ground != Ground::Open).then_some(self.floor_z as u32),
        }
    }

    /// Every pair of face-adjacent units is bonded (a unit connects to all its neighbours).
    pub(super) fn bond_masks(&self) -> Cow<'_, [u8]> {
        let mut masks = vec![0u8; self.st.len()];
        for &c in &self.units {
            let c = c as usize;
            for d in 0..6 {
                if self.st.types[self.st.nb(c, d)] != 0 {
                    masks[c] |= 1 << d;
                }
            }
        }
        Cow::Owned(masks)
    }

    pub(super) fn each_metric_value(&self, f: &mut dyn FnMut(&'static str, Metric)) {
        let n = self.units.len();
        f("steps", Metric::Count(self.steps));
        f("moves", Metric::Count(self.moves));
        f("units", Metric::Count(n as u64));
        f(
            "mean_difference",
            Metric::Real(self.total_difference() / n as f64),
        );
        f("matched", Metric::Real(self.zero as f64 / n as f64));
        f("completed", Metric::Count(u64::from(self.zero == n)));
        if self.targets.len() == 1 {
            f(
                "reached",
                self.reached.map_or(Metric::Missing, Metric::Count),
            );
        }
        f("movable", Metric::Count(self.movable.len() as u64));
        f("connectivity_checks", Metric::Count(self.scratch.checks));
        f(
            "connectivity_searches",
            Metric::Count(self.scratch.searches),
        );
        f(
            "connectivity_search_cells",
            Metric::Count(self.scratch.search_cells),
        );
        if self.targets.len() > 1 {
            f("target", Metric::Count(self.main_target() as u64));
            f("switches", Metric::Count(self.switches));
        }
        if self.light.is_some() {
            f(
                "displacement",
                Metric::Real(self.light_position() - self.start_light),
            );
            f("moves_toward", Metric::Count(self.moves_toward));
            f("moves_away", Metric::Count(self.moves_away));
        }
    }

    pub(super) fn field_values(&self, name: &str) -> Option<Cow<'_, [f32]>> {
        let per_unit = |f: &dyn Fn(usize) -> f32| -> Cow<'_, [f32]> {
            let mut out = vec![f32::NAN; self.st.len()];
            for &c in &self.units {
                out[c as usize] = f(c as usize);
            }
            Cow::Owned(out)
        };
        match name {
            "difference" => Some(per_unit(&|c| self.d0(c) as f32)),
            "movable" => Some(per_unit(&|c| f32::from(u8::from(self.eligible(c))))),
            "reachable" => {
                let mut s = Scratch::default();
                let mut out = vec![f32::NAN; self.st.len()];
                for &c in &self.units {
                    let c = c as usize;
                    out[c] = if self.eligible(c) {
                        self.st.reachable(c, &mut s);
                        s.moves.len() as f32
                    } else {
                        0.0
                    };
                }
                Some(Cow::Owned(out))
            }
            "lit" if self.light.is_some() => Some(per_unit(&|c| f32::from(u8::from(self.lit(c))))),
            _ => None,
        }
    }

    pub(super) fn inspect_cell(&self, i: usize) -> Map<String, Value> {
        let mut m = Map::new();
        if i >= self.st.len() {
            return m;
        }
        let c = self.st.coord(i);
        m.insert("x".into(), c[0].into());
        m.insert("y".into(), c[1].into());
        m.insert("z".into(), c[2].into());
        let target = &self.targets[if self.st.occupied(i) {
            self.target[i] as usize
        } else {
            self.main_target()
        }];
        if !target.name.is_empty() {
            m.insert("target".into(), target.name.clone().into());
        }
        if !self.st.occupied(i) {
            m.insert("unit".into(), false.into());
            m.insert("ghost".into(), target.ghost.contains(&(i as u32)).into());
            return m;
        }
        m.insert("unit".into(), true.into());
        let prof = self.st.profile(i);
        let list = TypeList::new(
            prof[0],
            prof[1..].iter().copied().filter(|&t| t != 0).collect(),
        );
        m.insert("type".into(), NAMES[prof[0] as usize].into());
        m.insert("type_list".into(), list.to_string().into());
        m.insert("difference".into(), json!(self.d0(i)));
        m.insert("movable".into(), self.eligible(i).into());
        m.insert("fixed".into(), self.fixed(i).into());
        m.insert(
            "held".into(),
            (self.flags[i] & (HELD_LIT | HELD_USER) != 0).into(),
        );
        if self.light.is_some() {
            m.insert("lit".into(), self.lit(i).into());
        }
        let reach = if self.eligible(i) {
            self.reach_report(i)
        } else {
            Vec::new()
        };
        m.insert(
            "reachable".into(),
            reach.iter().map(|r| Value::from(r.0)).collect(),
        );
        m.insert(
            "reachable_differences".into(),
            reach.iter().map(|r| json!(r.1)).collect(),
        );
        m
    }

    /// The difference and reachable positions (with the difference at each) of the unit at `p`.
    pub(super) fn reach_report(&self, p: usize) -> Vec<(u32, f64)> {
        let mut s = Scratch::default();
        self.st.reachable(p, &mut s);
        s.moves
            .iter()
            .map(|m| {
                (
                    m.dest,
                    self.difference(self.target[p], &self.st.profile_after(p, m.dest as usize)),
                )
            })
            .collect()
    }
}
