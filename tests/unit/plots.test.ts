import { describe, expect, it } from 'vitest';
// The name lives beside `download` (web/widgets/dom.ts), which needs no wasm.
import { figureFileName } from '../../web/widgets/dom';

describe('figure files', () => {
  it('are named after the experiment and the figure number, safe for any file system', () => {
    expect(figureFileName('amas-fig23', 1, 'svg')).toBe('amas-fig23-1.svg');
    expect(figureFileName('my sweep/2', 3, 'png')).toBe('my-sweep-2-3.png');
    expect(figureFileName('///', 2, 'svg')).toBe('experiment-2.svg');
  });
});
