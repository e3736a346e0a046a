// Where the follow camera looks: the centre of mass smoothed over a second,
// so the camera glides instead of shaking with every step. A pure function of
// time, so scrubbing and rendering a video frame by frame give the same view.
import { comAt } from './timeline.js';

/** Smoothed look-at point at time t: mean of the centre of mass over [t - w/2, t + w/2]. */
export function followTarget(frames, t, window = 1.0, samples = 11) {
  const sum = [0, 0, 0];
  for (let k = 0; k < samples; ++k) {
    const c = comAt(frames, t - window / 2 + (window * k) / (samples - 1));
    sum[0] += c[0]; sum[1] += c[1]; sum[2] += c[2];
  }
  return sum.map((v) => v / samples);
}

/**
 * The creature's size at the first frame: radius (m) of the sphere around all
 * parts' boxes, used to frame the camera. At least 0.1 m.
 */
export function creatureRadius(replay) {
  const f = replay.frames[0];
  const c = f.com;
  let r = 0;
  replay.parts.forEach((p, k) => {
    const pos = f.poses[k];
    const half = Math.hypot(...p.size) / 2;
    r = Math.max(r, Math.hypot(pos[0] - c[0], pos[1] - c[1], pos[2] - c[2]) + half);
  });
  return Math.max(r, 0.1);
}

/** Bounds of the centre of mass's path on the ground: {min, max, centre, span}. */
export function pathBounds(frames) {
  const min = [Infinity, Infinity], max = [-Infinity, -Infinity];
  for (const f of frames) {
    min[0] = Math.min(min[0], f.com[0]); max[0] = Math.max(max[0], f.com[0]);
    min[1] = Math.min(min[1], f.com[1]); max[1] = Math.max(max[1], f.com[1]);
  }
  return {
    min, max,
    centre: [(min[0] + max[0]) / 2, (min[1] + max[1]) / 2],
    span: Math.max(max[0] - min[0], max[1] - min[1]),
  };
}

/**
 * Direction from the look-at point towards the camera (unit xyz): on the
 * right of the creature's overall heading, turned a little towards its front
 * and raised, so it walks left to right across the screen. A creature that
 * barely moves is seen from -y.
 */
export function viewDirection(frames, ahead = 0.5, elevation = 0.42) {
  const a = frames[0].com, b = frames[frames.length - 1].com;
  let hx = b[0] - a[0], hy = b[1] - a[1];
  const n = Math.hypot(hx, hy);
  if (n < 0.05) {
    hx = 1;
    hy = 0;
  } else {
    hx /= n;
    hy /= n;
  }
  // right of the heading, turned `ahead` radians towards the front, then raised
  const sx = hy, sy = -hx;
  const x = sx * Math.cos(ahead) + hx * Math.sin(ahead);
  const y = sy * Math.cos(ahead) + hy * Math.sin(ahead);
  const c = Math.cos(elevation);
  return [x * c, y * c, Math.sin(elevation)];
}
