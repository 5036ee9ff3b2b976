// The run's transport under the view: play, step, reset, the speed, the timeline and the seed, the
// step count, status and progress of each frame; and the page's keys that move the run (Space, the
// arrows, R) and the view (+ - 0).
import type { Frame } from '../../contract.gen';
import type { PageContext } from '../../page/context';
import { onPlainKey } from '../../page/keys';
import { byId } from '../../widgets/dom';
import * as core from '../../wasm';
import { SPEED_MAX, speedText, stepsPerSecond } from './speed';

export function setupTransport(page: PageContext) {
  const { session, sim, view, prefs } = page;

  const speed = byId<HTMLInputElement>('speed');
  const speedOut = byId('speed-out');
  function applySpeed() {
    const position = Math.max(0, Math.min(SPEED_MAX, Number(speed.value)));
    const v = stepsPerSecond(position);
    const text = speedText(v);
    speedOut.textContent = text.short;
    speed.setAttribute('aria-valuetext', text.spoken);
    sim.setSpeed(v);
    prefs.speedIndex = position;
    page.persistPrefs();
  }
  speed.value = String(prefs.speedIndex);
  speed.addEventListener('input', applySpeed);
  applySpeed();

  const timeline = byId<HTMLInputElement>('timeline');
  /** While the timeline is dragged, frames do not move its thumb under the pointer. */
  let timelineDragging = false;
  timeline.addEventListener('input', () => sim.seek(Number(timeline.value)));
  timeline.addEventListener('pointerdown', () => (timelineDragging = true));
  timeline.addEventListener('pointerup', () => (timelineDragging = false));
  timeline.addEventListener('pointercancel', () => (timelineDragging = false));
  /**
   * Where the back presses sent so far lead. Each press goes back from the last one sent, not from
   * the frame in view: a rewind takes the worker a while, and presses made meanwhile must count.
   * Cleared once a frame shows that step, and whenever the run moves another way.
   */
  let backTarget: number | null = null;
  const stepBack = (count = 1) => {
    const frame = session.frame;
    if (!frame) return;
    const from = backTarget !== null && !session.playing ? backTarget : frame.steps;
    if (from <= 0) return;
    backTarget = Math.max(0, from - count);
    sim.seek(backTarget);
  };
  const forget = () => (backTarget = null);
  timeline.addEventListener('input', forget);

  // From now on Play is the transport's; one pressed while the page loaded starts the run with its
  // first frame, as does one pressed before a run has one.
  page.early.stop();
  let playWanted = page.early.play;
  const startWanted = () => {
    if (!playWanted) return;
    playWanted = false;
    sim.play();
  };

  const togglePlay = () => {
    forget();
    if (!session.frame) {
      playWanted = !playWanted;
      showPlaying(playWanted);
      return;
    }
    if (session.playing) sim.pause();
    else sim.play();
  };
  const stepOnce = () => {
    forget();
    sim.step(1);
  };
  const reset = () => {
    forget();
    session.reset();
  };
  byId('play').addEventListener('click', togglePlay);
  byId('step').addEventListener('click', stepOnce);
  byId('reset').addEventListener('click', reset);

  const seedInput = byId<HTMLInputElement>('seed');
  /** Sets the seed as written: the core checks it (a whole number it can carry exactly) and says why not. */
  function setSeed(seed: string) {
    void session.set('seed', seed || '""', { onProblem: (problem) => page.banner.report(`The seed was not changed: ${problem}`) });
  }
  seedInput.addEventListener('change', () => setSeed(seedInput.value.trim()));
  byId('new-seed').addEventListener('click', () => setSeed(String(core.freshSeed())));

  function showFrame(frame: Frame) {
    if (frame.steps === backTarget) backTarget = null;
    byId('step-count').textContent = frame.steps.toLocaleString('en-US');
    if (frame.hash) byId('state-hash').textContent = frame.hash;
    const status = byId('run-status');
    const goal = session.layout?.goal ?? true;
    status.textContent = frame.completed
      ? `completed in ${frame.steps.toLocaleString('en-US')} steps`
      : frame.finished
        ? goal
          ? 'step limit reached'
          : `ran ${frame.steps.toLocaleString('en-US')} steps`
        : '';
    status.classList.toggle('failed', frame.finished && !frame.completed && goal);
    // In an exercise the goal's verdict is the one in colour: completing may not be meeting it.
    status.classList.toggle('plain', session.doc().exercise !== undefined);
    if (!timelineDragging) {
      timeline.max = String(frame.furthest);
      timeline.value = String(frame.steps);
    }
    timeline.setAttribute('aria-valuetext', `step ${frame.steps} of ${frame.furthest}`);
    byId('timeline-out').textContent = `${frame.steps.toLocaleString('en-US')} / ${frame.furthest.toLocaleString('en-US')}`;
    const bar = byId('run-progress');
    const pct = frame.completed ? 100 : Math.min(100, (100 * frame.steps) / Math.max(1, frame.max_steps));
    (bar.firstElementChild as HTMLElement).style.width = `${pct}%`;
    bar.setAttribute('aria-valuenow', pct.toFixed(0));
  }

  function showPlaying(on: boolean) {
    const button = byId('play');
    button.textContent = on ? 'Pause' : 'Play';
    button.setAttribute('aria-label', on ? 'Pause (Space)' : 'Play (Space)');
    button.setAttribute('aria-pressed', String(on));
  }

  /** The seed of the scenario in view; a locked seed is read-only, and New seed cannot replace it by accident. */
  function showSeed() {
    seedInput.value = String(session.doc().seed ?? 0);
    const locked = (session.doc().exercise as { locked?: Record<string, unknown> } | undefined)?.locked ?? {};
    const seedLocked = 'seed' in locked;
    seedInput.readOnly = seedLocked;
    seedInput.setAttribute('aria-label', seedLocked ? 'Random seed, locked by the exercise' : 'Random seed');
    const newSeed = byId<HTMLButtonElement>('new-seed');
    newSeed.disabled = seedLocked;
    newSeed.title = seedLocked ? 'The exercise locks the seed' : '';
  }

  session.on('loaded', () => {
    forget();
    showSeed();
  });
  session.on('frame', (frame) => {
    showFrame(frame);
    startWanted();
  });
  session.on('playing', showPlaying);

  // ---- keys -------------------------------------------------------------------------------------

  /** When the Left arrow held down was first pressed. */
  let heldSince = 0;
  /**
   * Steps one Left-arrow event goes back: a press goes back one; held, the key's repeats scrub,
   * one step each for the first half second, then twice as many every further half second (to
   * 64), so a long run can be crossed by holding the key.
   */
  function backStride(e: KeyboardEvent): number {
    if (!e.repeat) {
      heldSince = e.timeStamp;
      return 1;
    }
    return 2 ** Math.min(6, Math.floor(Math.max(0, e.timeStamp - heldSince) / 500));
  }

  onPlainKey((e, { onView }) => {
    switch (e.key) {
      case ' ':
        e.preventDefault();
        togglePlay();
        return;
      case 'ArrowRight':
        e.preventDefault();
        stepOnce();
        return;
      case 'ArrowLeft':
        // Left steps back only from the view.
        if (!onView) return;
        e.preventDefault();
        stepBack(backStride(e));
        return;
      case 'r':
      case 'R':
        e.preventDefault();
        reset();
        return;
      case '+':
      case '=':
        view.zoom(1.25);
        return;
      case '-':
        view.zoom(0.8);
        return;
      case '0':
        view.fit();
        return;
    }
  });
  byId('zoom-in').addEventListener('click', () => view.zoom(1.25));
  byId('zoom-out').addEventListener('click', () => view.zoom(0.8));
  byId('zoom-fit').addEventListener('click', () => view.fit());
}
