// The grid's textures: each cell in its kind's colour with a darker edge,
// and a field's values as a heat map, clear at 0, warm above and cold below.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { CELL_PX, heatColor, heatGradient, paintCells, paintField } from '../src/cell_paint.js';

const kinds = [{ color: 0x336699 }, { color: 0xffffff }];

test('each cell is painted in its kind colour, row 0 first, with a darker last row and column', () => {
  const px = paintCells([0, 1, 1, 0], kinds, 2, 2);
  const W = 2 * CELL_PX;
  const at = (x, y) => Array.from(px.slice(4 * (y * W + x), 4 * (y * W + x) + 4));
  assert.equal(px.length, W * W * 4);
  assert.deepEqual(at(1, 1), [0x33, 0x66, 0x99, 255]);               // cell (0, 0)
  assert.deepEqual(at(CELL_PX + 1, 1), [255, 255, 255, 255]);         // cell (1, 0)
  assert.deepEqual(at(1, CELL_PX + 1), [255, 255, 255, 255]);         // cell (0, 1)
  assert.deepEqual(at(CELL_PX - 1, 1), [Math.round(0x33 * 0.82), Math.round(0x66 * 0.82), Math.round(0x99 * 0.82), 255]);
});

test('a heat colour is clear at 0, warm above, cold below, more opaque toward its end', () => {
  assert.deepEqual(heatColor(0, -15, 15), [0, 0, 0, 0]);
  const hot = heatColor(15, -15, 15), warm = heatColor(1, -15, 15), cold = heatColor(-15, -15, 15);
  assert.ok(hot[0] > hot[2] && warm[0] > warm[2], 'red over blue above 0');
  assert.ok(cold[2] > cold[0], 'blue over red below 0');
  assert.ok(hot[3] > warm[3] && warm[3] > 0);
  assert.deepEqual(heatColor(99, -15, 15), hot); // held at its end
  assert.deepEqual(heatColor(-1, 0, 15), [0, 0, 0, 0]); // a scale with no cold side
});

test('a field paints one texel per cell, and its scale reads as a gradient', () => {
  const tex = paintField({ width: 2, height: 1, lo: -15, hi: 15, values: [15, -15] });
  assert.deepEqual(Array.from(tex.slice(0, 4)), heatColor(15, -15, 15));
  assert.deepEqual(Array.from(tex.slice(4, 8)), heatColor(-15, -15, 15));
  assert.match(heatGradient(-15, 15), /^linear-gradient\(to right, rgba\(30, 50, 170, 0\.55\).*rgba\(190, 20, 30, 0\.55\)\)$/);
});
