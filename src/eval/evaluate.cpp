#include "eval/evaluate.h"

#include <algorithm>
#include <cmath>

#include "brain/brain_model.h"
#include "core/rng.h"
#include "geometry/ode.h"  // PhysicsFault
#include "physics/world.h"

namespace bx {

namespace {

// the stream of start poses (evolution.cpp's streams are 1-4, trials' 5, checks' 6)
constexpr std::uint64_t kStartStream = 7;

// `signals`: what the motors were given (the brain's outputs, or 0 while the
// task holds the motors off, or the diagnostic clamp)
void record(const CreatureModel& m, const World& w, const BrainState& bs,
            const std::vector<double>& signals, Replay& r) {
  ReplayFrame f;
  f.t = w.time();
  f.poses.reserve(7 * m.parts.size());
  for (int i = 0; i < m.n_parts(); ++i) {
    Pose p = w.part_pose(i);
    Quat q = to_quat(p.R);
    f.poses.insert(f.poses.end(), {p.p.x, p.p.y, p.p.z, q.w, q.x, q.y, q.z});
  }
  f.neurons.assign(bs.values.begin() + m.brain.n_sensors, bs.values.end());
  f.effectors = signals;
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
  Simulation(const CreatureModel& m, const SimConfig& cfg, double drop_height, double yaw, Replay* replay)
      : m_(m),
        cfg_(cfg),
        world_(cfg.physics),
        brain_(make_brain_state(m.brain)),
        replay_(replay),
        motors_off_(m.effectors.size(), 0.0),
        clamp_(cfg.effector_clamp.size() == 1
                   ? std::vector<double>(m.effectors.size(), cfg.effector_clamp[0])
                   : cfg.effector_clamp),
        sum_(m.effectors.size(), 0.0),
        sum_sq_(m.effectors.size(), 0.0) {
    // the creature resting drop_height above the ground
    // (turned by `yaw` about the vertical, which keeps its height)
    world_.add_creature(m, {{0, 0, drop_height - m.min_z()}, Mat3::rotation({0, 0, 1}, yaw)});
    if (replay_) record(m_, world_, brain_, motors_off_, *replay_);
  }

  World& world() { return world_; }
  const BrainState& brain() const { return brain_; }

  /// Sense and think before a physics step: every brain step due by the
  /// step's end (brain_steps_due) runs, each brain.rate_hz's length, on the
  /// sensor readings of now; when none is due the effectors hold.
  void think() {
    const long due = brain_steps_due(physics_steps_ + 1, cfg_.physics.dt, cfg_.brain_hz);
    if (brain_steps_ >= due) return;
    world_.read_sensors(m_, std::span<double>(brain_.values.data(), m_.brain.n_sensors));
    for (; brain_steps_ < due; ++brain_steps_) {
      brain_step(m_.brain, brain_, brain_dt_);
      // the release fires at the first brain step whose signal reaches the threshold
      if (m_.brain.has_release() && brain_.release_out >= ReleaseGene::kFiringThreshold)
        release_fired_ = true;
    }
  }

  /// True once a brain step's release signal has reached the firing threshold.
  bool release_fired() const { return release_fired_; }

  /// Act and step the physics (the motors follow the brain only when
  /// `controller_on`); false, with res.failed set, if the world blew up.
  bool act_and_step(bool controller_on, EvalResult& res) {
    const std::vector<double>& signals =
        !controller_on ? motors_off_ : clamp_.empty() ? brain_.effector_out : clamp_;
    if (controller_on) {
      // the signals' activity, for diagnostics
      for (std::size_t e = 0; e < signals.size(); ++e) {
        sum_[e] += signals[e];
        sum_sq_[e] += signals[e] * signals[e];
      }
      ++driven_steps_;
    }
    world_.apply_effectors(m_, cfg_.motor, signals);
    if (!controller_on && cfg_.motor.off_brake > 0) world_.brake_effectors(m_, cfg_.motor);
    world_.step();
    ++physics_steps_;
    ++res.steps;
    res.brain_steps = brain_steps_;
    // a blown-up simulation ends the evaluation with a failing score
    if (std::string why = world_.check_explosion(); !why.empty()) {
      res.failed = true;
      res.failure = "numerical explosion at t=" + std::to_string(world_.time()) + " s: " + why;
      return false;
    }
    // replay frame k is the first step at or after k / fps
    if (replay_ && world_.time() >= frames_ / cfg_.replay_fps - 1e-9) {
      record(m_, world_, brain_, signals, *replay_);
      ++frames_;
    }
    return true;
  }

  /// What the world measured of its accuracy, and the effectors' activity.
  EvalDiagnostics diagnostics() const {
    EvalDiagnostics d;
    const WorldStats& s = world_.stats();
    d.max_joint_gap = s.max_joint_gap;
    d.worst_joint = s.worst_joint;
    d.max_stop_overshoot = s.max_stop_overshoot;
    d.max_penetration = s.max_penetration;
    if (driven_steps_ > 0) {
      const double n = static_cast<double>(driven_steps_);
      for (std::size_t e = 0; e < sum_.size(); ++e) {
        double mean = sum_[e] / n;
        d.effector_mean.push_back(mean);
        d.effector_sd.push_back(std::sqrt(std::max(0.0, sum_sq_[e] / n - mean * mean)));
      }
    }
    return d;
  }

 private:
  const CreatureModel& m_;
  const SimConfig& cfg_;
  World world_;
  BrainState brain_;
  Replay* replay_;
  long frames_ = 1;
  const std::vector<double> motors_off_;
  const std::vector<double> clamp_;
  std::vector<double> sum_, sum_sq_;
  long driven_steps_ = 0;
  const double brain_dt_ = 1.0 / cfg_.brain_hz;
  long physics_steps_ = 0, brain_steps_ = 0;
  bool release_fired_ = false;
};

EvalResult evaluate_locomotion(const CreatureModel& m, const SimConfig& cfg, double yaw, EvalResult res,
                               Replay* replay) {
  const LocomotionDef& td = cfg.task;
  Simulation sim(m, cfg, td.drop_height, yaw, replay);
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
  res.diagnostics = sim.diagnostics();
  if (!res.failed) {
    res.distance = task.distance();
    res.fitness = task.fitness(m);
  }
  return res;
}

EvalResult evaluate_throwing(const CreatureModel& m, const SimConfig& cfg, double yaw, EvalResult res,
                             Replay* replay) {
  const ThrowingDef& td = cfg.throwing;
  if (m.projectile < 0) {
    res.note = "not a catapult: the throwing task needs a genome with a catapult block";
    return res;
  }
  Simulation sim(m, cfg, td.drop_height, yaw, replay);
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
    if (!task.released() && sim.release_fired()) {
      world.break_joint(m.release_joint);
      task.release(world.time(), world.part_pose(m.projectile).p);
    }
    if (!sim.act_and_step(true, res)) break;
    task.observe(world.time(), world.part_pose(m.projectile).p);
  }
  res.seconds = world.time();
  res.note = task.note();
  res.diagnostics = sim.diagnostics();
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
  // the seed's start: a turn within +-start_yaw_jitter degrees
  Rng start(stream_seed({seed, kStartStream}));
  const double yaw = start.uniform(-1, 1) * cfg.start_yaw_jitter * kPi / 180;
  try {
    switch (cfg.task_kind) {
      case TaskKind::Locomotion: return evaluate_locomotion(m, cfg, yaw, res, replay);
      case TaskKind::Throwing: return evaluate_throwing(m, cfg, yaw, res, replay);
    }
  } catch (const PhysicsFault& e) {
    // ODE gave up inside a step (its world is gone with the Simulation):
    // a failed evaluation, as an explosion is; the replay keeps its frames
    res.failed = true;
    res.failure = e.what();
  }
  return res;
}

}  // namespace

long brain_steps_due(long physics_steps, double dt, double brain_hz) {
  // the count of k >= 0 with k < physics_steps * dt * brain_hz, less a millionth
  return static_cast<long>(std::ceil(static_cast<double>(physics_steps) * dt * brain_hz - 1e-6));
}

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
  double fitness = res.fitness, least = res.fitness;
  for (int k = 1; k < cfg.trials; ++k) {
    EvalResult t = evaluate_once(m, cfg, trial_seed(seed, k), nullptr);
    res.trial_fitness.push_back(t.fitness);
    fitness += t.fitness;
    least = std::min(least, t.fitness);
    res.steps += t.steps;
    res.brain_steps += t.brain_steps;
    if (t.failed && !res.failed) {
      res.failed = true;
      res.failure = "trial " + std::to_string(k + 1) + " of " + std::to_string(cfg.trials) + ": " +
                    t.failure;
    }
  }
  // a creature that blows up in any trial is discarded (5.4), as in one
  res.fitness = res.failed ? 0 : cfg.trial_score == TrialScore::Min ? least : fitness / cfg.trials;
  return res;
}

}  // namespace bx
