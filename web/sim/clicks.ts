// What the exercise in view says of each click tool, for the page's list of tools: the run's
// answer at its step (as its apply judges a click: one rewound past no longer counts), or the
// scenario's before a run has started.
import type { Draft, Sim } from '../pkg/kumiki_wasm.js';
import type { ClickState } from './protocol';

export function clickStates(sim: Sim | null, draft: Draft, tools: { kind: string; label: string }[]): ClickState[] {
  return tools.map((t) =>
    sim ? (sim.click_state(t.kind, t.label) as ClickState) : { problem: draft.click_problem(t.kind, t.label) ?? null, left: draft.clicks_left(t.kind) ?? null },
  );
}
