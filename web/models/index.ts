// Model-specific editors by model name, one file each.
import { amasEditor } from './amas';
import { fractaEditor } from './fracta';
import type { ModelEditor } from './editor';

export type { EditorContext, ModelEditor, MountedEditor } from './editor';

export const modelEditors: Record<string, ModelEditor> = {
  amas: amasEditor,
  fracta: fractaEditor,
};
