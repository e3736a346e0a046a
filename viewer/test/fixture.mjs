// Small synthetic replays for the tests: two boxes joined by a hinge, moving
// along +x at 1 m/s for 2 s at 10 frames per second, the second part turning
// about z at 45 degrees per second (its hinge's angle, stops at +-2 rad), one
// neuron and the effector following sin(t), a joint-angle sensor reading the
// angle over 2 and a contact sensor always touching; a catapult throwing
// its projectile (makeCatapult), written as before replays held sensors and
// joint angles; a river crossing's scene record (makeRiver); a lessin2015
// creature with two muscles and an eye (makeLessin); fight-or-flight
// targets as the scene record's props (makeTargets); a light task's light,
// the scene record's point, 3 m away (makeLight); runs, a plain one
// (makeRun) and one of several stages (makeStagedRun); and a graph genome
// (makeGenome) with a creature grown from it whose replay holds its brain's
// wires (makeWired).

/** Quaternion [w, x, y, z] for `angle` radians about z. */
export function aboutZ(angle) {
  return [Math.cos(angle / 2), 0, 0, Math.sin(angle / 2)];
}

/** A fresh replay object (tests may change it). */
export function makeReplay({ frames = 21, dt = 0.1 } = {}) {
  const out = [];
  for (let k = 0; k < frames; ++k) {
    const t = k * dt;
    out.push({
      t,
      poses: [
        [t, 0, 0.1, 1, 0, 0, 0],
        [t + 0.3, 0, 0.1, ...aboutZ((Math.PI / 4) * t)],
      ],
      com: [t + 0.15, 0, 0.1],
      neurons: [Math.sin(t)],
      effectors: [Math.sin(t)],
      sensors: [(Math.PI / 4) * t / 2, 1],
      joint_angles: [[(Math.PI / 4) * t]],
    });
  }
  return {
    format: 'bestiary-replay',
    version: 1,
    bestiary: 'test',
    genome: 'fixture.json',
    dialect: 'sims1994',
    seed: 1,
    dt: 0.01,
    scene: { ground: { type: 'plane', z: 0, friction: 1 }, props: [] },
    parts: [
      { shape: 'box', size: [0.4, 0.2, 0.2], mass: 1, gene: 0, parent: -1, mirrored: false },
      { shape: 'capsule', size: [0.3, 0.1, 0.1], mass: 0.5, gene: 1, parent: 0, mirrored: true },
    ],
    joints: [{ type: 'hinge', parent: 0, child: 1, anchor: [-0.15, 0, 0], axis1: [0, 0, 1], axis2: [0, 1, 0], limits: [[-2, 2]] }],
    neurons: [{ part: 0, fn: 'sin' }],
    effectors: [{ joint: 0, dof: 0 }],
    sensors: [{ type: 'joint_angle', part: 1, joint: 0, dof: 0 }, { type: 'contact', part: 0, face: '-z' }],
    frames: out,
    result: { fitness: 2, distance: 2, failed: false, failure: '', seconds: 2, steps: 200, warnings: [] },
  };
}

/**
 * A synthetic run of generations 0..4 on three replays. Its line of descent:
 * #3 (random, generation 0) -> #7 (mutation, generation 1; not replayed) ->
 * #12 (crossover of #7 with #3, generation 2) -> #20 (mutation, generation 4,
 * the overall best). #12 is the best of generations 2 and 3 (an elite).
 */
export function makeRun() {
  const member = (id, gen, fitness, parent1, parent2, operator, replay_index) =>
    ({ id, gen, fitness, parent1, parent2, operator, replay_index });
  const gen = (g, best, best_id, rejected, failed) =>
    ({ gen: g, best, mean: best / 2, median: best / 2.5, best_id, evaluations: 10 * (g + 1), rejected, failed });
  return {
    name: 'quick', seed: '18446744073709551615', dialect: 'chaumont2007', algorithm: 'generational',
    population: 10, planned_generations: 6, replay_cap: 3,
    generations: [gen(0, 1, 3, 2, 0), gen(1, 2, 7, 1, 1), gen(2, 3, 12, 0, 0), gen(3, 3, 12, 4, 2), gen(4, 5, 20, 0, 0)],
    members: [
      { ...member(20, 4, 5, 12, null, 'mutation', 0), evaluations: 3 },
      member(3, 0, 1, null, null, 'random', 1),
      member(7, 1, 2, 3, null, 'mutation', null),
      member(12, 2, 3, 7, 3, 'crossover', 2),
    ],
    best_id: 20,
  };
}

/**
 * Centre of the fixture catapult's projectile at time t: carried along +x at
 * 2 m/s by the arm, then from the release at 0.5 s thrown up at 1.5 m/s
 * (g = 10) until it lands at z = 0.075, still moving along +x.
 */
export function projectileAt(t) {
  const u = Math.max(t - 0.5, 0);
  return [2 * t - 0.6, 0, Math.max(0.5 + 1.5 * u - 5 * u * u, 0.075)];
}

/**
 * A fresh catapult replay: an arm (the root) on a base, holding the
 * projectile (part 2), 1 s at 10 frames per second, released at 0.5 s;
 * `target` adds a target point, `release` changes the release (null: never).
 * Its scene record names the projectile and target and marks the release;
 * `legacy` writes it as version-1 files did before records: a `throw`, the
 * target a scene prop.
 */
export function makeCatapult({ target = null, release = 0.5, legacy = false } = {}) {
  const frames = [];
  for (let k = 0; k <= 10; ++k) {
    const t = k * 0.1;
    frames.push({
      t,
      poses: [
        [0.4, 0, 0.5, 1, 0, 0, 0],
        [0, 0, 0.2, 1, 0, 0, 0],
        [...projectileAt(t), 1, 0, 0, 0],
      ],
      com: [0.1, 0, 0.3],
      neurons: [],
      effectors: [],
    });
  }
  const props = target && legacy
    ? [{ name: 'target', shape: 'sphere', size: [0.12, 0.12, 0.12], color: '#d6336c', opacity: 0.8, pose: [...target, 1, 0, 0, 0] }]
    : [];
  const record = {
    markers: [{ name: 'begin', t: 0 }, ...(release === null ? [] : [{ name: 'release', t: release }])],
    parts: [{ name: 'projectile', part: 2, color: '#ffc61a' }],
    ...(target ? { points: [{ name: 'target', p: target, size: 0.12, color: '#d6336c' }] } : {}),
  };
  const thrown = Math.abs(projectileAt(1)[0] - projectileAt(0.5)[0]);
  return {
    format: 'bestiary-replay',
    version: 1,
    bestiary: 'test',
    genome: 'catapult.json',
    dialect: 'chaumont2007',
    seed: 1,
    dt: 0.01,
    scene: { ground: { type: 'plane', z: 0, friction: 1 }, props, ...(legacy ? {} : { record }) },
    ...(legacy ? { throw: { projectile: 2, release_t: release, target } } : {}),
    parts: [
      { shape: 'box', size: [0.8, 0.1, 0.05], mass: 4, gene: 0, parent: -1, mirrored: false },
      { shape: 'box', size: [0.8, 0.6, 0.12], mass: 57.6, gene: 1, parent: 0, mirrored: false },
      { shape: 'box', size: [0.15, 0.15, 0.15], mass: 3.375, gene: 2, parent: 0, mirrored: false },
    ],
    joints: [
      { type: 'hinge', parent: 0, child: 1, anchor: [0.4, 0, 0], axis1: [0, 1, 0], axis2: [0, 0, 1] },
      { type: 'fixed', parent: 0, child: 2, anchor: [0, 0, -0.05], axis1: [1, 0, 0], axis2: [0, 1, 0] },
    ],
    neurons: [],
    effectors: [],
    frames,
    result: {
      fitness: thrown, distance: thrown, failed: false, failure: '', seconds: 1, steps: 100, warnings: [],
      // an aim task's miss is its metric; older files held both as fields
      ...(legacy ? { throw_distance: thrown, target_miss: target ? 0.4 : null }
        : target ? { metrics: { 'target miss': 0.4 } } : {}),
    },
  };
}

/**
 * The fixture replay (makeReplay, 2 s) with a river crossing's scene record
 * on a 4 x 3 grid of 0.5 m cells from (-1, -0.5): kinds grass, stone (an
 * item), water, bridge; stones at (1, 0) and (2, 2), water down column 3.
 * At 0.5 s part 0 picks up the stone at (1, 0); at 1.5 s it puts it down on
 * (3, 1), a bridge. The field "landscape" on [-15, 15] at 0, then again at
 * 0.5 s; the counters level 1, score 0 then 1 at 1 s, deaths 0.
 */
export function makeRiver() {
  const r = makeReplay();
  delete r.dialect;
  r.creature = 'river';
  const grid = [
    0, 1, 0, 2,
    0, 0, 0, 2,
    0, 0, 1, 2,
  ];
  const field = (v) => ({ name: 'landscape', width: 4, height: 3, range: [-15, 15], values: Array.from({ length: 12 }, (_, k) => v[k] ?? 0) });
  r.scene.record = {
    cell_kinds: [
      { name: 'grass', color: '#a3c98a', item: false },
      { name: 'stone', color: '#7c838b', item: true },
      { name: 'water', color: '#3b82c4', item: false },
      { name: 'bridge', color: '#b49a7a', item: false },
    ],
    events: [
      { t: 0, grid: { origin: [-1, -0.5, 0], cell: 0.5, width: 4, height: 3, cells: grid } },
      { t: 0, counter: { name: 'level', value: 1 } },
      { t: 0, counter: { name: 'score', value: 0 } },
      { t: 0, counter: { name: 'deaths', value: 0 } },
      { t: 0, field: field([]) },
      { t: 0.5, cell: { x: 1, y: 0, kind: 0 } },
      { t: 0.5, carry: { part: 0, kind: 1 } },
      { t: 0.5, field: field({ 3: -15, 7: -15, 11: -15, 0: 15, 1: 6 }) },
      { t: 1, counter: { name: 'score', value: 1 } },
      { t: 1.5, cell: { x: 3, y: 1, kind: 3 } },
      { t: 1.5, carry: { part: 0, kind: -1 } },
    ],
  };
  return r;
}

/**
 * The fixture replay (makeReplay, 2 s) as a lessin2015 creature: part 1 a
 * 0.2 x 0.1 x 0.1 m box; muscle 0 from the root's top (0.15, 0, 0.05) to
 * part 1's (-0.05, 0, 0.05), 0.1 m long at t = 0; muscle 1 likewise on the
 * +y sides, (0.15, 0.1, 0) to (-0.05, 0.05, 0); effector 0
 * activates muscle 1 with 2 sin(t) (so clamped to [0, 1]), effector 1
 * muscle 0 with t / 2; an eye on part 1 looking along [0, 1, 1] (it reads
 * t / 4) and muscle 0's length sensor.
 */
export function makeLessin() {
  const r = makeReplay();
  r.dialect = 'lessin2015';
  r.parts[1] = { shape: 'box', size: [0.2, 0.1, 0.1], mass: 2, gene: 1, parent: 0, mirrored: false };
  r.joints[0].anchor = [-0.1, 0, 0];
  r.muscles = [
    { part_a: 0, part_b: 1, anchor_a: [0.15, 0, 0.05], anchor_b: [-0.05, 0, 0.05], strength: 2000, rest_length: 0.05 },
    { part_a: 0, part_b: 1, anchor_a: [0.15, 0.1, 0], anchor_b: [-0.05, 0.05, 0], strength: 1000, rest_length: 0.04 },
  ];
  r.effectors = [{ muscle: 1, hz: 0.159 }, { muscle: 0 }];
  r.sensors = [{ type: 'photoreceptor', part: 1, direction: [0, 1, 1] }, { type: 'muscle_length', part: 1, muscle: 0 }];
  r.frames.forEach((f) => {
    f.effectors = [2 * Math.sin(f.t), f.t / 2];
    f.sensors = [f.t / 4, 0.5];
  });
  return r;
}

/** Quaternion [w, x, y, z] turning a prop's axis (its x) up: -90 degrees about y. */
export const AXIS_UP = [Math.SQRT1_2, 0, -Math.SQRT1_2, 0];

/**
 * The fixture replay (makeReplay, 2 s) with fight-or-flight targets, its
 * scene record's props, from 0.5 s: a disc lying on the ground at (1, 1)
 * (a cylinder 0.02 m long and 0.6 m across, its axis up) and on it a stack
 * (a cylinder 0.3 m tall and 0.1 m across) turning at 2 rad/s.
 */
export function makeTargets() {
  const r = makeReplay();
  r.scene.record = {
    props: [
      { name: 'disc', shape: 'cylinder', size: [0.02, 0.6, 0.6], pose: [1, 1, 0.01, ...AXIS_UP], spin: 0, t: 0.5, color: '#3b82c4' },
      { name: 'stack', shape: 'cylinder', size: [0.3, 0.1, 0.1], pose: [1, 1, 0.17, ...AXIS_UP], spin: 2, t: 0.5, color: '#e8590c' },
    ],
  };
  return r;
}

/**
 * The fixture replay (makeReplay, 2 s) with a light task's light: the scene
 * record's point "light", 0.2 m across, placed as the task places it
 * (light.distance and light.height, 3 m and 0.5 m by default): `distance`
 * on the ground from the centre of mass at t = 0 (0.15, 0, 0.1) at `bearing`
 * degrees from the creature's way (+x, counterclockwise), `height` above the
 * ground.
 */
export function makeLight(bearing = 90, { distance = 3, height = 0.5 } = {}) {
  const r = makeReplay();
  const a = (bearing * Math.PI) / 180;
  const p = [0.15 + distance * Math.cos(a), distance * Math.sin(a), height];
  r.scene.record = { markers: [{ name: 'light on', t: 0 }], points: [{ name: 'light', p, size: 0.2, color: '#ffd200' }] };
  return r;
}

/**
 * A synthetic run of four stages (lessin2015's syllabus in small): forward
 * (generations 0-2), left (3-4, pandemonium group turn), face (5-7, group
 * aim, using forward and left) and fight (using face; not begun). Each
 * generation's best is a member of its own, replayed, the first parent the
 * last generation's; each stage's fitness on a scale of its own.
 */
export function makeStagedRun() {
  const bests = [1, 2, 3, 10, 12, 0.1, 0.2, 0.3];
  return {
    name: 'lessin2015-small', seed: '1', dialect: 'lessin2015', algorithm: 'generational',
    population: 10, planned_generations: 10, replay_cap: 8,
    generations: bests.map((best, g) =>
      ({ gen: g, best, mean: best / 2, median: best / 2, best_id: g + 1, evaluations: 10 * (g + 1), rejected: 0, failed: 0 })),
    members: bests.map((fitness, g) => ({ id: g + 1, gen: g, fitness, parent1: g ? g : null, parent2: null,
      operator: g ? 'mutation' : 'random', replay_index: g })),
    best_id: 8,
    stages: [
      { name: 'forward', uses: [], group: '', first_gen: 0, generations: 3, best: 3 },
      { name: 'left', uses: [], group: 'turn', first_gen: 3, generations: 2, best: 12 },
      { name: 'face', uses: ['forward', 'left'], group: 'aim', first_gen: 5, generations: 3, best: 0.3 },
      { name: 'fight', uses: ['face'], group: '', first_gen: null, generations: 0, best: null },
    ],
  };
}

/**
 * A graph genome (parsed), as docs/genome-format.md writes it: gene 0 a box
 * of recursive limit 3 with a sum neuron and a joint-angle sensor, its edge
 * 0 to itself (recursion, scale 0.8), edge 1 to gene 1 reflected across y,
 * edge 2 to gene 1 terminal-only (and no `reflect` written); gene 1 a
 * capsule with two neurons, a contact sensor and an effector; one global
 * neuron.
 */
export function makeGenome() {
  return {
    format: 'bestiary-genome', version: 1, dialect: 'sims1994',
    global_neurons: [{ fn: 'oscillate-wave', params: { freq: 1 } }],
    nodes: [
      {
        shape: 'box', size: [0.3, 0.2, 0.1], recursive_limit: 3,
        neurons: [{ fn: 'sum', inputs: [{ from: 'global', neuron: 0 }] }],
        sensors: [{ type: 'joint_angle', dof: 0 }],
        edges: [
          { to: 0, face: '+x', scale: 0.8, reflect: [], terminal_only: false },
          { to: 1, face: '+y', reflect: ['y'] },
          { to: 1, face: '+x', terminal_only: true },
        ],
      },
      {
        shape: 'capsule', size: [0.3, 0.05, 0.05],
        neurons: [{ fn: 'sin' }, { fn: 'sum' }],
        sensors: [{ type: 'contact', face: '-z' }],
        effectors: [{ dof: 0 }],
      },
    ],
  };
}

/**
 * A replay (makeReplay, 2 s) of a creature of four parts holding its brain's
 * wires: parts 0 and 1 of gene 0 (1 by recursion), 2 and 3 of gene 1 (3
 * mirrored) on part 1, by joints 0 (0-1), 1 (1-2) and 2 (1-3). Sensors: 0 the
 * angle of joint 0 (part 1), 1 and 2 contacts of parts 2 and 3. Neurons: 0
 * global; 1 on part 0 reading neuron 0 (slot 3); 2 on part 2 reading sensor 1
 * (weight -2); 3 on part 3 reading sensor 2 and, gated by neuron 0 (slot 3),
 * neuron 2 (slot 5). Effectors: 0 drives joint 1 (part 2) from neuron 2, 1
 * joint 2 (part 3) from neuron 3, 2 joint 0 (part 1) from sensor 0 and from
 * slot 99, which the brain lacks. Neuron 1 reaches 3 once (at 1 s).
 */
export function makeWired() {
  const r = makeReplay();
  const box = (gene, parent, mirrored = false) => ({ shape: gene ? 'capsule' : 'box', size: [0.3, 0.1, 0.1], mass: 1, gene, parent, mirrored });
  r.parts = [box(0, -1), box(0, 0), box(1, 1), box(1, 1, true)];
  const hinge = (parent, child) => ({ type: 'hinge', parent, child, anchor: [-0.15, 0, 0], axis1: [0, 0, 1], axis2: [0, 1, 0], limits: [[-1, 1]] });
  r.joints = [hinge(0, 1), hinge(1, 2), hinge(1, 3)];
  r.sensors = [
    { type: 'joint_angle', part: 1, joint: 0, dof: 0 },
    { type: 'contact', part: 2, face: '-z' },
    { type: 'contact', part: 3, face: '-z' },
  ];
  r.neurons = [
    { part: -1, fn: 'oscillate-wave', bias: 0, inputs: [] },
    { part: 0, fn: 'sum', bias: 0, inputs: [[3, 0.5]] },
    { part: 2, fn: 'sin', bias: 0, inputs: [[1, -2]] },
    { part: 3, fn: 'sin', bias: 0.25, inputs: [[2, -2], [5, 1, 3]] },
  ];
  r.effectors = [
    { joint: 1, dof: 0, bias: 0, inputs: [[5, 1.5]] },
    { joint: 2, dof: 0, bias: 0, inputs: [[6, 1.5]] },
    { joint: 0, dof: 0, bias: 0, inputs: [[0, 0.25], [99, 1]] },
  ];
  r.frames.forEach((f, k) => {
    f.poses = [f.poses[0], f.poses[1], f.poses[1], f.poses[1]];
    f.neurons = [Math.sin(f.t), k === 10 ? 3 : 0.5, -0.5, 0.25];
    f.sensors = [0.1, 1, -1];
    f.effectors = [0.5, -0.5, 0];
    f.joint_angles = [[0], [0], [0]];
  });
  return r;
}
