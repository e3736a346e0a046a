// A run of several stages: its syllabus as a layered graph, and each
// stage's own curve.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { CURVES, curveLayout } from '../src/curves.js';
import { parseRun } from '../src/data.js';
import { chartView, runRows } from '../src/run_panel.js';
import { GRAPH, isStaged, spanText, stageAt, stageDepths, stageRun, syllabusLayout } from '../src/syllabus.js';
import { stageTitle } from '../src/syllabus_view.js';
import { makeRun, makeStagedRun } from './fixture.mjs';

// presets/lessin2015-fast-small.toml's ten stages
const stage = (name, uses = [], group = '') => ({ name, uses, group, first_gen: null, generations: 0, best: null });
const LESSIN = [
  stage('forward'), stage('left', [], 'turn'), stage('right', [], 'turn'), stage('face', ['left', 'right'], 'aim'),
  stage('approach', ['face', 'forward']), stage('strike'), stage('attack', ['approach', 'strike'], 'react'),
  stage('face_away', ['left', 'right'], 'aim'), stage('retreat', ['face_away', 'forward'], 'react'),
  stage('fight', ['attack', 'retreat']),
];

test('a stage is one deeper than the deepest it uses', () => {
  assert.deepEqual(stageDepths(LESSIN), [0, 0, 0, 1, 2, 0, 3, 1, 2, 4]);
});

test('the graph: a column per depth, one edge per use, from the used stage to its user', () => {
  const L = syllabusLayout(LESSIN);
  const byName = new Map(L.nodes.map((n) => [n.name, n]));
  assert.deepEqual(L.nodes.map((n) => n.column), [0, 0, 0, 1, 2, 0, 3, 1, 2, 4]);
  // a column's boxes share their x, and each column is right of the last
  for (const n of L.nodes) assert.equal(n.x, L.nodes.find((m) => m.column === 0).x + n.column * (n.width + GRAPH.gapX), n.name);
  // every use is an edge, and nothing else
  const uses = LESSIN.flatMap((s, to) => s.uses.map((u) => `${u}->${s.name}`)).sort();
  assert.equal(L.edges.length, 12);
  assert.deepEqual(L.edges.map((e) => `${LESSIN[e.from].name}->${LESSIN[e.to].name}`).sort(), uses);
  // each edge leaves its used stage's right side and ends at its user's left side
  for (const e of L.edges) {
    const a = L.nodes[e.from], b = L.nodes[e.to];
    const ends = e.d.match(/-?[\d.]+/g).map(Number);
    assert.deepEqual(ends.slice(0, 2), [a.x + a.width, a.y + a.height / 2]);
    assert.deepEqual(ends.slice(-2), [b.x, b.y + b.height / 2]);
  }
  // no two boxes overlap; all fit in the graph
  for (const a of L.nodes) {
    assert.ok(a.x >= 0 && a.y >= 0 && a.x + a.width <= L.width && a.y + a.height <= L.height, a.name);
    for (const b of L.nodes)
      if (a !== b) assert.ok(a.column !== b.column || Math.abs(a.y - b.y) >= a.height, `${a.name} ${b.name}`);
  }
  // in a column, stages follow the stages they use: approach (face, forward) above retreat (face_away, forward)
  assert.ok(byName.get('approach').y < byName.get('retreat').y);
  assert.ok(byName.get('face').y < byName.get('face_away').y);
  // pandemonium groups in the order the stages first name them
  assert.deepEqual(L.groups, ['turn', 'aim', 'react']);
  assert.deepEqual(L.nodes.map((n) => n.group), [-1, 0, 0, 1, -1, -1, 2, 1, 2, -1]);
  // the boxes are wide enough for the longest name
  assert.ok(L.nodes[0].width >= 'face_away'.length * 6);
});

test('a plain run has no syllabus', () => {
  assert.equal(isStaged(makeRun()), false);
  assert.equal(isStaged(makeStagedRun()), true);
  assert.equal(runRows(makeRun()).find(([k]) => k === 'stages'), undefined);
  assert.deepEqual(runRows(makeStagedRun()).find(([k]) => k === 'stages'), ['stages', '3 of 4 begun']);
  assert.deepEqual(syllabusLayout([]), { nodes: [], edges: [], groups: [], width: 0, height: 0 });
});

test('the stage of a generation, and a stage not begun', () => {
  const run = makeStagedRun();
  assert.deepEqual([0, 2, 3, 4, 5, 7, 8].map((g) => stageAt(run.stages, g)), [0, 0, 1, 1, 2, 2, -1]);
  assert.equal(stageRun(run, run.stages[3]), null);
  assert.match(stageTitle(run.stages[2]), /^face: uses forward, left, pandemonium group aim; the run's generations 5-7, best fitness 0\.3/);
  assert.equal(stageTitle(run.stages[3]), 'fight: uses face; not begun');
  assert.equal(spanText([4, 4]), '4');
});

test("picking a stage gives the curve of its generations alone, counted from its first", () => {
  const run = makeStagedRun();
  const left = stageRun(run, run.stages[1]);
  assert.equal(left.offset, 3);
  assert.deepEqual(left.generations.map((g) => [g.gen, g.best, g.best_id]), [[0, 10, 4], [1, 12, 5]]);
  assert.deepEqual(left.members.map((m) => [m.id, m.gen]), [[4, 0], [5, 1]]);
  // two points a curve
  const pad = { left: 10, right: 10, top: 10, bottom: 10 };
  const L = curveLayout(left, 200, 100, pad);
  for (const k of CURVES) assert.equal(L.paths[k].match(/[ML]/g).length, 2, k);
  assert.deepEqual(L.xTicks.map((t) => t.value), [0, 1]);
  // on the stage's own scale: face's best (0.3) tops its chart, near the whole run's floor
  assert.equal(curveLayout(stageRun(run, run.stages[2]), 200, 100, pad).y(0.3), 10);
  assert.ok(curveLayout(run, 200, 100, pad).y(0.3) > 85);
  // the chart: its title and axis, and a click's choices in the stage's numbers (the run's: + offset)
  const v = chartView(run, 1);
  assert.equal(v.data.generations.length, 2);
  assert.equal(v.offset, 3);
  assert.deepEqual(v.choices.map((c) => [c.gen, c.id, c.replayIndex]), [[0, 4, 3], [1, 5, 4]]);
  assert.match(v.title, /stage left \(the run's 3-4\)/);
  assert.equal(v.xLabel, 'generation of left');
  // the whole run's, and a stage not begun falls back to it
  for (const i of [-1, 3]) {
    const w = chartView(run, i);
    assert.equal(w.data, run);
    assert.equal(w.offset, 0);
    assert.equal(w.choices.length, 8);
    assert.match(w.title, /the whole run/);
  }
  assert.equal(chartView(makeRun(), -1).title, 'Fitness per generation');
});

test('the page data of a run of stages is checked', () => {
  const run = makeStagedRun();
  assert.equal(parseRun(run, 8), run);
  const spoilt = (spoil) => {
    const r = makeStagedRun();
    spoil(r);
    return () => parseRun(r, 8);
  };
  assert.throws(spoilt((r) => (r.stages[2].uses = ['fight'])), { message: /^run\.stages\[2\]\.uses\[0\]: expected an earlier stage, got "fight"$/ });
  assert.throws(spoilt((r) => (r.stages[1].name = 'forward')), { message: /^run\.stages\[1\]\.name: given to two stages/ });
  assert.throws(spoilt((r) => (r.stages[0].best = null)), { message: /^run\.stages\[0\]\.best: expected a number, got null$/ });
  assert.throws(spoilt((r) => (r.stages[3].first_gen = 8)), { message: /^run\.stages\[3\]\.first_gen: expected null \(not begun\), got 8$/ });
  assert.throws(spoilt((r) => (r.stages[1].group = null)), { message: /^run\.stages\[1\]\.group: expected a string/ });
});
