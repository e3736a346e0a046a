// The genotype graph: a node per gene, an edge per genome edge (a
// self-loop, reflection and terminal-only marked), the recursive limits
// beside the genes, and its layout from the root down.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import {
  GENE_GRAPH, edgeMark, edgeText, geneDepths, geneText, geneTitle, geneUnits, genomeOf, genotypeLayout, genotypeModel, limitText,
} from '../src/genotype.js';
import { makeGenome, makeRiver, makeWired } from './fixture.mjs';

// the numbers in an SVG path, in order; a path's numbers are to 0.1 px
const numbers = (d) => d.match(/-?[\d.]+/g).map(Number);
const near = (a, b, what) => assert.ok(Math.abs(a - b) <= 0.05 + 1e-9, `${what}: ${a} is not ${b}`);

test('the genome comes from the page entry\'s genome text; another kind or none says why in one line', () => {
  const text = JSON.stringify(makeGenome());
  assert.equal(genomeOf({ replay: makeWired(), genome: text }).genome.nodes.length, 2);
  assert.equal(genomeOf({ replay: makeWired(), genome: text }).reason, null);
  const river = genomeOf({ replay: makeRiver(), genome: '{"kind": "river", "genes": [0.5]}' });
  assert.equal(river.genome, null);
  assert.match(river.reason, /river.*not a graph genome/);
  assert.doesNotMatch(river.reason, /\n/);
  assert.match(genomeOf({ replay: makeWired() }).reason, /does not hold the creature's genome file/);
  assert.match(genomeOf({ replay: makeWired(), genome: '{oops' }).reason, /not JSON/);
  assert.match(genomeOf({ replay: makeWired(), genome: '{"nodes": []}' }).reason, /no nodes/);
});

test('one node per gene with its shape, recursive limit, units and the parts grown from it', () => {
  const m = genotypeModel(makeGenome(), makeWired());
  assert.equal(m.nodes.length, 2);
  assert.deepEqual(m.nodes.map((n) => [n.index, n.shape, n.limit, n.neurons, n.sensors, n.effectors, n.parts]),
    [[0, 'box', 3, 1, 1, 0, 2], [1, 'capsule', 1, 2, 1, 1, 2]]);
  assert.equal(m.globals, 1);
  // without a replay, no part counts
  assert.equal(genotypeModel(makeGenome()).nodes[0].parts, null);
  // the labels: index and shape, units, the limit
  assert.equal(geneTitle(m.nodes[1]), '1 · capsule');
  assert.equal(geneUnits(m.nodes[1]), '2n 1s 1e');
  assert.deepEqual(m.nodes.map(limitText), ['×3', '×1']);
  assert.match(geneText(m.nodes[0]), /recursive limit 3; 1 neuron, 1 sensor, 0 effectors; 2 parts/);
});

test('edges: a self-loop, a reflected edge and a terminal-only one, each flagged', () => {
  const m = genotypeModel(makeGenome());
  assert.deepEqual(m.edges.map((e) => [e.from, e.to, e.index, e.self, e.reflect, e.terminal]), [
    [0, 0, 0, true, [], false],
    [0, 1, 1, false, ['y'], false],
    [0, 1, 2, false, [], true],
  ]);
  assert.deepEqual(m.edges.map(edgeMark), ['', 'R y', '']);
  assert.match(edgeText(m.edges[0]), /itself: recursion.*scale 0\.8/);
  assert.match(edgeText(m.edges[1]), /reflected across y \(2 copies\)/);
  assert.match(edgeText(m.edges[2]), /terminal only/);
  // an edge to a gene the genome lacks is left out
  const g = makeGenome();
  g.nodes[1].edges = [{ to: 7 }];
  assert.equal(genotypeModel(g).edges.length, 3);
});

test('creatures/sims_recursive.json: a self-loop of limit 5 and a terminal-only edge to its end', () => {
  const g = JSON.parse(readFileSync(new URL('../../creatures/sims_recursive.json', import.meta.url), 'utf8'));
  const m = genotypeModel(g);
  assert.equal(m.nodes.length, 2);
  assert.deepEqual(m.nodes.map(limitText), ['×5', '×1']);
  const loop = m.edges.find((e) => e.self);
  assert.deepEqual([loop.from, loop.to, loop.scale], [0, 0, 0.85]);
  const end = m.edges.find((e) => !e.self);
  assert.deepEqual([end.from, end.to, end.terminal, end.reflect], [0, 1, true, []]);
});

test('rows go down from the root; a gene reached only back up still gets a row', () => {
  const g = makeGenome();
  g.nodes.push({ shape: 'sphere', size: [0.1, 0.1, 0.1], edges: [{ to: 0 }] });
  g.nodes[1].edges = [{ to: 2 }];
  assert.deepEqual(geneDepths(genotypeModel(g)), [0, 1, 2]);
  // a gene no edge reaches: below the deepest
  g.nodes[1].edges = [];
  assert.deepEqual(geneDepths(genotypeModel(g)), [0, 1, 2]);
});

test('the layout: the child below its parent, parallel edges side by side, the loop at the corner, the limit beside', () => {
  const L = genotypeLayout(genotypeModel(makeGenome()));
  const [a, b] = L.nodes;
  assert.ok(b.y >= a.y + a.height + GENE_GRAPH.gapY - 1e-9);
  const [loop, reflected, terminal] = L.edges;
  // the self-loop leaves the gene's right side and comes back into its bottom
  const l = numbers(loop.d);
  near(l[0], a.x + a.width, 'leaves the right side');
  assert.ok(l[1] > a.y && l[1] < a.y + a.height);
  near(l.at(-1), a.y + a.height, 'comes back into the bottom');
  assert.ok(l.at(-2) > a.x && l.at(-2) < a.x + a.width);
  // the two edges to gene 1: bottom of 0 to top of 1, apart
  for (const e of [reflected, terminal]) {
    const p = numbers(e.d);
    near(p[1], a.y + a.height, 'leaves the bottom');
    near(p.at(-1), b.y, 'enters the top');
  }
  assert.notEqual(numbers(reflected.d)[0], numbers(terminal.d)[0]);
  // the reflection's mark at its edge's middle, between the two genes
  assert.ok(reflected.markAt[1] > a.y + a.height && reflected.markAt[1] < b.y);
  // the limit right of the box's top right corner, inside the drawing
  assert.ok(a.limitAt[0] > a.x + a.width && a.limitAt[1] < a.y + a.height / 2);
  for (const n of L.nodes) {
    assert.ok(n.x >= 0 && n.x + n.width <= L.width && n.y >= 0 && n.y + n.height <= L.height);
    assert.ok(n.limitAt[0] + limitText(n).length * GENE_GRAPH.charWidth <= L.width);
  }
});

test('an edge back up goes round the left of both genes', () => {
  const g = makeGenome();
  g.nodes[1].edges = [{ to: 0 }];
  const L = genotypeLayout(genotypeModel(g));
  const back = L.edges.find((e) => e.from === 1 && e.to === 0);
  const p = numbers(back.d);
  const [a, b] = L.nodes;
  near(p[0], b.x, 'leaves the left side');
  near(p.at(-2), a.x, 'enters the left side');
  assert.ok(p[2] < Math.min(a.x, b.x) && p[2] >= 0);
});
