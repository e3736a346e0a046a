// Shapes: every part drawn with its true extents.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { Box3, Mesh } from 'three';
import { DRAWABLE, shapeGeometry } from '../src/shapes.js';

function extents(shape, size) {
  const g = shapeGeometry(shape, size);
  const b = new Box3().setFromObject(new Mesh(g));
  return [b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z];
}
const close = (a, b, eps) => a.forEach((v, i) => assert.ok(Math.abs(v - b[i]) < eps, `${a} vs ${b}`));

test('a box has its size', () => {
  close(extents('box', [0.4, 0.2, 0.1]), [0.4, 0.2, 0.1], 1e-6); // float32 vertices
});

test('a sphere has diameter x', () => {
  close(extents('sphere', [0.3, 9, 9]), [0.3, 0.3, 0.3], 1e-6);
});

test('capsules and cylinders lie along x: length x, diameter y', () => {
  // round shapes are polygons: their extents across may fall short by cos(pi/segments)
  close(extents('capsule', [0.5, 0.2, 7]), [0.5, 0.2, 0.2], 0.005);
  close(extents('cylinder', [0.5, 0.2, 7]), [0.5, 0.2, 0.2], 0.005);
  // a capsule shorter than its diameter is a sphere
  close(extents('capsule', [0.1, 0.2, 0.2]), [0.2, 0.2, 0.2], 0.005);
});

test('an unknown shape is an error naming it', () => {
  assert.deepEqual(DRAWABLE, ['box', 'sphere', 'capsule', 'cylinder']);
  assert.throws(() => shapeGeometry('cone', [1, 1, 1]), /cannot draw shape "cone"/);
});
