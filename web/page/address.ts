// What the page's address asks for besides a link: `?embed` (in a course page's iframe, with
// `?embed=edit` its editors too) and `?debug` (the debug view: internal counters, crash recovery).

/** True when the page was opened with `?embed` (any value). */
export function embedRequested(search = location.search): boolean {
  return new URLSearchParams(search).has('embed');
}

/**
 * True when the embed also shows the scenario's editors (`?embed=edit`), so that an exercise
 * can be done inside the iframe: the fields it leaves open are editable, the locked ones not.
 */
export function embedEditRequested(search = location.search): boolean {
  return new URLSearchParams(search).get('embed') === 'edit';
}

/** True with `?debug` in the address. */
export function debugRequested(search = location.search): boolean {
  return new URLSearchParams(search).has('debug');
}
