// A small typed event bus: the session's events and the page's (web/page/context.ts) are two of
// them. Listeners run in the order they were added, at once; one that throws does not stop the
// others (its error is thrown again after them, where the browser reports it).

type Listener<T> = (value: T) => void;

export class Events<E> {
  private readonly listeners = new Map<keyof E, Listener<never>[]>();

  on<K extends keyof E>(event: K, listener: Listener<E[K]>) {
    const list = this.listeners.get(event) ?? [];
    list.push(listener as Listener<never>);
    this.listeners.set(event, list);
  }

  emit<K extends keyof E>(event: K, value: E[K]) {
    for (const listener of this.listeners.get(event) ?? []) {
      try {
        (listener as Listener<E[K]>)(value);
      } catch (e) {
        setTimeout(() => {
          throw e;
        });
      }
    }
  }
}
