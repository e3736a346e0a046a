// A creature's muscles (lessin2015): where each one's ends are at a moment,
// from its two parts' poses (the replay gives each end in its own part's
// frame), how active its effector has it, and how thick and what colour it is
// drawn for that. Drawn by muscle_view.js.
import { bracket, partPoseAt } from './timeline.js';
import { localToWorld } from './pose.js';

/** Colour of a silent muscle (activation 0): pale, so it reads as slack. */
export const MUSCLE_IDLE = 0xe8c4bc;
/** Colour of a fully active muscle (activation 1): a deep red. */
export const MUSCLE_ACTIVE = 0xc8102e;
/** A fully active muscle is this many times as thick as a silent one. */
export const MUSCLE_THICKENING = 3;

/**
 * Each muscle's effector: for muscle m, the index of the effector that
 * drives it (`effectors[e].muscle === m`), or -1 when none does.
 */
export function muscleDrivers(replay) {
  const out = new Array((replay.muscles ?? []).length).fill(-1);
  (replay.effectors ?? []).forEach((e, k) => {
    if (Number.isInteger(e.muscle) && e.muscle >= 0 && e.muscle < out.length && out[e.muscle] < 0) out[e.muscle] = k;
  });
  return out;
}

/** An effector's signal as an activation in [0, 1] (lessin2015's are; anything else is clamped, NaN 0). */
export function activation(v) {
  return v > 0 ? Math.min(v, 1) : 0;
}

/**
 * Activation of the muscle effector `e` (-1: none, 0) at time t: its signal
 * in the last frame at or before t, as outputs are steps (timeline.js's neuronAt).
 */
export function activationAt(frames, e, t) {
  return e < 0 ? 0 : activation(frames[bracket(frames, t).i].effectors[e]);
}

/** Muscle `m`'s two ends in world coordinates, given its parts' poses `poseA` and `poseB`. */
export function muscleEnds(m, poseA, poseB) {
  return [localToWorld(poseA, m.anchor_a), localToWorld(poseB, m.anchor_b)];
}

/** Muscle `m`'s ends at time t, its parts' poses interpolated between frames. */
export function muscleEndsAt(frames, m, t) {
  return muscleEnds(m, partPoseAt(frames, m.part_a, t), partPoseAt(frames, m.part_b, t));
}

/**
 * Radius (m) of a silent muscle of `replay`: a twentieth of its thinnest
 * part's smallest extent, within 2.5 mm and 1.5 cm, so it reads as a cord
 * beside the parts it joins.
 */
export function muscleBaseRadius(replay) {
  const thinnest = Math.min(...replay.parts.map((p) => Math.min(...p.size.filter((v) => v > 0))));
  const r = Number.isFinite(thinnest) ? thinnest / 20 : 0.005;
  return Math.min(Math.max(r, 0.0025), 0.015);
}

/** Radius of a muscle of base radius `base` at activation `a`: thicker the more active, MUSCLE_THICKENING times at 1. */
export function muscleRadius(base, a) {
  return base * (1 + (MUSCLE_THICKENING - 1) * activation(a));
}

/** Colour (0xRRGGBB) of a muscle at activation `a`: from MUSCLE_IDLE at 0 to MUSCLE_ACTIVE at 1. */
export function muscleColor(a) {
  const u = activation(a);
  const ch = (c, s) => (c >> s) & 255;
  const mix = (s) => Math.round(ch(MUSCLE_IDLE, s) + (ch(MUSCLE_ACTIVE, s) - ch(MUSCLE_IDLE, s)) * u);
  return (mix(16) << 16) | (mix(8) << 8) | mix(0);
}
