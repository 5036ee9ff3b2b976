// The rule editor: CodeMirror 6, imported by the Rules tab only when it opens (a chunk of its own,
// never in the page's first load). Rhai reads like Rust: the legacy Rust mode highlights it. The
// rules module's problem is marked at its line as a lint diagnostic (in the gutter, underlined,
// and read out by CodeMirror's lint panel commands). Keyboard: Tab indents; Escape then Tab leaves
// the editor (CodeMirror's tab-focus convention), as the tab's hint says. The editor lives in a
// shadow root of its own: there CodeMirror's styles are constructed style sheets, which the page's
// Content-Security-Policy (style-src 'self', no inline <style>) allows; in the document it would
// add <style> elements, which the policy refuses.
import { defaultKeymap, history, historyKeymap, indentWithTab } from '@codemirror/commands';
import { bracketMatching, defaultHighlightStyle, indentOnInput, StreamLanguage, syntaxHighlighting } from '@codemirror/language';
import { rust } from '@codemirror/legacy-modes/mode/rust';
import { lintGutter, setDiagnostics } from '@codemirror/lint';
import { EditorState } from '@codemirror/state';
import { EditorView, highlightActiveLine, keymap, lineNumbers } from '@codemirror/view';
import { type Placed, span } from './problems';

/** What the Rules tab asks of its editor. */
export interface RuleEditor {
  text(): string;
  /** Replaces the whole text (a slot chosen, a reset): one step of the editor's undo. */
  setText(text: string): void;
  /** Marks a problem at its place, or clears the mark (null). */
  mark(problem: Placed | null): void;
  focus(): void;
}

/**
 * The editor's look, in its shadow root (the page's colours are its custom properties, which reach
 * it). It grows with its script and wraps long lines: a region that scrolls would be one more stop
 * for the keyboard.
 */
const THEME = EditorView.theme({
  '&': { fontSize: '0.85rem', background: 'var(--panel)', color: 'var(--ink)' },
  '&.cm-focused': { outline: '2px solid var(--accent)', outlineOffset: '-2px' },
  '.cm-scroller': { fontFamily: 'ui-monospace, SFMono-Regular, Menlo, Consolas, monospace' },
  // The lint marks without CodeMirror's data: images, which the page's policy (img-src 'self') refuses.
  '.cm-lintRange-error': { backgroundImage: 'none', textDecoration: 'underline wavy var(--danger)', textDecorationSkipInk: 'none' },
  '.cm-lint-marker-error': { content: 'normal', background: 'var(--danger)', borderRadius: '50%', width: '0.7em', height: '0.7em', margin: '0.15em' },
});

/**
 * An editor in a shadow root of `host`, starting with `text`; `changed` is called with the text
 * after each change (typed, or set). `label` names it for screen readers (an id across the shadow
 * root's edge would name nothing).
 */
export function ruleEditor(host: HTMLElement, text: string, changed: (text: string) => void, label: string): RuleEditor {
  const root = host.shadowRoot ?? host.attachShadow({ mode: 'open' });
  // Keys typed here are the editor's: the page's keys (Space plays, R resets) see the event at the
  // host, outside the shadow root, where it no longer looks typed into a field.
  host.addEventListener('keydown', (e) => e.stopPropagation());
  const view = new EditorView({
    root,
    parent: root,
    state: EditorState.create({
      doc: text,
      extensions: [
        lineNumbers(),
        history(),
        indentOnInput(),
        bracketMatching(),
        highlightActiveLine(),
        StreamLanguage.define(rust),
        syntaxHighlighting(defaultHighlightStyle),
        lintGutter(),
        THEME,
        EditorView.lineWrapping,
        keymap.of([...defaultKeymap, ...historyKeymap, indentWithTab]),
        EditorView.contentAttributes.of({ 'aria-label': label, 'aria-multiline': 'true' }),
        EditorView.updateListener.of((update) => {
          if (update.docChanged) changed(update.state.doc.toString());
        }),
      ],
    }),
  });
  return {
    text: () => view.state.doc.toString(),
    setText(next: string) {
      view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: next } });
    },
    mark(problem: Placed | null) {
      const doc = view.state.doc.toString();
      const diagnostics = problem
        ? [{ ...span(doc, problem), severity: 'error' as const, message: problem.line === null ? problem.message : `line ${problem.line}: ${problem.message}` }]
        : [];
      view.dispatch(setDiagnostics(view.state, diagnostics));
    },
    focus: () => view.focus(),
  };
}
