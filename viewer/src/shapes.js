// The true shape of a part or prop as three.js geometry. Sizes are full
// extents along the local x, y, z (docs/replay-format.md): a sphere's diameter
// is x; capsules and cylinders lie along x with length x (caps included) and
// diameter y.
import { BoxGeometry, CapsuleGeometry, CylinderGeometry, SphereGeometry } from 'three';

/** Shapes this viewer can draw. */
export const DRAWABLE = ['box', 'sphere', 'capsule', 'cylinder'];

/**
 * Geometry of `shape` with full extents `size` = [x, y, z], centred on the
 * local origin. Throws on a shape it does not know.
 */
export function shapeGeometry(shape, size) {
  const [x, y, z] = size;
  switch (shape) {
    case 'box':
      return new BoxGeometry(x, y, z);
    case 'sphere':
      return new SphereGeometry(x / 2, 32, 16);
    case 'capsule': {
      // three's capsule stands along y with `length` between the caps' centres
      const r = y / 2;
      const g = new CapsuleGeometry(r, Math.max(x - 2 * r, 0), 8, 24);
      return g.rotateZ(-Math.PI / 2);
    }
    case 'cylinder': {
      const g = new CylinderGeometry(y / 2, y / 2, x, 32);
      return g.rotateZ(-Math.PI / 2);
    }
    default:
      throw new Error(`cannot draw shape "${shape}" (known: ${DRAWABLE.join(', ')})`);
  }
}
