// Time in a replay: which frames bracket a moment, and values between them.
import { lerp3, lerpPose } from './pose.js';

/** Length of the replay (s): the last frame's time. */
export function duration(frames) {
  return frames[frames.length - 1].t;
}

/**
 * The frames around time t: indices i <= j and the fraction u between them.
 * Times before the first frame or after the last clamp to it.
 */
export function bracket(frames, t) {
  const n = frames.length;
  const i = frameIndexAt(frames, t);
  const j = t > frames[0].t && t < frames[n - 1].t ? i + 1 : i;
  const span = frames[j].t - frames[i].t;
  return { i, j, u: span > 0 ? (t - frames[i].t) / span : 0 };
}

/**
 * The index of the last frame at or before time t (the first for an earlier
 * t, the last for a later one), by binary search, allocating nothing.
 */
export function frameIndexAt(frames, t) {
  const n = frames.length;
  if (!(t > frames[0].t)) return 0;
  if (t >= frames[n - 1].t) return n - 1;
  let lo = 0, hi = n - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (frames[mid].t <= t) lo = mid;
    else hi = mid;
  }
  return lo;
}

/** Pose of part `k` at time t, interpolated between frames. */
export function partPoseAt(frames, k, t) {
  const { i, j, u } = bracket(frames, t);
  return lerpPose(frames[i].poses[k], frames[j].poses[k], u);
}

/** Centre of mass at time t. */
export function comAt(frames, t) {
  const { i, j, u } = bracket(frames, t);
  return lerp3(frames[i].com, frames[j].com, u);
}

/** Output of neuron `k` at time t (the nearest earlier frame's: outputs are steps). */
export function neuronAt(frames, k, t) {
  return frames[bracket(frames, t).i].neurons[k];
}

/** Horizontal distance of the centre of mass at t from where it started. */
export function distanceAt(frames, t) {
  const c = comAt(frames, t), c0 = frames[0].com;
  return Math.hypot(c[0] - c0[0], c[1] - c0[1]);
}
