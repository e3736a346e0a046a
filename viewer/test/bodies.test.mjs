// The creature's meshes follow the replay, and joint markers hang on the child.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Vector3 } from 'three';
import { createBodies } from '../src/bodies.js';
import { geneColor, PROJECTILE_COLOR } from '../src/palette.js';
import { makeCatapult, makeReplay, projectileAt } from './fixture.mjs';

test('parts take their interpolated poses', () => {
  const bodies = createBodies(makeReplay());
  bodies.setTime(1.05);
  const p = bodies.parts[1].position;
  assert.ok(Math.abs(p.x - 1.35) < 1e-6 && Math.abs(p.z - 0.1) < 1e-9);
  // three stores w last: the child turned (pi / 4) * 1.05 about z
  const q = bodies.parts[1].quaternion;
  assert.ok(Math.abs(2 * Math.atan2(q.z, q.w) - (Math.PI / 4) * 1.05) < 1e-5);
});

test('joint markers are hidden until asked for, and sit at the anchor in the child frame', () => {
  const bodies = createBodies(makeReplay());
  const marker = bodies.parts[1].children.find((c) => c.type === 'Group');
  assert.equal(marker.visible, false);
  bodies.showJoints(true);
  assert.equal(marker.visible, true);
  bodies.setTime(0);
  bodies.group.updateMatrixWorld(true);
  const world = marker.getWorldPosition(new Vector3());
  // child at x = 0.3 at t = 0, anchor at -0.15 in its frame
  assert.ok(Math.abs(world.x - 0.15) < 1e-9, String(world.x));
});

test("a catapult's projectile has its own colour, whatever its gene", () => {
  const bodies = createBodies(makeCatapult());
  assert.equal(bodies.parts[2].material.color.getHex(), PROJECTILE_COLOR);
  assert.equal(bodies.parts[0].material.color.getHex(), geneColor(0));
  assert.equal(bodies.parts[1].material.color.getHex(), geneColor(1));
  // no gene has the projectile's colour
  for (let g = 0; g < 48; ++g) for (const m of [false, true]) assert.notEqual(geneColor(g, m), PROJECTILE_COLOR);
  bodies.setTime(0.8);
  const p = bodies.parts[2].position;
  assert.ok(Math.abs(p.x - projectileAt(0.8)[0]) < 1e-6 && Math.abs(p.z - projectileAt(0.8)[2]) < 1e-6);
  bodies.dispose();
});
