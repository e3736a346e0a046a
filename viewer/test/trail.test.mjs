// The centre of mass's trail on the ground.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { groundPath, TRAIL_LIFT, trailAt } from '../src/trail.js';
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
