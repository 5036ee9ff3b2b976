//! The simulation handle ([`Sim`]) and a bare run for the benchmarks ([`Stepper`]).

use js_sys::{Float32Array, Uint32Array, Uint8Array};
use kumiki_core::models::Scene;
use kumiki_core::playback::Playback;
use kumiki_core::{grading, hash, json, Run, Scenario};
use serde_json::Value;
use wasm_bindgen::prelude::*;

use crate::{js_err, to_js, Draft};

/// `performance.now()` of the page or worker, in milliseconds; `None` where there is none.
fn clock() -> Option<js_sys::Function> {
    let performance = js_sys::Reflect::get(&js_sys::global(), &"performance".into()).ok()?;
    let now = js_sys::Reflect::get(&performance, &"now".into()).ok()?;
    Some(now.dyn_into::<js_sys::Function>().ok()?.bind0(&performance))
}

/// One running simulation, with the keyframes that let it go back: a
/// [`Playback`](kumiki_core::playback::Playback), which keeps the run, its keyframes and its
/// chart record, read by the page's clock.
#[wasm_bindgen]
pub struct Sim {
    playback: Playback,
    clock: Option<js_sys::Function>,
    /// The scene the last frame carried, so a frame carries it only when it changed.
    last_scene: Option<Scene>,
}

impl Sim {
    pub(crate) fn run(&self) -> &Run {
        self.playback.run()
    }

    fn playing(run: Run) -> Sim {
        Sim {
            playback: Playback::new(run),
            clock: clock(),
            last_scene: None,
        }
    }
}

#[wasm_bindgen]
impl Sim {
    /// A run of scenario JSON, read and checked here (one too large for the draft to check at
    /// once, or a comparison's second run).
    #[wasm_bindgen(constructor)]
    pub fn new(scenario_json: &str) -> Result<Sim, JsError> {
        let scenario = Scenario::from_json(scenario_json).map_err(js_err)?;
        Ok(Sim::playing(Run::new(scenario).map_err(js_err)?))
    }

    /// A run of the scenario in view, built from what the draft checked: nothing is read or
    /// checked again (see `kumiki_core::draft::Draft::start`).
    pub fn start(draft: &mut Draft) -> Result<Sim, JsError> {
        Ok(Sim::playing(draft.draft.start().map_err(js_err)?))
    }

    /// The run as it stands, for the page's panels: a `Frame` (web/contract.gen.ts), with the
    /// state hash when `hashed`, the record of `chart` merged into at most `points` points when
    /// given, and the model's scene when it changed since the last frame (always in the first).
    pub fn frame(
        &mut self,
        hashed: bool,
        chart: Option<String>,
        points: u32,
    ) -> Result<JsValue, JsError> {
        let chart = chart.as_deref().map(|metric| (metric, points as usize));
        let mut frame = self.playback.frame(hashed, chart);
        let scene = self.run().model().scene();
        if self.last_scene.as_ref() != Some(&scene) {
            frame.scene = Some(scene.clone());
            self.last_scene = Some(scene);
        }
        to_js(&frame)
    }

    /// Takes up to `n` steps, keeping keyframes and every step's metrics; returns how many were
    /// taken.
    pub fn advance(&mut self, n: u32) -> u32 {
        let clock = &self.clock;
        let mut now = || {
            clock
                .as_ref()
                .and_then(|f| f.call0(&JsValue::NULL).ok())
                .and_then(|v| v.as_f64())
                .unwrap_or(0.0)
        };
        self.playback.advance(u64::from(n), &mut now) as u32
    }

    /// Goes to `step` (at most the furthest step reached) by replaying from the keyframe before
    /// it: the state is bit-identical to the one passed through.
    pub fn seek(&mut self, step: f64) {
        self.playback.seek(step.max(0.0) as u64);
    }

    pub fn steps(&self) -> f64 {
        self.run().steps() as f64
    }

    /// Why a rule's script stopped the run (the rule, the line and the cap), or undefined.
    pub fn stopped(&self) -> Option<String> {
        self.run().stopped().map(str::to_string)
    }

    pub fn finished(&self) -> bool {
        self.run().finished()
    }

    /// The 64-bit state hash in hex.
    pub fn hash(&self) -> String {
        hash::hex(self.run().state_hash())
    }

    /// Lattice, legends, fields and tools: see `kumiki_core::models::Layout`.
    pub fn layout(&self) -> Result<JsValue, JsError> {
        to_js(&self.run().model().layout())
    }

    pub fn metrics(&self) -> Result<JsValue, JsError> {
        to_js(&self.run().model().metrics())
    }

    /// One code per cell (a copy, for tests and tools: the page's view reads the model in place,
    /// see [`Viewer`](crate::Viewer)).
    pub fn cells(&self) -> Uint8Array {
        Uint8Array::from(self.run().model().cells().as_ref())
    }

    /// One value per cell (a copy), NaN where undefined; undefined for an unknown field.
    pub fn field(&self, name: &str) -> Option<Float32Array> {
        self.run()
            .model()
            .field(name)
            .map(|values| Float32Array::from(values.as_ref()))
    }

    /// Agents as `[cell, kind, cell, kind, ...]`.
    pub fn agents(&self) -> Uint32Array {
        let flat: Vec<u32> = self
            .run()
            .model()
            .agents()
            .iter()
            .flat_map(|a| [a.cell, u32::from(a.kind)])
            .collect();
        Uint32Array::from(flat.as_slice())
    }

    /// Events of the last step as `[cell, kind, ...]`.
    pub fn events(&self) -> Uint32Array {
        let flat: Vec<u32> = self
            .run()
            .model()
            .events()
            .iter()
            .flat_map(|e| [e.cell, u32::from(e.kind)])
            .collect();
        Uint32Array::from(flat.as_slice())
    }

    /// The code of one cell (0: empty or off the lattice).
    pub fn cell_code(&self, cell: u32) -> u8 {
        self.run()
            .model()
            .cells()
            .get(cell as usize)
            .copied()
            .unwrap_or(0)
    }

    /// The middle occupied cell in memory order (where a keyboard cursor starts), or -1.
    pub fn middle_occupied(&self) -> f64 {
        let cells = self.run().model().cells();
        let occupied = cells.iter().filter(|&&c| c != 0).count();
        let nth = cells
            .iter()
            .enumerate()
            .filter(|(_, &c)| c != 0)
            .nth(occupied / 2);
        nth.map_or(-1.0, |(i, _)| i as f64)
    }

    /// Applies an action now (a click tool) and records it in the scenario; a click in the past
    /// forks the run (see `kumiki_core::playback::Playback::apply`).
    pub fn apply(&mut self, action_json: &str) -> Result<(), JsError> {
        let action: Value = json::parse(action_json).map_err(js_err)?;
        let Value::Object(action) = action else {
            return Err(JsError::new("an action is a JSON object"));
        };
        self.playback.apply(action).map_err(js_err)
    }

    /// What the exercise in view says of a click of `kind` (the tool `label`) made now, as
    /// [`Sim::apply`] would judge it: a `ClickState` (`problem`: why it is refused, or null;
    /// `left`: how many more of its kind may be added, null without an exercise). A click
    /// rewound past no longer counts.
    pub fn click_state(&self, kind: &str, label: &str) -> Result<JsValue, JsError> {
        let (problem, left) = self.playback.click_state(kind, label);
        to_js(&serde_json::json!({ "problem": problem, "left": left }))
    }

    /// Bonds as one bit mask per cell (bit d: bonded to the neighbour in lattice direction d);
    /// empty for models without bonds. See `kumiki_core::models::Model::bonds`.
    pub fn bonds(&self) -> Uint8Array {
        Uint8Array::from(self.run().model().bonds().as_ref())
    }

    pub fn inspect(&self, cell: u32) -> Result<JsValue, JsError> {
        to_js(&self.run().model().inspect(cell as usize))
    }

    /// Ghost cells, light direction, ground plane and bonds for 3-D views (see
    /// `kumiki_core::models::Scene`); empty for models without them. Read it again after stepping:
    /// the ghost follows the current target.
    pub fn scene(&self) -> Result<JsValue, JsError> {
        to_js(&self.run().model().scene())
    }

    /// The scenario as it now stands, with clicked disturbances recorded.
    pub fn scenario_json(&self) -> String {
        self.run().scenario().to_json_pretty()
    }

    /// The exercise's verdict on the run as it stands: `{met, because}` with its points (a
    /// `Verdict`), or undefined when the scenario is no exercise. A scenario that broke a rule of
    /// its exercise (a locked field, a disturbance it does not allow) is never "Goal met".
    pub fn check_goal(&self) -> Result<JsValue, JsError> {
        match grading::verdict(self.run()) {
            Some(verdict) => to_js(&verdict),
            None => Ok(JsValue::UNDEFINED),
        }
    }
}

/// A bare run, without the keyframes and chart record a [`Sim`] keeps: the work `kumiki bench`
/// times natively, so `npm run bench` compares like with like.
#[wasm_bindgen]
pub struct Stepper {
    run: Run,
}

#[wasm_bindgen]
impl Stepper {
    #[wasm_bindgen(constructor)]
    pub fn new(scenario_json: &str) -> Result<Stepper, JsError> {
        let scenario = Scenario::from_json(scenario_json).map_err(js_err)?;
        Ok(Stepper {
            run: Run::new(scenario).map_err(js_err)?,
        })
    }

    /// Takes up to `n` steps; returns how many were taken.
    pub fn advance(&mut self, n: u32) -> u32 {
        self.run.advance(u64::from(n)) as u32
    }
}
