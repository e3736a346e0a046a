// The centre of mass drawn as a trail on the ground, from the start to the
// present moment.
import { BufferAttribute, BufferGeometry, Line, LineBasicMaterial } from 'three';
import { groundPath, trailAt } from './trail.js';

/** A trail for `frames`; `setTime(t)` grows or shrinks it to time t. */
export function createTrail(frames) {
  const path = groundPath(frames);
  // one slot per frame plus one for the interpolated head
  const positions = new Float32Array(path.length + 3);
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  const line = new Line(geometry, new LineBasicMaterial({ color: 0xd9480f }));
  line.frustumCulled = false;

  return {
    object: line,
    setTime(t) {
      const { count, head } = trailAt(frames, t);
      positions.set(path.subarray(0, 3 * count));
      positions.set(head, 3 * count);
      geometry.attributes.position.needsUpdate = true;
      geometry.setDrawRange(0, count + 1);
    },
    dispose() {
      geometry.dispose();
      line.material.dispose();
    },
  };
}
