// Model-specific editors: one plugin per model, web/models/<model>.ts, which exports its `editor`.
// They are found by their file names, so a new model's plugin is its file alone; a model without
// one gets the generic parameter form.
import type { ModelEditor } from './editor';

export type { EditorContext, ModelEditor, MountedEditor } from './editor';

const modules = import.meta.glob<{ editor?: ModelEditor }>(['./*.ts', '!./index.ts'], { eager: true });

/** Each model's editor, by model name (its plugin's file name). */
export const modelEditors: Record<string, ModelEditor> = Object.fromEntries(
  Object.entries(modules).flatMap(([path, module]) => (module.editor ? [[path.slice('./'.length, -'.ts'.length), module.editor]] : [])),
);
