#include "task/locomotion.h"

#include <algorithm>
#include <cmath>

#include "develop/creature_model.h"

namespace bx {

LocomotionTask::LocomotionTask(const LocomotionDef& def, double dt, int n_parts, double gravity)
    : def_(def), dt_(dt), gravity_(std::abs(gravity)), stillness_(def.settle, dt) {
  switch (def.activation) {
    case Activation::Always: phase_ = Phase::Measure; break;
    case Activation::Chaumont2007: phase_ = Phase::Settle1; break;
    case Activation::Settled: phase_ = Phase::Settle2; break;
  }
  stillness_.start(std::vector<Vec3>(needs_parts() ? n_parts : 0));
}

long LocomotionTask::max_steps() const {
  double longest = def_.seconds;
  if (def_.activation == Activation::Chaumont2007)
    longest += 2 * def_.settle.timeout + def_.burst_seconds;
  else if (def_.activation == Activation::Settled)
    longest += def_.settle.timeout;
  return std::lround(longest / dt_) + 1;
}

const std::vector<Vec3>& LocomotionTask::parts_of(const Observation& o) {
  // only a settling phase, or the burst before one, looks at them
  if (needs_parts() && phase_ != Phase::Measure && phase_ != Phase::Done) part_positions(o, parts_);
  else parts_.clear();
  return parts_;
}

void LocomotionTask::begin(const Observation& o) {
  work_ = o.muscle_work();
  if (def_.metric == DistanceMetric::Forward || def_.metric == DistanceMetric::Front)
    step_heading_ = heading_ = heading(o);
  start(o.centre_of_mass(), parts_of(o));
}

void LocomotionTask::observe(const Observation& o) {
  work_ = o.muscle_work();
  if (def_.metric == DistanceMetric::Forward || def_.metric == DistanceMetric::Front) {
    step_heading_ = heading_;
    heading_ = heading(o);
  }
  observe(o.time(), o.centre_of_mass(), parts_of(o));
}

void LocomotionTask::start(Vec3 com, const std::vector<Vec3>& parts) {
  if (needs_parts()) stillness_.start(parts);
  if (phase_ == Phase::Measure && def_.skip_fraction <= 0) begin_measure(0, com);
  last_ = com;
}

void LocomotionTask::begin_measure(double t, Vec3 com) {
  measured_ = true;
  start_ = com;
  t_start_ = t;
  work_start_ = work_;
  forward_ = {std::cos(heading_), std::sin(heading_), 0};
  const double end = def_.activation == Activation::Always ? def_.seconds : t + def_.seconds;
  window_ = (end - t) / std::max(1, def_.windows);
  marks_.assign(1, com);
  path_ = 0;
  path_marks_.assign(1, 0);
}

// moves on once the parts have been still for settle.seconds, gives up after
// the timeout
void LocomotionTask::settle(double t, bool still, Phase next) {
  if (still) {
    phase_ = next;
    phase_start_ = t;
    stillness_.restart();
  } else if (t - phase_start_ >= def_.settle.timeout - 1e-9) {
    phase_ = Phase::Done;
    note_ = "never settled within settle_timeout";
  }
}

void LocomotionTask::observe(double t, Vec3 com, const std::vector<Vec3>& parts) {
  t_ = t;
  // a settling phase counts still steps; the burst before the second keeps
  // the parts' positions for its first step
  const bool settling = phase_ == Phase::Settle1 || phase_ == Phase::Settle2;
  const bool still = settling && stillness_.observe(parts);
  if (phase_ == Phase::Burst) stillness_.start(parts);
  switch (phase_) {
    case Phase::Settle1: settle(t, still, Phase::Burst); break;
    case Phase::Burst:
      if (t - phase_start_ >= def_.burst_seconds - 1e-9) {
        phase_ = Phase::Settle2;
        phase_start_ = t;
      }
      break;
    case Phase::Settle2:
      settle(t, still, Phase::Measure);
      if (phase_ == Phase::Measure) begin_measure(t, com);
      break;
    case Phase::Measure: {
      // without the sequence, measuring starts after skip_fraction of the time
      if (!measured_ && t >= def_.skip_fraction * def_.seconds - 1e-9) begin_measure(t, com);
      // the step just taken, front first (not the one measuring began at)
      if (measured_ && t > t_start_ + 1e-12 && def_.metric == DistanceMetric::Front) {
        const Vec3 d = com - last_;
        path_ += d.x * std::cos(step_heading_) + d.y * std::sin(step_heading_);
      }
      if (measured_)
        while (static_cast<int>(marks_.size()) <= def_.windows &&
               t >= t_start_ + static_cast<double>(marks_.size()) * window_ - 1e-9) {
          marks_.push_back(com);
          path_marks_.push_back(path_);
        }
      double end = def_.activation == Activation::Always ? def_.seconds : phase_start_ + def_.seconds;
      if (t >= end - 1e-9) phase_ = Phase::Done;
      break;
    }
    case Phase::Done: break;
  }
  last_ = com;
}

double LocomotionTask::displacement(Vec3 from, Vec3 to) const {
  Vec3 d = to - from;
  switch (def_.metric) {
    case DistanceMetric::Planar: break;
    case DistanceMetric::AlongX: return d.x;
    case DistanceMetric::Forward: return d.x * forward_.x + d.y * forward_.y;
    case DistanceMetric::Front: break;  // a path, not a displacement (path_)
  }
  return std::hypot(d.x, d.y);
}

double LocomotionTask::distance() const {
  if (!measured_) return 0;
  return def_.metric == DistanceMetric::Front ? path_ : displacement(start_, last_);
}

double LocomotionTask::scored_distance() const {
  if (def_.windows <= 1) return distance();
  if (!measured_ || static_cast<int>(marks_.size()) < def_.windows + 1) return 0;
  auto window = [&](std::size_t i) {
    return def_.metric == DistanceMetric::Front ? path_marks_[i] - path_marks_[i - 1]
                                                : displacement(marks_[i - 1], marks_[i]);
  };
  double least = window(1);
  for (std::size_t i = 2; i < marks_.size(); ++i) least = std::min(least, window(i));
  return def_.windows * least;
}

double LocomotionTask::fitness(const CreatureModel& m) const {
  if (!measured_) return 0;
  switch (def_.fitness) {
    case LocomotionFitness::Distance: return scored_distance();
    case LocomotionFitness::Speed: return speed();
    case LocomotionFitness::Chaumont2007: return scored_distance() * chaumont_size_factor(m, def_.kappa);
    case LocomotionFitness::Lessin2015:
      return def_.speed_step * (std::floor(speed() / def_.speed_step) + efficiency(m)) / def_.max_speed;
  }
  return 0;
}

double LocomotionTask::speed() const {
  return measured_seconds() > 0 ? scored_distance() / measured_seconds() : 0;
}

double LocomotionTask::efficiency(const CreatureModel& m) const {
  return lessin_efficiency(scored_distance(), measured_seconds(), measured_work(), m.total_mass(), gravity_,
                           def_.basal_power);
}

void LocomotionTask::record(const Observation& o, SceneRecord& out) {
  if (!measured_) return;
  if (!recorded_from_) {
    out.markers.push_back({std::string(kScoredFrom), t_start_});
    out.add(t_start_, SceneCounter{"distance", 0, "m"});
    recorded_from_ = true;
  }
  const double d = distance();
  const bool end = phase_ == Phase::Done && !recorded_to_;
  if (std::abs(d - recorded_distance_) >= kDistanceStep || (end && d != recorded_distance_)) {
    out.add(o.time(), SceneCounter{"distance", d, "m"});
    recorded_distance_ = d;
  }
  if (end) {
    out.markers.push_back({std::string(kScoredTo), t_});
    recorded_to_ = true;
  }
}

TaskScore LocomotionTask::score(const CreatureModel& m) const {
  TaskScore out{fitness(m), distance(), {}};
  if (def_.fitness == LocomotionFitness::Lessin2015)
    out.metrics = {{"speed", speed()}, {"efficiency", efficiency(m)}, {"muscle_work", measured_work()}};
  return out;
}

double lessin_efficiency(double distance, double seconds, double work, double mass, double gravity,
                         double basal_power) {
  if (!(distance > 0)) return 0;
  const double weight_distance = mass * gravity * distance;
  if (!(weight_distance > 0)) return 0;
  const double spent = std::max(0.0, work) + std::max(0.0, basal_power) * mass * std::max(0.0, seconds);
  return 1 / (1 + spent / weight_distance);
}

double chaumont_size_factor(const CreatureModel& m, double kappa) {
  // means over the N blocks of the sums of edge lengths, surface areas and volumes
  double cl = 0, cs = 0, cv = 0;
  for (const auto& p : m.parts) {
    const Vec3& b = p.size;
    cl += b.x + b.y + b.z;
    cs += 2 * (b.x * b.y + b.x * b.z + b.y * b.z);
    cv += b.x * b.y * b.z;
  }
  double n = static_cast<double>(m.parts.size());
  if (n == 0) return 0;
  cl /= n, cs /= n, cv /= n;
  return cv / (cs * cl) * std::pow(kappa, n);
}

LocomotionDef settled_phases(double seconds, double drop_height, const SettleDef& settle) {
  LocomotionDef p;
  p.seconds = seconds;
  p.drop_height = drop_height;
  p.activation = Activation::Settled;
  p.settle = settle;
  return p;
}

}  // namespace bx
