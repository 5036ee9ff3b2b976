import { describe, expect, it } from 'vitest';
import { frameCount } from '../../web/sim/record';
import { recordingName, sanitizeName } from '../../web/features/record/record';

describe('recording file names', () => {
  it('carry the scenario, the seed and the step range', () => {
    expect(recordingName('amas-L', 1, 0, 400, 'webm')).toBe('amas-L_seed1_steps0-400.webm');
    expect(recordingName('amas-L', 7, 120, 120, 'png')).toBe('amas-L_seed7_step120.png');
    expect(recordingName('amas-L', 7, 120, 120, 'png', 2)).toBe('amas-L_seed7_step120_2x.png');
    expect(recordingName('amas-L', 1, 0, 400, 'webm', 2)).toBe('amas-L_seed1_steps0-400_2x.webm');
  });

  it('keep only letters, digits, dot, dash and underscore', () => {
    expect(sanitizeName('Class 3: ../../etc/passwd')).toBe('Class-3-etc-passwd');
    expect(sanitizeName('report\u202Efdp.exe\u0000')).toBe('report-fdp.exe');
    expect(sanitizeName('Café à la carte')).toBe('Cafe-a-la-carte');
    expect(sanitizeName('***')).toBe('kumiki');
    expect(sanitizeName('x'.repeat(200))).toHaveLength(60);
  });
});

describe('frame counts', () => {
  it('are one frame per interval, at least one', () => {
    expect(frameCount(400, 4)).toBe(100);
    expect(frameCount(10, 3)).toBe(3);
    expect(frameCount(2, 5)).toBe(1);
  });
});
