// The brain as a network: units grouped by part, wires decoded from their
// slots (sensors first, then neurons), gated wires, the layout's bands and
// wires, and the colours that follow the replay.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  NET, VALUE_COLORS, VALUE_STEPS, bandTitle, brainOf, decodeSlot, effectorPart, effectorShort, networkLayout,
  networkModel, neuronShort, sensorShort, valueScales, valueStep, wireWidth,
} from '../src/network.js';
import { noNetworkText } from '../src/brain_panel.js';
import { bracket, frameIndexAt } from '../src/timeline.js';
import { makeLessin, makeReplay, makeRiver, makeWired } from './fixture.mjs';

// the numbers in an SVG path, in order; a path's numbers are to 0.1 px
const numbers = (d) => d.match(/-?[\d.]+/g).map(Number);
const near = (a, b, what) => assert.ok(Math.abs(a - b) <= 0.05 + 1e-9, `${what}: ${a} is not ${b}`);

test('a slot is a sensor below the sensors\' count, then a neuron; past the neurons, nothing', () => {
  assert.deepEqual(decodeSlot(0, 3, 4), { kind: 'sensor', index: 0 });
  assert.deepEqual(decodeSlot(2, 3, 4), { kind: 'sensor', index: 2 });
  assert.deepEqual(decodeSlot(3, 3, 4), { kind: 'neuron', index: 0 });
  assert.deepEqual(decodeSlot(6, 3, 4), { kind: 'neuron', index: 3 });
  assert.equal(decodeSlot(7, 3, 4), null);
  assert.equal(decodeSlot(-1, 3, 4), null);
  // no sensors: slot 0 is neuron 0
  assert.deepEqual(decodeSlot(0, 0, 2), { kind: 'neuron', index: 0 });
});

test('units grouped by part, global neurons first; an effector on its joint\'s child or its muscle\'s', () => {
  const r = makeWired();
  const m = networkModel(r);
  assert.deepEqual(m.groups.map((g) => [g.part, g.gene, g.mirrored, g.sensors, g.neurons, g.effectors]), [
    [-1, -1, false, [], [0], []],
    [0, 0, false, [], [1], []],
    [1, 0, false, [0], [], [2]],
    [2, 1, false, [1], [2], [0]],
    [3, 1, true, [2], [3], [1]],
  ]);
  assert.deepEqual(m.groups.map(bandTitle), ['global', 'part 0 · gene 0', 'part 1 · gene 0', 'part 2 · gene 1', "part 3 · gene 1'"]);
  assert.deepEqual(r.effectors.map((e) => effectorPart(r, e)), [2, 3, 1]);
  const lessin = makeLessin();
  assert.deepEqual(lessin.effectors.map((e) => effectorPart(lessin, e)), [1, 1]);
});

test('wires: each input\'s source decoded, its weight, a gate decoded too; a slot the brain lacks is dropped', () => {
  const m = networkModel(makeWired());
  const text = (u) => (u ? `${u.kind} ${u.index}` : '-');
  assert.deepEqual(m.wires.map((w) => [text(w.from), text(w.to), w.weight, text(w.gate)]), [
    ['neuron 0', 'neuron 1', 0.5, '-'],
    ['sensor 1', 'neuron 2', -2, '-'],
    ['sensor 2', 'neuron 3', -2, '-'],
    ['neuron 2', 'neuron 3', 1, 'neuron 0'],
    ['neuron 2', 'effector 0', 1.5, '-'],
    ['neuron 3', 'effector 1', 1.5, '-'],
    ['sensor 0', 'effector 2', 0.25, '-'],
  ]);
  assert.equal(m.dropped, 1);
  assert.equal(m.maxWeight, 2);
  assert.equal(m.wired, true);
});

test('another kind\'s controller has no network; a replay without wires has its units only', () => {
  const river = makeRiver();
  river.neurons = [{ part: -1, fn: 'controller' }];
  assert.equal(brainOf(river).graph, false);
  assert.equal(networkModel(river), null);
  assert.match(noNetworkText(river, null), /^This creature \(river\) has no graph brain/);
  const old = networkModel(makeReplay());
  assert.equal(old.wired, false);
  assert.equal(old.wires.length, 0);
  assert.deepEqual(old.groups.map((g) => g.part), [0, 1]);
  assert.equal(noNetworkText(makeReplay(), old), '');
  const none = makeReplay();
  Object.assign(none, { neurons: [], sensors: [], effectors: [] });
  none.frames.forEach((f) => Object.assign(f, { neurons: [], sensors: [], effectors: [] }));
  assert.match(noNetworkText(none, networkModel(none)), /no sensors, neurons or effectors/);
});

test('short labels: what a unit reads or drives', () => {
  const r = makeWired();
  assert.deepEqual(r.sensors.map(sensorShort), ['0 angle 0', '1 touch -z', '2 touch -z']);
  assert.deepEqual(r.effectors.map(effectorShort), ['0 j1 d0', '1 j2 d0', '2 j0 d0']);
  assert.deepEqual(makeLessin().effectors.map(effectorShort), ['0 m1', '1 m0']);
  assert.deepEqual(makeLessin().sensors.map(sensorShort), ['0 eye', '1 len m0']);
  assert.equal(neuronShort({ fn: 'oscillate-wave' }, 12, 10), '12 oscill…');
});

test('the layout: a band per part, its units in three columns, wires from the source\'s right to the target\'s left', () => {
  const r = makeWired();
  const m = networkModel(r);
  const L = networkLayout(m, r);
  assert.equal(L.bands.length, 5);
  // the columns left to right; every unit inside its part's band
  assert.ok(L.columns.sensor < L.columns.neuron && L.columns.neuron < L.columns.effector);
  m.groups.forEach((g, i) => {
    const b = L.bands[i];
    for (const [kind, list] of [['sensor', g.sensors], ['neuron', g.neurons], ['effector', g.effectors]])
      for (const k of list) {
        const [x, y] = L.at[kind][k];
        assert.equal(x, L.columns[kind]);
        assert.ok(y > b.y + NET.head && y < b.y + b.height, `${kind} ${k}`);
      }
  });
  // bands stacked, inside the drawing
  for (let i = 1; i < L.bands.length; ++i) assert.ok(L.bands[i].y >= L.bands[i - 1].y + L.bands[i - 1].height);
  assert.ok(L.bands.at(-1).y + L.bands.at(-1).height <= L.height);
  assert.equal(L.wires.length, 7);
  for (const w of L.wires) {
    const p = numbers(w.d), a = L.at[w.from.kind][w.from.index], b = L.at[w.to.kind][w.to.index];
    near(p[1], a[1], 'starts at its source');
    near(p.at(-1), b[1], 'ends at its target');
    if (w.from.kind === 'neuron' && w.to.kind === 'neuron') {
      // between neurons: out of the left of the column and back
      near(p[0], a[0] - NET.node, 'leaves the neuron\'s left');
      assert.ok(p[2] < a[0] - NET.node);
    } else {
      near(p[0], a[0] + NET.node, 'leaves the source\'s right');
      near(p.at(-2), b[0] - NET.node, 'enters the target\'s left');
    }
  }
  // widths by |weight|: the largest the widest
  const width = (from, to) => L.wires.find((w) => w.from.kind === from[0] && w.from.index === from[1] && w.to.index === to).width;
  assert.equal(width(['sensor', 1], 2), NET.wireMax);
  assert.ok(width(['sensor', 0], 2) < width(['neuron', 0], 1));
  assert.equal(wireWidth(0, 2), NET.wireMin);
});

test('values to colours: white at 0, the sign\'s colour at the scale, clamped beyond', () => {
  assert.equal(VALUE_COLORS.length, 2 * VALUE_STEPS + 1);
  assert.equal(VALUE_COLORS[VALUE_STEPS], 'rgb(255,255,255)');
  assert.equal(VALUE_COLORS[2 * VALUE_STEPS], 'rgb(44,111,183)');
  assert.equal(VALUE_COLORS[0], 'rgb(201,79,79)');
  assert.equal(valueStep(0, 1), VALUE_STEPS);
  assert.equal(valueStep(1, 1), 2 * VALUE_STEPS);
  assert.equal(valueStep(-5, 1), 0);
  assert.equal(valueStep(2, 4), VALUE_STEPS + VALUE_STEPS / 2);
  assert.equal(valueStep(NaN, 1), VALUE_STEPS);
  // a neuron's scale: its largest |value| from frame 1 on, at least 1
  const r = makeWired();
  r.frames[0].neurons[2] = -40;
  assert.deepEqual([...valueScales(r.frames, 'neurons', 4)], [1, 3, 1, 1]);
});

test('the frame shown at a time is the one at or before it, as the other panels take it', () => {
  const frames = makeReplay().frames;
  for (const t of [-1, 0, 0.05, 0.1, 0.15, 1, 1.99, 2, 5]) assert.equal(frameIndexAt(frames, t), bracket(frames, t).i, `t ${t}`);
});
