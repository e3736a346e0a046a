// Gene colours: stable, distinct, mirrored parts a lighter shade.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { cssColor, geneColor, parseCssColor } from '../src/palette.js';

const rgb = (c) => [(c >> 16) & 255, (c >> 8) & 255, c & 255];

test('the same gene always gets the same colour', () => {
  assert.equal(geneColor(3), geneColor(3));
  assert.equal(geneColor(0), 0x3f7fc7);
});

test('the first 24 genes all differ', () => {
  const seen = new Set();
  for (let g = 0; g < 24; ++g) seen.add(geneColor(g));
  assert.equal(seen.size, 24);
});

test('a mirrored part is a lighter shade of its gene', () => {
  for (let g = 0; g < 12; ++g) {
    const a = rgb(geneColor(g)), b = rgb(geneColor(g, true));
    assert.notDeepEqual(a, b);
    a.forEach((v, i) => assert.ok(b[i] >= v, `gene ${g} channel ${i}`));
    // still closer to its own gene than to white
    assert.ok(b.some((v) => v < 230));
  }
});

test('colours as CSS text and back', () => {
  assert.equal(cssColor(0x0a0b0c), '#0a0b0c');
  assert.equal(parseCssColor('#0A0B0C'), 0x0a0b0c);
  assert.equal(parseCssColor('#f80'), 0xff8800);
  assert.equal(parseCssColor('red'), null);
  assert.equal(parseCssColor(7), null);
});
