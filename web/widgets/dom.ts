// Small DOM helpers. Text is always set through textContent: names and descriptions can come
// from a link and are never parsed as HTML.
import * as core from '../wasm';

export function byId<T extends HTMLElement = HTMLElement>(id: string): T {
  const el = document.getElementById(id);
  if (!el) throw new Error(`the page is missing #${id}`);
  return el as T;
}

type Attrs = Record<string, string | number | boolean | undefined>;

export function el<K extends keyof HTMLElementTagNameMap>(tag: K, attrs: Attrs = {}, ...children: (Node | string)[]): HTMLElementTagNameMap[K] {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === false) continue;
    if (k === 'text') node.textContent = String(v);
    else if (k === 'class') node.className = String(v);
    else node.setAttribute(k, v === true ? '' : String(v));
  }
  for (const c of children) node.append(c);
  return node;
}

export function clear(node: Element) {
  while (node.firstChild) node.firstChild.remove();
}

/** A file name for figure `index` (from 1) of an experiment: `amas-fig23-1.svg`. */
export function figureFileName(experiment: string, index: number, ext: 'svg' | 'png' | 'pdf'): string {
  const base = experiment.replace(/[^A-Za-z0-9._-]+/g, '-').replace(/^-+|-+$/g, '') || 'experiment';
  return `${base}-${index}.${ext}`;
}

/** Offers text (or bytes) as a file download. */
export function download(name: string, data: BlobPart, type: string) {
  const url = URL.createObjectURL(new Blob([data], { type }));
  const a = el('a', { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

export function formatNumber(v: unknown): string {
  if (typeof v === 'boolean') return v ? 'yes' : 'no';
  if (typeof v !== 'number') return v === null || v === undefined ? '–' : String(v);
  return core.formatNumber(v);
}

/** True when a key press is meant for a text field rather than the page's shortcuts. */
export function typingIn(target: EventTarget | null): boolean {
  if (!(target instanceof HTMLElement)) return false;
  if (target.isContentEditable) return true;
  const tag = target.tagName;
  if (tag === 'TEXTAREA' || tag === 'SELECT') return true;
  if (tag === 'INPUT') {
    const type = (target as HTMLInputElement).type;
    return !['checkbox', 'radio', 'button', 'range', 'file'].includes(type);
  }
  return false;
}

// Bidirectional controls (LRM, RLM, ALM, the embeddings, overrides and isolates) can make a name
// read as something else; NUL and other control characters have no business in a title.
// biome-ignore lint/suspicious/noControlCharactersInRegex: finding control characters is its purpose.
const HIDDEN = /[\u0000-\u0008\u000b-\u001f\u007f-\u009f\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]/g;

/**
 * Text from a scenario (a name, a description) as it may be shown: without bidirectional controls
 * or control characters, line breaks kept only when `lines` is true, and cut to `max` characters.
 */
export function displayText(text: string, max: number, lines = false): string {
  let clean = text.replace(HIDDEN, '');
  if (!lines) clean = clean.replace(/[\t\n]+/g, ' ');
  clean = clean.trim();
  const chars = Array.from(clean);
  return chars.length > max ? `${chars.slice(0, max - 1).join('')}…` : clean;
}

/**
 * The elements of a feature's own markup (its `.html` file, imported as text), ready to insert.
 * The markup is the feature's, written in the repository: never text from a link or a user.
 */
export function markup(html: string): DocumentFragment {
  const template = document.createElement('template');
  template.innerHTML = html;
  return template.content;
}
