// The centre of mass's trail on the ground.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { groundPath, ribbon, ribbonIndices, TRAIL_LIFT, trailAt } from '../src/trail.js';
import { makeReplay } from './fixture.mjs';

const frames = makeReplay().frames;

test('the path holds every frame centre of mass on the ground', () => {
  const p = groundPath(frames);
  assert.equal(p.length, frames.length * 3);
  assert.ok(Math.abs(p[3 * 4] - frames[4].com[0]) < 1e-6);
  for (let k = 0; k < frames.length; ++k) assert.ok(Math.abs(p[3 * k + 2] - TRAIL_LIFT) < 1e-9);
});

test('the trail grows with time and ends at the present centre of mass', () => {
  assert.equal(trailAt(frames, 0).count, 1);
  const mid = trailAt(frames, 0.55);
  assert.equal(mid.count, 6); // frames 0..5, then the head
  assert.ok(Math.abs(mid.head[0] - 0.7) < 1e-9);
  assert.equal(mid.head[2], TRAIL_LIFT);
  assert.equal(trailAt(frames, 10).count, frames.length);
});

test('the ribbon runs either side of the path, width apart', () => {
  const path = new Float32Array([0, 0, 0.004, 1, 0, 0.004, 1, 1, 0.004]);
  const out = ribbon(path, 3, 0.1, new Float32Array(18));
  // along +x at the start: left is +y, right is -y
  assert.deepEqual(Array.from(out.slice(0, 6)).map((v) => +v.toFixed(6)), [0, 0.05, 0.004, 0, -0.05, 0.004]);
  // at the corner the direction is diagonal; the pair is still width apart
  const d = Math.hypot(out[6] - out[9], out[7] - out[10]);
  assert.ok(Math.abs(d - 0.1) < 1e-6);
  // a path that stands still keeps a valid width
  const still = ribbon(new Float32Array(9), 3, 0.1, new Float32Array(18));
  assert.ok(Math.abs(still[1] - still[4] - 0.1) < 1e-6);
});

test('ribbon triangles join consecutive vertex pairs', () => {
  assert.deepEqual(Array.from(ribbonIndices(3)), [0, 1, 2, 1, 3, 2, 2, 3, 4, 3, 5, 4]);
  assert.equal(ribbonIndices(1).length, 0);
});
