// A run's line of descent, and what the page says about its members.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { bestOf, generationRanges, lineageOf, memberOfReplay, membersById } from '../src/lineage.js';
import { finerStepText, memberRows } from '../src/info_panel.js';
import { lineageText } from '../src/picker.js';
import { runRows } from '../src/run_panel.js';
import { makeRun } from './fixture.mjs';

test('a lineage follows the first parents back to generation 0', () => {
  const run = makeRun();
  const byId = membersById(run);
  assert.deepEqual(lineageOf(byId, 20).map((m) => m.id), [20, 12, 7, 3]);
  assert.deepEqual(lineageOf(byId, 12).map((m) => m.id), [12, 7, 3]);
  assert.deepEqual(lineageOf(byId, 3).map((m) => m.id), [3]);
  assert.deepEqual(lineageOf(byId, 99), []);
  // a loop in bad data ends
  byId.get(3).parent1 = 20;
  assert.deepEqual(lineageOf(byId, 20).map((m) => m.id), [20, 12, 7, 3]);
});

test('members by replay, and the generations each was the best of', () => {
  const run = makeRun();
  assert.equal(memberOfReplay(run, 2).id, 12);
  assert.equal(memberOfReplay(run, 5), null);
  assert.deepEqual(bestOf(run, 12), [2, 3]);
  assert.deepEqual(bestOf(run, 99), []);
  assert.equal(generationRanges([2, 3]), '2-3');
  assert.equal(generationRanges([0, 2, 3, 4, 7]), '0, 2-4, 7');
});

test('a member: its id, birth, parents, generations as the best and stored fitness', () => {
  const run = makeRun();
  const rows = (id) => Object.fromEntries(memberRows(membersById(run).get(id), run.best_id, bestOf(run, id)));
  assert.deepEqual(rows(12), {
    individual: '#12', 'born in': 'generation 2, by crossover', parents: '#7 and #3',
    'best of': 'generations 2-3', 'stored fitness': '3',
  });
  assert.equal(rows(20).individual, '#20 (the overall best)');
  assert.equal(rows(20)['best of'], 'generation 4');
  // an elite evaluated again: its stored fitness is a mean, its replay one evaluation
  assert.equal(rows(20)['stored fitness'], '5 (the mean of 3 evaluations under fresh seeds; the replay is the first)');
  // task.trial_score = min: their least
  assert.equal(Object.fromEntries(memberRows(membersById(run).get(20), run.best_id, [4], 'least'))['stored fitness'],
    '5 (the least of 3 evaluations under fresh seeds; the replay is the first)');
  // the 2nd, 4th, ... stepped at half the step (evolution.elite_half_step)
  assert.equal(Object.fromEntries(memberRows(membersById(run).get(20), run.best_id, [4], 'least', true))['stored fitness'],
    '5 (the least of 3 evaluations under fresh seeds, evaluation 2 at half the step; the replay is the first)');
  assert.equal(finerStepText(1), '');
  assert.equal(finerStepText(5), 'evaluations 2 and 4 at half the step');
  assert.equal(finerStepText(6), 'evaluations 2, 4 and 6 at half the step');
  // and a quarter of the step (evolution.elite_quarter_step): they cycle dt, dt/2, dt/4
  assert.equal(finerStepText(3, true, true), 'evaluation 2 at half the step, 3 at a quarter of it');
  assert.equal(finerStepText(6, true, true), 'evaluations 2 and 5 at half the step, 3 and 6 at a quarter of it');
  assert.equal(finerStepText(4, false, true), 'evaluations 2 and 4 at a quarter of the step');
  assert.equal(Object.fromEntries(memberRows(membersById(run).get(20), run.best_id, [4], 'least', true, true))['stored fitness'],
    '5 (the least of 3 evaluations under fresh seeds, evaluation 2 at half the step, 3 at a quarter of it; the replay is the first)');
  // the run's best measured where selection never looked (evolution.held_out_evaluations)
  assert.equal(rows(20)['held out'], undefined);
  const held = { ...membersById(run).get(20), held_out: { fitness: 3.5, evaluations: 100 } };
  assert.equal(Object.fromEntries(memberRows(held, run.best_id, [4]))['held out'],
    '3.5 (the mean of 100 evaluations under seeds the run never used: what it scores where selection never looked)');
  assert.equal(rows(3).parents, 'none');
  assert.equal(lineageText(membersById(run).get(12)), 'gen 2 · #12 · crossover with #3 · 3');
});

test('the run panel states the run: preset, seed, population, generations, failures', () => {
  const r = Object.fromEntries(runRows(makeRun()));
  assert.equal(r.preset, 'quick (chaumont2007, generational)');
  assert.equal(r['master seed'], '18446744073709551615'); // text: beyond a number's exact range
  assert.equal(r.population, '10');
  assert.equal(r.generations, '5 of 6');
  assert.equal(r.evaluations, '50, of which 3 failed');
  assert.equal(r.rejected, '7 non-viable children redrawn');
  assert.equal(r.replays, '3 of the 4 creatures named (at most 3)');
});
