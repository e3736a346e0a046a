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
