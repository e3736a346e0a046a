// A catapult's flight drawn in 3D: a tube along the path of the projectile's
// centre from its release to the present moment, and a small ball where it
// was released. Nothing is drawn before the release.
import { BufferAttribute, BufferGeometry, Group, Mesh, MeshStandardMaterial, SphereGeometry } from 'three';
import { centrePath, flightAt, flightPoints, throwOf, tube, tubeIndices } from './flight.js';
import { FLIGHT_COLOR } from './palette.js';

/** Vertices around the tube. */
const SIDES = 10;

/**
 * The flight of `replay`'s projectile (the replay must have a throw), for a
 * creature of `radius` (m); `setTime(t)` draws it up to time t.
 */
export function createFlight(replay, radius) {
  const frames = replay.frames;
  const th = throwOf(replay);
  const k = th.projectile;
  const path = centrePath(frames, k);
  // thick enough to see at the follow camera's distance, thinner than the projectile
  const size = Math.max(...replay.parts[k].size);
  const r = Math.min(Math.max(size * 0.1, radius * 0.012, 0.008), 0.05);
  // start, one point per frame, head
  const n = frames.length + 2;
  const points = new Float32Array(3 * n);
  const positions = new Float32Array(3 * n * SIDES), normals = new Float32Array(3 * n * SIDES);
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new BufferAttribute(normals, 3));
  geometry.setIndex(new BufferAttribute(tubeIndices(n, SIDES), 1));
  const material = new MeshStandardMaterial({ color: FLIGHT_COLOR, roughness: 0.5, metalness: 0 });
  const line = new Mesh(geometry, material);
  line.visible = false;
  line.frustumCulled = false;
  line.castShadow = true;
  const start = new Mesh(new SphereGeometry(r * 2.2, 16, 10), material);
  start.visible = false;
  start.castShadow = true;
  const group = new Group();
  group.add(line, start);

  return {
    object: group,
    /** Whether anything is drawn at the present moment (after the release). */
    get drawn() { return line.visible; },
    setTime(t) {
      const f = flightAt(frames, k, th.release, t);
      line.visible = start.visible = f !== null;
      if (!f) return;
      const m = flightPoints(path, f, points);
      tube(points, m, r, SIDES, positions, normals);
      geometry.attributes.position.needsUpdate = true;
      geometry.attributes.normal.needsUpdate = true;
      geometry.setDrawRange(0, 6 * SIDES * (m - 1));
      start.position.set(...f.start);
    },
    dispose() {
      geometry.dispose();
      start.geometry.dispose();
      material.dispose();
    },
  };
}
