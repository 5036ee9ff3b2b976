// Recording the view: a PNG, or a WebM video or GIF made by stepping the run frame by frame in the
// simulation worker, with an optional step counter, title and legend drawn over it.
import type { Feature } from '../../page/context';
import { recordPage, setupRecordDialog } from './record';

export const record: Feature = {
  name: 'record',
  mount: (page) => setupRecordDialog(recordPage(page)),
};
