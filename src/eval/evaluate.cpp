#include "eval/evaluate.h"

#include <cmath>

#include "brain/brain_model.h"
#include "core/rng.h"
#include "physics/world.h"

namespace bx {

namespace {

void record(const CreatureModel& m, const World& w, const BrainState& bs, Replay& r) {
  ReplayFrame f;
  f.t = w.time();
  f.poses.reserve(7 * m.parts.size());
  for (int i = 0; i < m.n_parts(); ++i) {
    Pose p = w.part_pose(i);
    Quat q = to_quat(p.R);
    f.poses.insert(f.poses.end(), {p.p.x, p.p.y, p.p.z, q.w, q.x, q.y, q.z});
  }
  f.neurons.assign(bs.values.begin() + m.brain.n_sensors, bs.values.end());
  f.effectors = bs.effector_out;
  // the readings the brain took before its last step (0 before its first)
  f.sensors.assign(bs.values.begin(), bs.values.begin() + m.brain.n_sensors);
  for (int j = 0; j < static_cast<int>(m.joints.size()); ++j)
    for (int d = 0; d < joint_dofs(m.joints[j].type); ++d) f.joint_angles.push_back(w.joint_position(j, d));
  f.com = w.centre_of_mass();
  r.frames.push_back(std::move(f));
}

// What every task's evaluation shares: the world with the creature dropped
// onto the ground, its brain, the sense-think-act step with the explosion
// test, and the replay frames.
class Simulation {
 public:
  Simulation(const CreatureModel& m, const SimConfig& cfg, double drop_height, Replay* replay)
      : m_(m),
        cfg_(cfg),
        world_(cfg.physics),
        brain_(make_brain_state(m.brain)),
        replay_(replay),
        motors_off_(m.effectors.size(), 0.0) {
    // the creature resting drop_height above the ground
    world_.add_creature(m, {{0, 0, drop_height - m.min_z()}, Mat3::identity()});
    if (replay_) record(m_, world_, brain_, *replay_);
  }

  World& world() { return world_; }
  const BrainState& brain() const { return brain_; }

  /// Sense and think: sensor readings in, one physics step's worth of brain steps.
  void think() {
    world_.read_sensors(m_, std::span<double>(brain_.values.data(), m_.brain.n_sensors));
    const int substeps = cfg_.brain_steps_per_physics_step;
    for (int k = 0; k < substeps; ++k) brain_step(m_.brain, brain_, cfg_.physics.dt / substeps);
  }

  /// Act and step the physics (the motors follow the brain only when
  /// `controller_on`); false, with res.failed set, if the world blew up.
  bool act_and_step(bool controller_on, EvalResult& res) {
    world_.apply_effectors(m_, cfg_.motor, controller_on ? brain_.effector_out : motors_off_);
    world_.step();
    ++res.steps;
    // a blown-up simulation ends the evaluation with a failing score
    if (std::string why = world_.check_explosion(); !why.empty()) {
      res.failed = true;
      res.failure = "numerical explosion at t=" + std::to_string(world_.time()) + " s: " + why;
      return false;
    }
    // replay frame k is the first step at or after k / fps
    if (replay_ && world_.time() >= frames_ / cfg_.replay_fps - 1e-9) {
      record(m_, world_, brain_, *replay_);
      ++frames_;
    }
    return true;
  }

 private:
  const CreatureModel& m_;
  const SimConfig& cfg_;
  World world_;
  BrainState brain_;
  Replay* replay_;
  long frames_ = 1;
  const std::vector<double> motors_off_;
};

EvalResult evaluate_locomotion(const CreatureModel& m, const SimConfig& cfg, EvalResult res,
                               Replay* replay) {
  const LocomotionDef& td = cfg.task;
  Simulation sim(m, cfg, td.drop_height, replay);
  World& world = sim.world();
  const double dt = cfg.physics.dt;
  LocomotionTask task(td, dt, m.n_parts());

  // the task ends the evaluation; this only bounds it
  double longest = td.activation == Activation::Chaumont2007
                       ? 2 * td.settle_timeout + td.burst_seconds + td.seconds
                       : td.seconds;
  const long max_steps = std::lround(longest / dt) + 1;
  std::vector<Vec3> parts(task.needs_parts() ? m.n_parts() : 0);
  auto part_positions = [&]() -> const std::vector<Vec3>& {
    for (std::size_t i = 0; i < parts.size(); ++i) parts[i] = world.part_pose(static_cast<int>(i)).p;
    return parts;
  };

  task.start(world.centre_of_mass(), part_positions());
  for (long step = 0; step < max_steps && !task.done(); ++step) {
    // sense, think, act (the task may hold the motors off)
    sim.think();
    if (!sim.act_and_step(task.controller_on(), res)) break;
    task.observe(world.time(), world.centre_of_mass(), part_positions());
  }
  res.seconds = world.time();
  res.note = task.note();
  if (!res.failed) {
    res.distance = task.distance();
    res.fitness = task.fitness(m);
  }
  return res;
}

EvalResult evaluate_throwing(const CreatureModel& m, const SimConfig& cfg, EvalResult res,
                             Replay* replay) {
  const ThrowingDef& td = cfg.throwing;
  if (m.projectile < 0) {
    res.note = "not a catapult: the throwing task needs a genome with a catapult block";
    return res;
  }
  Simulation sim(m, cfg, td.drop_height, replay);
  World& world = sim.world();
  const double dt = cfg.physics.dt;
  ThrowingTask task(td, dt);
  if (replay) {
    replay->projectile = m.projectile;
    if (td.fitness == ThrowFitness::Aim) replay->target = td.target;
  }

  // the controller drives the motors throughout (4.4: no activation sequence);
  // the evaluation ends when the projectile rests after its release
  const long max_steps = std::lround(td.seconds / dt);
  for (long step = 0; step < max_steps && !task.done(); ++step) {
    sim.think();
    // the release effector breaks the arm-projectile joint before this step
    if (!task.released() && sim.brain().release_out >= ReleaseGene::kFiringThreshold) {
      world.break_joint(m.release_joint);
      task.release(world.time(), world.part_pose(m.projectile).p);
    }
    if (!sim.act_and_step(true, res)) break;
    task.observe(world.time(), world.part_pose(m.projectile).p);
  }
  res.seconds = world.time();
  res.note = task.note();
  res.release_time = task.release_time();
  if (replay) replay->release_time = task.release_time();
  if (!res.failed) {
    res.distance = task.distance();
    if (td.fitness == ThrowFitness::Aim) res.target_miss = task.target_miss();
    res.fitness = task.fitness();
  }
  return res;
}

EvalResult evaluate_once(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed,
                         Replay* replay) {
  EvalResult res;
  res.warnings = m.warnings;
  reseed_physics(seed);
  switch (cfg.task_kind) {
    case TaskKind::Locomotion: return evaluate_locomotion(m, cfg, std::move(res), replay);
    case TaskKind::Throwing: return evaluate_throwing(m, cfg, std::move(res), replay);
  }
  return res;
}

}  // namespace

// the stream of trial seeds (evolution.cpp's streams are 1-4)
constexpr std::uint64_t kTrialStream = 5;

std::uint64_t trial_seed(std::uint64_t seed, int trial) {
  return trial == 0 ? seed : stream_seed({seed, kTrialStream, static_cast<std::uint64_t>(trial)});
}

EvalResult evaluate(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed,
                    Replay* replay) {
  EvalResult res = evaluate_once(m, cfg, seed, replay);
  if (cfg.trials <= 1) return res;
  // the first trial is the one a replay shows and the one distance, release
  // and target miss describe; the others only score
  res.trial_fitness = {res.fitness};
  double fitness = res.fitness;
  for (int k = 1; k < cfg.trials; ++k) {
    EvalResult t = evaluate_once(m, cfg, trial_seed(seed, k), nullptr);
    res.trial_fitness.push_back(t.fitness);
    fitness += t.fitness;
    res.steps += t.steps;
    if (t.failed && !res.failed) {
      res.failed = true;
      res.failure = "trial " + std::to_string(k + 1) + " of " + std::to_string(cfg.trials) + ": " +
                    t.failure;
    }
  }
  // a creature that blows up in any trial is discarded (5.4), as in one
  res.fitness = res.failed ? 0 : fitness / cfg.trials;
  return res;
}

}  // namespace bx
