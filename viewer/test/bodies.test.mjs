// The creature's meshes follow the replay, and joint markers hang on the child.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Vector3 } from 'three';
import { createBodies } from '../src/bodies.js';
import { makeReplay } from './fixture.mjs';

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
