// Checking the page's data: good data passes, bad data names the field.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { parsePageData, parseReplay, parseRun, parseThrow } from '../src/data.js';
import { makeCatapult, makeLessin, makeReplay, makeRun } from './fixture.mjs';

test('a well-formed replay passes unchanged', () => {
  const r = makeReplay();
  assert.equal(parseReplay(r), r);
});

test('errors name the field, what was expected and what was found', () => {
  const cases = [
    [(r) => (r.format = 'other'), /^replay\.format: expected "bestiary-replay", got "other"$/],
    [(r) => (r.version = 2), /^replay\.version: expected 1 .*, got 2$/],
    [(r) => (r.parts[1].shape = 'cone'), /^replay\.parts\[1\]\.shape: expected one of box, sphere, capsule, cylinder, got "cone"$/],
    [(r) => (r.parts[0].size = [1, 2]), /^replay\.parts\[0\]\.size: expected 3 numbers, got \[1,2\]$/],
    [(r) => r.frames[3].poses.pop(), /^replay\.frames\[3\]\.poses: expected 2 poses, got 1$/],
    [(r) => (r.frames[2].poses[1][6] = 'x'), /^replay\.frames\[2\]\.poses\[1\]: expected 7 numbers/],
    [(r) => (r.frames[5].t = 0), /^replay\.frames\[5\]\.t: expected a time >= 0\.4/],
    [(r) => (r.frames[0].neurons = []), /^replay\.frames\[0\]\.neurons: expected 1 numbers, got \[\]$/],
    [(r) => (r.joints[0].child = 7), /^replay\.joints\[0\]\.child: no such part, got 7$/],
    [(r) => (r.frames = []), /^replay\.frames: expected at least one frame/],
    [(r) => delete r.result, /^replay\.result: expected an object, got nothing$/],
    [(r) => r.frames[4].effectors.push(0), /^replay\.frames\[4\]\.effectors: expected 1 numbers, got \[/],
    [(r) => (r.effectors[0].joint = 3), /^replay\.effectors\[0\]\.joint: no such joint, got 3$/],
    [(r) => (r.effectors[0].hz = '30'), /^replay\.effectors\[0\]\.hz: expected a number, got "30"$/],
    [(r) => (r.sensors[1].type = 'smell'), /^replay\.sensors\[1\]\.type: expected one of joint_angle, contact, photoreceptor, muscle_length, got "smell"$/],
    [(r) => r.frames[6].sensors.pop(), /^replay\.frames\[6\]\.sensors: expected 2 numbers, got \[/],
    [(r) => (r.frames[2].joint_angles = [[0.1, 0.2]]), /^replay\.frames\[2\]\.joint_angles\[0\]: expected 1 numbers, got \[0\.1,0\.2\]$/],
    [(r) => (r.frames[2].joint_angles = []), /^replay\.frames\[2\]\.joint_angles: expected 1 joints, got 0$/],
    [(r) => delete r.frames[3].joint_angles, /^replay\.frames\[3\]\.joint_angles: expected an array, got nothing$/],
    [(r) => delete r.frames[0].joint_angles, /^replay\.frames\[1\]\.joint_angles: expected none, as frame 0 has none/],
    [(r) => (r.joints[0].type = 'weld'), /^replay\.joints\[0\]\.type: expected one of fixed, hinge/],
    [(r) => (r.joints[0].limits = [[1]]), /^replay\.joints\[0\]\.limits\[0\]: expected 2 numbers, got \[1\]$/],
    [(r) => (r.result.metrics = [1]), /^replay\.result\.metrics: expected an object, got \[1\]$/],
    [(r) => (r.result.metrics = { level: 1, 'food eaten': '2' }), /^replay\.result\.metrics\["food eaten"\]: expected a number, got "2"$/],
  ];
  for (const [spoil, message] of cases) {
    const r = makeReplay();
    spoil(r);
    assert.throws(() => parseReplay(r), { message });
  }
});

test('a replay written before sensors and joint angles were recorded passes', () => {
  const r = makeReplay();
  delete r.sensors;
  delete r.joints[0].limits;
  r.frames.forEach((f) => {
    delete f.sensors;
    delete f.joint_angles;
  });
  assert.equal(parseReplay(r), r);
});

test("a lessin2015 replay's muscles, muscle effectors and eyes' directions are read", () => {
  const r = makeLessin();
  assert.equal(parseReplay(r), r);
  assert.deepEqual(r.muscles[1], { part_a: 0, part_b: 1, anchor_a: [0.15, 0.1, 0], anchor_b: [-0.05, 0.05, 0], strength: 1000, rest_length: 0.04 });
  // a file without muscles (every other dialect's, and older files) has none
  assert.equal(parseReplay(makeReplay()).muscles, undefined);
  const cases = [
    [(x) => (x.muscles = {}), /^replay\.muscles: expected an array/],
    [(x) => (x.muscles[1].part_b = 2), /^replay\.muscles\[1\]\.part_b: no such part, got 2$/],
    [(x) => (x.muscles[0].part_a = -1), /^replay\.muscles\[0\]\.part_a: expected an integer >= 0, got -1$/],
    [(x) => (x.muscles[0].anchor_b = [0, 0]), /^replay\.muscles\[0\]\.anchor_b: expected 3 numbers, got \[0,0\]$/],
    [(x) => delete x.muscles[1].strength, /^replay\.muscles\[1\]\.strength: expected a number, got nothing$/],
    [(x) => (x.muscles[1].rest_length = '0.1'), /^replay\.muscles\[1\]\.rest_length: expected a number, got "0\.1"$/],
    [(x) => (x.effectors[0].muscle = 2), /^replay\.effectors\[0\]\.muscle: no such muscle, got 2$/],
    [(x) => delete x.muscles, /^replay\.effectors\[0\]\.muscle: no such muscle, got 1$/],
    [(x) => (x.effectors[1].muscle = 0.5), /^replay\.effectors\[1\]\.muscle: expected an integer >= 0, got 0\.5$/],
    [(x) => (x.sensors[0].direction = [0, 1]), /^replay\.sensors\[0\]\.direction: expected 3 numbers, got \[0,1\]$/],
    [(x) => (x.sensors[0].part = 5), /^replay\.sensors\[0\]\.part: no such part, got 5$/],
  ];
  for (const [spoil, message] of cases) {
    const x = makeLessin();
    spoil(x);
    assert.throws(() => parseReplay(x), { message });
  }
  // a joint effector still needs its joint and dof; an eye without a direction (older files) passes
  const x = makeLessin();
  x.effectors[0] = { dof: 0 };
  assert.throws(() => parseReplay(x), { message: /^replay\.effectors\[0\]\.joint: expected an integer >= 0, got nothing$/ });
  const old = makeLessin();
  delete old.sensors[0].direction;
  assert.equal(parseReplay(old), old);
});

test('page data holds labelled replays and an optional run', () => {
  const d = parsePageData({ replays: [{ label: 'a', replay: makeReplay() }], run: null });
  assert.equal(d.replays.length, 1);
  assert.equal(d.run, null);
  // a run whose best creatures are among the replays
  const three = [0, 1, 2].map((i) => ({ label: `g${i}`, replay: makeReplay() }));
  assert.deepEqual(parsePageData({ replays: three, run: makeRun() }).run, makeRun());
});

test('bad page data is refused with the place of the fault', () => {
  assert.throws(() => parsePageData({ replays: [] }), { message: /^data\.replays: expected at least one replay/ });
  assert.throws(() => parsePageData({ replays: [{ label: 3, replay: makeReplay() }] }), { message: /^replays\[0\]\.label: expected a string/ });
  assert.throws(() => parsePageData({ replays: [{ label: 'a', replay: makeReplay(), genome: {} }] }), { message: /^replays\[0\]\.genome: expected a string/ });
  const bad = makeReplay();
  bad.version = 9;
  assert.throws(() => parsePageData({ replays: [{ label: 'x', replay: bad }] }), { message: /^replays\[0\]\.replay\.version/ });
  // run: a member's replay that is not on the page, a curve value that is not a number
  assert.throws(() => parseRun(makeRun(), 2), { message: /^run\.members\[3\]\.replay_index: no such replay \(the page has 2\), got 2$/ });
  const spoilt = (spoil) => {
    const run = makeRun();
    spoil(run);
    return () => parseRun(run, 3);
  };
  assert.throws(spoilt((r) => (r.generations[3].mean = null)), { message: /^run\.generations\[3\]\.mean: expected a number, got null$/ });
  assert.throws(spoilt((r) => (r.seed = 1)), { message: /^run\.seed: expected a string, got 1$/ });
  assert.throws(spoilt((r) => (r.generations[1].failed = -1)), { message: /^run\.generations\[1\]\.failed: expected an integer >= 0/ });
  assert.throws(spoilt((r) => (r.members[2].parent1 = 'x')), { message: /^run\.members\[2\]\.parent1: expected an id or null/ });
  assert.throws(spoilt((r) => (r.members[0].evaluations = 0)), { message: /^run\.members\[0\]\.evaluations: expected an integer >= 1/ });
  assert.throws(spoilt((r) => (r.evaluation_score = 'median')), { message: /^run\.evaluation_score: expected "mean" or "least", got "median"$/ });
  assert.throws(spoilt((r) => (r.members[0].held_out = { fitness: 'x', evaluations: 3 })), { message: /^run\.members\[0\]\.held_out\.fitness: expected a number/ });
  assert.throws(spoilt((r) => (r.members[0].held_out = { fitness: 1, evaluations: 0 })), { message: /^run\.members\[0\]\.held_out\.evaluations: / });
  assert.throws(spoilt((r) => (r.evaluation_half_step = 'yes')), { message: /^run\.evaluation_half_step: expected true or false, got "yes"$/ });
  assert.throws(spoilt((r) => (r.evaluation_quarter_step = 1)), { message: /^run\.evaluation_quarter_step: expected true or false, got 1$/ });
  // every replay is exactly one member's, every generation's best a member, the best replayed
  assert.throws(spoilt((r) => (r.members[2].replay_index = 1)), { message: /^run\.members\[2\]\.replay_index: also member 1's/ });
  assert.throws(spoilt((r) => (r.members[1].replay_index = null)), { message: /^run\.members: expected one with each of the 3 replays, got 2$/ });
  assert.throws(spoilt((r) => (r.generations[0].best_id = 99)), { message: /^run\.generations\[0\]\.best_id: not among the members, got 99$/ });
  assert.throws(spoilt((r) => (r.best_id = 7)), { message: /^run\.best_id: expected a member with a replay, got 7$/ });
});

test('a catapult replay passes, with or without a target or a release', () => {
  for (const opts of [{}, { target: [2, 0, 0.075] }, { release: null }, { release: 0 }]) {
    const r = makeCatapult(opts);
    assert.equal(parseReplay(r), r);
    assert.equal(parseReplay(makeCatapult({ ...opts, legacy: true })).throw.projectile, 2);  // written before records
  }
  // other replays have no throw
  const r = makeReplay();
  r.throw = null;
  assert.equal(parseReplay(r), r);
});

test("an old file's bad throw names its field", () => {
  const cases = [
    [(r) => (r.throw = 3), /^replay\.throw: expected an object, got 3$/],
    [(r) => (r.throw.projectile = 3), /^replay\.throw\.projectile: no such part \(the creature has 3\), got 3$/],
    [(r) => (r.throw.projectile = -1), /^replay\.throw\.projectile: expected an integer >= 0, got -1$/],
    [(r) => (r.throw.projectile = '2'), /^replay\.throw\.projectile: expected an integer >= 0, got "2"$/],
    [(r) => (r.throw.release_t = -0.5), /^replay\.throw\.release_t: expected a time >= 0 or null, got -0\.5$/],
    [(r) => (r.throw.release_t = '0.5'), /^replay\.throw\.release_t: expected a time >= 0 or null, got "0\.5"$/],
    [(r) => delete r.throw.release_t, /^replay\.throw\.release_t: expected a time >= 0 or null, got nothing$/],
    [(r) => (r.throw.target = [1, 2]), /^replay\.throw\.target: expected 3 numbers, got \[1,2\]$/],
    [(r) => delete r.throw.target, /^replay\.throw\.target: expected 3 numbers, got nothing$/],
    [(r) => (r.result.throw_distance = null), /^replay\.result\.throw_distance: expected a number, got null$/],
    [(r) => (r.result.target_miss = 'far'), /^replay\.result\.target_miss: expected a number, got "far"$/],
  ];
  for (const [spoil, message] of cases) {
    const r = makeCatapult({ legacy: true });
    spoil(r);
    assert.throws(() => parseReplay(r), { message });
  }
  // on its own, with its own path
  assert.throws(() => parseThrow({ projectile: 0, release_t: Infinity, target: null }, 1), { message: /^throw\.release_t: / });
  // a run page names the replay
  const bad = makeCatapult({ legacy: true });
  bad.throw.projectile = 9;
  assert.throws(() => parsePageData({ replays: [{ label: 'a', replay: makeCatapult() }, { label: 'b', replay: bad }] }),
    { message: /^replays\[1\]\.replay\.throw\.projectile: no such part/ });
});
