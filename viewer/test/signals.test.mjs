// The signals panel's series: effectors and sensors on [-1, 1], joint angles
// in degrees against their stops, each with its range and whether it is
// constant.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parseReplay } from '../src/data.js';
import {
  effectorSeries, isLinearDof, jointAngleSeries, jointDofs, sensorLabel, sensorSeries, signalGroups, stopShare,
} from '../src/signals.js';
import { rangeText, stats } from '../src/series.js';
import { makeCatapult, makeLessin, makeReplay } from './fixture.mjs';

test('stats: min, max and spread from a frame on', () => {
  const s = stats([0, -1, -1, -1], 1);
  assert.deepEqual([s.min, s.max, s.mean, s.std], [-1, -1, -1, 0]);
  const all = stats([0, -1, -1, -1]);
  assert.ok(Math.abs(all.std - Math.sqrt(3) / 4) < 1e-12);
});

test('an effector: labelled by joint and dof, on [-1, 1] with a zero line, its range as text', () => {
  const [e] = effectorSeries(makeReplay());
  assert.equal(e.label, '0: joint 0 · dof 0');
  assert.match(e.title, /drives dof 0 of joint 0 \(hinge, part 1 on part 0\)/);
  assert.deepEqual([e.lo, e.hi], [-1, 1]);
  assert.deepEqual(e.lines, [{ v: 0, kind: 'zero' }]);
  assert.equal(rangeText(e), '0.100 .. 1.000'); // sin(t) from t = 0.1 to 2
  assert.equal(e.constant, false);
});

test("an effector's label has its dominant frequency when the replay has it, and none when not", () => {
  const label = (hz) => {
    const r = makeReplay();
    r.effectors[0].hz = hz;
    return effectorSeries(parseReplay(r))[0].label;
  };
  assert.equal(label(30), '0: joint 0 · dof 0 · 30 Hz');
  assert.equal(label(0.159), '0: joint 0 · dof 0 · 0.159 Hz'); // sin(t)
  assert.equal(label(2.5), '0: joint 0 · dof 0 · 2.5 Hz');
  assert.equal(label(0), '0: joint 0 · dof 0 · constant');
  // an older replay, without the field
  const old = effectorSeries(parseReplay(makeReplay()))[0].label;
  assert.equal(old, '0: joint 0 · dof 0');
  assert.doesNotMatch(old, /Hz|constant/);
});

test('an effector held at -1 is constant, though frame 0 (before the brain ran) reads 0', () => {
  const r = makeReplay();
  r.frames.forEach((f, i) => (f.effectors = [i === 0 ? 0 : -1]));
  const [e] = effectorSeries(r);
  assert.equal(e.constant, true);
  assert.equal(rangeText(e), '-1.000 .. -1.000');
  // a wobble above 1e-3 is not constant
  r.frames.forEach((f, i) => (f.effectors = [i % 2 ? -1 : -0.99]));
  assert.equal(effectorSeries(r)[0].constant, false);
});

test('sensors: a joint angle and a contact, on [-1, 1]', () => {
  const [angle, contact] = sensorSeries(makeReplay());
  assert.equal(angle.label, '0: angle · joint 0 · dof 0');
  assert.equal(contact.label, '1: contact · part 0 -z');
  assert.equal(sensorLabel({ type: 'joint_angle', part: 0, joint: -1, dof: 0 }, 3), '3: angle · part 0 (root)');
  for (const s of [angle, contact]) assert.deepEqual([s.lo, s.hi], [-1, 1]);
  assert.equal(angle.constant, false);
  assert.equal(contact.constant, true); // always touching
  assert.equal(rangeText(contact), '1.000 .. 1.000');
});

test("lessin2015's sensors: a photoreceptor and a muscle's length are named by what they read", () => {
  assert.equal(sensorLabel({ type: 'photoreceptor', part: 2, direction: [0, 1, 1] }, 4), '4: eye · part 2');
  assert.equal(sensorLabel({ type: 'muscle_length', part: 1, muscle: 3 }, 5), '5: muscle 3 length · part 1');
});

test("lessin2015's effectors are named by the muscle they activate", () => {
  const [e0, e1] = effectorSeries(parseReplay(makeLessin()));
  assert.equal(e0.label, '0: muscle 1 · 0.159 Hz');
  assert.equal(e1.label, '1: muscle 0');
  assert.equal(e0.title, 'effector 0: activates muscle 1 (part 1 to part 0), in [0, 1]');
  const [eye, length] = sensorSeries(makeLessin());
  assert.match(eye.title, /light seen by an eye on part 1/);
  assert.match(length.title, /length of muscle 0 \(part 1 to part 0\)/);
});

test('a joint angle in degrees, drawn against its stops with a margin', () => {
  const [a] = jointAngleSeries(makeReplay());
  assert.equal(a.label, 'joint 0 · dof 0 (hinge)');
  assert.ok(Math.abs(a.values[20] - 90) < 1e-4); // 45 degrees per second for 2 s
  assert.equal(rangeText(a), '0.0° .. 90.0°'); // all frames: frame 0 is a real pose
  const stop = (2 * 180) / Math.PI;
  assert.ok(Math.abs(a.stops[0] + stop) < 1e-9 && Math.abs(a.stops[1] - stop) < 1e-9);
  assert.ok(a.lo < -stop && a.hi > stop);
  assert.deepEqual(a.lines.map((l) => l.kind), ['zero', 'stop', 'stop']);
  assert.equal(a.atStop, 0);
  assert.equal(a.constant, false);
});

test('a joint held at its stop: most of the replay at it', () => {
  const r = makeReplay();
  r.frames.forEach((f, i) => (f.joint_angles = [[i < 4 ? -0.5 * i : -2.01]]));
  const [a] = jointAngleSeries(r);
  assert.ok(a.atStop > 0.8, a.atStop);
  // past the stop: the drawn range takes it in
  assert.ok(a.lo < a.min);
  assert.equal(stopShare([-1, 0, 0.99, 1.5], [-1, 1]), 0.75);
});

test('joint dofs without stops share one range; translations are in metres', () => {
  const r = makeReplay();
  r.joints = [
    { ...r.joints[0], type: 'universal', limits: [] },
    { ...r.joints[0], type: 'cylindrical', limits: [] },
  ];
  r.frames.forEach((f) => (f.joint_angles = [[0.1 * f.t, -0.2 * f.t], [0.05 * f.t, 0.3 * f.t]]));
  const a = jointAngleSeries(r);
  assert.deepEqual(a.map((s) => s.label), [
    'joint 0 · dof 0 (universal)', 'joint 0 · dof 1 (universal)', 'joint 1 · dof 0 (cylindrical)', 'joint 1 · dof 1 (cylindrical)',
  ]);
  // the three rotations share a range, the translation has its own
  const rot = [a[0], a[1], a[3]];
  for (const s of rot) assert.deepEqual([s.lo, s.hi], [rot[0].lo, rot[0].hi]);
  assert.ok(rot[0].lo < -0.4 * (180 / Math.PI) && rot[0].hi > 0.6 * (180 / Math.PI));
  assert.equal(a[2].format(0.1), '0.100 m');
  assert.ok(a[2].hi < 1);
  assert.equal(jointDofs('spherical'), 3);
  assert.equal(jointDofs('fixed'), 0);
  assert.equal(isLinearDof('slider', 0), true);
  assert.equal(isLinearDof('cylindrical', 1), false);
});

test('groups: effectors, sensors, joint angles; an older replay lacks the last two', () => {
  const g = signalGroups(makeReplay());
  assert.deepEqual(g.map((x) => [x.key, x.series.length, x.missing]), [['effectors', 1, false], ['sensors', 2, false], ['joints', 1, false]]);
  const old = signalGroups(makeCatapult());
  assert.deepEqual(old.map((x) => [x.key, x.series.length, x.missing]), [['effectors', 0, false], ['sensors', 0, true], ['joints', 0, true]]);
});
