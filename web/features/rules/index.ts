// The Rules tab: the model's rule slots (the decisions a scenario's script may take in place of the
// paper's rule, docs/rules.md), each documented beside an editor of its script; run, reset to the
// paper's rule, and the paper's rule compared with the script side by side. The editor (CodeMirror)
// and the simulation's rules module load only when the tab opens.
import type { Feature } from '../../page/context';
import { setupRules } from './rules';

export const rules: Feature = {
  name: 'rules',
  tab: 'Rules',
  mount: setupRules,
};
