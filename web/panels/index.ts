// The page's panels, each set up once with the page's context (see page.ts).
export { type Inspector, setupInspector } from './inspector';
export { type Keys, setupKeys, TABS } from './keys';
export type { LoadOptions, Page } from './page';
export { type RunPanel, setupRunPanel } from './run';
export { type ScenarioPanel, setupScenarioPanel } from './scenario';
export { type SharePanel, setupSharePanel } from './share';
