// The centre of mass's trail: the path from the start to the current moment,
// drawn on the ground.
import { bracket, comAt } from './timeline.js';

/** Height of the trail above the ground (m), clear of the grid lines. */
export const TRAIL_LIFT = 0.004;

/** Every frame's centre of mass on the ground, as one flat xyz array. */
export function groundPath(frames) {
  const out = new Float32Array(frames.length * 3);
  frames.forEach((f, k) => {
    out[3 * k] = f.com[0];
    out[3 * k + 1] = f.com[1];
    out[3 * k + 2] = TRAIL_LIFT;
  });
  return out;
}

/**
 * The trail at time t: the frames up to t and then the interpolated present
 * point. Returns how many points of `path` to draw and the head point.
 */
export function trailAt(frames, t) {
  const { i } = bracket(frames, t);
  const c = comAt(frames, t);
  return { count: i + 1, head: [c[0], c[1], TRAIL_LIFT] };
}

/**
 * A flat ribbon `width` wide along the first `n` points of `path` (flat xyz):
 * two vertices per point, either side of the path's direction there, written
 * into `out` (at least 6 n floats). WebGL draws lines one pixel wide, too thin
 * to see at a distance; a ribbon scales with the scene.
 */
export function ribbon(path, n, width, out) {
  let tx = 1, ty = 0; // the direction at a point where the path stands still
  for (let k = 0; k < n; ++k) {
    // direction: from the previous point to the next (the ends use their one neighbour)
    const a = Math.max(k - 1, 0), b = Math.min(k + 1, n - 1);
    const dx = path[3 * b] - path[3 * a], dy = path[3 * b + 1] - path[3 * a + 1];
    const len = Math.hypot(dx, dy);
    if (len > 1e-9) {
      tx = dx / len;
      ty = dy / len;
    }
    const ox = (-ty * width) / 2, oy = (tx * width) / 2;
    const x = path[3 * k], y = path[3 * k + 1], z = path[3 * k + 2];
    out.set([x + ox, y + oy, z, x - ox, y - oy, z], 6 * k);
  }
  return out;
}

/** Triangles joining a ribbon's vertex pairs: 6 indices per segment. */
export function ribbonIndices(n) {
  const idx = new Uint32Array(Math.max(n - 1, 0) * 6);
  for (let k = 0; k + 1 < n; ++k) {
    const l0 = 2 * k, r0 = l0 + 1, l1 = l0 + 2, r1 = l0 + 3;
    idx.set([l0, r0, l1, r0, r1, l1], 6 * k);
  }
  return idx;
}
