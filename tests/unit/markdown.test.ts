import { describe, expect, test } from 'vitest';
import { parseMarkdown } from '../../web/widgets/markdown';

describe('the exercise Markdown subset', () => {
  test('paragraphs, lists, bold, emphasis and code', () => {
    expect(parseMarkdown('Build the **L** with *fewer* collisions.\nUse `relay`.\n\n- one\n- two')).toEqual([
      {
        kind: 'p',
        spans: [
          { kind: 'text', text: 'Build the ' },
          { kind: 'strong', text: 'L' },
          { kind: 'text', text: ' with ' },
          { kind: 'em', text: 'fewer' },
          { kind: 'text', text: ' collisions. Use ' },
          { kind: 'code', text: 'relay' },
          { kind: 'text', text: '.' },
        ],
      },
      { kind: 'ul', items: [[{ kind: 'text', text: 'one' }], [{ kind: 'text', text: 'two' }]] },
    ]);
  });

  test('markup in the text stays text', () => {
    expect(parseMarkdown('<img src=x onerror="alert(1)"> **<b>hi</b>**')).toEqual([
      {
        kind: 'p',
        spans: [
          { kind: 'text', text: '<img src=x onerror="alert(1)"> ' },
          { kind: 'strong', text: '<b>hi</b>' },
        ],
      },
    ]);
  });
});
