// Reading a class's hand-ins from what a teacher has: links pasted one a line (as `kumiki check
// --file` reads them), or the CSV or text export of a form or a learning platform, one hand-in a
// row with the student's name in another column. Nothing here leaves the page.
import type { Graded } from '../../contract.gen';

/** One hand-in: its row in the input, the student's name from the export (if any), its link. */
export interface Handin {
  row: number;
  /** The name in the export's other columns; empty when the row has only the link. */
  student: string;
  /** The Kumiki link, or null when the row has none (graded as an error, like kumiki check). */
  link: string | null;
  /** The row as it was, for a row with no link. */
  text: string;
}

/** A Kumiki link in a cell: a URL with `#k1.…`, or the bare `#k1.…` / `k1.…` part. */
const LINK = /(?:https?:\/\/[^\s"',;]*)?#?k1\.[A-Za-z0-9_-]+/;

/** The cells of one CSV, TSV or semicolon-separated row; quoted cells may hold separators. */
export function cells(line: string): string[] {
  const sep = line.includes('\t') ? '\t' : line.split(';').length > line.split(',').length ? ';' : ',';
  const out: string[] = [];
  let cell = '';
  let quoted = false;
  for (let i = 0; i < line.length; i++) {
    const c = line[i];
    if (quoted) {
      if (c === '"' && line[i + 1] === '"') {
        cell += '"';
        i++;
      } else if (c === '"') quoted = false;
      else cell += c;
    } else if (c === '"' && cell.trim() === '') {
      quoted = true;
      cell = '';
    } else if (c === sep) {
      out.push(cell.trim());
      cell = '';
    } else cell += c;
  }
  out.push(cell.trim());
  return out;
}

/**
 * The hand-ins in `text`. Blank lines and lines starting with `#` that hold no link are skipped
 * (as `kumiki check --file` does); a first row with no link is a header. The student's name is
 * the first other cell that is not a number or a date, read from a header column named like
 * "name" or "student" when there is one.
 */
export function parseHandins(text: string): Handin[] {
  const lines = text.split(/\r?\n/);
  const out: Handin[] = [];
  let nameColumn = -1;
  let first = true;
  for (const [i, raw] of lines.entries()) {
    const line = raw.trim();
    if (!line) continue;
    const found = LINK.exec(line);
    if (!found && line.startsWith('#')) continue;
    const row = cells(line);
    if (first && !found) {
      // A header: remember which column names the student.
      nameColumn = row.findIndex((h) => /name|student|learner|user/i.test(h));
      first = false;
      continue;
    }
    first = false;
    const link = found ? found[0] : null;
    const others = row.filter((c) => c && !LINK.test(c));
    const named = nameColumn >= 0 && nameColumn < row.length && !LINK.test(row[nameColumn]) ? row[nameColumn] : '';
    const student = named || (others.find((c) => !/^[\d\s:./+-]+(T[\d:.]+Z?)?$/.test(c)) ?? '');
    out.push({ row: i + 1, student, link, text: line });
  }
  return out;
}

/** A value as one CSV cell. */
function csvCell(v: unknown): string {
  const raw = v === undefined || v === null ? '' : String(v);
  // Text a spreadsheet would read as a formula (a student's name can be anything) gets a leading
  // `'`, as the core's CSV does (export::csv_text); numbers are written as they are.
  const s = typeof v === 'string' && /^[=+\-@\t\r]/.test(raw) ? `'${raw}` : raw;
  return /[",\n\r]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
}

/**
 * One row of the Grade view: the hand-in's number, its student and link, and the core's `Graded`
 * answer for it, a grade or an error, read field by field (each field absent in the other case).
 */
export type GradedRow = { handin: number; student: string; link: string | null } & Partial<Extract<Graded, { met: boolean }>> &
  Partial<Extract<Graded, { error: string }>>;

/** The Grade view's table as CSV: kumiki check's columns, with the student and the link first. */
export function gradesCsv(rows: GradedRow[]): string {
  const metrics = [...new Set(rows.flatMap((r) => Object.keys(r.goal_metrics ?? {})))].sort();
  const head = [
    'handin',
    'student',
    'name',
    'met',
    'because',
    'completed',
    'steps',
    'hash',
    'locked_edited',
    'changed',
    'exercise_edited',
    ...metrics.map((m) => `metrics.${m}`),
    'error',
    'link',
  ];
  const lines = [head.join(',')];
  for (const r of rows) {
    const graded = r.error === undefined;
    lines.push(
      [
        r.handin,
        r.student,
        r.name ?? '',
        graded ? r.met : false,
        r.because ?? '',
        r.completed ?? '',
        r.steps ?? '',
        r.hash ?? '',
        (r.locked_edited ?? []).join('; '),
        (r.changed ?? []).join('; '),
        r.exercise_edited ?? '',
        ...metrics.map((m) => r.goal_metrics?.[m] ?? ''),
        r.error ?? '',
        r.link ?? '',
      ]
        .map(csvCell)
        .join(','),
    );
  }
  return `${lines.join('\n')}\n`;
}
