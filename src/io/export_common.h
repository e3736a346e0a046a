// What the creature exporters (io/mjcf.h, io/urdf.h) share: a number's
// shortest exact text, and a joint's degrees of freedom as one-axis joints,
// the form both formats describe joints in.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "develop/creature_model.h"

namespace bx {

namespace xml {
/// The shortest text that reads back as the same double ("0", never "-0").
std::string num(double v);
/// "x y z" of num each.
std::string vec(Vec3 v);
}  // namespace xml

/// One degree of freedom of a joint: a hinge or a slide along `axis` (in the
/// creature frame at the built pose), with its limit if the joint has one.
struct ExportDof {
  bool slide = false;
  Vec3 axis;
  const Limit* limit = nullptr;
};

/// A joint's degrees of freedom in their order (JointModel::limits'): a
/// universal's axis1 then axis2, a spherical's Euler axes (axis1, the third
/// axis, axis2: genome.h), a cylindrical's slide then its turn; none for a
/// fixed joint.
std::vector<ExportDof> export_dofs(const JointModel& j);

}  // namespace bx
