// Model-specific editors by model name, one file each.
import { amasEditor } from './amas';
import { chobieEditor } from './chobie';
import { cubes3dEditor } from './cubes3d';
import type { ModelEditor } from './editor';
import { fractaEditor } from './fracta';

export type { EditorContext, ModelEditor, MountedEditor } from './editor';

export const modelEditors: Record<string, ModelEditor> = {
  amas: amasEditor,
  chobie: chobieEditor,
  cubes3d: cubes3dEditor,
  fracta: fractaEditor,
};
