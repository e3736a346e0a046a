#include "task/throwing.h"

#include <algorithm>
#include <cmath>

#include "physics/world_edits.h"

namespace bx {

double point_segment_distance(Vec3 p, Vec3 a, Vec3 b) {
  Vec3 ab = b - a;
  double len2 = dot(ab, ab);
  double u = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return norm(p - (a + u * ab));
}

ThrowingTask::ThrowingTask(const ThrowingDef& def, double dt, int projectile, int release_joint)
    : def_(def), dt_(dt), projectile_(projectile), release_joint_(release_joint),
      settling_(def.start == ThrowStart::Settled), stillness_(def.settle, dt) {}

long ThrowingTask::max_steps() const {
  // settled: the settling at its longest, then the throw and a step
  return def_.start == ThrowStart::Settled ? std::lround((def_.settle.timeout + def_.seconds) / dt_) + 1
                   : std::lround(def_.seconds / dt_);
}

void ThrowingTask::begin(const Observation& o) {
  if (!settling_) return;
  part_positions(o, parts_);
  stillness_.start(parts_);
}

void ThrowingTask::act(const CreatureModel&, std::span<const double> outputs, WorldEdits& w, const Observation& o) {
  if (settling_ || released_ || outputs[0] < kFires) return;
  w.break_joint(release_joint_);
  release(o.time(), o.part_pose(projectile_).p);
}

void ThrowingTask::observe(const Observation& o) {
  const double t = o.time();
  if (settling_) {
    // the throw begins once every part has been still for settle.seconds
    part_positions(o, parts_);
    if (stillness_.observe(parts_)) {
      settling_ = false;
      t_begin_ = t;
    } else if (t >= def_.settle.timeout - 1e-9) {
      done_ = true;
      note_ = "never settled within settle_timeout";
    }
    return;
  }
  observe(t, o.part_pose(projectile_).p, o.touches_part(projectile_));
  if (!done_ && def_.start == ThrowStart::Settled && t - t_begin_ >= def_.seconds - 1e-9) {
    done_ = true;
    t_end_ = t;
  }
}

TaskScore ThrowingTask::score(const CreatureModel&) const {
  TaskScore s{fitness(), distance(), {}};
  // D_t, once there is a path to measure it on
  if (def_.fitness == ThrowFitness::Aim && released_) s.metrics.push_back({kTargetMiss, target_miss()});
  return s;
}

void ThrowingTask::record(const Observation&, SceneRecord& out) {
  // what holds throughout: the projectile, the aim task's target
  if (!recorded_items_) {
    if (projectile_ >= 0) out.parts.push_back({"projectile", projectile_, kProjectileColor, true});
    if (def_.fitness == ThrowFitness::Aim) out.points.push_back({"target", def_.target, kTargetSize, kTargetColor});
    recorded_items_ = true;
  }
  // each moment once, when it has happened
  if (!settling_ && !recorded_begin_) {
    out.markers.push_back({"begin", t_begin_});
    recorded_begin_ = true;
  }
  // the scored span: the projectile's path from its release to its rest
  if (released_ && !recorded_release_) {
    out.markers.push_back({"release", t_release_});
    out.markers.push_back({std::string(kScoredFrom), t_release_});
    recorded_release_ = true;
  }
  if (released_ && done_ && !recorded_end_) {
    out.markers.push_back({std::string(kScoredTo), t_end_});
    recorded_end_ = true;
  }
  if (t_touch_end_ >= 0 && !recorded_touch_) {
    out.markers.push_back({"touch end", t_touch_end_});
    recorded_touch_ = true;
  }
}

void ThrowingTask::release(double t, Vec3 projectile) {
  if (released_) return;
  released_ = true;
  t_release_ = t;
  start_ = last_ = projectile;
  miss_ = norm(projectile - def_.target);
}

void ThrowingTask::observe(double t, Vec3 projectile, bool touched) {
  if (!released_ || done_) return;
  if (touched && def_.touch_seconds >= 0 && t - t_release_ > def_.touch_seconds + 1e-9) {
    // a push or carry, not a throw: measured where the projectile is
    done_ = true;
    t_touch_end_ = t_end_ = t;
  }
  // the path since the release, one segment per step
  miss_ = std::min(miss_, point_segment_distance(def_.target, last_, projectile));
  // at rest: barely moving, step after step, for rest_seconds
  double moved = norm(projectile - last_);
  still_steps_ = moved < def_.rest_speed * dt_ ? still_steps_ + 1 : 0;
  if (still_steps_ > 0 && static_cast<double>(still_steps_) * dt_ >= def_.rest_seconds - 1e-9) {
    done_ = true;
    t_end_ = t;
  }
  last_ = projectile;
}

double ThrowingTask::distance() const {
  if (!released_) return 0;
  return std::hypot(last_.x - start_.x, last_.y - start_.y);
}

double ThrowingTask::fitness() const {
  if (!released_) return 0;
  switch (def_.fitness) {
    case ThrowFitness::Distance: return distance();
    case ThrowFitness::Aim: return distance() - miss_;
  }
  return 0;
}

std::string ThrowingTask::note() const {
  if (!note_.empty()) return note_;
  return released_ ? std::string() : std::string("the projectile was never released");
}

}  // namespace bx
