// Model-specific editors by model name, one file each.
import { amasEditor } from './amas';
import type { ModelEditor } from './editor';

export type { EditorContext, ModelEditor, MountedEditor } from './editor';

export const modelEditors: Record<string, ModelEditor> = {
  amas: amasEditor,
};
