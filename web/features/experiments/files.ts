// The experiment in view as a link and as a file, a file opened into the editor, and the sweep's
// exports saved as files: the Experiments tab's buttons that take things in and out of the page.
import { experimentInfo, packExperiment } from '../../lab';
import { byId, download } from '../../widgets/dom';
import { copyLink } from '../../widgets/copylink';
import * as core from '../../wasm';

type Format = 'csv' | 'json' | 'traces';

export interface FilesHooks {
  editor: HTMLTextAreaElement;
  status: HTMLElement;
  /** Says what is wrong, as an error. */
  problem: (text: string | null) => void;
  /** Shows a text opened from a file as an edited experiment. */
  showEdited: (text: string) => void;
  /** The sweep in view's name and exports, once it has ended; null before. */
  exports: () => ({ name: string } & Partial<Record<Format, string>>) | null;
}

export function shareFiles({ editor, status, problem, showEdited, exports }: FilesHooks) {
  const linkButton = byId<HTMLButtonElement>('experiment-link');
  linkButton.addEventListener('click', async () => {
    let payload: string;
    try {
      payload = packExperiment(editor.value);
    } catch (e) {
      problem(`This experiment cannot be shared: ${core.message(e)}`);
      return;
    }
    const url = `${location.origin}${location.pathname}${location.search}#${payload}`;
    history.replaceState(null, '', `#${payload}`);
    await copyLink(linkButton, url, 'Copy experiment link');
  });
  byId<HTMLButtonElement>('experiment-save').addEventListener('click', () => {
    let name = 'experiment';
    try {
      name = experimentInfo(editor.value).name;
    } catch {
      // A draft that does not read yet is saved as it is, under a neutral name.
    }
    download(`${name}.json`, editor.value, 'application/json');
  });
  const openInput = byId<HTMLInputElement>('experiment-open');
  openInput.addEventListener('change', async () => {
    const file = openInput.files?.[0];
    openInput.value = '';
    if (!file) return;
    showEdited(await file.text());
    status.textContent = `Opened ${file.name}.`;
  });

  const save = (format: Format) => {
    const sweep = exports();
    const text = sweep?.[format];
    if (!sweep || text === undefined) return;
    const ext = format === 'json' ? 'jsonl' : 'csv';
    const name = format === 'traces' ? `${sweep.name}-traces` : sweep.name;
    download(`${name}.${ext}`, text, format === 'json' ? 'application/x-ndjson' : 'text/csv');
  };
  for (const format of ['csv', 'json', 'traces'] as const) byId(`export-${format}`).addEventListener('click', () => save(format));
}
