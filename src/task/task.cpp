#include "task/task.h"

#include <algorithm>
#include <cmath>

namespace bx {

double heading(const Observation& o) {
  // the root's x axis is the first column of its rotation
  const Mat3& R = o.part_pose(0).R;
  const double x = R.m[0][0], y = R.m[1][0];
  if (std::hypot(x, y) < 1e-12) return 0;
  return std::atan2(y, x);
}

double root_level(const Observation& o) {
  const Mat3& R = o.part_pose(0).R;
  return std::hypot(R.m[0][0], R.m[1][0]);
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
