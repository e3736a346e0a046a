#include "eval/evaluate.h"

#include <cmath>

#include "brain/brain_model.h"
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
  f.com = w.centre_of_mass();
  r.frames.push_back(std::move(f));
}

}  // namespace

EvalResult evaluate(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed,
                    Replay* replay) {
  EvalResult res;
  res.warnings = m.warnings;
  reseed_physics(seed);

  // world with the creature resting drop_height above the ground
  World world(cfg.physics);
  Pose placement{{0, 0, cfg.task.drop_height - m.min_z()}, Mat3::identity()};
  world.add_creature(m, placement);
  BrainState brain = make_brain_state(m.brain);
  const double dt = cfg.physics.dt;
  LocomotionTask task(cfg.task, dt, m.n_parts());

  const int substeps = cfg.brain_steps_per_physics_step;
  // the task ends the evaluation; this only bounds it
  const LocomotionDef& td = cfg.task;
  double longest = td.activation == Activation::Chaumont2007
                       ? 2 * td.settle_timeout + td.burst_seconds + td.seconds
                       : td.seconds;
  const long max_steps = std::lround(longest / dt) + 1;
  long frames = 1;  // replay frame k is the first step at or after k / fps
  std::span<double> sensor_slots(brain.values.data(), m.brain.n_sensors);
  const std::vector<double> motors_off(m.effectors.size(), 0.0);
  std::vector<Vec3> parts(task.needs_parts() ? m.n_parts() : 0);
  auto part_positions = [&]() -> const std::vector<Vec3>& {
    for (std::size_t i = 0; i < parts.size(); ++i) parts[i] = world.part_pose(static_cast<int>(i)).p;
    return parts;
  };

  task.start(world.centre_of_mass(), part_positions());
  if (replay) record(m, world, brain, *replay);
  for (long step = 0; step < max_steps && !task.done(); ++step) {
    // sense, think, act (the task may hold the motors off)
    world.read_sensors(m, sensor_slots);
    for (int k = 0; k < substeps; ++k) brain_step(m.brain, brain, dt / substeps);
    world.apply_effectors(m, cfg.motor, task.controller_on() ? brain.effector_out : motors_off);
    world.step();
    res.steps = step + 1;
    // a blown-up simulation ends the evaluation with a failing score
    if (std::string why = world.check_explosion(); !why.empty()) {
      res.failed = true;
      res.failure = "numerical explosion at t=" + std::to_string(world.time()) + " s: " + why;
      break;
    }
    task.observe(world.time(), world.centre_of_mass(), part_positions());
    if (replay && world.time() >= frames / cfg.replay_fps - 1e-9) {
      record(m, world, brain, *replay);
      ++frames;
    }
  }
  res.seconds = world.time();
  res.note = task.note();
  if (!res.failed) {
    res.distance = task.distance();
    res.fitness = task.fitness(m);
  }
  return res;
}

}  // namespace bx
