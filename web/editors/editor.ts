// What a model-specific editor (target shapes, type-lists, statements) gets from the page, and
// what it gives back. Editors mount above the generic parameter form in the Scenario tab; each
// model's plugin (web/models/<model>.ts) builds its editors from the shared ones here.
import type { Layout } from '../contract.gen';

export interface EditorContext {
  /** The scenario as it now stands, parsed. */
  scenario(): Record<string, unknown>;
  /**
   * Applies changes to top-level scenario keys. The core validates the result; on failure the
   * scenario is unchanged and the message, which names the field, is what it resolves to.
   */
  change(changes: Record<string, unknown>): Promise<string | null>;
  /** The layout of the loaded run, once it has loaded. */
  layout(): Layout | null;
}

export interface MountedEditor {
  /** The scenario changed (undo, a preset, a link): show it. */
  update(scenario: Record<string, unknown>): void;
  destroy(): void;
}

export interface ModelEditor {
  /** Heading shown above the editor. */
  title: string;
  /** Scenario keys this editor edits; the generic parameter form leaves them out. */
  owns: string[];
  mount(root: HTMLElement, ctx: EditorContext): MountedEditor;
}
