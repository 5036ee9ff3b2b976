//! CHOBIE II: sliding cellular robots that crawl and build a load-adaptive bridge under
//! temporary leaders, after Suzuki, Inou, Kimura and Koseki. See `crate/models/chobie/README.md` for
//! the ODD description and every interpretation made.
//!
//! - [`spec`]: the scenario body and the world text;
//! - [`init`]: the model built from a scenario;
//! - [`motion`]: the lattice and line motion with its constraints;
//! - [`signals`]: time slots and messages;
//! - [`election`]: temporary leaders and their commands; [`leader`]: the rule slot `leader`,
//!   rule 3 of the election, which a scenario's script may take;
//! - [`frame`]: the plane-frame stress model;
//! - [`cycle`]: one transformation, phase by phase;
//! - [`view`], [`actions`], [`queries`]: what the page draws, the load tool, helper calls;
//! - [`paper`]: the paper's claims beside the experiments' figures.

use kumiki_model::entry::{self, ModelEntry};
use kumiki_model::model::Event;

pub mod actions;
pub mod cycle;
pub mod election;
pub mod frame;
pub mod init;
pub mod leader;
pub mod limits;
pub mod metrics;
pub mod motion;
pub mod paper;
pub mod queries;
pub mod signals;
pub mod spec;
pub mod view;

#[cfg(test)]
mod tests;

use election::{Elected, Mode};
use motion::Body;
use spec::{Leader, Mechanics, Method, Task};

pub const ENTRY: ModelEntry = ModelEntry {
    name: "chobie",
    title: "CHOBIE II: temporary leaders, crawl and load-adaptive bridges",
    default_max_steps: 200,
    model_version: 4,
    metrics: metrics::METRICS,
    limits: &limits::LIMITS,
    parse: entry::parse::<spec::Spec>,
    schema: entry::schema_of::<spec::Spec>(),
    disturbance: entry::schema_of::<actions::LoadAction>(),
    slots: &[<leader::Leader as kumiki_model::slot::Slot>::INFO],
    queries: &[
        entry::Query {
            name: "crawl",
            description: "The world text of a crawl form (figure 7): {\"robots\": odd n ≥ 3, \"form\": 1-4, \"margin\": empty columns}",
            run: queries::crawl,
        },
        entry::Query {
            name: "layers",
            description: "The world text's robots and terrain, each as a square shape: {\"world\": text} → {\"robots\", \"terrain\"}",
            run: queries::layers,
        },
        entry::Query {
            name: "merge",
            description: "Two square shapes, robots and terrain, merged into world text: {\"robots\", \"terrain\"} → {\"world\"}",
            run: queries::merge,
        },
    ],
    pins: &[],
};

/// The checked parameters a run uses.
#[derive(Clone, Copy, Debug)]
pub struct Params {
    pub task: Task,
    pub leader: Leader,
    pub method: Method,
    pub priority: bool,
    pub adaptation: bool,
    pub construction: bool,
    pub goal: Option<u32>,
    pub tip_load: f64,
    pub hop_us: f64,
    /// The base's guide holds the robots resting on it (no tipping).
    pub anchored: bool,
    pub mech: Mechanics,
    /// The priority sequence of figure 18.
    pub order: [election::Kind; 4],
}

impl Params {
    /// A leader kind's place in the priority sequence; a kind outside it comes last.
    pub fn rank(&self, kind: election::Kind) -> usize {
        self.order
            .iter()
            .position(|&o| o == kind)
            .unwrap_or(usize::MAX)
    }
}

/// Counters over the whole run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Totals {
    pub transformations: u64,
    pub slots: u64,
    pub messages: u64,
    /// Robot-cells driven.
    pub energy: u64,
    /// Elections in which an algorithm tried found no leader.
    pub election_failures: u64,
    /// Transformations whose commands could not be carried out.
    pub refused: u64,
    /// Transformations made in load-adaptation mode.
    pub adaptations: u64,
    /// Transformations in which a leader 1's command (section 3.4, step 7) moved.
    pub reinforcements: u64,
}

/// What the last step did, for metrics and the page.
#[derive(Clone, Debug, Default)]
pub struct Last {
    pub leaders: Vec<Elected>,
    pub driven: Vec<u32>,
    pub signals: Vec<Event>,
    /// The transformation's slots in order, with their senders.
    pub trace: Vec<signals::Slot>,
    pub slots: u64,
    pub messages: u64,
    pub moved: bool,
}

#[derive(Clone)]
pub struct Chobie {
    body: Body,
    p: Params,
    /// Applied loads per robot, newtons downward (the tip load comes on top).
    loads: Vec<f64>,
    /// A load lifted by the move tool and not yet put down, newtons.
    held: f64,
    mode: Mode,
    steps: u64,
    totals: Totals,
    last: Last,
    /// The fixed leader of the baseline.
    permanent: u32,
    start_x: f64,
    /// The last column of terrain under the starting structure (the cliff edge).
    edge: i32,
    stress: Vec<f64>,
    disp: Vec<[f64; 3]>,
    /// Largest peak stress seen so far, Pa.
    worst: f64,
    /// Whether the structure still stands; once failed it moves no more.
    failure: Failure,
    /// Times the robots went back from load adaptation to construction (the overload cleared).
    resumed: u64,
    /// The stress solver's band, kept from one step to the next.
    band: frame::Scratch,
    /// Rule 3 of the election: the paper's, or a scenario's script (the slot `leader`).
    leader: kumiki_model::slot::Rule<leader::Leader>,
    /// Why a script stopped the run, once one did.
    stopped: Option<String>,
}

/// A structure that broke or fell stays so.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Failure {
    Standing = 0,
    /// A robot's stress passed the tensile strength of ABS.
    Broken = 1,
    /// The weights and loads beyond the cliff edge turned the structure over it.
    Tipped = 2,
}
