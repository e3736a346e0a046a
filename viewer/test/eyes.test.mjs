// Eyes (lessin2015's photoreceptors): a cone where the eye's direction from
// its part's centre leaves the part's shape, pointing that way, as bright as
// its reading.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Vector3 } from 'three';
import { eyeBrightnessAt, eyeHeight, eyePlacement, eyesOf, surfaceDistance } from '../src/eyes.js';
import { createEyes, eyeGlow } from '../src/eye_view.js';
import { createBodies } from '../src/bodies.js';
import { parseReplay } from '../src/data.js';
import { makeLessin, makeReplay } from './fixture.mjs';

const near = (a, b, eps = 1e-9) => assert.ok(a.every((v, i) => Math.abs(v - b[i]) < eps), `${a} vs ${b}`);
const unit = (v) => v.map((x) => x / Math.hypot(...v));

test('the distance from the centre to the surface: box, sphere, capsule, cylinder', () => {
  const box = [0.4, 0.2, 0.1];
  assert.equal(surfaceDistance('box', box, [1, 0, 0]), 0.2);
  assert.equal(surfaceDistance('box', box, [0, -1, 0]), 0.1);
  assert.ok(Math.abs(surfaceDistance('box', box, unit([1, 0, 1])) - 0.05 * Math.SQRT2) < 1e-12);  // the top face first
  assert.equal(surfaceDistance('sphere', [0.3, 9, 9], unit([1, 2, 3])), 0.15);
  // a capsule 0.5 long (caps included), 0.2 across: its side, its end cap
  const cap = [0.5, 0.2, 0.2];
  assert.ok(Math.abs(surfaceDistance('capsule', cap, [0, 0, 1]) - 0.1) < 1e-12);
  assert.ok(Math.abs(surfaceDistance('capsule', cap, [-1, 0, 0]) - 0.25) < 1e-12);
  const d = unit([1, 0, 0.2]);  // past the cylinder's end (|t dx| > 0.15): on the cap, 0.1 from its centre
  const p = d.map((v) => v * surfaceDistance('capsule', cap, d));
  assert.ok(Math.abs(Math.hypot(p[0] - 0.15, p[1], p[2]) - 0.1) < 1e-12);
  const side = unit([0.5, 0, 1]);  // within the cylinder part
  assert.ok(Math.abs(surfaceDistance('capsule', cap, side) * side[2] - 0.1) < 1e-12);
  // a cylinder: its flat end, its side
  assert.equal(surfaceDistance('cylinder', cap, [1, 0, 0]), 0.25);
  assert.ok(Math.abs(surfaceDistance('cylinder', cap, [0, 1, 0]) - 0.1) < 1e-12);
});

test('an eye sits where its direction leaves the part, looking along it', () => {
  const part = { shape: 'box', size: [0.2, 0.1, 0.1] };
  const e = eyePlacement(part, [0, 1, 1]);
  near(e.at, [0, 0.05, 0.05]);  // the top +y edge
  near(e.dir, [0, Math.SQRT1_2, Math.SQRT1_2]);
  assert.ok(Math.abs(e.height - 0.1 / 3) < 1e-12);
  assert.equal(eyePlacement(part, [0, 0, 0]), null);
  // sizes kept between 1.5 and 6 cm
  assert.equal(eyeHeight({ size: [0.01, 0.01, 0.01] }), 0.015);
  assert.equal(eyeHeight({ size: [2, 2, 2] }), 0.06);
  // a replay's eyes: photoreceptors with a direction
  const r = makeLessin();
  assert.deepEqual(eyesOf(r).map((x) => [x.sensor, x.part]), [[0, 1]]);
  delete r.sensors[0].direction;  // written before replays held it
  assert.deepEqual(eyesOf(r), []);
  assert.deepEqual(eyesOf(makeReplay()), []);
});

test("an eye's brightness is its reading at the moment, clamped to [0, 1]; unknown without readings", () => {
  const r = makeLessin();
  assert.equal(eyeBrightnessAt(r.frames, 0, 1.05), 0.25);
  r.frames[10].sensors[0] = 3;
  assert.equal(eyeBrightnessAt(r.frames, 0, 1.05), 1);
  r.frames[10].sensors[0] = -0.5;
  assert.equal(eyeBrightnessAt(r.frames, 0, 1.05), 0);
  r.frames.forEach((f) => delete f.sensors);
  assert.equal(eyeBrightnessAt(r.frames, 0, 1.05), null);
  assert.ok(eyeGlow(1) > eyeGlow(0.5) && eyeGlow(0.5) > eyeGlow(0));
  assert.equal(eyeGlow(null), eyeGlow(0.5));
});

test('the cone stands on its part at the eye, its tip along the direction, glowing with the reading', () => {
  const bodies = createBodies(parseReplay(makeLessin()));
  const [cone] = bodies.eyes.meshes;
  assert.equal(bodies.eyes.meshes.length, 1);
  assert.equal(cone.parent, bodies.parts[1]);
  bodies.setTime(1.0);
  bodies.group.updateMatrixWorld(true);
  const h = 0.1 / 3;
  // base centre sunk a little below the surface point, tip a cone's height out along the direction
  const part = bodies.parts[1].matrixWorld;
  const dir = new Vector3(0, 1, 1).normalize();
  const at = new Vector3(0, 0.05, 0.05);
  cone.geometry.computeBoundingBox();
  const box = cone.geometry.boundingBox;
  const tip = new Vector3(0, box.max.y, 0).applyMatrix4(cone.matrixWorld);
  const base = new Vector3(0, box.min.y, 0).applyMatrix4(cone.matrixWorld);
  const want = (s) => at.clone().addScaledVector(dir, s).applyMatrix4(part);
  assert.ok(tip.distanceTo(want(0.85 * h)) < 1e-6, `${tip.toArray()} vs ${want(0.85 * h).toArray()}`);
  assert.ok(base.distanceTo(want(-0.15 * h)) < 1e-6);
  assert.equal(cone.material.emissiveIntensity, eyeGlow(0.25));
  assert.deepEqual(bodies.eyes.state()[0].brightness, 0.25);
  bodies.setTime(2);
  assert.equal(cone.material.emissiveIntensity, eyeGlow(0.5));
  bodies.dispose();
  // createEyes alone, on given part meshes
  const r = makeLessin();
  const parts = r.parts.map(() => bodies.parts[0].clone(false));
  assert.equal(createEyes(r, parts).meshes[0].parent, parts[1]);
});
