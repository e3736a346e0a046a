#include "task/task.h"

#include <algorithm>
#include <cmath>

namespace bx {

Vec3 axis_vector(RootAxis a) {
  const double sign = static_cast<int>(a) % 2 == 0 ? 1 : -1;
  Vec3 v;
  v[static_cast<int>(a) / 2] = sign;
  return v;
}

double heading(const Observation& o) {
  const Vec3 f = o.part_pose(0).R * o.front();
  if (std::hypot(f.x, f.y) < 1e-12) return 0;
  return std::atan2(f.y, f.x);
}

double root_level(const Observation& o) {
  const Vec3 f = o.part_pose(0).R * o.front();
  return std::hypot(f.x, f.y);
}

double heading_step(double from, double to) { return std::remainder(to - from, 2 * kPi); }

void part_positions(const Observation& o, std::vector<Vec3>& out) {
  out.resize(static_cast<std::size_t>(o.n_parts()));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = o.part_pose(static_cast<int>(i)).p;
}

bool Stillness::observe(const std::vector<Vec3>& parts) {
  double largest = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) largest = std::max(largest, norm(parts[i] - prev_[i]));
  prev_ = parts;
  still_steps_ = largest < def_.speed * dt_ ? still_steps_ + 1 : 0;
  return still_steps_ > 0 && static_cast<double>(still_steps_) * dt_ >= def_.seconds - 1e-9;
}

}  // namespace bx
