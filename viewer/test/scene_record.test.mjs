// A replay's scene record: checked with the path of a bad field, the scene
// it describes at any moment (the grid, its cells, the item carried, the
// field, the counters), and the record an old file's `throw` means.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { cellsAt, countersText, hasCounter, hasWorld, markerTime, parseRecord, partNamed, pointNamed, recordOf, sceneAt, scoredSpan } from '../src/scene_record.js';
import { AXIS_UP, makeCatapult, makeReplay, makeRiver, makeTargets } from './fixture.mjs';

test("a catapult's record names its projectile and target and marks its release", () => {
  const rec = recordOf(makeCatapult({ target: [2, 0, 0.075] }));
  assert.equal(markerTime(rec, 'release'), 0.5);
  assert.equal(markerTime(rec, 'begin'), 0);
  assert.equal(markerTime(rec, 'touch end'), null);
  assert.deepEqual(partNamed(rec, 'projectile'), { name: 'projectile', part: 2, color: 0xffc61a });
  assert.deepEqual(pointNamed(rec, 'target'), { name: 'target', p: [2, 0, 0.075], size: 0.12, color: 0xd6336c });
  assert.equal(hasWorld(rec), false);
});

test("an old file's throw means the same record, its target left to the props", () => {
  const rec = recordOf(makeCatapult({ target: [2, 0, 0.075], legacy: true }));
  assert.equal(markerTime(rec, 'release'), 0.5);
  assert.equal(partNamed(rec, 'projectile').part, 2);
  assert.equal(pointNamed(rec, 'target'), null);
  assert.equal(markerTime(recordOf(makeCatapult({ release: null, legacy: true })), 'release'), null);
  // a creature with neither: an empty record
  const none = recordOf(makeReplay());
  assert.deepEqual([none.markers, none.parts, none.events], [[], [], []]);
});

test('the scene at a moment: the grid, its cells changed so far, the item carried, the field, the counters', () => {
  const rec = recordOf(makeRiver());
  assert.equal(hasWorld(rec), true);
  const start = sceneAt(rec, 0);
  assert.equal(start.grid.width, 4);
  assert.deepEqual(start.grid.origin, [-1, -0.5, 0]);
  assert.equal(start.carry, null);
  assert.equal(start.fields.landscape.t, 0);
  assert.deepEqual(start.counters, [['level', 1, ''], ['score', 0, ''], ['deaths', 0, '']]);
  assert.equal(cellsAt(rec, 0)[1], 1); // the stone at (1, 0)
  // picked up at 0.5 s: its cell is grass, part 0 carries a stone, a new landscape
  const carrying = sceneAt(rec, 0.7);
  assert.deepEqual(carrying.carry, { part: 0, kind: 1 });
  assert.equal(cellsAt(rec, 0.7)[1], 0);
  assert.notEqual(carrying.cellsKey, start.cellsKey);
  assert.equal(carrying.fields.landscape.t, 0.5);
  assert.equal(carrying.fields.landscape.values[3], -15);
  // just before: still as at the start
  assert.equal(cellsAt(rec, 0.49)[1], 1);
  assert.equal(sceneAt(rec, 0.49).cellsKey, start.cellsKey);
  // the score at 1 s, the bridge and the stone set down at 1.5 s
  assert.deepEqual(sceneAt(rec, 1.2).counters, [['level', 1, ''], ['score', 1, ''], ['deaths', 0, '']]);
  const end = sceneAt(rec, 2);
  assert.equal(end.carry, null);
  assert.equal(cellsAt(rec, 2)[1 * 4 + 3], 3);
  assert.equal(countersText(end.counters), 'level 1   score 1   deaths 0');
  assert.equal(countersText([]), '');
});

test('a task\'s distance: a counter in metres, and the span it scored, from its markers', () => {
  const walker = (markers) => {
    const r = makeReplay();
    r.scene.record = {
      markers,
      events: [
        { t: 0.25, counter: { name: 'distance', value: 0, unit: 'm' } },
        { t: 1, counter: { name: 'distance', value: 0.3456, unit: 'm' } },
      ],
    };
    return r;
  };
  const rec = recordOf(walker([{ name: 'scored from', t: 0.25 }, { name: 'scored to', t: 1.75 }]));
  assert.equal(hasCounter(rec, 'distance'), true);
  assert.equal(hasCounter(rec, 'score'), false);
  assert.deepEqual(scoredSpan(rec, 2), { from: 0.25, to: 1.75 });
  assert.deepEqual(sceneAt(rec, 0.1).counters, []);  // before the span: nothing counted yet
  assert.equal(countersText(sceneAt(rec, 0.5).counters), 'distance 0 m');
  assert.equal(countersText(sceneAt(rec, 1.5).counters), 'distance 0.35 m');
  // a span not yet ended runs to the replay's end; none without its start
  assert.deepEqual(scoredSpan(recordOf(walker([{ name: 'scored from', t: 0.25 }])), 2), { from: 0.25, to: 2 });
  assert.equal(scoredSpan(recordOf(makeRiver()), 2), null);
});

test('a new grid replaces the last, and the changes start over from it', () => {
  const r = makeRiver();
  r.scene.record.events.push({ t: 1.8, grid: { origin: [5, 5, 0], cell: 0.5, width: 2, height: 1, cells: [1, 1] } },
    { t: 1.9, cell: { x: 1, y: 0, kind: 0 } });
  const rec = recordOf(r);
  assert.deepEqual(sceneAt(rec, 1.85).grid.origin, [5, 5, 0]);
  assert.deepEqual(cellsAt(rec, 1.85), [1, 1]);
  assert.deepEqual(cellsAt(rec, 2), [1, 0]);
});

test("a record's props: each one's shape, size, pose, spin, time and colour", () => {
  const rec = recordOf(makeTargets());
  assert.deepEqual(rec.props[0], {
    name: 'disc', shape: 'cylinder', size: [0.02, 0.6, 0.6], pose: [1, 1, 0.01, ...AXIS_UP], spin: 0, t: 0.5, color: 0x3b82c4,
  });
  assert.equal(rec.props[1].spin, 2);
  assert.equal(hasWorld(rec), false);
  assert.deepEqual(recordOf(makeReplay()).props, []);
});

test('a bad prop names its field and what was wrong', () => {
  const cases = [
    [(p) => (p.shape = 'cone'), /^scene\.record\.props\[1\]\.shape: expected one of box, sphere, capsule, cylinder, got "cone"$/],
    [(p) => (p.size = [0.3, 0, 0.1]), /^scene\.record\.props\[1\]\.size: expected extents > 0, got \[0\.3,0,0\.1\]$/],
    [(p) => (p.color = 'orange'), /^scene\.record\.props\[1\]\.color: expected "#rrggbb", got "orange"$/],
    [(p) => (p.t = -1), /^scene\.record\.props\[1\]\.t: expected a time >= 0, got -1$/],
    [(p) => (p.spin = 'fast'), /^scene\.record\.props\[1\]\.spin: expected a number, got "fast"$/],
    [(p) => (p.pose = [0, 0, 0, 0.5, 0, 0, 0]),
      /^scene\.record\.props\[1\]\.pose: expected \[x, y, z, qw, qx, qy, qz\] with a unit quaternion, got \[0,0,0,0\.5,0,0,0\]$/],
    [(p) => (p.pose = [0, 0, 0]), /^scene\.record\.props\[1\]\.pose: expected \[x, y, z, qw, qx, qy, qz\]/],
  ];
  for (const [spoil, message] of cases) {
    const r = makeTargets();
    spoil(r.scene.record.props[1]);
    assert.throws(() => recordOf(r), { message });
  }
});

test('a bad record names the field and what was wrong', () => {
  const cases = [
    [(r) => (r.markers = [{ name: 'release', t: 'soon' }]), /^scene\.record\.markers\[0\]\.t: expected a number, got "soon"$/],
    [(r) => (r.parts = [{ name: 'p', part: 2, color: '#ffffff' }]), /^scene\.record\.parts\[0\]\.part: no such part \(the creature has 2\), got 2$/],
    [(r) => (r.points = [{ name: 'x', p: [0, 0], size: 1, color: '#fff' }]), /^scene\.record\.points\[0\]\.p: expected 3 numbers/],
    [(r) => (r.cell_kinds[1].color = 'grey'), /^scene\.record\.cell_kinds\[1\]\.color: expected "#rrggbb", got "grey"$/],
    [(r) => (r.cell_kinds[1].item = 'yes'), /^scene\.record\.cell_kinds\[1\]\.item: expected true or false/],
    [(r) => (r.events[0].grid.cells[5] = 4), /^scene\.record\.events\[0\]\.grid\.cells\[5\]: no such cell kind \(the record has 4\), got 4$/],
    [(r) => r.events[0].grid.cells.pop(), /^scene\.record\.events\[0\]\.grid\.cells: expected 12 cell kinds, got 11$/],
    [(r) => (r.events[5].cell.x = 4), /^scene\.record\.events\[5\]\.cell\.x: outside the grid's 4 columns, got 4$/],
    [(r) => (r.events[6].carry.part = 5), /^scene\.record\.events\[6\]\.carry\.part: no such part \(the creature has 2\), got 5$/],
    [(r) => (r.events[4].field.range = [1, -1]), /^scene\.record\.events\[4\]\.field\.range: expected \[lo, hi\] with lo < hi/],
    [(r) => r.events[4].field.values.pop(), /^scene\.record\.events\[4\]\.field\.values: expected 12 numbers/],
    [(r) => (r.events[8].t = 0.2), /^scene\.record\.events\[8\]\.t: expected a time >= 0\.5, got 0\.2$/],
    [(r) => (r.events[8] = { t: 1, light: {} }), /^scene\.record\.events\[8\]: expected one of grid, cell, carry, field, counter/],
    [(r) => (r.events = {}), /^scene\.record\.events: expected an array, got \{\}$/],
    [(r) => (r.events[1].counter.unit = 3), /^scene\.record\.events\[1\]\.counter\.unit: expected a string, got 3$/],
    [(r) => r.events.splice(0, 1), /^scene\.record\.events\[4\]\.cell: a cell changed before any grid was laid/],
  ];
  for (const [spoil, message] of cases) {
    const r = makeRiver();
    spoil(r.scene.record);
    assert.throws(() => recordOf(r), { message });
  }
  assert.throws(() => parseRecord([], 1), { message: /^scene\.record: expected an object, got \[\]$/ });
});
