#include "task/turn.h"

#include <algorithm>
#include <cmath>

namespace bx {

TurnTask::TurnTask(const TurnDef& def, double dt, int n_parts)
    : SettledTask(def.seconds, def.drop_height, def.settle, dt, n_parts),
      def_(def),
      sign_(def.direction == TurnDirection::Left ? 1 : -1) {}

void TurnTask::begin_measure(const Observation& o) {
  heading_ = heading(o);
  level_ = root_level(o) >= def_.min_level;
  turned_ = 0;
  start_ = o.centre_of_mass();
  travel_ = 0;
  t_start_ = o.time();
  window_ = def_.seconds / std::max(1, def_.windows);
  marks_.assign(1, 0.0);
}

void TurnTask::measure(const Observation& o) {
  // the heading counts only from one level enough step to the next (TurnDef::min_level)
  const double h = heading(o);
  const bool level = root_level(o) >= def_.min_level;
  if (level && level_) turned_ += heading_step(heading_, h);
  heading_ = h;
  level_ = level;
  const Vec3 d = o.centre_of_mass() - start_;
  travel_ = std::max(travel_, std::hypot(d.x, d.y));
  const double t = o.time();
  while (static_cast<int>(marks_.size()) <= def_.windows &&
         t >= t_start_ + static_cast<double>(marks_.size()) * window_ - 1e-9)
    marks_.push_back(turned_);
}

double TurnTask::scored_turn() const {
  if (!measuring()) return 0;
  if (def_.windows <= 1) return sign_ * turned_;
  if (static_cast<int>(marks_.size()) < def_.windows + 1) return 0;
  double least = sign_ * (marks_[1] - marks_[0]);
  for (std::size_t i = 2; i < marks_.size(); ++i) least = std::min(least, sign_ * (marks_[i] - marks_[i - 1]));
  return def_.windows * least;
}

double TurnTask::turn_rate() const {
  const double s = measured_seconds();
  return s > 0 ? scored_turn() / s : 0;
}

double TurnTask::fitness() const {
  return std::max(0.0, turn_rate()) / (1 + travel_ / def_.travel_scale);
}

TaskScore TurnTask::score(const CreatureModel&) const {
  return {fitness(),
          travel_,
          {{"turn_rate", turn_rate()},
           {"turned", sign_ * turned_},
           {"travel", travel_},
           {"muscle_work", phases().measured_work()}}};
}

}  // namespace bx
