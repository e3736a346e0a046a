// What the side panel says about a creature, and about a catapult's throw.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { infoRows } from '../src/info_panel.js';
import { makeCatapult, makeReplay } from './fixture.mjs';

const rows = (replay) => Object.fromEntries(infoRows({ label: 'x', replay }));

test('a creature: its body, distance and fitness', () => {
  const r = rows(makeReplay());
  assert.equal(r.body, '2 parts, 1 joints, 1 neurons');
  assert.equal(r.distance, '2.00 m');
  assert.equal(r.fitness, '2');
  assert.equal(r.projectile, undefined);
  assert.equal(r.release, undefined);
});

test('a creature of another kind: its kind, and its controller\'s signals for neurons', () => {
  const replay = makeReplay();
  delete replay.dialect;
  replay.creature = 'river';
  const r = rows(replay);
  assert.equal(r.creature, 'river');
  assert.equal(r.dialect, undefined);
  assert.equal(r.body, '2 parts, 1 joints, 1 controller signals');
  assert.equal(rows(makeReplay()).dialect, 'sims1994');
});

test('a catapult: its projectile, the release, the throw distance', () => {
  const r = rows(makeCatapult());
  assert.equal(r.projectile, 'part 2');
  assert.equal(r.release, 'released at 0.50 s');
  assert.equal(r['throw distance'], '1.00 m');
  assert.equal(r['target miss'], undefined); // no target
  assert.equal(r.distance, undefined); // the throw distance says it
  assert.equal(rows(makeCatapult({ release: null })).release, 'not released');
});

test('a catapult aiming at a target: the miss too', () => {
  const r = rows(makeCatapult({ target: [2, 0, 0.075] }));
  assert.equal(r['target miss'], '0.40 m');
  // rows in order: the throw's facts before the fitness
  const keys = infoRows({ label: 'x', replay: makeCatapult({ target: [2, 0, 0.075] }) }).map(([k]) => k);
  assert.deepEqual(keys.slice(-5), ['projectile', 'release', 'throw distance', 'target miss', 'fitness']);
  // a file from before the task's metrics held the miss as a field of its own
  assert.equal(rows(makeCatapult({ target: [2, 0, 0.075], legacy: true }))['target miss'], '0.40 m');
});

test("a task's named measures, each a row", () => {
  const replay = makeReplay();
  replay.result.metrics = { level: 2, 'food eaten': 3, 'level 1 completed': 1 };
  const r = rows(replay);
  assert.equal(r.level, '2');
  assert.equal(r['food eaten'], '3');
  assert.equal(r['level 1 completed'], '1');
  assert.equal(r.distance, '2.00 m');
});

test('a fitness averaged over trials says so, and which trial is shown', () => {
  const replay = makeCatapult();
  replay.result.fitness = 2;
  replay.result.trial_fitness = [1, 2.5, 2.5];
  const r = rows(replay);
  assert.equal(r.fitness, '2');
  assert.equal(r.trials, 'mean of 3: 1, 2.5, 2.5 (shown: the first)');
  // task.trial_score = min: the fitness is the least trial's
  replay.result.fitness = 1;
  assert.equal(rows(replay).trials, 'least of 3: 1, 2.5, 2.5 (shown: the first)');
  // all equal: their mean and least agree
  replay.result.trial_fitness = [1, 1, 1];
  assert.equal(rows(replay).trials, 'mean of 3: 1, 1, 1 (shown: the first)');
  // a later trial's frames (bestiary simulate --trial 3) say which
  replay.result.trial = 3;
  assert.equal(rows(replay).trials, 'mean of 3: 1, 1, 1 (shown: trial 3)');
  assert.equal(rows(makeCatapult()).trials, undefined); // one trial: no row
});
