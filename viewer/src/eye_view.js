// The eyes drawn (eyes.js): each a small dark cone standing on its part's
// surface and pointing where it looks, carried by the part's mesh, and
// glowing yellow as bright as its reading at the moment.
import { ConeGeometry, Mesh, MeshStandardMaterial, Quaternion, Vector3 } from 'three';
import { eyeBrightnessAt, eyesOf } from './eyes.js';

/** An eye's own colour (dark, so it reads on every gene's colour), and its glow's. */
export const EYE_COLOR = 0x22262b;
export const EYE_GLOW = 0xffd43b;
/** Glow of an eye whose readings the replay does not hold. */
const UNKNOWN = 0.5;
/** Share of a cone's height sunk below the surface, so a curved or slanted surface does not show a gap. */
const SUNK = 0.15;

const UP = new Vector3(0, 1, 0);

/** How strongly an eye of brightness b (null: unknown) glows. */
export function eyeGlow(b) {
  return 0.08 + 0.92 * (b ?? UNKNOWN);
}

/**
 * The eyes of `replay` on the part meshes `parts` (bodies.js's, in the
 * replay's part order; each eye is a child of its part's mesh, so it moves
 * with it): `setTime(t)` sets their glow; `state()` says, per eye, its sensor,
 * part, place and direction in the part's frame and its brightness (null:
 * unknown); `dispose()` frees them.
 */
export function createEyes(replay, parts) {
  const eyes = eyesOf(replay);
  const meshes = eyes.map((e) => {
    const radius = 0.45 * e.height;
    const geometry = new ConeGeometry(radius, e.height, 16).translate(0, (0.5 - SUNK) * e.height, 0);
    const mesh = new Mesh(geometry, new MeshStandardMaterial({
      color: EYE_COLOR, emissive: EYE_GLOW, emissiveIntensity: eyeGlow(null), roughness: 0.35, metalness: 0,
    }));
    mesh.position.set(...e.at);
    mesh.quaternion.copy(new Quaternion().setFromUnitVectors(UP, new Vector3(...e.dir)));
    mesh.castShadow = true;
    parts[e.part].add(mesh);
    return mesh;
  });
  const brightness = eyes.map(() => null);

  return {
    meshes,
    setTime(t) {
      eyes.forEach((e, k) => {
        brightness[k] = eyeBrightnessAt(replay.frames, e.sensor, t);
        meshes[k].material.emissiveIntensity = eyeGlow(brightness[k]);
      });
    },
    state() {
      return eyes.map((e, k) => ({ sensor: e.sensor, part: e.part, at: e.at, dir: e.dir, brightness: brightness[k] }));
    },
    dispose() {
      meshes.forEach((m) => {
        m.removeFromParent();
        m.geometry.dispose();
        m.material.dispose();
      });
    },
  };
}
