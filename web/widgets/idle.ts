// Work that must not compete with the first frame: run in an idle moment of the main thread.

/** Runs `run` in an idle moment of the main thread, or after `timeoutMs` where none comes (after a second where the browser cannot say when). */
export function whenIdle(run: () => void, timeoutMs: number) {
  if ('requestIdleCallback' in window) requestIdleCallback(run, { timeout: timeoutMs });
  else setTimeout(run, Math.min(timeoutMs, 1000));
}
