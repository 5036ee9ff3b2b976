// The grade table, virtualised: a class of 10,000 rows keeps in the page only the rows in view
// and a few either side, between two spacer rows that give the scroll bar its length; drawn at
// most once a frame, however many rows were graded meanwhile. It stays a table for screen
// readers (aria-rowcount on the table, aria-rowindex on each row) and scrolls with the keyboard
// (the scroller is focusable; tabbing to a row's link scrolls the next rows in).
import { el, formatNumber } from '../../widgets/dom';
import { answerText, type GradeRow, isGraded, nameText, partsText, pointsText, reasonText, recordText, studentOf, verdict } from './handins';

/** The table's columns: a row not graded yet spans those after its number. */
const COLUMNS = 10;
/** Rows drawn beyond the view on each side. */
const OVERSCAN = 12;
/** A row's height in pixels until one is drawn and measured (static/style.css fixes it). */
const GUESS_PX = 45;

/** The rows a table shows: row `i`, or undefined while it is not graded. */
export interface TableRows {
  readonly length: number;
  at(index: number): GradeRow | undefined;
}

/** A drawn row: its element and what it shows (the row, or which kind of row not graded yet). */
interface Drawn {
  tr: HTMLTableRowElement;
  shows: GradeRow | 'pending' | 'not graded';
}

export class GradeTable {
  private rows: TableRows = { length: 0, at: () => undefined };
  private grading = false;
  private drawn = new Map<number, Drawn>();
  private readonly top = spacer();
  private readonly bottom = spacer();
  private rowPx = GUESS_PX;
  private frame = 0;

  constructor(
    private readonly scroller: HTMLElement,
    private readonly table: HTMLTableElement,
    body: HTMLElement,
  ) {
    body.replaceChildren(this.top, this.bottom);
    scroller.addEventListener('scroll', () => this.request(), { passive: true });
    this.table.setAttribute('aria-rowcount', '1');
  }

  /** A new table of `rows`, scrolled to its top. */
  reset(rows: TableRows, grading: boolean) {
    this.rows = rows;
    this.grading = grading;
    for (const d of this.drawn.values()) d.tr.remove();
    this.drawn.clear();
    this.scroller.scrollTop = 0;
    this.table.setAttribute('aria-rowcount', String(rows.length + 1));
    this.draw();
  }

  /** Whether the rows not graded yet are being graded (or were left when grading stopped). */
  setGrading(grading: boolean) {
    this.grading = grading;
    this.request();
  }

  /** Draws at the next frame (once, however often it is asked). */
  request() {
    if (!this.frame) this.frame = requestAnimationFrame(() => this.draw());
  }

  /** Draws now if a row in view was graded since it was drawn (the rows in view only are looked at). */
  refresh() {
    for (const [i, d] of this.drawn) {
      if ((this.rows.at(i) ?? d.shows) !== d.shows) {
        this.draw();
        return;
      }
    }
  }

  /** Draws the rows in view now: new ones added, those scrolled away removed, those graded since redrawn. */
  draw() {
    if (this.frame) cancelAnimationFrame(this.frame);
    this.frame = 0;
    const n = this.rows.length;
    const head = this.table.tHead?.offsetHeight ?? 0;
    const from = Math.max(0, this.scroller.scrollTop - head);
    const first = Math.min(n, Math.max(0, Math.floor(from / this.rowPx) - OVERSCAN));
    const end = Math.min(n, Math.ceil((from + this.scroller.clientHeight) / this.rowPx) + OVERSCAN);
    for (const [i, d] of this.drawn) {
      if (i < first || i >= end) {
        d.tr.remove();
        this.drawn.delete(i);
      }
    }
    let after: ChildNode = this.top;
    for (let i = first; i < end; i++) {
      const shows = this.rows.at(i) ?? (this.grading ? 'pending' : 'not graded');
      let d = this.drawn.get(i);
      if (d && d.shows !== shows) {
        const tr = rowElement(i, shows);
        d.tr.replaceWith(tr);
        d = { tr, shows };
        this.drawn.set(i, d);
      }
      if (!d) {
        d = { tr: rowElement(i, shows), shows };
        this.drawn.set(i, d);
      }
      if (after.nextSibling !== d.tr) after.after(d.tr);
      after = d.tr;
    }
    const measured = this.drawn.get(first)?.tr.getBoundingClientRect().height;
    if (measured) this.rowPx = measured;
    this.top.style.height = `${first * this.rowPx}px`;
    this.bottom.style.height = `${(n - end) * this.rowPx}px`;
  }
}

/** A spacer row: as tall as the rows it stands for, hidden from screen readers. */
function spacer(): HTMLTableRowElement {
  return el('tr', { class: 'spacer', 'aria-hidden': 'true' }, el('td', { colspan: String(COLUMNS) }));
}

function rowElement(index: number, shows: Drawn['shows']): HTMLTableRowElement {
  const tr = typeof shows === 'string' ? pendingRow(index + 1, shows) : tableRow(shows);
  tr.setAttribute('aria-rowindex', String(index + 2));
  return tr;
}

/** A cell whose content is cut to the row's height, its whole text on hover when it is cut. */
function cell(attrs: Record<string, string | undefined>, ...content: (Node | string)[]): HTMLTableCellElement {
  return el('td', attrs, el('div', { class: 'cell' }, ...content));
}

/** A row not graded yet: still to come, or left when grading was cancelled. */
function pendingRow(handin: number, shows: 'pending' | 'not graded'): HTMLTableRowElement {
  return el(
    'tr',
    { class: 'pending' },
    cell({}, String(handin)),
    cell({ colspan: String(COLUMNS - 1), class: 'hint' }, shows === 'pending' ? 'being graded…' : 'not graded'),
  );
}

/** Text a student wrote (a name, an answer), isolated from the table's direction and cut, whole on hover. */
function studentText(text: { shown: string; full: string }): HTMLElement {
  return el('bdi', { dir: 'auto', title: text.full !== text.shown ? text.full : undefined, text: text.shown });
}

const ROW_CLASS = { met: 'met', 'not met': 'unmet', 'over budget': 'over', 'could not be graded': 'error', skipped: 'skipped' } as const;

function tableRow(r: GradeRow): HTMLTableRowElement {
  const v = verdict(r);
  const metrics = isGraded(r)
    ? Object.entries(r.goal_metrics)
        .map(([k, value]) => `${k.replace(/_/g, ' ')} ${formatNumber(value)}`)
        .join(', ')
    : '';
  const open = r.link
    ? el('a', {
        href: r.link.startsWith('http') ? r.link : `${location.pathname}${r.link.startsWith('#') ? '' : '#'}${r.link}`,
        target: '_blank',
        rel: 'noopener',
        text: 'open',
        'aria-label': `Open hand-in ${r.handin}`,
      })
    : '';
  const parts = partsText(r);
  const points: (Node | string)[] = [pointsText(r)];
  if (parts.length) points.push(el('ul', {}, ...parts.map((p) => el('li', { text: p }))));
  const answer = answerText(r);
  const answered: Node[] = answer.shown ? [studentText(answer)] : [];
  const said = recordText(r);
  if (said) answered.push(el('span', { class: 'hint', text: said }));
  const why = reasonText(r);
  return el(
    'tr',
    { class: ROW_CLASS[v] },
    cell({}, String(r.handin)),
    cell({ class: 'grade-student' }, studentText(nameText(studentOf(r)))),
    cell({ class: 'grade-verdict' }, v),
    cell({ class: 'grade-points', title: parts.join('\n') || undefined }, ...points),
    cell({}, isGraded(r) ? r.steps.toLocaleString('en-US') : ''),
    cell({ title: metrics || undefined }, metrics),
    cell({ class: 'reason', title: why || undefined }, why),
    cell({ class: 'grade-answer', title: answer.full || undefined }, ...answered),
    cell({}, el('code', { text: isGraded(r) ? r.hash : '' })),
    cell({}, open),
  );
}
