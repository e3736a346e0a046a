#include "task/reach.h"

#include <algorithm>
#include <cmath>

#include "develop/creature_model.h"

namespace bx {

double part_top(const PartModel& part, const Pose& pose) {
  const Mat3& R = pose.R;
  const Vec3& s = part.size;
  // the z components of the part's axes in the world
  const double zx = R.m[2][0], zy = R.m[2][1], zz = R.m[2][2];
  switch (part.shape) {
    case Shape::Box: return pose.p.z + (std::abs(zx) * s.x + std::abs(zy) * s.y + std::abs(zz) * s.z) / 2;
    case Shape::Sphere: return pose.p.z + s.x / 2;
    case Shape::Capsule:  // a segment of length x - y along x, swept by a ball of diameter y
      return pose.p.z + std::abs(zx) * std::max(s.x - s.y, 0.0) / 2 + s.y / 2;
    case Shape::Cylinder:  // its end discs' rims: the axis's rise, and the rim's across it
      return pose.p.z + std::abs(zx) * s.x / 2 + std::sqrt(std::max(0.0, 1 - zx * zx)) * s.y / 2;
  }
  return pose.p.z;
}

ReachTask::ReachTask(const ReachDef& def, const CreatureModel& m, double dt)
    : SettledTask(def.seconds, def.drop_height, def.settle, dt, m.n_parts()), def_(def), parts_(m.parts) {}

double ReachTask::top(const Observation& o) const {
  double t = -1e300;
  for (std::size_t i = 0; i < parts_.size(); ++i)
    t = std::max(t, part_top(parts_[i], o.part_pose(static_cast<int>(i))));
  return t;
}

void ReachTask::begin_measure(const Observation& o) {
  t_start_ = reach_t_ = o.time();
  start_top_ = reach_ = top(o);
}

void ReachTask::measure(const Observation& o) {
  if (const double t = top(o); t > reach_) {
    reach_ = t;
    reach_t_ = o.time();
  }
}

TaskScore ReachTask::score(const CreatureModel&) const {
  return {reach(),
          phases().scored_distance(),
          {{"reach", reach()},
           {"start_top", measuring() ? start_top_ : 0},
           {"reach_time", measuring() ? reach_t_ - t_start_ : 0},
           {"muscle_work", phases().measured_work()}}};
}

}  // namespace bx
