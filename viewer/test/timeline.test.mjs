// Time lookup: which frames bracket a moment, and values between frames.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { bracket, comAt, distanceAt, duration, neuronAt, partPoseAt } from '../src/timeline.js';
import { aboutZ, makeReplay } from './fixture.mjs';

const frames = makeReplay().frames; // t = 0, 0.1, ..., 2.0
const near = (a, b, eps = 1e-6) => assert.ok(Math.abs(a - b) < eps, `${a} != ${b}`);

test('duration is the last frame time', () => {
  near(duration(frames), 2.0);
});

test('bracket finds the frames around a time and the fraction between them', () => {
  assert.deepEqual(bracket(frames, -1), { i: 0, j: 0, u: 0 });
  assert.deepEqual(bracket(frames, 0), { i: 0, j: 0, u: 0 });
  assert.deepEqual(bracket(frames, 5), { i: 20, j: 20, u: 0 });
  const b = bracket(frames, 0.125);
  assert.equal(b.i, 1);
  assert.equal(b.j, 2);
  near(b.u, 0.25);
  // on a frame's time exactly: that frame
  const on = bracket(frames, frames[7].t);
  assert.equal(on.i, 7);
  near(on.u, 0);
});

test('poses, centre of mass and distance interpolate between frames', () => {
  const p = partPoseAt(frames, 1, 1.05);
  near(p[0], 1.35);
  const q = aboutZ((Math.PI / 4) * 1.05);
  [3, 4, 5, 6].forEach((k, i) => near(p[k], q[i], 1e-6));
  near(comAt(frames, 0.55)[0], 0.7);
  near(distanceAt(frames, 1.5), 1.5);
  near(distanceAt(frames, 99), 2.0);
});

test('a neuron output holds until the next frame', () => {
  near(neuronAt(frames, 0, 0.55), Math.sin(0.5));
  near(neuronAt(frames, 0, 0.5), Math.sin(0.5));
});
