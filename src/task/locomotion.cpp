#include "task/locomotion.h"

#include <algorithm>
#include <cmath>

#include "develop/creature_model.h"

namespace bx {

LocomotionTask::LocomotionTask(const LocomotionDef& def, double dt, int n_parts)
    : def_(def), dt_(dt), stillness_(def.settle, dt) {
  phase_ = def.activation == Activation::Chaumont2007 ? Phase::Settle1 : Phase::Measure;
  stillness_.start(std::vector<Vec3>(needs_parts() ? n_parts : 0));
}

long LocomotionTask::max_steps() const {
  double longest = def_.activation == Activation::Chaumont2007
                       ? 2 * def_.settle.timeout + def_.burst_seconds + def_.seconds
                       : def_.seconds;
  return std::lround(longest / dt_) + 1;
}

const std::vector<Vec3>& LocomotionTask::parts_of(const Observation& o) {
  // only a settling phase, or the burst before one, looks at them
  if (needs_parts() && phase_ != Phase::Measure && phase_ != Phase::Done) part_positions(o, parts_);
  else parts_.clear();
  return parts_;
}

void LocomotionTask::begin(const Observation& o) { start(o.centre_of_mass(), parts_of(o)); }

void LocomotionTask::observe(const Observation& o) { observe(o.time(), o.centre_of_mass(), parts_of(o)); }

void LocomotionTask::start(Vec3 com, const std::vector<Vec3>& parts) {
  if (needs_parts()) stillness_.start(parts);
  if (phase_ == Phase::Measure && def_.skip_fraction <= 0) begin_measure(0, com);
  last_ = com;
}

void LocomotionTask::begin_measure(double t, Vec3 com) {
  measured_ = true;
  start_ = com;
  t_start_ = t;
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
      double end = def_.activation == Activation::Chaumont2007 ? phase_start_ + def_.seconds
                                                               : def_.seconds;
      if (t >= end - 1e-9) phase_ = Phase::Done;
      break;
    }
    case Phase::Done: break;
  }
  last_ = com;
}

double LocomotionTask::distance() const {
  if (!measured_) return 0;
  Vec3 d = last_ - start_;
  return def_.metric == DistanceMetric::AlongX ? d.x : std::hypot(d.x, d.y);
}

double LocomotionTask::fitness(const CreatureModel& m) const {
  if (!measured_) return 0;
  switch (def_.fitness) {
    case LocomotionFitness::Distance: return distance();
    case LocomotionFitness::Speed: {
      double s = measured_seconds();
      return s > 0 ? distance() / s : 0;
    }
    case LocomotionFitness::Chaumont2007: return distance() * chaumont_size_factor(m, def_.kappa);
  }
  return 0;
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

}  // namespace bx
