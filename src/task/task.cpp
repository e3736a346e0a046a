#include "task/task.h"

#include <cmath>

namespace bx {

double heading(const Observation& o) {
  // the root's x axis is the first column of its rotation
  const Mat3& R = o.part_pose(0).R;
  const double x = R.m[0][0], y = R.m[1][0];
  if (std::hypot(x, y) < 1e-12) return 0;
  return std::atan2(y, x);
}

}  // namespace bx
