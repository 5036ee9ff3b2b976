//! The model built from its scenario.

use super::election::{Kind, Mode};
use super::motion::Body;
use super::spec::{self, Mechanics, Spec, Task};
use super::{Chobie, Last, Params, Totals};
use crate::error::Result;
use crate::models;
use crate::scenario::Scenario;

/// The priority sequence of figure 18, highest first: the vertical commands (lift the left
/// end, lower the right end) before the horizontal ones. Figure 18 is not in the text; of the
/// 24 orders, those that put top + left ahead of top + right let the most two-tier forms with
/// several leaders crawl (`tests::priority_sequence_lets_form_d_crawl`).
pub const PRIORITY: [Kind; 4] = [
    Kind::TopLeft,
    Kind::BottomRight,
    Kind::TopRight,
    Kind::BottomLeft,
];

/// The largest goal, in cells.
pub const MAX_GOAL: u32 = 100_000;

impl Chobie {
    pub fn new(scenario: &Scenario) -> Result<Chobie> {
        let s: Spec = models::body(scenario)?;
        let world = spec::parse_world(&s.world, s.extend)?;
        let mech = Mechanics::from_spec(&s)?;
        let tip_load = spec::non_negative("tip_load", s.tip_load, 1e7)?;
        let hop_us = spec::positive("hop_us", s.hop_us, 1e9)?;
        if let Some(g) = s.goal {
            if g == 0 || g > MAX_GOAL {
                return Err(crate::Error::field(
                    "goal",
                    format!("must be from 1 to {MAX_GOAL} cells"),
                ));
            }
        }
        let body = Body::from_world(&world);
        let lowest = body.pos.iter().map(|p| p.1).max().unwrap_or(0);
        let left = body
            .pos
            .iter()
            .filter(|p| p.1 == lowest)
            .map(|p| p.0)
            .min()
            .unwrap_or(0);
        let mut edge = left;
        while body.ground_at(edge + 1, lowest + 1) {
            edge += 1;
        }
        let n = body.len();
        let mut model = Chobie {
            start_x: body.centre_x(),
            body,
            p: Params {
                task: s.task,
                leader: s.leader,
                method: s.method,
                priority: s.priority,
                adaptation: s.adaptation,
                construction: s.construction,
                goal: s.goal,
                tip_load,
                hop_us,
                mech,
                order: PRIORITY,
            },
            loads: vec![0.0; n],
            mode: match s.task {
                Task::Crawl => Mode::Crawl,
                Task::Bridge => Mode::Construction,
            },
            steps: 0,
            totals: Totals::default(),
            last: Last::default(),
            permanent: 0,
            edge,
            stress: vec![0.0; n],
            disp: vec![[0.0; 3]; n],
            worst: 0.0,
        };
        model.solve();
        Ok(model)
    }
}
