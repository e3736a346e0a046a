// The muscles drawn (muscles.js): each a thin cylinder from one end to the
// other, placed from its parts' poses at every moment, thicker and redder
// the more active its effector has it.
import { CylinderGeometry, Group, Mesh, MeshStandardMaterial, Quaternion, Vector3 } from 'three';
import {
  activationAt, muscleBaseRadius, muscleColor, muscleDrivers, muscleEndsAt, muscleRadius,
} from './muscles.js';

const UP = new Vector3(0, 1, 0);

/**
 * Places `mesh`, a unit cylinder along its y axis (height 1, radius 1), from
 * point a to point b with radius r; hides it when the two meet.
 */
export function placeSegment(mesh, a, b, r) {
  const d = new Vector3(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  const len = d.length();
  mesh.visible = len > 1e-9;
  if (!mesh.visible) return;
  mesh.position.set((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2);
  mesh.quaternion.copy(new Quaternion().setFromUnitVectors(UP, d.divideScalar(len)));
  mesh.scale.set(r, len, r);
}

/**
 * The muscles of `replay` (none for a creature without them) as one group:
 * `setTime(t)` places and shades them; `state()` says, per muscle, its ends,
 * activation and radius as drawn; `dispose()` frees them.
 */
export function createMuscles(replay) {
  const group = new Group();
  const muscles = replay.muscles ?? [];
  const drivers = muscleDrivers(replay);
  const base = muscleBaseRadius(replay);
  const geometry = new CylinderGeometry(1, 1, 1, 12, 1);
  const meshes = muscles.map(() => {
    const mesh = new Mesh(geometry, new MeshStandardMaterial({ roughness: 0.5, metalness: 0 }));
    mesh.castShadow = true;
    group.add(mesh);
    return mesh;
  });
  const shown = muscles.map(() => ({ ends: null, activation: 0, radius: base }));

  return {
    object: group,
    meshes,
    setTime(t) {
      muscles.forEach((m, k) => {
        const ends = muscleEndsAt(replay.frames, m, t);
        const a = activationAt(replay.frames, drivers[k], t);
        const r = muscleRadius(base, a);
        placeSegment(meshes[k], ends[0], ends[1], r);
        const color = muscleColor(a);
        meshes[k].material.color.setHex(color);
        // an active muscle glows a little, so it reads in the shade too
        meshes[k].material.emissive.setHex(color);
        meshes[k].material.emissiveIntensity = 0.35 * a;
        shown[k] = { ends, activation: a, radius: r };
      });
    },
    state() {
      return shown.map((s) => ({ ...s }));
    },
    dispose() {
      geometry.dispose();
      meshes.forEach((m) => m.material.dispose());
    },
  };
}
