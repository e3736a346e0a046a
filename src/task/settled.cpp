#include "task/settled.h"

namespace bx {

SettledTask::SettledTask(double seconds, double drop_height, const SettleDef& settle, double dt, int n_parts)
    : phases_(settled_phases(seconds, drop_height, settle), dt, n_parts), drop_height_(drop_height) {}

void SettledTask::begin(const Observation& o) {
  phases_.begin(o);
  if (phases_.phase() == Phase::Measure) {
    measuring_ = true;
    begin_measure(o);
  }
}

void SettledTask::observe(const Observation& o) {
  const bool was_measuring = phases_.phase() == Phase::Measure;
  phases_.observe(o);
  if (was_measuring) {
    measure(o);
  } else if (phases_.phase() == Phase::Measure) {
    // the step on which settling ended: measuring begins here
    measuring_ = true;
    begin_measure(o);
  }
}

}  // namespace bx
