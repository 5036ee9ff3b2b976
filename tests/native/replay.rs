//! Clicks in the page are recorded in the scenario, so a copied link replays them. For every
//! preset and every click tool: click a cell part-way through a run, read the recorded scenario
//! back as a link would, replay it, and get the identical state.

use kumiki_core::{link, presets, Run};
use serde_json::json;

/// Steps before the click, and after it.
const BEFORE: u64 = 30;
const AFTER: u64 = 30;

#[test]
fn recorded_clicks_survive_a_link_and_replay_identically() {
    let mut exercised = 0;
    for name in presets::names() {
        let scenario = presets::scenario(name).unwrap();
        let probe = Run::new(scenario.clone()).unwrap();
        let tools = probe.model().layout().tools;
        let cells = probe.model().cells().len();
        for tool in tools {
            let mut live = Run::new(scenario.clone()).unwrap();
            live.advance(BEFORE);
            // The first cell, scanning from the middle, where this tool does something now.
            let clicked = (0..cells).map(|k| (k + cells / 2) % cells).find(|&cell| {
                let mut action = tool.action.clone();
                action.insert("cells".into(), json!([cell]));
                live.apply_now(action).is_ok()
            });
            let Some(cell) = clicked else { continue };
            live.advance(AFTER);
            let shared = link::encode(live.scenario());
            let reread = link::decode(&shared).unwrap_or_else(|e| {
                panic!(
                    "{name}: a link with a '{}' click on cell {cell} does not load: {e}",
                    tool.name
                )
            });
            let mut replay = Run::new(reread).unwrap();
            // A click on a finished run is recorded at its last step, and applied when the
            // replay reaches that step and steps on: run it to its end, as the page and the CLI do.
            match live.finished() {
                true => replay.run_to_end(),
                false => _ = replay.advance(live.steps()),
            }
            assert_eq!(
                replay.state_hash(),
                live.state_hash(),
                "{name}: '{}' on cell {cell} replays differently",
                tool.name
            );
            exercised += 1;
        }
    }
    assert!(
        exercised >= 6,
        "only {exercised} tool clicks were exercised"
    );
}
