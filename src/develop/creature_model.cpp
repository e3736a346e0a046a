#include "develop/creature_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bx {

namespace {

// half extents of a part's axis-aligned bounding box in the creature frame
Vec3 aabb_half(const PartModel& p) {
  Vec3 h = p.shape == Shape::Box ? 0.5 * p.size : Vec3{p.size.x / 2, p.size.y / 2, p.size.y / 2};
  if (p.shape == Shape::Sphere) return {p.size.x / 2, p.size.x / 2, p.size.x / 2};
  Vec3 out;
  for (int i = 0; i < 3; ++i)
    out[i] = std::abs(p.pose.R.m[i][0]) * h.x + std::abs(p.pose.R.m[i][1]) * h.y +
             std::abs(p.pose.R.m[i][2]) * h.z;
  return out;
}

}  // namespace

double CreatureModel::total_mass() const {
  double m = 0;
  for (const auto& p : parts) m += p.mass;
  return m;
}

double CreatureModel::body_length() const {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& p : parts) {
    Vec3 h = aabb_half(p);
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p.pose.p[i] - h[i]);
      hi[i] = std::max(hi[i], p.pose.p[i] + h[i]);
    }
  }
  return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
}

double CreatureModel::min_z() const {
  double z = std::numeric_limits<double>::infinity();
  for (const auto& p : parts) z = std::min(z, p.pose.p.z - aabb_half(p).z);
  return z;
}

}  // namespace bx
