//! The model seen from outside: what the page draws (cells, stress field, leaders, signals),
//! the metrics and the state hash.

use std::borrow::Cow;
use std::rc::Rc;

use serde_json::{json, Map, Value};

use super::election::{Kind, Mode};
use super::motion::NONE;
use super::signals::kind;
use super::Chobie;
use kumiki_model::error::Result;
use kumiki_model::hash::StateHasher;
use kumiki_model::lattice::LatticeKind;
use kumiki_model::model::{
    Action, Agent, CellMark, Event, FieldInfo, Layout, LegendEntry, Metric, Model, ToolInfo,
};
use kumiki_model::slot::Script;

/// Cell codes.
pub mod code {
    pub const EMPTY: u8 = 0;
    pub const TERRAIN: u8 = 1;
    /// R: a robot that rested in the last transformation.
    pub const RESTING: u8 = 2;
    /// D: a robot that drove in the last transformation.
    pub const DRIVING: u8 = 3;
    /// A robot whose stress is above the threshold.
    pub const OVERLOADED: u8 = 4;
    /// A robot carrying an applied load.
    pub const LOADED: u8 = 5;
    /// A robot of a structure that failed: stressed beyond the breaking stress, or any robot of
    /// a structure that tipped over the cliff edge.
    pub const FAILED: u8 = 6;
}

fn tool(name: &str, label: &str, action: Value) -> ToolInfo {
    ToolInfo {
        name: name.into(),
        label: label.into(),
        action: action.as_object().cloned().unwrap_or_default(),
    }
}

impl Model for Chobie {
    fn layout(&self) -> Layout {
        Layout {
            lattice: LatticeKind::Square,
            dims: [self.body.w, self.body.h, 1],
            cells: vec![
                LegendEntry::new(code::TERRAIN, "terrain", "#8a7a63"),
                LegendEntry::new(code::RESTING, "R: resting robot", "#bfccd6"),
                LegendEntry::new(code::DRIVING, "D: driving robot", "#2b95d6"),
                // Marked in every view, the stress field included, and named with the figures.
                LegendEntry::new(
                    code::OVERLOADED,
                    &format!(
                        "overloaded (ringed): stress over the {} MPa threshold",
                        self.p.mech.threshold / 1e6
                    ),
                    "#db3737",
                )
                .marked(CellMark::Ring),
                LegendEntry::new(code::LOADED, "robot carrying a load", "#f2b824"),
                LegendEntry::new(
                    code::FAILED,
                    &format!(
                        "failed (crossed): broken, over {} MPa, or tipped over the edge",
                        self.p.mech.strength / 1e6
                    ),
                    "#8e5cd9",
                )
                .marked(CellMark::Cross),
            ],
            agents: Kind::ALL
                .iter()
                .map(|k| LegendEntry::new(*k as u8, k.name(), k.color()))
                .collect(),
            events: vec![
                LegendEntry::new(kind::ELECTION, "election signal", "#9bbf30"),
                LegendEntry::new(kind::ANNOUNCE, "leader / completion relay", "#d1d5d8"),
                LegendEntry::new(kind::COMMAND, "drive command", "#2965cc"),
                LegendEntry::new(kind::OVERLOAD, "overload signal", "#c23030"),
                LegendEntry::new(kind::CHAIN, "load-adaptation relay", "#d9822b"),
                LegendEntry::new(kind::GATHER, "report to the permanent leader", "#8f398f"),
            ],
            fields: vec![
                FieldInfo {
                    name: "stress".into(),
                    label: "stress, MPa".into(),
                    arrows: false,
                },
                FieldInfo {
                    name: "utilisation".into(),
                    label: "stress / threshold".into(),
                    arrows: false,
                },
                FieldInfo {
                    name: "deflection".into(),
                    label: "vertical deflection, mm (down positive)".into(),
                    arrows: false,
                },
            ],
            tools: vec![
                tool("load", "Load (N)", json!({"kind": "load", "force": 100.0})),
                tool("move", "Move load", json!({"kind": "move"})),
                tool("unload", "Remove load", json!({"kind": "unload"})),
            ],
            cell_labels: false,
            chart: match self.p.task {
                super::spec::Task::Crawl => "distance".into(),
                super::spec::Task::Bridge => "peak_stress".into(),
            },
            // Without a goal distance or span, a crawl or a bridge simply runs its course.
            goal: self.p.goal.is_some(),
        }
    }

    fn step(&mut self) {
        if let Err(stop) = self.cycle() {
            self.stopped = Some(stop.0);
        }
        self.steps += 1;
    }

    fn install(&mut self, slot: &str, script: Rc<dyn Script>) -> Result<()> {
        match slot {
            "leader" => {
                self.leader.install(script);
                Ok(())
            }
            _ => Err(kumiki_model::Error::field(
                format!("rules.{slot}"),
                "CHOBIE II has one rule slot: leader",
            )),
        }
    }

    fn stopped(&self) -> Option<&str> {
        self.stopped.as_deref()
    }

    fn steps(&self) -> u64 {
        self.steps
    }

    fn completed(&self) -> bool {
        match (self.p.goal, self.p.task) {
            (None, _) => false,
            (Some(g), super::spec::Task::Crawl) => self.distance() >= g as f64 - 1e-9,
            // A bridge is done when it spans the goal and stands; with load adaptation, also
            // when no robot is overloaded (the next load check would switch to adaptation).
            (Some(g), super::spec::Task::Bridge) => {
                self.span() >= g as i64
                    && self.failure == super::Failure::Standing
                    && !(self.p.adaptation && self.peak() > self.p.mech.threshold)
            }
        }
    }

    fn each_metric(&self, f: &mut dyn FnMut(&'static str, Metric)) {
        let t = &self.totals;
        // Per transformation cycle (one step: election, command, move), moved or not.
        let per = |v: u64| match self.steps {
            0 => Metric::Missing,
            n => Metric::Real(v as f64 / n as f64),
        };
        let overloads = self.stress.iter().filter(|&&s| self.overloaded(s)).count();
        f("adaptations", Metric::Count(t.adaptations));
        f(
            "beam_theory_stress",
            Metric::Real(self.beam_theory_stress() / 1e6),
        );
        f("distance", Metric::Real(self.distance()));
        f("election_failures", Metric::Count(t.election_failures));
        f("energy", Metric::Count(t.energy));
        f("failed", Metric::Count(self.failure as u64));
        f("leaders", Metric::Count(self.last.leaders.len() as u64));
        f("max_peak_stress", Metric::Real(self.worst / 1e6));
        f("messages", Metric::Count(t.messages));
        f(
            "messages_per_robot",
            match self.steps {
                0 => Metric::Missing,
                n => Metric::Real(t.messages as f64 / n as f64 / self.body.len() as f64),
            },
        );
        f("messages_per_transformation", per(t.messages));
        f("mode", Metric::Count(self.mode as u64));
        f("overloads", Metric::Count(overloads as u64));
        f("overturning", Metric::Real(self.overturning()));
        f("peak_stress", Metric::Real(self.peak() / 1e6));
        f("refused", Metric::Count(t.refused));
        f("reinforcements", Metric::Count(t.reinforcements));
        f("reserves", Metric::Count(self.reserves() as u64));
        f("resumed", Metric::Count(self.resumed));
        f("robots", Metric::Count(self.body.len() as u64));
        f("slot_us", Metric::Real(self.slot_us()));
        f("slots", Metric::Count(t.slots));
        f("slots_per_transformation", per(t.slots));
        f("span", Metric::Count(self.span() as u64));
        f("stalled", Metric::Flag(!self.last.moved && self.steps > 0));
        f("strength", Metric::Real(self.p.mech.strength / 1e6));
        f("threshold", Metric::Real(self.p.mech.threshold / 1e6));
        f("transformations", Metric::Count(t.transformations));
    }

    fn hash_state(&self, h: &mut StateHasher) {
        for &(x, y) in &self.body.pos {
            h.u32(x as u32);
            h.u32(y as u32);
        }
        for &l in &self.loads {
            h.f64(l);
        }
        // Only while the move tool holds a load, so earlier states hash as before.
        if self.held > 0.0 {
            h.f64(self.held);
        }
        h.u8(self.mode as u8);
        // Only once the structure failed, so standing states hash as before.
        if self.failure != super::Failure::Standing {
            h.u8(self.failure as u8);
        }
        let t = &self.totals;
        for v in [
            t.transformations,
            t.slots,
            t.messages,
            t.energy,
            t.election_failures,
            t.refused,
            t.adaptations,
        ] {
            h.u64(v);
        }
        h.f64(self.worst);
    }

    fn cells(&self) -> Cow<'_, [u8]> {
        let mut out: Vec<u8> = self
            .body
            .ground
            .iter()
            .map(|&g| if g { code::TERRAIN } else { code::EMPTY })
            .collect();
        for (r, &(x, y)) in self.body.pos.iter().enumerate() {
            let Some(i) = self.body.index(x, y) else {
                continue;
            };
            let failed = match self.failure {
                super::Failure::Standing => false,
                super::Failure::Broken => self.stress[r] > self.p.mech.strength,
                super::Failure::Tipped => true,
            };
            out[i] = if failed {
                code::FAILED
            } else if self.overloaded(self.stress[r]) {
                code::OVERLOADED
            } else if self.last.driven.contains(&(r as u32)) {
                code::DRIVING
            } else if self.loads[r] > 0.0 || (r as u32 == self.tip() && self.p.tip_load > 0.0) {
                code::LOADED
            } else {
                code::RESTING
            };
        }
        Cow::Owned(out)
    }

    fn field(&self, name: &str) -> Option<Cow<'_, [f32]>> {
        let value: fn(&Chobie, usize) -> f32 = match name {
            "stress" => |m, r| (m.stress[r] / 1e6) as f32,
            "utilisation" => |m, r| (m.stress[r] / m.p.mech.threshold) as f32,
            "deflection" => |m, r| (-m.disp[r][1] * 1e3) as f32,
            _ => return None,
        };
        let mut out = vec![f32::NAN; self.body.occ.len()];
        for (r, &(x, y)) in self.body.pos.iter().enumerate() {
            if let Some(i) = self.body.index(x, y) {
                out[i] = value(self, r);
            }
        }
        Some(Cow::Owned(out))
    }

    fn agents(&self) -> Vec<Agent> {
        self.last
            .leaders
            .iter()
            .filter_map(|e| {
                let (x, y) = self.body.pos[e.robot as usize];
                self.body.index(x, y).map(|i| Agent {
                    cell: i as u32,
                    kind: e.kind as u8,
                })
            })
            .collect()
    }

    fn events(&self) -> Vec<Event> {
        self.last.signals.clone()
    }

    fn check_action(&self, action: &Action) -> Result<()> {
        super::actions::check_load(action)
    }

    fn apply(&mut self, action: &Action) -> Result<()> {
        self.apply_load(action)
    }

    fn inspect(&self, cell: usize) -> Map<String, Value> {
        let mut m = Map::new();
        if cell >= self.body.occ.len() {
            return m;
        }
        let x = (cell % self.body.w as usize) as i32;
        let y = (cell / self.body.w as usize) as i32;
        m.insert("x".into(), x.into());
        m.insert("y".into(), y.into());
        m.insert(
            "mode".into(),
            match self.mode {
                Mode::Crawl => "crawl",
                Mode::Construction => "bridge construction",
                Mode::Adaptation => "load adaptation",
            }
            .into(),
        );
        // The last transformation slot by slot, for the page's slot stepper: each slot's
        // meaning and its senders as (cell, lit faces) pairs.
        m.insert(
            "slots".into(),
            self.last
                .trace
                .iter()
                .map(|s| {
                    json!({
                        "meaning": s.meaning,
                        "count": s.count,
                        "signals": s.senders.iter().flat_map(|&(c, f)| [c, f as u32]).collect::<Vec<u32>>(),
                    })
                })
                .collect::<Vec<Value>>()
                .into(),
        );
        // Every robot's frame-node displacement in cells (x right, y down), for the page's
        // exaggerated deflection view.
        let length = self.p.mech.length;
        let mut displacement = Vec::with_capacity(3 * self.body.len());
        for (r, &(x, y)) in self.body.pos.iter().enumerate() {
            if let (Some(i), Some(d)) = (self.body.index(x, y), self.disp.get(r)) {
                displacement.extend([i as f64, d[0] / length, -d[1] / length]);
            }
        }
        m.insert("displacement".into(), json!(displacement));
        if self.held > 0.0 {
            m.insert("held_load_n".into(), json!(self.held));
        }
        let r = self.body.occ[cell];
        if r == NONE {
            if self.body.ground[cell] {
                m.insert("terrain".into(), true.into());
            }
            return m;
        }
        let ri = r as usize;
        m.insert("robot".into(), r.into());
        m.insert("stress_mpa".into(), json!(self.stress[ri] / 1e6));
        m.insert("overloaded".into(), self.overloaded(self.stress[ri]).into());
        m.insert(
            "structure".into(),
            match self.failure {
                super::Failure::Standing => "standing",
                super::Failure::Broken => "broken: a robot passed the breaking stress",
                super::Failure::Tipped => "tipped over the cliff edge",
            }
            .into(),
        );
        m.insert("deflection_mm".into(), json!(-self.disp[ri][1] * 1e3));
        m.insert("load_n".into(), json!(self.loads[ri]));
        m.insert("on_terrain".into(), self.body.grounded(r).into());
        m.insert(
            "state".into(),
            if self.last.driven.contains(&r) {
                "D (drove)"
            } else {
                "R (rested)"
            }
            .into(),
        );
        if let Some(e) = self.last.leaders.iter().find(|e| e.robot == r) {
            m.insert("leader".into(), e.kind.name().into());
        }
        m
    }
}
