// Reading a class's hand-ins for the Grade view: pasted links, and the CSV or text exports of
// forms and learning platforms, with the student's name where the export has it.
import { describe, expect, test } from 'vitest';
import { cells, gradesCsv, parseHandins } from '../../web/features/grade/handins';

const A = 'https://example.org/kumiki/#k1.jZLBbsIwDIbvfYqo5x6S';
const B = '#k1.AbC-d_e';

describe('hand-ins', () => {
  test('links one a line, with comments and blank lines skipped as kumiki check does', () => {
    const got = parseHandins(`# class 3\n${A}\n\n${B}\nk1.xyz\n`);
    expect(got.map((h) => h.link)).toEqual([A, B, 'k1.xyz']);
    expect(got.map((h) => h.student)).toEqual(['', '', '']);
  });

  test("a form's CSV export: the header names the student's column; quoted names keep their commas", () => {
    const csv = `Timestamp,"Full name",Your Kumiki link\n2026-11-25 10:02:11,"Lovelace, Ada",${A}\n2026-11-25 10:03:40,Grace Hopper,"${B}"\n2026-11-25 10:04:00,Linus,I forgot the link\n`;
    const got = parseHandins(csv);
    expect(got.map((h) => [h.student, h.link])).toEqual([
      ['Lovelace, Ada', A],
      ['Grace Hopper', B],
      ['Linus', null],
    ]);
    expect(got[2].row).toBe(4);
  });

  test('tab- and semicolon-separated exports, without a header: the first cell that is not a date', () => {
    expect(parseHandins(`2026-11-25T10:00:00Z\tAda\t${A}`)[0].student).toBe('Ada');
    expect(parseHandins(`Ada;12;${B}`)[0].student).toBe('Ada');
    expect(cells('a;"b;c";d')).toEqual(['a', 'b;c', 'd']);
  });

  test('the CSV export has a column for every metric the goal read, and the error rows', () => {
    const text = gradesCsv([
      {
        handin: 1,
        student: 'Ada',
        link: A,
        name: 'Ada',
        met: true,
        because: 'the run completed',
        completed: true,
        steps: 209,
        hash: '2cce7f7c37266b5e',
        locked_edited: [],
        changed: ['collision'],
        exercise_edited: false,
        goal_metrics: { collisions: 9 },
      },
      { handin: 2, student: 'Linus', link: null, error: 'row 4 holds no Kumiki link: I forgot, sorry' },
    ]);
    expect(text.split('\n')).toEqual([
      'handin,student,name,met,because,completed,steps,hash,locked_edited,changed,exercise_edited,metrics.collisions,error,link',
      `1,Ada,Ada,true,the run completed,true,209,2cce7f7c37266b5e,,collision,false,9,,${A}`,
      '2,Linus,,false,,,,,,,,,"row 4 holds no Kumiki link: I forgot, sorry",',
      '',
    ]);
  });
});
