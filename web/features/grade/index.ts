// Grading hand-ins in the browser: pasted links or a form's CSV export, replayed on a pool of
// workers and judged as `kumiki check` judges them, exported as CSV.
import type { Feature } from '../../page/context';
import { setupGrade } from './grade';

export const grade: Feature = {
  name: 'grade',
  mount: setupGrade,
};
