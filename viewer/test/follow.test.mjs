// The follow camera's target and framing.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  creatureRadius, distanceToShow, FOLLOW_REACH, followTarget, followView, nextMode, partTarget, pathBounds, showHalfAngle,
  viewDirection, viewScale,
} from '../src/follow.js';
import { pointsOfInterest } from '../src/interest.js';
import { recordOf } from '../src/scene_record.js';
import { makeCatapult, makeLight, makeReplay } from './fixture.mjs';

const near = (a, b, eps = 1e-6) => assert.ok(Math.abs(a - b) < eps, `${a} != ${b}`);

test('on steady motion the smoothed target is the centre of mass itself', () => {
  const frames = makeReplay().frames;
  near(followTarget(frames, 1.0)[0], 1.15);
  near(followTarget(frames, 1.0)[1], 0);
  // at the ends the window clamps, pulling the target inwards
  assert.ok(followTarget(frames, 0)[0] > frames[0].com[0]);
});

test('the target is a pure function of time', () => {
  const frames = makeReplay().frames;
  assert.deepEqual(followTarget(frames, 0.77), followTarget(frames, 0.77));
});

test('the creature radius covers its parts', () => {
  const r = makeReplay();
  const radius = creatureRadius(r);
  // the capsule's far end is 0.15 + 0.3 / 2 + a bit from the centre of mass
  assert.ok(radius >= 0.3 && radius < 0.6, String(radius));
});

test('path bounds span the centre of mass path', () => {
  const b = pathBounds(makeReplay().frames);
  near(b.min[0], 0.15);
  near(b.max[0], 2.15);
  near(b.span, 2);
  near(b.centre[0], 1.15);
});

test('the camera looks from the right of the heading, a little ahead and above', () => {
  const d = viewDirection(makeReplay().frames); // heading +x
  near(Math.hypot(...d), 1);
  assert.ok(d[1] < 0, 'right of +x is -y');
  assert.ok(d[0] > 0, 'turned towards the front');
  assert.ok(d[2] > 0, 'above');
  // a creature that stays put is seen from -y
  const still = makeReplay();
  still.frames.forEach((f) => (f.com = [0, 0, 0.1]));
  const s = viewDirection(still.frames);
  assert.ok(s[1] < 0);
});

test("a catapult's camera can follow its projectile, and orbit over its flight", () => {
  const frames = makeCatapult().frames;
  // the projectile moves along x at 2 m/s throughout: its smoothed x is its x
  near(partTarget(frames, 2, 0.5)[0], 0.4);
  near(followTarget(frames, 0.5)[0], 0.1); // the centre of mass stays put
  // the orbit view's bounds take in the projectile's path
  near(pathBounds(frames).span, 0);
  const b = pathBounds(frames, 2);
  near(b.min[0], -0.6);
  near(b.max[0], 1.4);
});

test('the camera button goes follow, projectile (catapults only), orbit', () => {
  assert.equal(nextMode('follow', true), 'projectile');
  assert.equal(nextMode('projectile', true), 'orbit');
  assert.equal(nextMode('orbit', true), 'follow');
  assert.equal(nextMode('follow', false), 'orbit');
  assert.equal(nextMode('orbit', false), 'follow');
  assert.equal(nextMode('projectile', false), 'orbit');
});

test("a catapult is seen across its throw's direction", () => {
  const r = makeCatapult();
  // the centre of mass stays put: seen from -y; the projectile flies along +x: also from -y, turned ahead
  const d = viewDirection(r.frames, 0.5, 0.42, 2);
  assert.ok(d[1] < 0 && d[0] > 0, JSON.stringify(d));
  // thrown along +y instead: seen from +x
  r.frames.forEach((f) => (f.poses[2] = [0, f.poses[2][0], f.poses[2][2], 1, 0, 0, 0]));
  const e = viewDirection(r.frames, 0.5, 0.42, 2);
  assert.ok(e[0] > 0.5 && e[1] > 0, JSON.stringify(e));
});

test('the view keeps its size for creatures of a metre or two and grows with larger ones', () => {
  assert.equal(viewScale(0.1), 1);
  assert.equal(viewScale(2), 1);
  assert.equal(viewScale(45), 22.5);
});

test('the bounds of the path take in the lights and targets, with their extent', () => {
  const r = makeLight(90); // at (0.15, 3, 0.5), 0.2 m across
  const b = pathBounds(r.frames, -1, pointsOfInterest(recordOf(r)));
  near(b.min[0], 0.05);
  near(b.min[1], 0);
  near(b.max[0], 2.15);
  near(b.max[1], 3.1);
  near(b.span, 3.1);
  near(b.centre[1], 1.55);
  // none: the path's own bounds
  assert.deepEqual(pathBounds(r.frames, -1, []), pathBounds(r.frames));
});

// the angle (rad) between the view's axis (from the camera to `at`) and the ray from the camera to p
function offAxis(at, dir, dist, p) {
  const cam = at.map((v, i) => v + dir[i] * dist);
  const ray = p.map((v, i) => v - cam[i]);
  const dot = -(ray[0] * dir[0] + ray[1] * dir[1] + ray[2] * dir[2]);
  return Math.acos(dot / Math.hypot(...ray));
}

test('the distance that shows a sphere puts all of it within the cone', () => {
  const half = showHalfAngle(40);
  near(half, 0.8 * 20 * (Math.PI / 180));
  // a point 1 m off the axis of a camera looking straight down: just on the cone's edge
  const dir = [0, 0, 1];
  const d = distanceToShow([0, 0, 0], dir, { p: [1, 0, 0], radius: 0 }, half);
  near(d, 1 / Math.tan(half));
  near(offAxis([0, 0, 0], dir, d, [1, 0, 0]), half);
  // a sphere: all of it within the cone at that distance, not half a metre nearer
  const q = { p: [1, 0.5, -0.3], radius: 0.2 };
  const s = distanceToShow([0, 0, 0], dir, q, half);
  const rim = (dist) => {
    // the angle off the axis of the sphere's farthest point, from a camera at (0, 0, dist)
    const ray = [q.p[0], q.p[1], q.p[2] - dist];
    const len = Math.hypot(...ray);
    return Math.acos(-ray[2] / len) + Math.asin(q.radius / len);
  };
  assert.ok(rim(s) <= half + 1e-12, `${rim(s)} > ${half}`);
  assert.ok(rim(s - 0.5) > half);
});

test('the follow view without lights or targets is the standard one itself', () => {
  const dir = viewDirection(makeReplay().frames);
  const v = followView([0.15, 0, 0.1], dir, 2, [], showHalfAngle(40));
  assert.equal(v.dir, dir);
  assert.equal(v.dist, 2);
});

test('the follow view turns by the least angle, and moves back the least, to show the nearest light', () => {
  const half = showHalfAngle(40);
  const at = [0, 0, 0.1];
  const dir = [0, -Math.cos(0.42), Math.sin(0.42)]; // seen from -y
  // beyond the creature, seen past it: the standard view, moved back just enough
  const beyond = { p: [0, 3, 0.5], radius: 0.1 };
  const b = followView(at, dir, 2, [beyond], half);
  assert.equal(b.dir, dir);
  near(b.dist, Math.max(2, distanceToShow(at, dir, beyond, half)));
  assert.ok(offAxis(at, b.dir, b.dist, beyond.p) <= half);
  // nearer than the camera on its side: moving back alone would need more
  // than the reach, so it turns, by the least angle that can show it
  const behind = { p: [0.5, -3, 0.5], radius: 0.1 };
  assert.ok(distanceToShow(at, dir, behind, half) > 2 * FOLLOW_REACH);
  const t = followView(at, dir, 2, [behind], half);
  const turn = Math.acos((t.dir[0] * dir[0] + t.dir[1] * dir[1]) / (Math.cos(0.42) ** 2));
  assert.ok(turn > 0.1, String(turn));
  near(t.dir[2], dir[2]); // the same height angle
  near(Math.hypot(...t.dir), 1);
  assert.ok(t.dist <= 2 * FOLLOW_REACH && t.dist >= 2);
  assert.ok(offAxis(at, t.dir, t.dist, behind.p) <= half);
  // a whole number of degrees, and no smaller turn either way would do
  const deg = Math.round((turn * 180) / Math.PI);
  near(turn, (deg * Math.PI) / 180, 1e-6);
  for (let k = 0; k < deg; ++k) {
    for (const a of [k, -k].map((u) => (u * Math.PI) / 180)) {
      const d = [dir[0] * Math.cos(a) - dir[1] * Math.sin(a), dir[0] * Math.sin(a) + dir[1] * Math.cos(a), dir[2]];
      assert.ok(distanceToShow(at, d, behind, half) > 2 * FOLLOW_REACH, `${k} degrees`);
    }
  }
  // the nearest light decides
  const far = { p: [0, 40, 0.5], radius: 0.1 };
  assert.deepEqual(followView(at, dir, 2, [far, behind], half), t);
  // too far to show within the reach: the standard view
  const v = followView(at, dir, 2, [far], half);
  assert.equal(v.dir, dir);
  assert.equal(v.dist, 2);
});
