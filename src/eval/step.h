// The one evaluation loop: a public per-evaluation state and the step that
// advances it (model first, as MuJoCo's mj_step(model, data)). Every task
// runs in it; a replay recorder observes it.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "brain/controller.h"
#include "core/result.h"
#include "develop/creature_model.h"
#include "eval/evaluate.h"
#include "eval/sim_config.h"
#include "physics/world.h"
#include "task/task.h"

namespace bx {

/// What a task reads of the world (Observation): a view of it, each
/// quantity read when asked.
class WorldObservation : public Observation {
 public:
  WorldObservation(const CreatureModel& m, const World& w, Vec3 front = {1, 0, 0}) : m_(m), w_(w), front_(front) {}
  double time() const override { return w_.time(); }
  Vec3 centre_of_mass() const override { return w_.centre_of_mass(); }
  int n_parts() const override { return m_.n_parts(); }
  Pose part_pose(int i) const override { return w_.part_pose(i); }
  bool touches_part(int i) const override { return w_.touches_part(i); }
  double muscle_work() const override { return w_.muscle_work(); }
  bool touches_prop(int k) const override { return w_.prop_touched(k); }
  Vec3 front() const override { return front_; }

 private:
  const CreatureModel& m_;
  const World& w_;
  Vec3 front_;
};

/// How one evaluation's start differs from the task's scenario: what a
/// physics seed draws (evaluate.cpp: task.start_yaw_jitter,
/// task.start_drop_jitter).
struct StartPose {
  double yaw = 0;   ///< a turn about the vertical (rad)
  double lift = 0;  ///< added to the scenario's drop height (m)
};

/// Everything that changes during one evaluation (MuJoCo's mjData): the
/// world with the creature in it, the controller's state, the task's state
/// and the counters. Made with the creature placed on the task's scenario;
/// not copyable.
struct EvalState {
  /// The creature starts as the task's scenario says, moved by `start`,
  /// driven by a fresh state of `controller` (which must fit the creature's
  /// sensors and effectors and the task's inputs).
  EvalState(const CreatureModel& m, const ControllerModel& controller, const SimConfig& cfg,
            std::unique_ptr<Task> task, StartPose start = {});

  World world;
  Vec3 front;  ///< the creature's front in its root's frame (task.front)
  std::unique_ptr<ControllerState> controller;
  std::unique_ptr<Task> task;
  long physics_steps = 0;
  long brain_steps = 0;       ///< controller steps due, at brain.rate_hz
  long brain_waits = 0;       ///< of them, those the controller waited (the task had its brain off)
  std::vector<double> sensor_readings, task_inputs;  ///< of the last controller step
  bool failed = false;        ///< the world blew up (failure says how)
  std::string failure;
  /// What the motors did in the last step: followed `signals` (Driven), or
  /// were braked because the task had the controller off (Off: with
  /// motor.off_brake of their force, none at 0) or held every joint (Held).
  enum class Motors { Driven, Off, Held };
  Motors motors = Motors::Off;
  /// The signals the motors were given in the last step: the controller's,
  /// the diagnostic clamp, or the task's "off" zeros (all 0 before the first
  /// step).
  std::span<const double> signals;

  // the effectors' activity while the controller drove the motors
  std::vector<double> signal_sum, signal_sum_sq;
  long driven_steps = 0;
  /// Whether every driven step's signals go to signal_trace (the step's
  /// signals in turn, effector by effector), for their dominant frequencies:
  /// SimConfig::effector_spectrum, or set by a replay's recorder.
  bool record_signals = false;
  std::vector<double> signal_trace;

  // constants of the evaluation
  const std::vector<double> motors_off;
  const std::vector<double> clamp;
};

/// One physics step of the evaluation: every controller step due by the
/// step's end (sense, think), the task's act on the controller's actions, the
/// motors (the controller's signals, or held off while the task says so), the
/// physics step, the explosion test, the task's observation. False (and
/// nothing observed) once the world blew up: s.failed and s.failure say why.
bool step(const CreatureModel& m, const SimConfig& cfg, EvalState& s);

/// The scene's changes since the last call (Task::record, then
/// ControllerState::record), stamped with the world's time: what a replay
/// records before the first step and after each.
void record_scene(const CreatureModel& m, EvalState& s, SceneRecord& out);

/// What the world measured of its accuracy, and the effectors' activity
/// (their frequencies too, when recorded).
EvalDiagnostics diagnostics(const EvalState& s);

}  // namespace bx
