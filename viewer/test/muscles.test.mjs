// Muscles (lessin2015): each end placed from its own part's pose, each
// muscle drawn as a cylinder between its ends, thicker and redder the more
// active its effector has it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Vector3 } from 'three';
import {
  activation, activationAt, MUSCLE_ACTIVE, MUSCLE_IDLE, MUSCLE_THICKENING, muscleBaseRadius, muscleColor,
  muscleDrivers, muscleEnds, muscleEndsAt, muscleRadius,
} from '../src/muscles.js';
import { createMuscles } from '../src/muscle_view.js';
import { createBodies } from '../src/bodies.js';
import { parseReplay } from '../src/data.js';
import { aboutZ, makeLessin, makeReplay } from './fixture.mjs';

const near = (a, b, eps = 1e-9) => assert.ok(a.every((v, i) => Math.abs(v - b[i]) < eps), `${a} vs ${b}`);

// a mesh's cylinder's two end centres in world coordinates (a unit cylinder along y, from end a to end b)
function meshEnds(mesh) {
  mesh.updateMatrixWorld(true);
  return [-0.5, 0.5].map((y) => new Vector3(0, y, 0).applyMatrix4(mesh.matrixWorld).toArray());
}

test("each muscle's effector, and an effector's signal as an activation in [0, 1]", () => {
  const r = makeLessin();
  assert.deepEqual(muscleDrivers(r), [1, 0]);
  assert.deepEqual(muscleDrivers(makeReplay()), []);  // no muscles: joint effectors drive none
  assert.deepEqual([-0.5, 0, 0.3, 1, 1.7, NaN].map(activation), [0, 0, 0.3, 1, 1, 0]);
  // the signal of the last frame at or before t (frames every 0.1 s), clamped
  assert.equal(activationAt(r.frames, 1, 0.45), 0.2);
  assert.equal(activationAt(r.frames, 0, 1.0), 1);  // 2 sin(1) = 1.68
  assert.equal(activationAt(r.frames, 0, 0), 0);
  assert.equal(activationAt(r.frames, -1, 1.0), 0);  // a muscle no effector drives
});

test("a muscle's ends follow its parts' poses, each end in its own part's frame", () => {
  const [m] = makeLessin().muscles;
  // part a at the origin unturned, part b 0.3 m along x turned a quarter about z
  const [a, b] = muscleEnds(m, [0, 0, 0, 1, 0, 0, 0], [0.3, 0, 0.1, ...aboutZ(Math.PI / 2)]);
  near(a, [0.15, 0, 0.05]);
  near(b, [0.3, -0.05, 0.15]);  // (-0.05, 0, 0.05) turned: (0, -0.05, 0.05)
  // in the fixture's frames: at t = 1 the root is at x = 1, part 1 at 1.3 turned pi/4
  const [a1, b1] = muscleEndsAt(makeLessin().frames, m, 1);
  near(a1, [1.15, 0, 0.15], 1e-6);
  near(b1, [1.3 - 0.05 * Math.SQRT1_2, -0.05 * Math.SQRT1_2, 0.15], 1e-6);
});

test('a muscle thickens and reddens with its activation', () => {
  assert.equal(muscleBaseRadius(makeLessin()), 0.005);  // a twentieth of 0.1 m
  assert.equal(muscleBaseRadius({ parts: [{ size: [10, 10, 10] }] }), 0.015);
  assert.equal(muscleBaseRadius({ parts: [{ size: [0.01, 0.01, 0.01] }] }), 0.0025);
  assert.equal(muscleRadius(0.005, 0), 0.005);
  assert.equal(muscleRadius(0.005, 1), 0.005 * MUSCLE_THICKENING);
  assert.equal(muscleRadius(0.005, 7), muscleRadius(0.005, 1));  // clamped
  assert.ok(muscleRadius(0.005, 0.3) < muscleRadius(0.005, 0.6));
  assert.equal(muscleColor(0), MUSCLE_IDLE);
  assert.equal(muscleColor(1), MUSCLE_ACTIVE);
  assert.equal(muscleColor(-1), MUSCLE_IDLE);
});

test('each muscle is drawn between its ends, as thick as its activation makes it', () => {
  const r = parseReplay(makeLessin());
  const view = createMuscles(r);
  assert.equal(view.meshes.length, 2);
  for (const t of [0, 0.45, 1.0, 1.95]) {
    view.setTime(t);
    const state = view.state();
    r.muscles.forEach((m, k) => {
      const ends = muscleEndsAt(r.frames, m, t);
      near(meshEnds(view.meshes[k]).flat(), ends.flat(), 1e-6);
      const a = activationAt(r.frames, muscleDrivers(r)[k], t);
      assert.ok(Math.abs(view.meshes[k].scale.x - muscleRadius(0.005, a)) < 1e-12);
      assert.equal(view.meshes[k].scale.z, view.meshes[k].scale.x);
      assert.equal(state[k].activation, a);
      assert.equal(view.meshes[k].material.color.getHex(), muscleColor(a));
    });
  }
  // at 0.45 s muscle 1's effector reads 2 sin(0.4) = 0.78, muscle 0's 0.2
  view.setTime(0.45);
  const [m0, m1] = view.meshes;
  assert.ok(m1.scale.x > m0.scale.x);
  view.dispose();
});

test("the creature's meshes carry its muscles, posed with its parts", () => {
  const bodies = createBodies(parseReplay(makeLessin()));
  assert.equal(bodies.muscles.meshes.length, 2);
  assert.ok(bodies.group.children.includes(bodies.muscles.object));
  bodies.setTime(1.3);
  bodies.group.updateMatrixWorld(true);
  // muscle 0's part end sits on part 1's mesh, wherever the mesh is
  const onPart = new Vector3(-0.05, 0, 0.05).applyMatrix4(bodies.parts[1].matrixWorld).toArray();
  near(meshEnds(bodies.muscles.meshes[0])[1], onPart, 1e-6);
  bodies.dispose();
  // a creature of joint motors has none
  assert.equal(createBodies(makeReplay()).muscles.meshes.length, 0);
});
