// What the Grade view shows of a graded row: its verdict in words (over budget marked), its points
// and each credit part's, why, the student's answer and record, and the student's name cut to fit
// with the whole of it kept for hovering. The rows themselves are the lab's (`grade_row`, the
// core's grading::table::Row): read, graded and exported as `kumiki check` does.
import type { Graded, Row } from '../../contract.gen';
import { displayText } from '../../widgets/dom';

/** One row of the grade table: the hand-in's number, the student and link, and its grade or error. */
export type GradeRow = Row & Graded;
/** A row that was graded (not one that could not be). */
export type GradedRow = Row & Extract<Graded, { met: boolean }>;

/** The longest name shown in a row, in characters; the whole name is its title. */
export const NAME_CHARS = 40;
/** The longest answer shown in a row, in characters. */
export const ANSWER_CHARS = 200;
/** The most of a name or an answer kept for hovering. */
const TITLE_CHARS = 2000;

export const isGraded = (r: GradeRow): r is GradedRow => !('error' in r);

/** How a row the teacher skipped says so: its error starts with it (in the table and the CSV). */
export const SKIPPED = 'skipped: ';

/** A row's verdict in words. */
export type Verdict = 'met' | 'not met' | 'over budget' | 'could not be graded' | 'skipped';

/** The verdict in words: met, not met, over budget (stopped at the exercise's budget), could not be graded, or skipped by the teacher. */
export function verdict(r: GradeRow): Verdict {
  if (!isGraded(r)) return r.error.startsWith(SKIPPED) ? 'skipped' : 'could not be graded';
  if (r.over_budget) return 'over budget';
  return r.met ? 'met' : 'not met';
}

/** The points earned of the most, "7 of 10"; empty when the exercise gives none. */
export function pointsText(r: GradeRow): string {
  if (!isGraded(r) || r.max_points === undefined || r.max_points === null) return '';
  return `${r.points ?? 0} of ${r.max_points}`;
}

/** Each credit part as judged: "5 of 5: completed". */
export function partsText(r: GradeRow): string[] {
  if (!isGraded(r)) return [];
  return (r.credit ?? []).map((c) => `${c.earned} of ${c.points}: ${c.goal}`);
}

/** Why: the error, or the verdict's reason with what the hand-in changed and the disturbances it added. */
export function reasonText(r: GradeRow): string {
  if (!isGraded(r)) return r.error;
  return [r.because, r.changed.length ? `changed: ${r.changed.join(', ')}` : '', ...r.disturbances].filter(Boolean).join('. ');
}

/** The student's answer to the exercise's question, as they wrote it (cut), and its whole. */
export function answerText(r: GradeRow): { shown: string; full: string } {
  const answer = isGraded(r) ? (r.record?.answer ?? '') : '';
  return { shown: displayText(answer, ANSWER_CHARS, true), full: displayText(answer, TITLE_CHARS, true) };
}

/** The hand-in's record of itself in words: "handed in 2026-11-28T10:15:00Z, 3 checks, 1 hint". */
export function recordText(r: GradeRow): string {
  const record = isGraded(r) ? r.record : null;
  if (!record) return '';
  const plural = (n: number, word: string) => `${n} ${word}${n === 1 ? '' : 's'}`;
  return [record.made ? `handed in ${record.made}` : '', plural(record.checks, 'check'), plural(record.hints, 'hint')].filter(Boolean).join(', ');
}

/** A name as the row shows it (hidden and direction-changing characters left out, cut to fit) and its whole for hovering. */
export function nameText(name: string): { shown: string; full: string } {
  return { shown: displayText(name, NAME_CHARS) || '(no name)', full: displayText(name, TITLE_CHARS) };
}

/** The student's name in a row: the class's file's, else the one the hand-in carries. */
export const studentOf = (r: GradeRow): string => r.student || (isGraded(r) ? r.name : '');

/** How a class graded so far. */
export interface Tally {
  met: number;
  unmet: number;
  over: number;
  errors: number;
  skipped: number;
}

export const emptyTally = (): Tally => ({ met: 0, unmet: 0, over: 0, errors: 0, skipped: 0 });

/** Counts a row in the tally. */
export function count(tally: Tally, r: GradeRow) {
  countVerdict(tally, verdict(r));
}

/** Counts a row of verdict `v` in the tally. */
export function countVerdict(tally: Tally, v: Verdict) {
  if (v === 'met') tally.met++;
  else if (v === 'not met') tally.unmet++;
  else if (v === 'over budget') tally.over++;
  else if (v === 'skipped') tally.skipped++;
  else tally.errors++;
}

/** The tally in words, as `kumiki check` says it: "1 met, 3 not met (1 over budget), 1 could not be graded", then the rows skipped. */
export function tallyText(t: Tally): string {
  const over = t.over ? ` (${t.over} over budget)` : '';
  const skipped = t.skipped ? `, ${t.skipped} skipped` : '';
  return `${t.met} met, ${t.unmet + t.over} not met${over}, ${t.errors} could not be graded${skipped}`;
}
