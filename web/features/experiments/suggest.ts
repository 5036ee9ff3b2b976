// The core's "did you mean" for a near miss in an experiment (a misspelt grid key, metric or
// field), read from its message and applied to the experiment's JSON at the press of a button.
import { el } from '../../widgets/dom';
import * as core from '../../wasm';

/** A near miss: the name written and the one the core suggests; `field` when it is a key. */
export interface NearMiss {
  wrong: string;
  right: string;
  field: boolean;
}

/** The near miss a core message names ("… unknown field 'robot'; did you mean 'robots'?"), if any. */
export function nearMiss(message: string): NearMiss | null {
  const m = message.match(/(unknown field )?'([^']+)'[^']*; did you mean '([^']+)'\?/);
  return m ? { wrong: m[2], right: m[3], field: m[1] !== undefined } : null;
}

const literal = (s: string) => s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

/** Replaces the misspelt name by the suggested one: as a key (a field), or in the text of values (a metric). */
function fix(value: unknown, miss: NearMiss, word: RegExp): unknown {
  if (Array.isArray(value)) return value.map((v) => fix(v, miss, word));
  if (typeof value === 'string') return miss.field ? value : value.replace(word, miss.right);
  if (!value || typeof value !== 'object') return value;
  const out: Record<string, unknown> = {};
  for (const [k, v] of Object.entries(value)) {
    const prose = k === 'title' || k === 'description' || k === 'name';
    out[miss.field && k === miss.wrong ? miss.right : k] = prose ? v : fix(v, miss, word);
  }
  return out;
}

/** The experiment's JSON with the near miss corrected (two-space indented), or null if it does not read. */
export function applyNearMiss(json: string, miss: NearMiss): string | null {
  let value: unknown;
  try {
    value = JSON.parse(json);
  } catch {
    return null;
  }
  // A metric is a word of its own: "metrics.placd" in "metrics.placd >= 0.5", not in "metrics.placed".
  const word = new RegExp(`(?<![\\w.])${literal(miss.wrong)}(?![\\w])`, 'g');
  const fixed = JSON.stringify(fix(value, miss, word), null, 2);
  return fixed === JSON.stringify(value, null, 2) ? null : fixed;
}

/**
 * A core message as the page says it: where it sends the reader to docs/metrics.md for a metric
 * with no near name, the page lists the model's metrics instead (`metricsOf` gives a model's).
 */
export function pageWords(message: string, metricsOf: (model: string) => string[]): string {
  return message.replace(/ is not a metric of ([\w-]+(?: or [\w-]+)*) \(each model's metrics are in docs\/metrics\.md\)/, (whole, models: string) => {
    let names: string[];
    try {
      names = [...new Set(models.split(' or ').flatMap(metricsOf))];
    } catch {
      return whole;
    }
    return names.length ? ` is not a metric of ${models}, whose metrics are ${names.join(', ')}` : whole;
  });
}

/**
 * Writes a core message into `box` in the page's words; where it suggests a name for a near miss
 * in `json`, a button hands `use` the text with the name put right.
 */
export function explain(box: HTMLElement, text: string, json: string, use: (fixed: string) => void) {
  box.replaceChildren(pageWords(text, (model) => core.metricTable(model).map((m) => m.name)));
  const miss = nearMiss(text);
  const fixed = miss && applyNearMiss(json, miss);
  if (!miss || !fixed) return;
  const button = el('button', { type: 'button', text: `Use '${miss.right}'`, 'aria-label': `Use '${miss.right}' in place of '${miss.wrong}'` });
  button.addEventListener('click', () => use(fixed));
  box.append(' ', button);
}
