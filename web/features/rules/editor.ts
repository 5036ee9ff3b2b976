// The rule editor: CodeMirror 6, imported by the Rules tab only when it opens (a chunk of its own,
// never in the page's first load). Rhai reads like Rust: the legacy Rust mode highlights it. The
// rules module's problem is marked at its line as a lint diagnostic (in the gutter, underlined,
// and read out by CodeMirror's lint panel commands). Keyboard: Tab indents; Escape then Tab leaves
// the editor (CodeMirror's tab-focus convention), as the tab's hint says.
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
 * An editor in `parent`, starting with `text`; `changed` is called with the text after each change
 * (typed, or set). `labelledBy` and `describedBy` name the ids of the label and the slot's
 * documentation, for screen readers.
 */
export function ruleEditor(parent: HTMLElement, text: string, changed: (text: string) => void, labelledBy: string, describedBy: string): RuleEditor {
  const view = new EditorView({
    parent,
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
        keymap.of([...defaultKeymap, ...historyKeymap, indentWithTab]),
        EditorView.contentAttributes.of({ 'aria-labelledby': labelledBy, 'aria-describedby': describedBy, 'aria-multiline': 'true' }),
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
