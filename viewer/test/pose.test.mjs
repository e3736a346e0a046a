// Pose math: interpolation between frames and rotation of vectors.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { lerpPose, localToWorld, rotate, slerp } from '../src/pose.js';
import { aboutZ } from './fixture.mjs';

const close = (a, b, eps = 1e-9) =>
  a.forEach((v, i) => assert.ok(Math.abs(v - b[i]) < eps, `${JSON.stringify(a)} != ${JSON.stringify(b)}`));

test('slerp gives its ends and the rotation halfway', () => {
  const a = aboutZ(0), b = aboutZ(Math.PI / 2);
  close(slerp(a, b, 0), a);
  close(slerp(a, b, 1), b);
  close(slerp(a, b, 0.5), aboutZ(Math.PI / 4));
});

test('slerp takes the short way when the quaternions have opposite signs', () => {
  const a = aboutZ(0.2), b = aboutZ(0.6).map((c) => -c); // same rotation as aboutZ(0.6)
  const mid = slerp(a, b, 0.5);
  // the same rotation as 0.4 rad about z, whatever its sign
  const ref = aboutZ(0.4);
  const sign = Math.sign(mid[0] * ref[0] + mid[3] * ref[3]);
  close(mid.map((c) => c * sign), ref);
});

test('rotate turns x into y a quarter turn about z', () => {
  close(rotate(aboutZ(Math.PI / 2), [1, 0, 0]), [0, 1, 0]);
  close(rotate([1, 0, 0, 0], [0.3, -2, 5]), [0.3, -2, 5]);
  // half a turn about x flips y and z
  close(rotate([0, 1, 0, 0], [1, 2, 3]), [1, -2, -3]);
});

test('lerpPose blends positions linearly and orientations by slerp', () => {
  const p0 = [0, 0, 0, ...aboutZ(0)], p1 = [2, 4, -2, ...aboutZ(1)];
  close(lerpPose(p0, p1, 0.25), [0.5, 1, -0.5, ...aboutZ(0.25)]);
  close(lerpPose(p0, p1, 0), p0);
  close(lerpPose(p0, p1, 1), p1);
});

test('localToWorld places a point of a part in the world', () => {
  const pose = [1, 2, 3, ...aboutZ(Math.PI / 2)];
  close(localToWorld(pose, [0.5, 0, 0]), [1, 2.5, 3]);
});
