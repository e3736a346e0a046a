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
  LocomotionScore score(cfg.task);

  const double dt = cfg.physics.dt;
  const int substeps = cfg.brain_steps_per_physics_step;
  const long n_steps = std::lround(cfg.task.seconds / dt);
  long frames = 1;  // replay frame k is the first step at or after k / fps
  std::span<double> sensor_slots(brain.values.data(), m.brain.n_sensors);

  score.observe(0, world.centre_of_mass());
  if (replay) record(m, world, brain, *replay);
  for (long step = 0; step < n_steps; ++step) {
    // sense, think, act
    world.read_sensors(m, sensor_slots);
    for (int k = 0; k < substeps; ++k) brain_step(m.brain, brain, dt / substeps);
    world.apply_effectors(m, cfg.motor, brain.effector_out);
    world.step();
    res.steps = step + 1;
    // a blown-up simulation ends the evaluation with a failing score
    if (std::string why = world.check_explosion(); !why.empty()) {
      res.failed = true;
      res.failure = "numerical explosion at t=" + std::to_string(world.time()) + " s: " + why;
      break;
    }
    score.observe(world.time(), world.centre_of_mass());
    if (replay && world.time() >= frames / cfg.replay_fps - 1e-9) {
      record(m, world, brain, *replay);
      ++frames;
    }
  }
  res.seconds = world.time();
  if (!res.failed) {
    res.distance = score.distance();
    res.fitness = res.distance;
  }
  return res;
}

}  // namespace bx
