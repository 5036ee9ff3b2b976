// The banner over the view: one message at a time, with at most one button that offers a way out.
import { byId } from './dom';

export class Banner {
  private readonly box = byId('banner');
  private readonly text = byId('banner-text');
  private readonly action = byId<HTMLButtonElement>('banner-action');
  /** Set while the banner explains the load that follows (a restart, a link that could not be
   * opened), so that load does not clear it. */
  keep = false;
  /** The banner is showing the watchdog's message. */
  stallShown = false;

  constructor() {
    byId('banner-close').addEventListener('click', () => this.dismiss());
  }

  /** Shows a message, with one button that offers a way out when `action` is given. */
  report(text: string, action?: { label: string; run: () => void }) {
    this.text.textContent = text;
    this.action.hidden = !action;
    if (action) this.action.textContent = action.label;
    this.action.onclick = action
      ? () => {
          this.dismiss();
          action.run();
        }
      : null;
    this.box.hidden = false;
  }

  dismiss() {
    this.box.hidden = true;
  }

  get shown(): boolean {
    return !this.box.hidden;
  }
}
