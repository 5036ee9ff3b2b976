// Classroom exercises in the page: the student's panel (instructions, goal, hints, Check, Hand in)
// and the teacher's editor that makes an exercise from the scenario in view.
import type { Feature } from '../../page/context';
import { setupExerciseEditor, setupStudentPanel } from './exercise';

export const exercise: Feature = {
  name: 'exercise',
  mount(page) {
    setupStudentPanel(page);
    setupExerciseEditor(page);
  },
};
