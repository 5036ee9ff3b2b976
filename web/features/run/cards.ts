// The metric cards of the Run tab: which metrics show first (those the model marks key, in its
// table's order), which a click away (the rest), and which only in the debug view (the model's
// internal counters); and one card: the metric's name in words, its explanation from the model's
// table on hover and focus, and its value (both runs' while comparing).
import type { MetricInfo } from '../../contract.gen';
import type { RunLabels } from '../../widgets/chart';
import { el, formatNumber } from '../../widgets/dom';

export interface ShownMetric {
  name: string;
  info: MetricInfo | undefined;
}

/**
 * The metrics a frame reports, split into the key ones and the rest, each in the order of the
 * model's table (a metric the table does not know goes last, with the rest); the internal
 * counters are left out unless `debug`.
 */
export function arrangeMetrics(names: string[], table: Map<string, MetricInfo>, debug: boolean): { key: ShownMetric[]; more: ShownMetric[] } {
  const order = [...table.keys()];
  const rank = (name: string) => {
    const i = order.indexOf(name);
    return i < 0 ? order.length : i;
  };
  const shown = names
    .map((name) => ({ name, info: table.get(name) }))
    .filter((m) => debug || m.info?.shown !== 'debug')
    .sort((a, b) => rank(a.name) - rank(b.name));
  return { key: shown.filter((m) => m.info?.shown === 'key'), more: shown.filter((m) => m.info?.shown !== 'key') };
}

/** A metric's card; `runs` names the two runs while comparing (the card then holds both values). */
export function metricCard(name: string, info: MetricInfo | undefined, runs: RunLabels | null) {
  const value = el('strong');
  // The explanation shows on hover and on focus (a card with one is in the Tab order) and is the
  // card's description for a screen reader. It sits between the name and the value (it is drawn
  // apart from both), so the card still starts with its name and ends with its value.
  const tip = info ? [el('span', { class: 'metric-about', role: 'tooltip', id: `metric-about-${name}`, text: `${info.about} Unit: ${info.unit}.` })] : [];
  // While comparing, the card holds both runs' values, each named for a screen reader.
  const second = runs ? el('strong', { class: 'second' }) : null;
  const pair =
    runs && second
      ? [el('span', { class: 'sr-only', text: `${runs[0]}: ` }), value, el('span', { class: 'sr-only', text: `, ${runs[1]}: ` }), second]
      : [value];
  const node = el(
    'div',
    {
      class: info?.shown === 'debug' ? 'metric internal' : 'metric',
      tabindex: info ? 0 : undefined,
      'aria-describedby': info ? `metric-about-${name}` : undefined,
    },
    el('span', { text: name.replace(/_/g, ' ') }),
    ...tip,
    ...pair,
  );
  return { node, value, second };
}

/** A metric's value as its card shows it: a fraction as a percentage, anything else as a number. */
export function metricText(value: unknown, info: MetricInfo | undefined): string {
  if (info?.unit === 'fraction' && typeof value === 'number' && Number.isFinite(value)) return `${Number((value * 100).toFixed(1))} %`;
  return formatNumber(value);
}
