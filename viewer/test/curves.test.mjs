// A run's fitness curves and the choice of a generation's best creature.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { CURVES, curveLayout, generationChoices, nearestChoice, niceTicks } from '../src/curves.js';
import { makeRun } from './fixture.mjs';

test('ticks are round numbers covering the range', () => {
  assert.deepEqual(niceTicks(0, 5, 5), [0, 1, 2, 3, 4, 5]);
  assert.deepEqual(niceTicks(0, 1, 4), [0, 0.5, 1]);
  assert.deepEqual(niceTicks(-3, 7, 5), [-2, 0, 2, 4, 6]);
  assert.deepEqual(niceTicks(2, 2, 4), [2, 2.5, 3]); // an empty range widens
});

test('each curve is a path with one point per generation', () => {
  const L = curveLayout(makeRun(), 200, 100, { left: 10, right: 10, top: 10, bottom: 10 });
  for (const k of CURVES) {
    assert.equal(L.paths[k].match(/[ML]/g).length, 5, k);
    assert.ok(L.paths[k].startsWith('M10,'), L.paths[k]);
  }
  // generation 0 on the left edge, the last on the right
  assert.equal(L.x(0), 10);
  assert.equal(L.x(4), 190);
  // higher fitness is higher up; zero is on the axis
  assert.ok(L.y(5) < L.y(1));
  assert.equal(L.y(0), 90);
  assert.equal(Math.round(L.genAt(100)), 2);
  assert.ok(L.yTicks.length >= 3);
  assert.deepEqual(L.xTicks.map((t) => t.value), [0, 1, 2, 3, 4]);
});

test('the best of each generation, playable when replayed, in generation order', () => {
  const c = generationChoices(makeRun());
  assert.deepEqual(c, [
    { gen: 0, id: 3, best: 1, replayIndex: 1 },
    { gen: 1, id: 7, best: 2, replayIndex: null },
    { gen: 2, id: 12, best: 3, replayIndex: 2 },
    { gen: 3, id: 12, best: 3, replayIndex: 2 },
    { gen: 4, id: 20, best: 5, replayIndex: 0 },
  ]);
  // the nearest playable one: generation 1's best is not replayed
  assert.equal(nearestChoice(c, 3.6).gen, 4);
  assert.equal(nearestChoice(c, 0.9).gen, 0);
  assert.equal(nearestChoice(c, 1.1).gen, 2);
  assert.equal(nearestChoice([], 1), null);
});

test('the fitness range holds the members too', () => {
  const run = makeRun();
  run.members[2].fitness = -4; // an ancestor below every curve
  const L = curveLayout(run, 200, 100, { left: 10, right: 10, top: 10, bottom: 10 });
  assert.equal(L.y(-4), 90); // the bottom of the plot
});

test('a run of one generation still lays out', () => {
  const run = { generations: [{ gen: 0, best: 1, mean: 1, median: 1 }], members: [] };
  const L = curveLayout(run, 200, 100);
  assert.match(L.paths.best, /^M[\d.]+,[\d.]+$/);
  assert.ok(Number.isFinite(L.x(0)));
  assert.deepEqual(L.xTicks.map((t) => t.value), [0]); // not a second tick on top of it
});
