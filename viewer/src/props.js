// Props: things of a task's scene other than the creature (projectiles,
// targets, lights, grid cells). Each is drawn from its description in the
// replay's scene.props, so a new task needs no viewer change unless it brings
// a new shape. A description:
//   { "name": "ball", "shape": "sphere", "size": [0.2, 0.2, 0.2],
//     "color": "#cc3333", "opacity": 1, "pose": [x, y, z, qw, qx, qy, qz] }
// name, color, opacity and pose are optional. A prop that moves has its pose
// per frame in frames[f].props[i]; one that does not has a fixed "pose".
import { DRAWABLE } from './shapes.js';
import { DataError, numbers } from './data.js';
import { parseCssColor } from './palette.js';
import { bracket } from './timeline.js';
import { lerpPose } from './pose.js';

/** Colour of a prop whose description names none. */
export const PROP_COLOR = 0xb0b4b8;

/** Identity pose at the origin. */
const ORIGIN = [0, 0, 0, 1, 0, 0, 0];

/**
 * A prop's description, checked and with defaults filled in:
 * { name, shape, size, color, opacity, pose }.
 */
export function parseProp(d, i) {
  const at = `scene.props[${i}]`;
  if (d === null || typeof d !== 'object') throw new DataError(`${at}: expected an object`);
  if (!DRAWABLE.includes(d.shape))
    throw new DataError(`${at}.shape: expected one of ${DRAWABLE.join(', ')}, got ${JSON.stringify(d.shape)}`);
  numbers(d.size, 3, `${at}.size`);
  if (d.size.some((v) => v <= 0)) throw new DataError(`${at}.size: expected positive extents, got ${JSON.stringify(d.size)}`);
  let color = PROP_COLOR;
  if (d.color !== undefined && d.color !== null) {
    color = parseCssColor(d.color);
    if (color === null) throw new DataError(`${at}.color: expected "#rrggbb", got ${JSON.stringify(d.color)}`);
  }
  const opacity = d.opacity ?? 1;
  if (typeof opacity !== 'number' || !(opacity >= 0 && opacity <= 1))
    throw new DataError(`${at}.opacity: expected a number in [0, 1], got ${JSON.stringify(d.opacity)}`);
  const pose = d.pose === undefined ? ORIGIN : numbers(d.pose, 7, `${at}.pose`);
  return { name: typeof d.name === 'string' ? d.name : `prop ${i}`, shape: d.shape, size: d.size, color, opacity, pose };
}

/** Every prop of a replay's scene, checked. */
export function sceneProps(replay) {
  return (replay.scene.props ?? []).map(parseProp);
}

/** Pose of prop `i` at time t: from the frames when they carry props, else fixed. */
export function propPoseAt(replay, prop, i, t) {
  const frames = replay.frames;
  if (!frames[0].props) return prop.pose.slice();
  const { i: a, j: b, u } = bracket(frames, t);
  return lerpPose(frames[a].props[i], frames[b].props[i], u);
}
