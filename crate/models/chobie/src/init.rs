//! The scenario's description checked, and the model built from it.

use super::actions;
use super::election::{Kind, Mode};
use super::motion::Body;
use super::spec::{self, Mechanics, Spec, Task, World};
use super::{Chobie, Last, Params, Totals};
use kumiki_model::error::Result;
use kumiki_model::limits::Limits;
use kumiki_model::model::{self, Action, Model};

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

/// A description whose every key is checked, with its world read from the text.
#[derive(Clone)]
pub struct Checked {
    spec: Spec,
    world: World,
    mech: Mechanics,
    tip_load: f64,
    hop_us: f64,
}

impl model::Spec for Spec {
    type Checked = Checked;

    fn validate(&self, limits: &Limits) -> Result<Checked> {
        let world = spec::parse_world(&self.world, self.extend, limits)?;
        let mech = Mechanics::from_spec(self)?;
        let (tip_load, hop_us) = (self.tip_load, self.hop_us);
        Ok(Checked {
            spec: self.clone(),
            world,
            mech,
            tip_load,
            hop_us,
        })
    }

    fn check_action(_: &Checked, action: &Action) -> Result<()> {
        actions::check_load(action)
    }

    fn build(checked: Checked, _seed: u64) -> Box<dyn Model> {
        Box::new(Chobie::from_checked(checked))
    }
}

impl Chobie {
    /// The model at step 0. Nothing in it is random, so it takes no seed.
    pub fn from_checked(checked: Checked) -> Chobie {
        let Checked {
            spec: s,
            world,
            mech,
            tip_load,
            hop_us,
        } = checked;
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
                anchored: s.anchored,
                mech,
                order: PRIORITY,
            },
            loads: vec![0.0; n],
            held: 0.0,
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
            failure: super::Failure::Standing,
            resumed: 0,
            band: super::frame::Scratch::default(),
            leader: Default::default(),
            stopped: None,
        };
        model.solve();
        model
    }
}
