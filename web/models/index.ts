// The models' page plugins: one per model, web/models/<model>.ts, which exports its `editor` (the
// model's own editors) and its built-in scenarios' `titles` in words. They are found by their file
// names, so a new model's plugin is its file alone; a model without one gets the generic
// parameter form and its scenarios go by their code names.
import type { ModelEditor } from '../editors/editor';

export type { EditorContext, ModelEditor, MountedEditor } from '../editors/editor';

const modules = import.meta.glob<{ editor?: ModelEditor; titles?: Record<string, string> }>(['./*.ts', '!./index.ts'], { eager: true });
const byModel = Object.entries(modules).map(([path, module]) => [path.slice('./'.length, -'.ts'.length), module] as const);

/** Each model's editor, by model name (its plugin's file name). */
export const modelEditors: Record<string, ModelEditor> = Object.fromEntries(
  byModel.flatMap(([model, module]) => (module.editor ? [[model, module.editor]] : [])),
);

/** A built-in scenario's title in words, by its code name; undefined for another scenario. */
export function scenarioTitle(name: string): string | undefined {
  for (const [, module] of byModel) {
    const title = module.titles?.[name];
    if (title) return title;
  }
  return undefined;
}
