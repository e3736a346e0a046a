// What lights up together: a part's gene, every part grown from it, and
// their sensors, neurons and effectors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { highlightIndex, highlightText } from '../src/highlight.js';
import { makeLessin, makeWired } from './fixture.mjs';

const lists = (h) => ({ gene: h.gene, parts: h.parts, sensors: h.sensors, neurons: h.neurons, effectors: h.effectors });

test('a part: its gene, every part of that gene (mirrored and recursive copies too) and their units', () => {
  const ix = highlightIndex(makeWired());
  // part 3, gene 1's mirrored copy: gene 1 is parts 2 and 3
  assert.deepEqual(lists(ix.ofPart(3)), { gene: 1, parts: [2, 3], sensors: [1, 2], neurons: [2, 3], effectors: [0, 1] });
  // part 0, the root: gene 0 is it and its recursive copy, part 1 (the effector on joint 0 is part 1's)
  assert.deepEqual(lists(ix.ofPart(0)), { gene: 0, parts: [0, 1], sensors: [0], neurons: [1], effectors: [2] });
  // the same for a part and for its gene
  assert.equal(ix.ofPart(2), ix.of(1));
  assert.equal(ix.ofPart(-1), ix.none);
  assert.equal(ix.ofPart(9), ix.none);
  // a gene no part grew from: none of it
  assert.deepEqual(lists(ix.of(5)), { gene: 5, parts: [], sensors: [], neurons: [], effectors: [] });
});

test('a unit: the highlight of its part; a global neuron alone', () => {
  const ix = highlightIndex(makeWired());
  assert.equal(ix.ofUnit('neuron', 3), ix.of(1));
  assert.equal(ix.ofUnit('sensor', 0), ix.of(0));
  assert.equal(ix.ofUnit('effector', 0), ix.of(1));
  assert.equal(ix.ofUnit('effector', 2), ix.of(0));
  assert.deepEqual(lists(ix.ofUnit('neuron', 0)), { gene: -1, parts: [], sensors: [], neurons: [0], effectors: [] });
  assert.equal(ix.ofUnit('neuron', 0), ix.ofUnit('neuron', 0));
  assert.equal(ix.ofUnit('neuron', 42), ix.none);
  // a muscle's effector is its child end's (lessin2015)
  const lessin = highlightIndex(makeLessin());
  assert.deepEqual(lessin.ofPart(1).effectors, [0, 1]);
  assert.deepEqual(lessin.ofPart(0).effectors, []);
});

test('in words, for the panel\'s line', () => {
  const ix = highlightIndex(makeWired());
  assert.equal(highlightText(ix.ofPart(2)), 'gene 1: parts 2, 3 · 2 neurons, 2 sensors, 2 effectors');
  assert.equal(highlightText(ix.ofUnit('neuron', 0)), 'global neuron 0: belongs to no part');
  assert.equal(highlightText(ix.of(5)), 'gene 5: no parts · 0 neurons, 0 sensors, 0 effectors');
});
