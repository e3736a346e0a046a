// The page's data: which replays it holds and, for a run, its fitness curves.
// Validation happens once, here, so the rest of the viewer can trust shapes
// and lengths. Errors name the field's path and what was wrong.

const SHAPES = ['box', 'sphere', 'capsule', 'cylinder'];

/** Degrees of freedom of each joint type, in the order `dof` indices count them. */
export const JOINT_DOFS = { fixed: 0, hinge: 1, universal: 2, spherical: 3, slider: 1, cylindrical: 2 };

const SENSOR_TYPES = ['joint_angle', 'contact', 'photoreceptor', 'muscle_length'];

/** An error in the page's data; `message` names the field. */
export class DataError extends Error {}

function fail(path, what, got) {
  let shown;
  try {
    shown = JSON.stringify(got);
  } catch {
    shown = String(got);
  }
  if (shown === undefined) shown = 'nothing';
  if (shown.length > 60) shown = shown.slice(0, 57) + '...';
  throw new DataError(`${path}: ${what}, got ${shown}`);
}

const isNum = (v) => typeof v === 'number' && Number.isFinite(v);

function num(v, path) {
  if (!isNum(v)) fail(path, 'expected a number', v);
  return v;
}

function int(v, path, min = -Infinity) {
  if (!Number.isInteger(v) || v < min) fail(path, `expected an integer >= ${min}`, v);
  return v;
}

function arr(v, path) {
  if (!Array.isArray(v)) fail(path, 'expected an array', v);
  return v;
}

/** Checks an array of `n` finite numbers. */
export function numbers(v, n, path) {
  if (!Array.isArray(v) || v.length !== n || !v.every(isNum))
    fail(path, `expected ${n} numbers`, v);
  return v;
}

function obj(v, path) {
  if (v === null || typeof v !== 'object' || Array.isArray(v)) fail(path, 'expected an object', v);
  return v;
}

/** Checks a part's shape name (the four shapes of a creature's parts). */
export function partShape(v, path) {
  if (!SHAPES.includes(v)) fail(path, `expected one of ${SHAPES.join(', ')}`, v);
  return v;
}

/**
 * Checks a replay object (docs/replay-format.md, version 1) and returns it.
 * Frames must have one pose per part, one output per neuron and one signal
 * per effector, in time order; when the replay records them (newer files
 * do), one reading per sensor and one position per joint degree of freedom.
 * An effector drives a joint's degree of freedom (`joint`, `dof`) or a
 * muscle (`muscle`, an index into `muscles`, which a file without muscles
 * leaves out).
 */
export function parseReplay(r, path = 'replay') {
  obj(r, path);
  if (r.format !== 'bestiary-replay') fail(`${path}.format`, 'expected "bestiary-replay"', r.format);
  if (r.version !== 1) fail(`${path}.version`, 'expected 1 (this viewer reads version 1)', r.version);
  // the body: parts, joints, neurons
  const parts = arr(r.parts, `${path}.parts`);
  if (parts.length === 0) fail(`${path}.parts`, 'expected at least one part', parts);
  parts.forEach((p, i) => {
    const at = `${path}.parts[${i}]`;
    obj(p, at);
    partShape(p.shape, `${at}.shape`);
    numbers(p.size, 3, `${at}.size`);
    int(p.gene, `${at}.gene`, 0);
    int(p.parent, `${at}.parent`, -1);
  });
  arr(r.joints, `${path}.joints`).forEach((j, i) => {
    const at = `${path}.joints[${i}]`;
    obj(j, at);
    if (int(j.child, `${at}.child`, 0) >= parts.length) fail(`${at}.child`, 'no such part', j.child);
    numbers(j.anchor, 3, `${at}.anchor`);
    numbers(j.axis1, 3, `${at}.axis1`);
    numbers(j.axis2, 3, `${at}.axis2`);
    if (j.limits !== undefined) {
      arr(j.limits, `${at}.limits`).forEach((l, d) => numbers(l, 2, `${at}.limits[${d}]`));
    }
  });
  const joints = r.joints;
  // muscles (lessin2015; files without any have none): two parts, each end
  // in its own part's frame, a strength (N/m) and a rest length (m)
  const muscles = arr(r.muscles ?? [], `${path}.muscles`);
  muscles.forEach((m, i) => {
    const at = `${path}.muscles[${i}]`;
    obj(m, at);
    for (const end of ['a', 'b']) {
      const k = `part_${end}`;
      if (int(m[k], `${at}.${k}`, 0) >= parts.length) fail(`${at}.${k}`, 'no such part', m[k]);
      numbers(m[`anchor_${end}`], 3, `${at}.anchor_${end}`);
    }
    num(m.strength, `${at}.strength`);
    num(m.rest_length, `${at}.rest_length`);
  });
  // effectors and sensors: what drives which joint (or muscle), what reads what
  const effectors = arr(r.effectors ?? [], `${path}.effectors`);
  effectors.forEach((e, i) => {
    const at = `${path}.effectors[${i}]`;
    obj(e, at);
    if (e.muscle !== undefined) {
      if (int(e.muscle, `${at}.muscle`, 0) >= muscles.length) fail(`${at}.muscle`, 'no such muscle', e.muscle);
    } else {
      if (int(e.joint, `${at}.joint`, 0) >= joints.length) fail(`${at}.joint`, 'no such joint', e.joint);
      int(e.dof, `${at}.dof`, 0);
    }
    if (e.hz !== undefined) num(e.hz, `${at}.hz`);
  });
  const sensors = r.sensors === undefined ? null : arr(r.sensors, `${path}.sensors`);
  sensors?.forEach((s, i) => {
    const at = `${path}.sensors[${i}]`;
    obj(s, at);
    if (!SENSOR_TYPES.includes(s.type)) fail(`${at}.type`, `expected one of ${SENSOR_TYPES.join(', ')}`, s.type);
    int(s.part, `${at}.part`, 0);
    // a photoreceptor is drawn on its part, looking along its direction
    // (files before the direction was written have none: not drawn)
    if (s.type === 'photoreceptor') {
      if (s.part >= parts.length) fail(`${at}.part`, 'no such part', s.part);
      if (s.direction !== undefined) numbers(s.direction, 3, `${at}.direction`);
    }
  });
  const neurons = arr(r.neurons, `${path}.neurons`);
  neurons.forEach((n, i) => {
    obj(n, `${path}.neurons[${i}]`);
    int(n.part, `${path}.neurons[${i}].part`, -1);
  });
  // the scene: props are checked by props.js when drawn; here only the list
  obj(r.scene, `${path}.scene`);
  const props = arr(r.scene.props ?? [], `${path}.scene.props`);
  // frames: times ascending, poses, neuron outputs and signals complete
  const frames = arr(r.frames, `${path}.frames`);
  if (frames.length === 0) fail(`${path}.frames`, 'expected at least one frame', frames);
  // joint angles: in every frame or in none
  const angles = obj(frames[0], `${path}.frames[0]`).joint_angles !== undefined;
  if (angles) {
    joints.forEach((j, i) => {
      if (!(j.type in JOINT_DOFS)) fail(`${path}.joints[${i}].type`, `expected one of ${Object.keys(JOINT_DOFS).join(', ')}`, j.type);
    });
  }
  let last = -Infinity;
  frames.forEach((f, k) => {
    const at = `${path}.frames[${k}]`;
    obj(f, at);
    if (num(f.t, `${at}.t`) < last) fail(`${at}.t`, `expected a time >= ${last}`, f.t);
    last = f.t;
    const poses = arr(f.poses, `${at}.poses`);
    if (poses.length !== parts.length) fail(`${at}.poses`, `expected ${parts.length} poses`, poses.length);
    poses.forEach((p, i) => numbers(p, 7, `${at}.poses[${i}]`));
    numbers(f.com, 3, `${at}.com`);
    numbers(f.neurons, neurons.length, `${at}.neurons`);
    numbers(f.effectors, effectors.length, `${at}.effectors`);
    if (sensors) numbers(f.sensors, sensors.length, `${at}.sensors`);
    if (angles) {
      const ja = arr(f.joint_angles, `${at}.joint_angles`);
      if (ja.length !== joints.length) fail(`${at}.joint_angles`, `expected ${joints.length} joints`, ja.length);
      ja.forEach((a, i) => numbers(a, JOINT_DOFS[joints[i].type], `${at}.joint_angles[${i}]`));
    } else if (f.joint_angles !== undefined) {
      fail(`${at}.joint_angles`, 'expected none, as frame 0 has none', f.joint_angles);
    }
    if (f.props !== undefined) {
      arr(f.props, `${at}.props`);
      if (f.props.length !== props.length) fail(`${at}.props`, `expected ${props.length} poses`, f.props.length);
      f.props.forEach((p, i) => numbers(p, 7, `${at}.props[${i}]`));
    }
  });
  if (r.throw !== undefined && r.throw !== null) parseThrow(r.throw, parts.length, `${path}.throw`);
  obj(r.result, `${path}.result`);
  parseTaskResult(r.result, `${path}.result`);
  return r;
}

/**
 * Checks a catapult's throw (optional in a replay): { projectile: part index,
 * release_t: time (s) >= 0 or null when it never released, target: [x, y, z]
 * or null }.
 */
export function parseThrow(th, nParts, path = 'throw') {
  obj(th, path);
  if (int(th.projectile, `${path}.projectile`, 0) >= nParts)
    fail(`${path}.projectile`, `no such part (the creature has ${nParts})`, th.projectile);
  if (th.release_t !== null && !(isNum(th.release_t) && th.release_t >= 0))
    fail(`${path}.release_t`, 'expected a time >= 0 or null', th.release_t);
  if (th.target !== null) numbers(th.target, 3, `${path}.target`);
  return th;
}

// the task's metrics, when present: an object of numbers by name; and a
// throw's results as files before the metrics held them: D_p a number, D_t a
// number or null
function parseTaskResult(res, path) {
  if (res.metrics !== undefined) {
    obj(res.metrics, `${path}.metrics`);
    for (const [name, v] of Object.entries(res.metrics)) num(v, `${path}.metrics[${JSON.stringify(name)}]`);
  }
  if (res.throw_distance !== undefined) num(res.throw_distance, `${path}.throw_distance`);
  if (res.target_miss !== undefined && res.target_miss !== null) num(res.target_miss, `${path}.target_miss`);
}

const isId = (v) => v === null || (Number.isInteger(v) && v >= 0);

/**
 * Checks a run (null when the page is not a run's): its context, generations
 * (fitness statistics, best, evaluations, rejected and failed counts), the
 * individuals it names (each with its parents and its replay, or null when it
 * was not re-simulated) and its overall best, which must have a replay.
 */
export function parseRun(run, nReplays, path = 'run') {
  if (run === null || run === undefined) return null;
  obj(run, path);
  for (const k of ['name', 'seed', 'dialect', 'algorithm'])
    if (typeof run[k] !== 'string') fail(`${path}.${k}`, 'expected a string', run[k]);
  // (pages written before an elite's evaluations could fold to their least have none: the mean)
  if (run.evaluation_score !== undefined && !['mean', 'least'].includes(run.evaluation_score))
    fail(`${path}.evaluation_score`, 'expected "mean" or "least"', run.evaluation_score);
  for (const k of ['evaluation_half_step', 'evaluation_quarter_step'])
    if (run[k] !== undefined && typeof run[k] !== 'boolean') fail(`${path}.${k}`, 'expected true or false', run[k]);
  int(run.population, `${path}.population`, 1);
  int(run.planned_generations, `${path}.planned_generations`, 0);
  int(run.replay_cap, `${path}.replay_cap`, 0);
  arr(run.generations, `${path}.generations`).forEach((g, i) => {
    const at = `${path}.generations[${i}]`;
    obj(g, at);
    int(g.gen, `${at}.gen`, 0);
    for (const k of ['best', 'mean', 'median']) num(g[k], `${at}.${k}`);
    for (const k of ['best_id', 'evaluations', 'rejected', 'failed']) int(g[k], `${at}.${k}`, 0);
  });
  const ids = new Set();
  arr(run.members, `${path}.members`).forEach((m, i) => {
    const at = `${path}.members[${i}]`;
    obj(m, at);
    ids.add(int(m.id, `${at}.id`, 0));
    int(m.gen, `${at}.gen`, 0);
    num(m.fitness, `${at}.fitness`);
    for (const k of ['parent1', 'parent2']) if (!isId(m[k])) fail(`${at}.${k}`, 'expected an id or null', m[k]);
    if (typeof m.operator !== 'string') fail(`${at}.operator`, 'expected a string', m.operator);
    // (pages written before elites were evaluated again have none: one evaluation)
    if (m.evaluations !== undefined) int(m.evaluations, `${at}.evaluations`, 1);
    // the run's best measured where selection never looked (evolution.held_out_evaluations)
    if (m.held_out !== undefined) {
      obj(m.held_out, `${at}.held_out`);
      num(m.held_out.fitness, `${at}.held_out.fitness`);
      int(m.held_out.evaluations, `${at}.held_out.evaluations`, 1);
    }
    if (m.replay_index !== null && int(m.replay_index, `${at}.replay_index`, 0) >= nReplays)
      fail(`${at}.replay_index`, `no such replay (the page has ${nReplays})`, m.replay_index);
  });
  // every replay is one member's
  const owners = new Map();
  run.members.forEach((m, i) => {
    if (m.replay_index === null) return;
    if (owners.has(m.replay_index)) fail(`${path}.members[${i}].replay_index`, `also member ${owners.get(m.replay_index)}'s`, m.replay_index);
    owners.set(m.replay_index, i);
  });
  if (owners.size !== nReplays) fail(`${path}.members`, `expected one with each of the ${nReplays} replays`, owners.size);
  run.generations.forEach((g, i) => {
    if (!ids.has(g.best_id)) fail(`${path}.generations[${i}].best_id`, 'not among the members', g.best_id);
  });
  const best = run.members.find((m) => m.id === run.best_id);
  if (!best || best.replay_index === null) fail(`${path}.best_id`, 'expected a member with a replay', run.best_id);
  // a run of several stages: its syllabus, each stage using earlier ones (a
  // plain run, and a page written before stages, has none)
  if (run.stages !== undefined) {
    const names = new Set();
    arr(run.stages, `${path}.stages`).forEach((st, i) => {
      const at = `${path}.stages[${i}]`;
      obj(st, at);
      if (typeof st.name !== 'string' || st.name === '') fail(`${at}.name`, 'expected a name', st.name);
      if (names.has(st.name)) fail(`${at}.name`, 'given to two stages', st.name);
      arr(st.uses, `${at}.uses`).forEach((u, k) => {
        if (!names.has(u)) fail(`${at}.uses[${k}]`, 'expected an earlier stage', u);
      });
      names.add(st.name);
      if (typeof st.group !== 'string') fail(`${at}.group`, 'expected a string', st.group);
      if (int(st.generations, `${at}.generations`, 0) > 0) {
        int(st.first_gen, `${at}.first_gen`, 0);
        num(st.best, `${at}.best`);
      } else {
        for (const k of ['first_gen', 'best']) if (st[k] !== null) fail(`${at}.${k}`, 'expected null (not begun)', st[k]);
      }
    });
  }
  // `show RUN --watch`: where the run stood when the page was made, and how
  // often (s) the page asks its server whether it stores more
  if (run.watch !== undefined) {
    obj(run.watch, `${path}.watch`);
    if (typeof run.watch.stamp !== 'string' || run.watch.stamp === '') fail(`${path}.watch.stamp`, 'expected a stamp', run.watch.stamp);
    if (!(isNum(run.watch.every) && run.watch.every > 0)) fail(`${path}.watch.every`, 'expected seconds > 0', run.watch.every);
  }
  return run;
}

/**
 * Checks the page's data: { replays: [{label, replay, genome?}], run: null |
 * {...} }. Returns it with every replay checked.
 */
export function parsePageData(d) {
  obj(d, 'data');
  const replays = arr(d.replays, 'data.replays');
  if (replays.length === 0) fail('data.replays', 'expected at least one replay', replays);
  replays.forEach((e, i) => {
    obj(e, `replays[${i}]`);
    if (typeof e.label !== 'string') fail(`replays[${i}].label`, 'expected a string', e.label);
    if (e.genome !== undefined && typeof e.genome !== 'string') fail(`replays[${i}].genome`, 'expected a string', e.genome);
    parseReplay(e.replay, `replays[${i}].replay`);
  });
  return { replays, run: parseRun(d.run, replays.length) };
}
