// The signals between brain and body over time: each effector's signal, each
// sensor's reading and each joint degree of freedom's position, as series
// (series.js) for the signals panel, so that a controller stuck at a
// constant or a joint held at its stop shows at a glance.
import { JOINT_DOFS } from './data.js';
import { hertz } from './format.js';
import { brainFrom, makeSeries } from './series.js';

/** Degrees of freedom of a joint type (0 for an unknown one). */
export function jointDofs(type) {
  return JOINT_DOFS[type] ?? 0;
}

/** Whether dof `d` of a joint of `type` is a translation (m) rather than a rotation (rad). */
export function isLinearDof(type, d) {
  return d === 0 && (type === 'slider' || type === 'cylindrical');
}

/** Share of a stop's span within which a joint counts as at the stop. */
export const STOP_BAND = 0.02;
/** Share of the replay at or beyond a stop from which a joint is marked "at stop". */
export const AT_STOP_SHARE = 0.5;

const DEG = 180 / Math.PI;
const degrees = (v) => `${v.toFixed(Math.abs(v) >= 99.95 ? 0 : 1)}°`;
const metres = (v) => `${v.toFixed(3)} m`;

/**
 * How an effector is named: the joint and degree of freedom it drives (or
 * the muscle, lessin2015's), and its signal's dominant frequency ("constant"
 * for 0) when the replay has it.
 */
export function effectorLabel(e, k) {
  const hz = e.hz === undefined ? '' : ` · ${e.hz > 0 ? hertz(e.hz) : 'constant'}`;
  if (e.muscle !== undefined) return `${k}: muscle ${e.muscle}${hz}`;
  return `${k}: joint ${e.joint} · dof ${e.dof}${hz}`;
}

/**
 * How a sensor is named: a joint angle's joint and dof, a contact's part and face, a
 * photoreceptor's part, a muscle length's muscle (lessin2015).
 */
export function sensorLabel(s, k) {
  if (s.type === 'contact') return `${k}: contact · part ${s.part} ${s.face ?? '?'}`;
  if (s.type === 'photoreceptor') return `${k}: eye · part ${s.part}`;
  if (s.type === 'muscle_length') return `${k}: muscle ${s.muscle ?? '?'} length · part ${s.part}`;
  if (s.joint < 0) return `${k}: angle · part ${s.part} (root)`;
  return `${k}: angle · joint ${s.joint} · dof ${s.dof}`;
}

/** How a joint's degree of freedom is named. */
export function jointDofLabel(j, k, d) {
  return `joint ${k} · dof ${d} (${j.type})`;
}

// what a joint joins, for a tooltip
function joining(replay, k) {
  const j = replay.joints[k];
  return j ? `joint ${k} (${j.type}, part ${j.child} on part ${j.parent})` : `joint ${k}`;
}

// what a muscle joins, for a tooltip
function pulling(replay, k) {
  const m = (replay.muscles ?? [])[k];
  return m ? `muscle ${k} (part ${m.part_b} to part ${m.part_a})` : `muscle ${k}`;
}

// what an effector drives, for a tooltip
function effectorTitle(replay, e, k) {
  if (e.muscle !== undefined) return `effector ${k}: activates ${pulling(replay, e.muscle)}, in [0, 1]`;
  return `effector ${k}: drives dof ${e.dof} of ${joining(replay, e.joint)}`;
}

// what a sensor reads, for a tooltip
function sensorTitle(replay, s, k) {
  switch (s.type) {
    case 'contact': return `sensor ${k}: contact of part ${s.part}'s ${s.face} face (+1 touching, -1 not)`;
    case 'photoreceptor': return `sensor ${k}: light seen by an eye on part ${s.part}, in [0, 1]`;
    case 'muscle_length': return `sensor ${k}: length of ${pulling(replay, s.muscle)} over twice its built length, in [0, 1]`;
    default:
      return s.joint < 0
        ? `sensor ${k}: joint angle of the root part ${s.part}, which has no joint (reads 0)`
        : `sensor ${k}: angle of dof ${s.dof} of ${joining(replay, s.joint)}, scaled to [-1, 1]`;
  }
}

/** One series per effector: its signal, drawn on the fixed range [-1, 1] with a zero line. */
export function effectorSeries(replay) {
  const frames = replay.frames;
  const from = brainFrom(frames);
  return (replay.effectors ?? []).map((e, k) => fixedRange(makeSeries({
    label: effectorLabel(e, k), kind: 'effector', from,
    title: effectorTitle(replay, e, k),
    values: Float32Array.from(frames, (f) => f.effectors[k]),
  })));
}

/**
 * One series per sensor: its reading, drawn on [-1, 1] with a zero line;
 * empty when the replay has no sensors recorded (written before they were).
 */
export function sensorSeries(replay) {
  if (!Array.isArray(replay.sensors)) return [];
  const frames = replay.frames;
  const from = brainFrom(frames);
  return replay.sensors.map((s, k) => fixedRange(makeSeries({
    label: sensorLabel(s, k), kind: 'sensor', from,
    title: sensorTitle(replay, s, k),
    values: Float32Array.from(frames, (f) => f.sensors[k]),
  })));
}

function fixedRange(s) {
  s.lo = -1;
  s.hi = 1;
  s.lines.push({ v: 0, kind: 'zero' });
  return s;
}

/**
 * One series per joint degree of freedom, in degrees (metres for a
 * translation), over all frames. A dof with stops is drawn against them (the
 * stops marked, a margin beyond, and wider if it went past them) and says
 * which share of the replay it spent at or beyond one (`atStop`); the dofs
 * without stops share one range per unit. Empty when the replay has no
 * joint angles recorded.
 */
export function jointAngleSeries(replay) {
  const frames = replay.frames;
  if (!frames.every((f) => Array.isArray(f.joint_angles))) return [];
  const out = [];
  replay.joints.forEach((j, k) => {
    for (let d = 0; d < jointDofs(j.type); ++d) {
      const linear = isLinearDof(j.type, d);
      const scale = linear ? 1 : DEG;
      const lim = Array.isArray(j.limits) ? j.limits[d] : undefined;
      const stops = lim && lim[1] > lim[0] ? [lim[0] * scale, lim[1] * scale] : null;
      const s = makeSeries({
        label: jointDofLabel(j, k, d), kind: 'joint', scale, format: linear ? metres : degrees,
        title: `dof ${d} of ${joining(replay, k)}` +
          (stops ? `; stops ${(linear ? metres : degrees)(stops[0])} .. ${(linear ? metres : degrees)(stops[1])}` : '; no stops'),
        values: Float32Array.from(frames, (f) => f.joint_angles[k][d]),
      });
      s.linear = linear;
      s.stops = stops;
      if (stops) {
        s.atStop = stopShare(s.values, stops);
        const lo = Math.min(stops[0], s.min), hi = Math.max(stops[1], s.max);
        const margin = 0.1 * (hi - lo);
        s.lo = lo - margin;
        s.hi = hi + margin;
        s.lines.push({ v: stops[0], kind: 'stop' }, { v: stops[1], kind: 'stop' });
      }
      out.push(s);
    }
  });
  // the dofs without stops: one range per unit
  for (const linear of [false, true]) {
    const free = out.filter((s) => !s.stops && s.linear === linear);
    if (free.length === 0) continue;
    let lo = Math.min(...free.map((s) => s.min)), hi = Math.max(...free.map((s) => s.max));
    if (hi - lo < 1e-6) {
      const w = linear ? 0.01 : 1;
      lo -= w;
      hi += w;
    }
    const margin = 0.05 * (hi - lo);
    for (const s of free) {
      s.lo = lo - margin;
      s.hi = hi + margin;
    }
  }
  for (const s of out) if (s.lo < 0 && s.hi > 0) s.lines.unshift({ v: 0, kind: 'zero' });
  return out;
}

/** Share of `values` at a stop (within STOP_BAND of its span) or beyond it. */
export function stopShare(values, [lo, hi]) {
  const band = STOP_BAND * (hi - lo);
  let n = 0;
  for (const v of values) if (v <= lo + band || v >= hi - band) ++n;
  return values.length ? n / values.length : 0;
}

/**
 * The signals panel's groups: effectors, sensors and joint angles, each
 * {key, title, axis (what the plots' vertical range is), series, missing
 * (true when the replay does not record them)}.
 */
export function signalGroups(replay) {
  const hasSensors = Array.isArray(replay.sensors);
  const hasAngles = replay.frames.every((f) => Array.isArray(f.joint_angles));
  return [
    { key: 'effectors', title: 'Effectors', axis: 'axis -1 .. 1', series: effectorSeries(replay), missing: false },
    { key: 'sensors', title: 'Sensors', axis: 'axis -1 .. 1', series: sensorSeries(replay), missing: !hasSensors },
    { key: 'joints', title: 'Joint angles', axis: replay.joints.some((j) => isLinearDof(j.type, 0)) ? 'degrees (m), stops dashed' : 'degrees, stops dashed', series: jointAngleSeries(replay), missing: !hasAngles },
  ];
}
