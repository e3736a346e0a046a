#include "eval/step.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "eval/spectrum.h"

namespace bx {

EvalState::EvalState(const CreatureModel& m, const ControllerModel& c, const SimConfig& cfg,
                     std::unique_ptr<Task> t, StartPose start)
    : world(cfg.physics),
      front(axis_vector(cfg.front)),
      controller(c.make_state()),
      task(std::move(t)),
      sensor_readings(m.sensors.size(), 0.0),
      task_inputs(static_cast<std::size_t>(task->n_inputs()), 0.0),
      signal_sum(m.effectors.size(), 0.0),
      signal_sum_sq(m.effectors.size(), 0.0),
      record_signals(cfg.effector_spectrum),
      motors_off(m.effectors.size(), 0.0),
      clamp(cfg.effector_clamp.size() == 1 ? std::vector<double>(m.effectors.size(), cfg.effector_clamp[0])
                                           : cfg.effector_clamp) {
  assert(c.n_sensors() == static_cast<int>(m.sensors.size()));
  assert(c.n_effectors() == static_cast<int>(m.effectors.size()));
  assert(c.n_task_inputs() == task->n_inputs());
  assert(c.n_task_outputs() >= task->n_outputs());
  // the creature resting drop_height (+ lift) above the ground (turned by
  // `yaw` about the vertical, which keeps its height)
  const double drop = task->scenario().drop_height + start.lift;
  world.add_creature(m, {{0, 0, drop - m.min_z()}, Mat3::rotation({0, 0, 1}, start.yaw)});
  signals = motors_off;
  task->begin(WorldObservation(m, world, front));
}

namespace {

// Sense and think before a physics step: every controller step due by the
// step's end (brain_steps_due) runs, each brain.rate_hz's length, on the
// sensor readings and task inputs of now; when none is due the effectors hold.
void think(const CreatureModel& m, const SimConfig& cfg, EvalState& s, const Observation& obs) {
  const long due = brain_steps_due(s.physics_steps + 1, cfg.physics.dt, cfg.brain_hz);
  if (s.brain_steps >= due) return;
  if (!s.task->brain_on()) {  // the controller waits, its clock with it
    s.brain_waits += due - s.brain_steps;
    s.brain_steps = due;
    return;
  }
  s.world.read_sensors(m, s.sensor_readings);
  if (!s.task_inputs.empty()) s.task->inputs(obs, s.task_inputs);
  const double dt = 1.0 / cfg.brain_hz;
  for (; s.brain_steps < due; ++s.brain_steps) s.controller->step(s.sensor_readings, s.task_inputs, dt);
}

}  // namespace

bool step(const CreatureModel& m, const SimConfig& cfg, EvalState& s) {
  const WorldObservation obs(m, s.world, s.front);
  // sense, think, and what the actions do
  think(m, cfg, s, obs);
  s.task->act(m, s.controller->task_outputs(), s.world, obs);

  // act: the motors follow the controller only while the task has it on
  const bool on = s.task->controller_on();
  const bool hold = (on && cfg.hold_joints) || s.task->joints_held();
  s.signals = !on || hold ? std::span<const double>(s.motors_off)
             : s.clamp.empty() ? s.controller->effectors() : std::span<const double>(s.clamp);
  if (on) {
    // the signals' activity, for diagnostics
    for (std::size_t e = 0; e < s.signals.size(); ++e) {
      s.signal_sum[e] += s.signals[e];
      s.signal_sum_sq[e] += s.signals[e] * s.signals[e];
    }
    ++s.driven_steps;
    if (s.record_signals) s.signal_trace.insert(s.signal_trace.end(), s.signals.begin(), s.signals.end());
  }
  s.motors = hold ? EvalState::Motors::Held : on ? EvalState::Motors::Driven : EvalState::Motors::Off;
  s.world.apply_effectors(m, cfg.motor, s.signals);
  if (hold) s.world.brake_effectors(m, cfg.motor, 1);  // every joint held with all its motor's force
  else if (!on && cfg.motor.off_brake > 0) s.world.brake_effectors(m, cfg.motor, cfg.motor.off_brake);

  // step, and end a blown-up simulation with a failing score
  s.world.step();
  ++s.physics_steps;
  if (std::string why = s.world.check_explosion(); !why.empty()) {
    s.failed = true;
    s.failure = "numerical explosion at t=" + std::to_string(s.world.time()) + " s: " + why;
    return false;
  }
  s.task->observe(obs);
  return true;
}

void record_scene(const CreatureModel& m, EvalState& s, SceneRecord& out) {
  s.task->record(WorldObservation(m, s.world, s.front), out);
  s.controller->record(s.world.time(), out);
}

EvalDiagnostics diagnostics(const EvalState& s) {
  EvalDiagnostics d;
  const WorldStats& w = s.world.stats();
  d.max_joint_gap = w.max_joint_gap;
  d.worst_joint = w.worst_joint;
  d.max_stop_overshoot = w.max_stop_overshoot;
  d.max_penetration = w.max_penetration;
  if (s.driven_steps > 0) {
    const double n = static_cast<double>(s.driven_steps);
    for (std::size_t e = 0; e < s.signal_sum.size(); ++e) {
      double mean = s.signal_sum[e] / n;
      d.effector_mean.push_back(mean);
      d.effector_sd.push_back(std::sqrt(std::max(0.0, s.signal_sum_sq[e] / n - mean * mean)));
    }
  }
  if (s.record_signals) {
    const std::size_t ne = s.signal_sum.size(), steps = ne ? s.signal_trace.size() / ne : 0;
    std::vector<double> one(steps);
    for (std::size_t e = 0; e < ne; ++e) {
      for (std::size_t k = 0; k < steps; ++k) one[k] = s.signal_trace[k * ne + e];
      d.effector_hz.push_back(dominant_frequency(one, 1 / s.world.def().dt));  // one sample a step
    }
  }
  return d;
}

}  // namespace bx
