// Points of interest: what of a task's scene the camera should show beside
// the creature, from its scene record (scene_record.js): each point (the light
// tasks' light, an aim task's target) and each prop (fight-or-flight's
// targets) as a sphere around its centre, with the time it is shown from.
// The camera (follow.js, camera_rig.js) frames them; a scene without any
// frames only the creature, as ever.

/**
 * The record's points of interest, its points then its props:
 * [{ name, p: [x, y, z], radius, t }]. A point is shown throughout (the
 * viewer draws it from the start), its radius half its size. A prop from its
 * time on; its radius is half its box's diagonal, which holds it at every
 * angle its spin turns it to (about the vertical through its centre, which
 * stays put).
 */
export function pointsOfInterest(rec) {
  return [
    ...rec.points.map((q) => ({ name: q.name, p: q.p.slice(), radius: q.size / 2, t: 0 })),
    ...rec.props.map((d) => ({ name: d.name, p: d.pose.slice(0, 3), radius: Math.hypot(...d.size) / 2, t: d.t })),
  ];
}

/** Those of `interest` shown at some time up to `t` (a replay's end: those it ever shows). */
export function shownBy(interest, t) {
  return interest.filter((q) => q.t <= t);
}

/**
 * The first moment any of `interest` is shown, up to `end`, and those shown
 * then: { t, shown }; null when none is shown by `end`.
 */
export function firstShown(interest, end) {
  const by = shownBy(interest, end);
  if (!by.length) return null;
  const t = Math.min(...by.map((q) => q.t));
  return { t, shown: shownBy(by, t) };
}
