// Where the follow camera looks: the centre of mass (or a catapult's
// projectile) smoothed over a second, so the camera glides instead of shaking
// with every step. A pure function of time, so scrubbing and rendering a
// video frame by frame give the same view. And how the cameras frame the
// creature, its path and the scene's lights and targets (interest.js).
import { comAt, partPoseAt } from './timeline.js';

/** Mean of the point `at(t)` over [t - w/2, t + w/2], from `samples` samples. */
export function smoothed(at, t, window = 1.0, samples = 11) {
  const sum = [0, 0, 0];
  for (let k = 0; k < samples; ++k) {
    const c = at(t - window / 2 + (window * k) / (samples - 1));
    sum[0] += c[0]; sum[1] += c[1]; sum[2] += c[2];
  }
  return sum.map((v) => v / samples);
}

/** The camera modes, in the order the camera button goes through them. */
export const CAMERA_MODES = ['follow', 'projectile', 'orbit'];

/**
 * The camera mode after `mode`, skipping "projectile" for a creature without
 * one (where it means "follow").
 */
export function nextMode(mode, hasProjectile) {
  const modes = hasProjectile ? CAMERA_MODES : CAMERA_MODES.filter((m) => m !== 'projectile');
  return modes[(Math.max(modes.indexOf(mode), 0) + 1) % modes.length];
}

/** Smoothed look-at point at time t: mean of the centre of mass over [t - w/2, t + w/2]. */
export function followTarget(frames, t, window = 1.0, samples = 11) {
  return smoothed((u) => comAt(frames, u), t, window, samples);
}

/** Smoothed look-at point following part `k` (a projectile) instead. */
export function partTarget(frames, k, t, window = 1.0, samples = 11) {
  return smoothed((u) => partPoseAt(frames, k, u), t, window, samples);
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

/**
 * How much larger than a creature of metres the view must be for one of
 * `radius` (m): 1 up to 2 m, then radius / 2. The fog, the camera's depth
 * range and the ground are sized for creatures of a metre or two; a larger
 * one (a creature grown to giant blocks) scales them by this so it
 * is not lost in the fog.
 */
export function viewScale(radius) {
  return Math.max(1, radius / 2);
}

/**
 * Bounds of the centre of mass's path on the ground: {min, max, centre, span};
 * with `k` >= 0, of part k's path (a projectile's) as well; with `interest`
 * (interest.js: spheres {p, radius}), of the squares around them on the
 * ground too.
 */
export function pathBounds(frames, k = -1, interest = []) {
  const min = [Infinity, Infinity], max = [-Infinity, -Infinity];
  const add = (p) => {
    min[0] = Math.min(min[0], p[0]); max[0] = Math.max(max[0], p[0]);
    min[1] = Math.min(min[1], p[1]); max[1] = Math.max(max[1], p[1]);
  };
  for (const f of frames) {
    add(f.com);
    if (k >= 0) add(f.poses[k]);
  }
  for (const q of interest) {
    add([q.p[0] - q.radius, q.p[1] - q.radius]);
    add([q.p[0] + q.radius, q.p[1] + q.radius]);
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
 * barely moves is seen from -y. With `k` >= 0 the heading is part k's (a
 * catapult's projectile: it flies across the screen).
 */
export function viewDirection(frames, ahead = 0.5, elevation = 0.42, k = -1) {
  const at = (f) => (k >= 0 ? f.poses[k] : f.com);
  const a = at(frames[0]), b = at(frames[frames.length - 1]);
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

/**
 * The half-angle (rad) of the cone about the view's axis in which the camera
 * keeps a light or target: four fifths of half the camera's vertical field
 * of view `fov` (degrees), a margin from the picture's edge. In a window
 * wider than tall the vertical field is the narrower, so the cone lies within
 * the picture.
 */
export function showHalfAngle(fov) {
  return 0.8 * (fov / 2) * (Math.PI / 180);
}

/**
 * The least distance from the look-at point `at`, along the unit direction
 * `dir` towards the camera, at which the sphere `q` ({p, radius}) lies within
 * the cone of half-angle `half` about the view's axis. Every point of the
 * sphere is at most b + r off the axis and at least d - a - r ahead of the
 * camera (a: its centre's distance towards the camera, b: off the axis), so
 * d >= a + r + (b + r) / tan(half) is enough.
 */
export function distanceToShow(at, dir, q, half) {
  const w = [q.p[0] - at[0], q.p[1] - at[1], q.p[2] - at[2]];
  const a = w[0] * dir[0] + w[1] * dir[1] + w[2] * dir[2];
  const b = Math.hypot(w[0] - a * dir[0], w[1] - a * dir[1], w[2] - a * dir[2]);
  return a + q.radius + (b + q.radius) / Math.tan(half);
}

/** How many times the standard follow distance the camera may move back to show a light or target. */
export const FOLLOW_REACH = 3;

/** `dir` turned by `angle` (rad) about the vertical, counterclockwise seen from above. */
function turned(dir, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return [dir[0] * c - dir[1] * s, dir[0] * s + dir[1] * c, dir[2]];
}

/**
 * The follow view ({dir, dist}) that shows, beside the creature at `at`, the
 * nearest of `interest` (spheres {p, radius}: the scene's lights and targets
 * then shown), from the standard view's direction `dir` and distance `dist`:
 * the camera keeps looking at the creature from the same height angle, turns
 * about the vertical by the least angle (in whole degrees, counterclockwise
 * first) at which moving back, never beyond FOLLOW_REACH times `dist`, brings
 * that sphere within the cone of half-angle `half` (distanceToShow), and
 * moves back just that far. The least turn keeps the standard view when
 * moving back is enough (the creature still walks across the picture); a
 * light near the camera's side, which the camera would have to pass to see,
 * makes it turn until it looks past the creature towards the light. With no
 * interest, or one too far to show within the reach, the standard view
 * itself (the same `dir` and `dist`).
 */
export function followView(at, dir, dist, interest, half) {
  if (!interest.length) return { dir, dist };
  const away = (q) => Math.hypot(q.p[0] - at[0], q.p[1] - at[1], q.p[2] - at[2]);
  const q = interest.reduce((best, x) => (away(x) < away(best) ? x : best));
  const reach = dist * FOLLOW_REACH;
  for (let deg = 0; deg <= 180; ++deg) {
    for (const sign of deg === 0 ? [1] : [1, -1]) {
      const d = deg === 0 ? dir : turned(dir, (sign * deg * Math.PI) / 180);
      const need = distanceToShow(at, d, q, half);
      if (need <= reach) return { dir: d, dist: Math.max(dist, need) };
    }
  }
  return { dir, dist };
}

/**
 * The overview's distance from `centre` along `dir` that also shows every
 * sphere of `spheres` within the cone of half-angle `half`: at least `dist`.
 */
export function distanceToShowAll(centre, dir, dist, spheres, half) {
  return spheres.reduce((d, q) => Math.max(d, distanceToShow(centre, dir, q, half)), dist);
}
