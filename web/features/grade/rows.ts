// The class's rows as graded so far: each as the worker sent it (the lab's row as JSON, and its
// verdict for the tally), parsed only when the table shows it. Ten thousand rows as objects took
// the page's thread half a second to receive; as strings they cross in milliseconds, and the CSV
// export joins them as they are.
import { countVerdict, emptyTally, type GradeRow, type Tally, type Verdict } from './handins';

export class GradedRows {
  private readonly json: (string | undefined)[];
  private readonly parsed: (GradeRow | undefined)[];
  /** How many are graded. */
  done = 0;
  readonly tally: Tally = emptyTally();

  /** `length` rows, none graded yet. */
  constructor(readonly length: number) {
    this.json = new Array(length);
    this.parsed = new Array(length);
  }

  /** Records row `index` (`json`: the lab's row; `verdict`: its verdict), unless it has one already (graded, then skipped). */
  record(index: number, json: string, verdict: Verdict) {
    if (this.json[index] !== undefined) return;
    this.json[index] = json;
    countVerdict(this.tally, verdict);
    this.done++;
  }

  /** Row `index`, when graded (the same object each time it is asked). */
  at(index: number): GradeRow | undefined {
    const json = this.json[index];
    if (json === undefined) return undefined;
    this.parsed[index] ??= JSON.parse(json) as GradeRow;
    return this.parsed[index];
  }

  /** The rows graded, in the table's order, as one JSON array (what the lab's CSV writer reads). */
  toJson(): string {
    return `[${this.json.filter((j) => j !== undefined).join(',')}]`;
  }
}
