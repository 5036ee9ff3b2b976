// Which of the worker's two wasm modules a message needs, and the questions only the rules module
// answers. The page's module (kumiki_wasm) runs every scenario without rule scripts; its rules
// module (kumiki_wasm_rules, the same module with the script engine) is fetched only for a scenario
// that carries `rules` (docs/rules.md), or for the Rules tab's questions. Whether a message needs
// it is read here from the text the page sends, before the wasm sees it.
import type { SlotDoc } from '../contract.gen';
import type { ToWorker } from './protocol';

/** Whether a `rules` section holds a script for any slot (null is the paper's rule: no script). */
function holdsScript(section: unknown): boolean {
  if (typeof section === 'string') return true;
  return !!section && typeof section === 'object' && Object.values(section).some((v) => v !== null);
}

/**
 * Whether scenario text carries rule scripts. Text without the key is not parsed at all (a large
 * scenario's text is megabytes); text that is not JSON is the Draft's to refuse.
 */
export function carriesRules(text: string): boolean {
  if (!/"rules"\s*:/.test(text)) return false;
  try {
    return holdsScript((JSON.parse(text) as { rules?: unknown }).rules);
  } catch {
    return false;
  }
}

/** Whether an edit (a JSON object from dotted path to value) puts a script in a slot. */
export function editsRules(changes: string): boolean {
  if (!changes.includes('"rules')) return false;
  try {
    const entries = Object.entries(JSON.parse(changes) as Record<string, unknown>);
    return entries.some(([path, value]) => (path === 'rules' ? holdsScript(value) : path.startsWith('rules.') && value !== null));
  } catch {
    return false;
  }
}

/** An opening or an edit that puts rule scripts in the scenario: only the rules module runs it. */
export function needsRules(msg: ToWorker): boolean {
  if (msg.type === 'open') return carriesRules(msg.text);
  if (msg.type === 'edit') return editsRules(msg.changes);
  return false;
}

/** What the Rules tab asks the worker's rules module. */
export interface RuleQueries {
  /** Every model's rule slots, with the paper's rule as each slot's script. */
  slots(): Promise<SlotDoc[]>;
  /** Why `source` cannot be the script of `model`'s slot `slot`, in the rules module's words; null when it can. */
  check(model: string, slot: string, source: string): Promise<string | null>;
}

/** The rule queries, asked through `ask` (the simulation client's question and answer). */
export function ruleQueries(ask: (message: (id: number) => ToWorker) => Promise<unknown>): RuleQueries {
  /** An answer that is not of the expected shape: the worker's error, or it stopped (null). */
  const failed = (value: unknown, what: string) => new Error((value as { error?: string } | null)?.error ?? `the simulation stopped before it ${what}`);
  return {
    async slots() {
      const value = await ask((id) => ({ type: 'rule-slots', id }));
      if (Array.isArray(value)) return value as SlotDoc[];
      throw failed(value, 'listed the rule slots');
    },
    async check(model, slot, source) {
      const value = await ask((id) => ({ type: 'check-rule', id, model, slot, source }));
      if (value && typeof value === 'object' && 'problem' in value) return (value as { problem: string | null }).problem;
      throw failed(value, 'checked the rule');
    },
  };
}
