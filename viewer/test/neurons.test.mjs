// The neurons' series for their traces.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { neuronAxis, neuronLabel, neuronSeries, sparkPoints } from '../src/neurons.js';
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
  // inside -1..1: drawn on it, with a zero line
  assert.equal(s.lo, -1);
  assert.equal(s.hi, 1);
  assert.deepEqual(s.lines, [{ v: 0, kind: 'zero' }]);
  assert.equal(neuronAxis([s]), 'axis -1 .. 1');
});

test('neurons beyond -1..1 share one range; the others keep -1..1', () => {
  const r = makeReplay();
  r.neurons = [{ part: 0, fn: 'sum' }, { part: 0, fn: 'sin' }, { part: -1, fn: 'integrate' }];
  r.frames.forEach((f) => (f.neurons = [3 * f.t, Math.sin(f.t), -f.t]));
  const [sum, sin, integral] = neuronSeries(r);
  assert.deepEqual([sin.lo, sin.hi], [-1, 1]);
  // sum 0.3..6, integral -2..-0.1 (from frame 1 on): together -2..6
  for (const s of [sum, integral]) {
    assert.ok(Math.abs(s.lo + 2) < 1e-6 && Math.abs(s.hi - 6) < 1e-6, `${s.lo} ${s.hi}`);
    assert.deepEqual(s.lines, [{ v: 0, kind: 'zero' }]);
  }
  assert.equal(neuronAxis([sum, sin, integral]), 'axis -1 .. 1; 2 beyond it share -2.000 .. 6.000');
  assert.equal(neuronAxis([sum, integral]), 'axis -2.000 .. 6.000, shared');
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
  // the first value drawn, sin(0.1), on the range -1..1
  assert.ok(Math.abs(pts[1] - (2 + (1 - (Math.sin(0.1) + 1) / 2) * 16)) < 1e-4);
  // from frame 0 when asked
  const all = sparkPoints({ ...s, from: 0 }, times, 100, 20, 2);
  assert.equal(all.length, 2 * r.frames.length);
  assert.equal(all[0], 0);
});
