// The neurons' series for the sparklines.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { neuronLabel, neuronSeries, sparkPoints } from '../src/neurons.js';
import { makeReplay } from './fixture.mjs';

test('labels name the neuron, its part and its function', () => {
  assert.equal(neuronLabel({ part: 2, fn: 'sigmoid' }, 5), '5: part 2 · sigmoid');
  assert.equal(neuronLabel({ part: -1, fn: 'osc' }, 0), '0: global · osc');
});

test('one series per neuron with its range', () => {
  const r = makeReplay();
  const [s] = neuronSeries(r);
  assert.equal(s.values.length, r.frames.length);
  assert.ok(Math.abs(s.max - Math.sin(1.6)) < 1e-6); // sin peaks at t = 1.6 of the frames
  assert.equal(s.min, 0);
});

test('a constant output gets a range around it', () => {
  const r = makeReplay();
  r.frames.forEach((f) => (f.neurons = [0.3]));
  const [s] = neuronSeries(r);
  assert.ok(s.min < 0.3 && s.max > 0.3);
});

test('points span the box: time across, value up', () => {
  const r = makeReplay();
  const [s] = neuronSeries(r);
  const pts = sparkPoints(s, r.frames.map((f) => f.t), 100, 20, 2);
  assert.equal(pts.length, 2 * r.frames.length);
  assert.equal(pts[0], 0);
  assert.equal(pts[pts.length - 2], 100);
  // the first value is the minimum: bottom of the box
  assert.ok(Math.abs(pts[1] - 18) < 1e-6);
});
