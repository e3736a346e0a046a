// The neurons' series for their traces.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { neuronLabel, neuronSeries, sparkPoints } from '../src/neurons.js';
import { makeReplay } from './fixture.mjs';

test('labels name the neuron, its part and its function', () => {
  assert.equal(neuronLabel({ part: 2, fn: 'sigmoid' }, 5), '5: part 2 · sigmoid');
  assert.equal(neuronLabel({ part: -1, fn: 'osc' }, 0), '0: global · osc');
});

test('one series per neuron with its range from frame 1 on (frame 0 is before the first brain step)', () => {
  const r = makeReplay();
  const [s] = neuronSeries(r);
  assert.equal(s.values.length, r.frames.length);
  assert.equal(s.from, 1);
  assert.ok(Math.abs(s.max - Math.sin(1.6)) < 1e-6); // sin peaks at t = 1.6 of the frames
  assert.ok(Math.abs(s.min - Math.sin(0.1)) < 1e-6);
  assert.equal(s.constant, false);
  // drawn over its own range, with no zero line (all values are positive)
  assert.equal(s.lo, s.min);
  assert.equal(s.hi, s.max);
  assert.deepEqual(s.lines, []);
});

test('a constant output is constant, with a drawn range around it', () => {
  const r = makeReplay();
  r.frames.forEach((f, i) => (f.neurons = [i === 0 ? 0 : 0.3]));
  const [s] = neuronSeries(r);
  assert.ok(Math.abs(s.min - 0.3) < 1e-6 && Math.abs(s.max - 0.3) < 1e-6);
  assert.equal(s.constant, true); // frame 0's 0 does not count
  assert.ok(s.lo < 0.3 && s.hi > 0.3);
});

test('points span the box from frame 1 on: time across, value up', () => {
  const r = makeReplay();
  const [s] = neuronSeries(r);
  const times = r.frames.map((f) => f.t);
  const pts = sparkPoints(s, times, 100, 20, 2);
  assert.equal(pts.length, 2 * (r.frames.length - 1));
  assert.ok(Math.abs(pts[0] - (times[1] / times[times.length - 1]) * 100) < 1e-4);
  assert.equal(pts[pts.length - 2], 100);
  // the first value drawn is the minimum: bottom of the box
  assert.ok(Math.abs(pts[1] - 18) < 1e-5);
  // from frame 0 when asked
  const all = sparkPoints({ ...s, from: 0 }, times, 100, 20, 2);
  assert.equal(all.length, 2 * r.frames.length);
  assert.equal(all[0], 0);
});
