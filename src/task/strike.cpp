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
    : SettledTask(def.seconds, def.drop_height, def.settle, dt, n_parts),
      def_(def),
      meter_(def.window, def.threshold, dt) {}

void StrikeTask::begin_measure(const Observation& o) {
  t_start_ = o.time();
  meter_.start(o.time(), o.centre_of_mass().z);
}

void StrikeTask::measure(const Observation& o) { meter_.observe(o.time(), o.centre_of_mass().z); }

TaskScore StrikeTask::score(const CreatureModel&) const {
  const double impact = measuring() ? meter_.peak() : 0;
  const double strike = meter_.first_strike();
  return {impact,
          phases().scored_distance(),
          {{"impact", impact},
           {"impact_time", measuring() ? meter_.peak_time() - t_start_ : 0},
           {"strike_time", strike < 0 ? -1 : strike - t_start_},
           {"muscle_work", phases().measured_work()}}};
}

}  // namespace bx
