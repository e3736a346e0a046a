// Locomotion on flat ground: how far the creature's centre of mass travels.
#pragma once

#include "core/math.h"

namespace bx {

/// Which displacement counts as distance.
enum class DistanceMetric {
  Planar,  ///< horizontal distance (x, y) of the centre of mass
  AlongX,  ///< signed displacement along +x (miconi2006 5.2)
};

/// A locomotion task.
struct LocomotionDef {
  double seconds = 10;        ///< evaluation length (s)
  double drop_height = 0.0;   ///< gap between the lowest part and the ground at the start (m)
  DistanceMetric metric = DistanceMetric::Planar;
  /// Distance is measured from this fraction of the evaluation on
  /// (miconi2006 5.2: 1/8, so falling over does not count).
  double skip_fraction = 0.0;
};

/// Accumulates a locomotion score over an evaluation.
class LocomotionScore {
 public:
  explicit LocomotionScore(const LocomotionDef& def) : def_(def) {}
  /// Call after every physics step with the time and the centre of mass.
  void observe(double t, Vec3 com) {
    if (!started_ && t >= def_.skip_fraction * def_.seconds - 1e-9) {
      started_ = true;
      start_ = com;
    }
    last_ = com;
  }
  /// Distance travelled since measurement started (0 if it never did).
  double distance() const {
    if (!started_) return 0;
    Vec3 d = last_ - start_;
    return def_.metric == DistanceMetric::AlongX ? d.x : std::hypot(d.x, d.y);
  }

 private:
  LocomotionDef def_;
  bool started_ = false;
  Vec3 start_, last_;
};

}  // namespace bx
