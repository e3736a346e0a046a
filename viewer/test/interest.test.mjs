// The points of interest of a replay's scene: its lights and targets.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { firstShown, pointsOfInterest, shownBy } from '../src/interest.js';
import { recordOf } from '../src/scene_record.js';
import { makeCatapult, makeLight, makeReplay, makeRiver, makeTargets } from './fixture.mjs';

const near = (a, b, eps = 1e-9) => assert.ok(Math.abs(a - b) < eps, `${a} != ${b}`);

test("a light is a point of interest at its place, its radius half its size, shown throughout", () => {
  const r = makeLight(90);
  const [light, ...more] = pointsOfInterest(recordOf(r));
  assert.equal(more.length, 0);
  assert.equal(light.name, 'light');
  assert.deepEqual(light.p, r.scene.record.points[0].p);
  near(light.radius, 0.1);
  assert.equal(light.t, 0);
});

test('props are points of interest at their centres from their times, with a sphere holding them however they spin', () => {
  const [disc, stack] = pointsOfInterest(recordOf(makeTargets()));
  assert.deepEqual(disc.p, [1, 1, 0.01]);
  assert.deepEqual(stack.p, [1, 1, 0.17]);
  assert.equal(disc.t, 0.5);
  // the disc: 0.02 m thick, 0.6 m across; its farthest point from the centre is a rim's
  near(disc.radius, Math.hypot(0.02, 0.6, 0.6) / 2);
  assert.ok(disc.radius >= Math.hypot(0.01, 0.3));
  near(stack.radius, Math.hypot(0.3, 0.1, 0.1) / 2);
});

test("an aim task's target is one too; a scene without points or props has none", () => {
  assert.deepEqual(pointsOfInterest(recordOf(makeCatapult({ target: [3, 0, 0.075] }))).map((q) => q.name), ['target']);
  assert.deepEqual(pointsOfInterest(recordOf(makeReplay())), []);
  assert.deepEqual(pointsOfInterest(recordOf(makeRiver())), []);
  assert.deepEqual(pointsOfInterest(recordOf(makeCatapult())), []);
});

test('what is shown by a time, and the first moment anything is', () => {
  const targets = pointsOfInterest(recordOf(makeTargets()));
  assert.equal(shownBy(targets, 0.4).length, 0);
  assert.equal(shownBy(targets, 0.5).length, 2);
  assert.equal(firstShown(targets, 0.4), null); // the replay ends before they appear
  const first = firstShown(targets, 2);
  assert.equal(first.t, 0.5);
  assert.deepEqual(first.shown.map((q) => q.name), ['disc', 'stack']);
  // a later prop is not among those shown first
  const later = [...targets, { name: 'late', p: [0, 0, 0], radius: 0.1, t: 1 }];
  assert.deepEqual(firstShown(later, 2).shown.map((q) => q.name), ['disc', 'stack']);
  assert.equal(firstShown([], 2), null);
});
