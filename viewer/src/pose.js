// Pose math on plain arrays, as the replay stores it: a pose is
// [x, y, z, qw, qx, qy, qz]: the part's centre and its orientation.

/** Unit quaternion [w, x, y, z] between a and b at fraction u (shortest arc). */
export function slerp(a, b, u) {
  let [aw, ax, ay, az] = a;
  let [bw, bx, by, bz] = b;
  // take the short way round
  let dot = aw * bw + ax * bx + ay * by + az * bz;
  if (dot < 0) {
    dot = -dot;
    bw = -bw; bx = -bx; by = -by; bz = -bz;
  }
  let ka, kb;
  if (dot > 0.9995) {
    // nearly equal: linear blend, normalised below
    ka = 1 - u;
    kb = u;
  } else {
    const theta = Math.acos(dot);
    const s = Math.sin(theta);
    ka = Math.sin((1 - u) * theta) / s;
    kb = Math.sin(u * theta) / s;
  }
  const q = [ka * aw + kb * bw, ka * ax + kb * bx, ka * ay + kb * by, ka * az + kb * bz];
  const n = Math.hypot(...q) || 1;
  return q.map((c) => c / n);
}

/** Pose between p0 and p1 at fraction u: position lerped, orientation slerped. */
export function lerpPose(p0, p1, u) {
  if (u <= 0) return p0.slice();
  if (u >= 1) return p1.slice();
  const q = slerp(p0.slice(3), p1.slice(3), u);
  return [p0[0] + (p1[0] - p0[0]) * u, p0[1] + (p1[1] - p0[1]) * u, p0[2] + (p1[2] - p0[2]) * u, ...q];
}

/** Vector v rotated by unit quaternion q = [w, x, y, z]. */
export function rotate(q, v) {
  const [w, x, y, z] = q;
  // t = 2 (q.xyz x v); v' = v + w t + q.xyz x t
  const tx = 2 * (y * v[2] - z * v[1]);
  const ty = 2 * (z * v[0] - x * v[2]);
  const tz = 2 * (x * v[1] - y * v[0]);
  return [
    v[0] + w * tx + (y * tz - z * ty),
    v[1] + w * ty + (z * tx - x * tz),
    v[2] + w * tz + (x * ty - y * tx),
  ];
}

/** A point given in a part's local frame, in world coordinates. */
export function localToWorld(pose, v) {
  const r = rotate(pose.slice(3), v);
  return [pose[0] + r[0], pose[1] + r[1], pose[2] + r[2]];
}

/** Linear blend of two 3-vectors. */
export function lerp3(a, b, u) {
  return [a[0] + (b[0] - a[0]) * u, a[1] + (b[1] - a[1]) * u, a[2] + (b[2] - a[2]) * u];
}
