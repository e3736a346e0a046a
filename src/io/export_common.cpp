#include "io/export_common.h"

#include <cmath>

#include "core/text.h"

namespace bx {

std::string xml::num(double v) { return shortest_number(std::abs(v) < 1e-300 ? 0.0 : v); }

std::string xml::vec(Vec3 v) { return xml::num(v.x) + " " + xml::num(v.y) + " " + xml::num(v.z); }

std::vector<ExportDof> export_dofs(const JointModel& j) {
  auto lim = [&](int k) { return k < static_cast<int>(j.limits.size()) ? &j.limits[k] : nullptr; };
  switch (j.type) {
    case JointType::Fixed: return {};
    case JointType::Hinge: return {{false, j.axis1, lim(0)}};
    case JointType::Universal: return {{false, j.axis1, lim(0)}, {false, j.axis2, lim(1)}};
    case JointType::Spherical:
      return {{false, j.axis1, lim(0)}, {false, normalized(cross(j.axis2, j.axis1)), lim(1)}, {false, j.axis2, lim(2)}};
    case JointType::Slider: return {{true, j.axis1, lim(0)}};
    case JointType::Cylindrical: return {{true, j.axis1, lim(0)}, {false, j.axis1, lim(1)}};
  }
  return {};
}

}  // namespace bx
