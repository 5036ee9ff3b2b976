// A small, safe Markdown subset for exercise instructions: paragraphs, "- " lists, **bold**,
// *emphasis* and `code`. The text is parsed into spans, and the page builds DOM nodes from them
// with text only: no HTML in the text is ever parsed, so instructions cannot inject anything.
import { el } from './dom';

export type Span = { kind: 'text' | 'strong' | 'em' | 'code'; text: string };
export type Block = { kind: 'p'; spans: Span[] } | { kind: 'ul'; items: Span[][] };

/** Inline spans: **bold**, *emphasis*, `code`; everything else is text. */
export function spans(text: string): Span[] {
  const out: Span[] = [];
  const pattern = /\*\*([^*]+)\*\*|\*([^*]+)\*|`([^`]+)`/g;
  let last = 0;
  for (let m = pattern.exec(text); m; m = pattern.exec(text)) {
    if (m.index > last) out.push({ kind: 'text', text: text.slice(last, m.index) });
    if (m[1] !== undefined) out.push({ kind: 'strong', text: m[1] });
    else if (m[2] !== undefined) out.push({ kind: 'em', text: m[2] });
    else out.push({ kind: 'code', text: m[3] });
    last = m.index + m[0].length;
  }
  if (last < text.length) out.push({ kind: 'text', text: text.slice(last) });
  return out;
}

/** Blocks: paragraphs separated by blank lines, and lists of lines starting with "- ". */
export function parseMarkdown(text: string): Block[] {
  const blocks: Block[] = [];
  for (const block of text.split(/\n\s*\n/)) {
    const lines = block.split('\n').filter((l) => l.trim() !== '');
    if (!lines.length) continue;
    if (lines.every((l) => /^\s*[-*] /.test(l))) blocks.push({ kind: 'ul', items: lines.map((l) => spans(l.replace(/^\s*[-*] /, ''))) });
    else blocks.push({ kind: 'p', spans: spans(lines.join(' ')) });
  }
  return blocks;
}

const node = (s: Span): Node | string => (s.kind === 'text' ? s.text : el(s.kind, { text: s.text }));

/** The instructions as DOM nodes, built from text only. */
export function renderMarkdown(text: string): HTMLElement[] {
  return parseMarkdown(text).map((b) =>
    b.kind === 'p' ? el('p', {}, ...b.spans.map(node)) : el('ul', {}, ...b.items.map((item) => el('li', {}, ...item.map(node)))),
  );
}
