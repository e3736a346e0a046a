#include "task/strike.h"

#include <algorithm>
#include <cmath>

namespace bx {

ImpactMeter::ImpactMeter(double window, double threshold, double dt)
    : threshold_(threshold), dt_(dt), half_(std::max(1, static_cast<int>(std::lround(window / dt / 2)))) {}

void ImpactMeter::start(double t, double z) {
  z_.assign(1, z);
  peak_ = 0;
  peak_t_ = t;
  first_ = -1;
}

void ImpactMeter::observe(double t, double z) {
  z_.push_back(z);
  if (static_cast<int>(z_.size()) > 2 * half_ + 1) z_.erase(z_.begin());
  if (static_cast<int>(z_.size()) < 2 * half_ + 1) return;  // a whole window first
  // the mean vertical velocity over the window's second half less that over its first
  const double span = half_ * dt_;
  const double rise = ((z_[2 * half_] - z_[half_]) - (z_[half_] - z_[0])) / span;
  if (rise > peak_) {
    peak_ = rise;
    peak_t_ = t;
  }
  if (first_ < 0 && rise >= threshold_) first_ = t;
}

StrikeTask::StrikeTask(const StrikeDef& def, double dt, int n_parts)
    : def_(def), phases_(settled_phases(def.seconds, def.drop_height, def.settle), dt, n_parts), meter_(def.window, def.threshold, dt) {}

void StrikeTask::begin(const Observation& o) {
  phases_.begin(o);
  if (phases_.phase() == Phase::Measure) {
    measuring_ = true;
    t_start_ = o.time();
    meter_.start(o.time(), o.centre_of_mass().z);
  }
}

void StrikeTask::observe(const Observation& o) {
  const bool was_measuring = phases_.phase() == Phase::Measure;
  phases_.observe(o);
  if (!was_measuring) {
    // the step on which settling ended: measuring begins here
    if (phases_.phase() == Phase::Measure) {
      measuring_ = true;
      t_start_ = o.time();
      meter_.start(o.time(), o.centre_of_mass().z);
    }
    return;
  }
  meter_.observe(o.time(), o.centre_of_mass().z);
}

TaskScore StrikeTask::score(const CreatureModel&) const {
  const double impact = measuring_ ? meter_.peak() : 0;
  const double strike = meter_.first_strike();
  return {impact,
          phases_.scored_distance(),
          {{"impact", impact},
           {"impact_time", measuring_ ? meter_.peak_time() - t_start_ : 0},
           {"strike_time", strike < 0 ? -1 : strike - t_start_},
           {"muscle_work", phases_.measured_work()}}};
}

}  // namespace bx
