// The phases every lessin2015 skill's task shares (turn, strike, light,
// high reach): as its forward locomotion (task.activation = "settled"), the
// creature first settles with its controller off, then is measured for a
// span with it on. A SettledTask drives a LocomotionTask of those phases
// (settled_phases) and hands its task the moment measuring begins and each
// measured observation after it, so each task holds only what it measures.
#pragma once

#include <string>

#include "task/locomotion.h"
#include "task/task.h"

namespace bx {

class SettledTask : public Task {
 public:
  /// Settling as `settle` says, then `seconds` measured; the creature
  /// dropped from `drop_height` (m).
  SettledTask(double seconds, double drop_height, const SettleDef& settle, double dt, int n_parts);

  Scenario scenario() const override { return {drop_height_}; }
  /// The settling timeout and the measured span, and a step.
  long max_steps() const override { return phases_.max_steps(); }
  /// Calls begin_measure() if measuring begins at once (nothing to settle).
  void begin(const Observation& o) final;
  /// Calls begin_measure() on the observation on which settling ended,
  /// measure() on every measured one after it.
  void observe(const Observation& o) final;
  bool controller_on() const override { return phases_.controller_on(); }
  bool done() const override { return phases_.done(); }
  /// Why the score is 0 by rule: never settled.
  std::string note() const override { return phases_.note(); }
  Phase phase() const { return phases_.phase(); }
  /// Whether measuring has begun.
  bool measuring() const { return measuring_; }
  double measured_seconds() const { return phases_.measured_seconds(); }

 protected:
  /// Once, with the observation on which measuring begins.
  virtual void begin_measure(const Observation& o) = 0;
  /// After every measured step but that one.
  virtual void measure(const Observation& o) = 0;
  /// The phases (their travel, their muscle work while measured).
  const LocomotionTask& phases() const { return phases_; }

 private:
  LocomotionTask phases_;
  double drop_height_;
  bool measuring_ = false;
};

}  // namespace bx
