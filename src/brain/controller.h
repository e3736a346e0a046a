// A controller: what turns sensor readings (and a task's inputs) into
// effector signals (and outputs for the task), as the evaluation loop
// (eval/step.h) sees it.
// Like the creature, it comes in two halves: a model, immutable and shared by
// every evaluation, and its per-evaluation state. Sims' graph brain
// (GraphBrain, below) is one implementation; a controller over a fixed body
// (the river crossing's layered networks) is another, and neither touches
// the other.
#pragma once

#include <memory>
#include <span>

#include "brain/brain_model.h"
#include "core/scene_record.h"

namespace bx {

/// A controller's state during one evaluation.
class ControllerState {
 public:
  virtual ~ControllerState() = default;
  /// One controller step of `dt` seconds on these readings: the body's
  /// sensors (model's n_sensors) and the task's inputs (n_task_inputs).
  virtual void step(std::span<const double> sensors, std::span<const double> task_inputs, double dt) = 0;
  /// The effector signals in [-1, 1], one per effector (0 before the first
  /// step); valid until the next step.
  virtual std::span<const double> effectors() const = 0;
  /// What it asks of the task beside the effector signals, one value per
  /// task output (the model's n_task_outputs: a catapult's release, a river
  /// crossing's pick-up or put-down), 0 before the first step; valid until
  /// the next step. Task inputs' mirror: the task says what each means.
  virtual std::span<const double> task_outputs() const { return {}; }
  /// The sensor readings of its last step (0 before the first), for replays.
  virtual std::span<const double> sensors() const = 0;
  /// Its internal signals (a graph brain's neuron outputs), for replays.
  virtual std::span<const double> internals() const = 0;
  /// What a replay shows of it in the scene (core/scene_record.h: the river
  /// crossing's landscape, a field over the task's grid): appends to `out`
  /// what changed since the last call, stamped `t` (s). The loop calls it
  /// while it records a replay, before the first step and after every step.
  virtual void record(double t, SceneRecord& out) {}
};

/// A compiled controller: its shape and the state it starts from.
class ControllerModel {
 public:
  virtual ~ControllerModel() = default;
  virtual int n_sensors() const = 0;
  virtual int n_effectors() const = 0;
  /// Inputs it takes from the task beside the body's sensors.
  virtual int n_task_inputs() const { return 0; }
  /// Outputs it gives the task beside the effector signals (ControllerState::task_outputs).
  virtual int n_task_outputs() const { return 0; }
  /// A fresh state for one evaluation.
  virtual std::unique_ptr<ControllerState> make_state() const = 0;
};

/// Sims' graph brain (brain_model.h) as a controller: each step writes the
/// readings into its sensor slots and runs brain_step. Its task outputs are
/// the brain's latches (BrainModel::task_output_*: a catapult's release,
/// which fires once, chaumont2007 4.1).
/// Holds a reference to the brain, which must outlive it and its states.
class GraphBrain : public ControllerModel {
 public:
  explicit GraphBrain(const BrainModel& m) : m_(m) {}
  int n_sensors() const override { return m_.n_sensors; }
  int n_effectors() const override { return m_.n_effectors(); }
  int n_task_outputs() const override { return m_.n_task_outputs(); }
  std::unique_ptr<ControllerState> make_state() const override;

 private:
  const BrainModel& m_;
};

}  // namespace bx
