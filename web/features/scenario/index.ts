// Editing the scenario in view: the Scenario tab (the model's editor, every parameter as a form
// field, the JSON text, undo and redo) and the scenario's name at the top of the page.
import type { Feature } from '../../page/context';
import { setupScenarioPanel } from './scenario';

export const scenario: Feature = {
  name: 'scenario',
  tab: 'Scenario',
  mount: setupScenarioPanel,
};
