// A creature's photoreceptors (lessin2015's eyes): where each sits on its
// part, which way it looks, how big it is drawn and how bright its reading
// makes it. An eye sits where its direction from the part's centre leaves
// the part's shape, as the simulation places it (develop's surface_distance,
// physics' receptor points), and looks along that direction. Drawn by
// eye_view.js.
import { bracket } from './timeline.js';

/**
 * Distance from the centre of a part of `shape` and full extents `size` to
 * its surface along the unit direction `d` (in the part's frame). Shapes as
 * shapes.js draws them: a sphere's diameter is x; capsules and cylinders lie
 * along x, length x (a capsule's caps included), diameter y.
 */
export function surfaceDistance(shape, size, d) {
  const [x, y, z] = size;
  const radial = Math.hypot(d[1], d[2]);
  switch (shape) {
    case 'sphere':
      return x / 2;
    case 'cylinder': {
      let t = radial > 1e-12 ? y / 2 / radial : Infinity;
      if (Math.abs(d[0]) > 1e-12) t = Math.min(t, x / 2 / Math.abs(d[0]));
      return t;
    }
    case 'capsule': {
      const r = y / 2, h = Math.max(x / 2 - r, 0);
      const t = radial > 1e-12 ? r / radial : Infinity;
      if (Math.abs(t * d[0]) <= h) return t;
      // the end cap: |t d - c| = r with c = (+-h, 0, 0)
      const dc = Math.abs(d[0]) * h;
      return dc + Math.sqrt(Math.max(dc * dc - h * h + r * r, 0));
    }
    default: {
      // a box
      let t = Infinity;
      [x, y, z].forEach((s, i) => {
        if (Math.abs(d[i]) > 1e-12) t = Math.min(t, s / 2 / Math.abs(d[i]));
      });
      return t;
    }
  }
}

/**
 * Height (m) of the cone an eye on `part` is drawn as: a third of the part's
 * smallest extent, within 1.5 and 6 cm; its base's radius is 0.45 of it.
 */
export function eyeHeight(part) {
  const smallest = Math.min(...part.size.filter((v) => v > 0));
  const h = Number.isFinite(smallest) ? smallest / 3 : 0.03;
  return Math.min(Math.max(h, 0.015), 0.06);
}

/**
 * An eye looking along `direction` (any length; in the frame of `part`, a
 * replay's part): { at: the point on the part's surface (part frame), dir:
 * the unit direction, height: its cone's }; null for a zero direction.
 */
export function eyePlacement(part, direction) {
  const n = Math.hypot(...direction);
  if (!(n > 1e-12)) return null;
  const dir = direction.map((v) => v / n);
  const s = surfaceDistance(part.shape, part.size, dir);
  return { at: dir.map((v) => v * s), dir, height: eyeHeight(part) };
}

/**
 * Every eye of `replay` that can be drawn: { sensor: its index among the
 * sensors, part, ...eyePlacement }. A photoreceptor without a direction
 * (written before replays held it) is left out.
 */
export function eyesOf(replay) {
  const out = [];
  (replay.sensors ?? []).forEach((s, k) => {
    if (s.type !== 'photoreceptor' || !Array.isArray(s.direction)) return;
    const p = eyePlacement(replay.parts[s.part], s.direction);
    if (p) out.push({ sensor: k, part: s.part, ...p });
  });
  return out;
}

/**
 * Brightness in [0, 1] of sensor `k`'s eye at time t: its reading (lessin2015's
 * are in [0, 1]; clamped) in the last frame at or before t; null when the
 * frames hold no readings.
 */
export function eyeBrightnessAt(frames, k, t) {
  const f = frames[bracket(frames, t).i];
  if (!Array.isArray(f.sensors)) return null;
  const v = f.sensors[k];
  return v > 0 ? Math.min(v, 1) : 0;
}
