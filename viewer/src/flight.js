// A catapult's throw (its scene record's projectile, release and target): which part is the
// projectile, when it was released, and the path of its centre in 3D from
// the release to the present moment, as points and as a tube around them.
import { bracket, partPoseAt } from './timeline.js';
import { metres } from './format.js';
import { markerTime, partNamed, pointNamed, recordOf } from './scene_record.js';

/**
 * The throw of a replay, or null for a creature that throws nothing: from
 * its scene record (scene_record.js), the part "projectile", the marker
 * "release" and the point "target": { projectile: part index, release: time
 * (s) or null, target: xyz or null, color: the projectile's }.
 */
export function throwOf(replay) {
  const rec = recordOf(replay);
  const part = partNamed(rec, 'projectile');
  if (!part) return null;
  return { projectile: part.part, release: markerTime(rec, 'release'), target: pointNamed(rec, 'target')?.p ?? null, color: part.color };
}

/** Centre of part `k` at time t, interpolated between frames. */
export function centreAt(frames, k, t) {
  return partPoseAt(frames, k, t).slice(0, 3);
}

/** Centre of part `k` in every frame, as one flat xyz array. */
export function centrePath(frames, k) {
  const out = new Float32Array(frames.length * 3);
  frames.forEach((f, i) => out.set(f.poses[k].slice(0, 3), 3 * i));
  return out;
}

/**
 * The flight of part `k` released at `release` (s), at time t: null before
 * the release (or when it never happened); else the whole frames after the
 * release up to t (`count` of them from frame `from`) between the
 * interpolated centre at the release (`start`) and at t (`head`).
 */
export function flightAt(frames, k, release, t) {
  if (release === null || !(t >= release)) return null;
  // first frame strictly after the release; last frame at or before t
  const r = bracket(frames, release).i;
  const from = frames[r].t > release ? r : r + 1;
  const to = bracket(frames, t).i;
  return { from, count: Math.max(to - from + 1, 0), start: centreAt(frames, k, release), head: centreAt(frames, k, t) };
}

/**
 * The points of `flight` (from flightAt) written into `out` as flat xyz:
 * start, the frames' centres from `path` (centrePath), head. Returns how
 * many points were written (count + 2).
 */
export function flightPoints(path, flight, out) {
  out.set(flight.start, 0);
  out.set(path.subarray(3 * flight.from, 3 * (flight.from + flight.count)), 3);
  out.set(flight.head, 3 * (flight.count + 1));
  return flight.count + 2;
}

/**
 * Horizontal distance (m) of part `k`'s centre at t from where it was
 * released: 0 before the release, null when it never released. At rest this
 * is the throw distance D_p.
 */
export function thrownAt(frames, k, release, t) {
  if (release === null) return null;
  if (!(t > release)) return 0;
  const a = centreAt(frames, k, release), b = centreAt(frames, k, t);
  return Math.hypot(b[0] - a[0], b[1] - a[1]);
}

/** What the page's line of text says of throw `th` at time t: "held", "thrown 1.23 m" or "not released". */
export function throwStatus(frames, th, t) {
  const d = thrownAt(frames, th.projectile, th.release, t);
  if (d === null) return 'not released';
  return t < th.release ? 'held' : `thrown ${metres(d)}`;
}

// unit vector, or null when too short to have a direction
function unit(x, y, z) {
  const n = Math.hypot(x, y, z);
  return n > 1e-9 ? [x / n, y / n, z / n] : null;
}

// a unit vector at right angles to unit d: across d and z, or across d and x when d is vertical
function across(d) {
  return unit(d[1], -d[0], 0) ?? unit(0, d[2], -d[1]);
}

/**
 * A tube of `radius` around the first `n` points of `path` (flat xyz):
 * a ring of `sides` vertices per point, written into `out` (at least
 * 3 n sides floats), and their outward unit normals into `normals` if given.
 * Each ring stands square to the path's direction there (from the previous
 * point to the next); its first vertex's direction is carried along the path
 * (parallel transport) so the tube does not twist. A line seen from afar is
 * one pixel wide; a tube is as thick as it is.
 */
export function tube(path, n, radius, sides, out, normals = null) {
  let dir = [1, 0, 0], side = null;
  for (let k = 0; k < n; ++k) {
    const a = Math.max(k - 1, 0), b = Math.min(k + 1, n - 1);
    dir = unit(path[3 * b] - path[3 * a], path[3 * b + 1] - path[3 * a + 1], path[3 * b + 2] - path[3 * a + 2]) ?? dir;
    // the previous ring's side, made square to the new direction
    if (side) {
      const d = side[0] * dir[0] + side[1] * dir[1] + side[2] * dir[2];
      side = unit(side[0] - d * dir[0], side[1] - d * dir[1], side[2] - d * dir[2]);
    }
    side = side ?? across(dir);
    // the ring: side and up (dir x side) at right angles, both square to dir
    const up = [dir[1] * side[2] - dir[2] * side[1], dir[2] * side[0] - dir[0] * side[2], dir[0] * side[1] - dir[1] * side[0]];
    for (let s = 0; s < sides; ++s) {
      const ang = (2 * Math.PI * s) / sides, c = Math.cos(ang), sn = Math.sin(ang);
      const nx = c * side[0] + sn * up[0], ny = c * side[1] + sn * up[1], nz = c * side[2] + sn * up[2];
      const o = 3 * (k * sides + s);
      out[o] = path[3 * k] + radius * nx;
      out[o + 1] = path[3 * k + 1] + radius * ny;
      out[o + 2] = path[3 * k + 2] + radius * nz;
      if (normals) {
        normals[o] = nx;
        normals[o + 1] = ny;
        normals[o + 2] = nz;
      }
    }
  }
  return out;
}

/** Triangles joining a tube's consecutive rings of `sides` vertices: 6 indices per side and segment. */
export function tubeIndices(n, sides) {
  const idx = new Uint32Array(Math.max(n - 1, 0) * sides * 6);
  for (let k = 0; k + 1 < n; ++k) {
    for (let s = 0; s < sides; ++s) {
      const a = k * sides + s, b = k * sides + ((s + 1) % sides);
      idx.set([a, b, a + sides, b, b + sides, a + sides], 6 * (k * sides + s));
    }
  }
  return idx;
}
