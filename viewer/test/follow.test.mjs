// The follow camera's target and framing.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { creatureRadius, followTarget, nextMode, partTarget, pathBounds, viewDirection, viewScale } from '../src/follow.js';
import { makeCatapult, makeReplay } from './fixture.mjs';

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
