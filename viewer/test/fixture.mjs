// A small synthetic replay for the tests: two boxes joined by a hinge, moving
// along +x at 1 m/s for 2 s at 10 frames per second, the second part turning
// about z at 45 degrees per second, one neuron following sin(t).

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
    joints: [{ type: 'hinge', parent: 0, child: 1, anchor: [-0.15, 0, 0], axis1: [0, 0, 1], axis2: [0, 1, 0] }],
    neurons: [{ part: 0, fn: 'sin' }],
    effectors: [{ joint: 0, dof: 0 }],
    frames: out,
    result: { fitness: 2, distance: 2, failed: false, failure: '', seconds: 2, steps: 200, warnings: [] },
  };
}

/** A synthetic run: generations 0..4, fitness rising, best of 0, 2 and 4 kept. */
export function makeRun() {
  return {
    generations: [0, 1, 2, 3, 4].map((g) => ({ gen: g, best: 1 + g, mean: 0.5 + g / 2, median: 0.4 + g / 2 })),
    best_of_generation: [
      { gen: 0, replay_index: 0 },
      { gen: 4, replay_index: 2 },
      { gen: 2, replay_index: 1 },
    ],
  };
}
