// The run told to screen readers in a polite live region: a scenario opened, the disturbances it
// meets, its end, the exercise's verdict, the keyboard cursor, and calmly its progress.
import type { Feature } from '../../page/context';
import { cellCoords } from '../../render/geometry';
import { byId, displayText } from '../../widgets/dom';
import { Announcer, type Disturbance } from './announcer';

export const announce: Feature = {
  name: 'announce',
  mount({ session, prefs, events }) {
    const announcer = new Announcer(byId('run-live'));
    const cellText = (cell: number) => `cell ${session.layout ? cellCoords(session.layout, cell) : ''}`;
    const disturbances = () => (session.doc().disturbances as Disturbance[] | undefined) ?? [];
    session.on('loaded', () => {
      const doc = session.doc() as { name?: string };
      announcer.loaded(displayText(doc.name ?? '', 100) || 'The scenario', disturbances());
    });
    session.on('frame', (frame) => announcer.frame(frame, session.playing, prefs.chartMetric, cellText));
    session.on('recorded', () => announcer.disturbed(disturbances(), cellText));
    events.on('say', (text) => announcer.say(text));
    events.on('goal', ({ met, because }) => announcer.say(met ? `Goal met: ${because}.` : `Goal not met yet: ${because}.`));
  },
};
