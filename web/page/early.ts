// What a visitor does while the page loads, before the features are mounted (the page's code and
// its wasm module are still arriving): a press of Play (a click, or Space) is kept, shown on the
// button, and acted on by the run feature once the run can start; any click or key at all means the
// page is in use, and a first visit's welcome then does not open over it.

export class EarlyInput {
  /** Play was pressed (an odd number of times) while the page loaded. */
  play = false;
  /** The page was clicked or a key pressed while it loaded. */
  used = false;
  private readonly listening = new AbortController();

  constructor() {
    const signal = this.listening.signal;
    const button = document.getElementById('play');
    document.addEventListener('pointerdown', () => (this.used = true), { capture: true, signal });
    document.addEventListener(
      'keydown',
      (e) => {
        this.used = true;
        // Space is the page's Play where no control takes it (as web/page/keys.ts decides once mounted).
        const free = document.activeElement === document.body || document.activeElement?.id === 'view';
        if (e.key === ' ' && free && !e.ctrlKey && !e.metaKey && !e.altKey) {
          e.preventDefault();
          this.toggle(button);
        }
      },
      { capture: true, signal },
    );
    button?.addEventListener('click', () => this.toggle(button), { signal });
  }

  private toggle(button: HTMLElement | null) {
    this.play = !this.play;
    if (!button) return;
    button.textContent = this.play ? 'Pause' : 'Play';
    button.setAttribute('aria-label', this.play ? 'Pause (Space)' : 'Play (Space)');
    button.setAttribute('aria-pressed', String(this.play));
  }

  /** The features take over: nothing more is kept. */
  stop() {
    this.listening.abort();
  }
}
