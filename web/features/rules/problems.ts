// Where the rules module places a script's problem: its reasons start with "line L, column C: "
// (or "line L: ") when the engine knows the place (crate/rules, `check_rule` in crate/wasm).
// The editor marks that place; a problem without one marks the script's first line.
import type { SlotDoc, SlotInfo } from '../../contract.gen';

/** A problem of a script, placed at its line and column (1-based) when the engine gave them. */
export interface Placed {
  line: number | null;
  column: number | null;
  /** The reason, without its place. */
  message: string;
}

const PLACE = /^line (\d+)(?:, column (\d+))?: /;

/** Reads the place off the front of a reason from the rules module. */
export function place(reason: string): Placed {
  const m = PLACE.exec(reason);
  if (!m) return { line: null, column: null, message: reason };
  return { line: Number(m[1]), column: m[2] ? Number(m[2]) : null, message: reason.slice(m[0].length) };
}

/**
 * The characters of `text` a placed problem marks, as offsets: from its column to the end of its
 * line, at least one character where the text has one; the first line when it has no place. A place
 * past the end of the text marks its end.
 */
export function span(text: string, problem: Placed): { from: number; to: number } {
  const lines = text.split('\n');
  const line = Math.min(Math.max(problem.line ?? 1, 1), lines.length);
  let start = 0;
  for (let i = 0; i < line - 1; i++) start += lines[i].length + 1;
  const length = lines[line - 1].length;
  let from = start + Math.min(Math.max((problem.column ?? 1) - 1, 0), length);
  let to = start + length;
  if (to <= from) {
    to = Math.min(from + 1, text.length);
    if (to <= from && from > 0) from -= 1;
  }
  return { from, to };
}

/** The rule slots of `model`, from the rules module's list of every model's. */
export function slotsOf(all: SlotDoc[], model: string): SlotInfo[] {
  return all.filter((d) => d.model === model).map((d) => d.slot);
}

/** The script a scenario (its parsed document) puts in slot `slot`, or null: the paper's rule. */
export function scriptIn(doc: Record<string, unknown>, slot: string): string | null {
  const rules = doc.rules as Record<string, unknown> | undefined;
  const script = rules?.[slot];
  return typeof script === 'string' ? script : null;
}

/**
 * A copy of a scenario (its parsed document) with the paper's rule in slot `slot`: without its
 * script, without an empty `rules`, and without a comparison of that slot.
 */
export function withoutScript(doc: Record<string, unknown>, slot: string): Record<string, unknown> {
  const copy: Record<string, unknown> = { ...doc };
  const rules = { ...((doc.rules as Record<string, unknown> | undefined) ?? {}) };
  delete rules[slot];
  if (Object.keys(rules).length > 0) copy.rules = rules;
  else delete copy.rules;
  if ((doc.compare as { path?: string } | undefined)?.path === `rules.${slot}`) delete copy.compare;
  return copy;
}
