// The centre of mass drawn as a trail on the ground, from the start to the
// present moment: a flat ribbon, a few centimetres wide.
import { BufferAttribute, BufferGeometry, DoubleSide, Mesh, MeshBasicMaterial } from 'three';
import { groundPath, ribbon, ribbonIndices, trailAt } from './trail.js';

/** A trail for `frames` of a creature of `radius`; `setTime(t)` grows or shrinks it to time t. */
export function createTrail(frames, radius) {
  const path = groundPath(frames);
  const width = Math.min(Math.max(radius * 0.05, 0.012), 0.06);
  // one point per frame plus one for the interpolated head
  const points = new Float32Array(path.length + 3);
  const n = frames.length + 1;
  const positions = new Float32Array(6 * n);
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  geometry.setIndex(new BufferAttribute(ribbonIndices(n), 1));
  const mesh = new Mesh(geometry, new MeshBasicMaterial({ color: 0xd9480f, side: DoubleSide }));
  mesh.frustumCulled = false;

  return {
    object: mesh,
    setTime(t) {
      const { count, head } = trailAt(frames, t);
      points.set(path.subarray(0, 3 * count));
      points.set(head, 3 * count);
      ribbon(points, count + 1, width, positions);
      geometry.attributes.position.needsUpdate = true;
      geometry.setDrawRange(0, 6 * count);
    },
    dispose() {
      geometry.dispose();
      mesh.material.dispose();
    },
  };
}
