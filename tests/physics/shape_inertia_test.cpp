// A part's mass and inertia by its shape, against closed forms: a part spun
// about a hinge through its centre by a constant torque, without gravity,
// turns at torque x time / I about that axis (a principal one). Spheres and
// capsules are lessin2015's shapes (III-A); boxes are every dialect's.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/world.h"
#include "support/parts.h"

namespace bx {
namespace {

constexpr double kTorque = 0.01;  // N m: strength 1 x cross-section 0.01

// the rate after 1 s of kTorque about `axis` through the centre of a part
// of this shape, size and mass (a fixed base block beside it holds the hinge)
double spun_rate(Shape shape, Vec3 size, double mass, Vec3 axis) {
  PhysicsDef def;
  def.gravity = 0;
  def.dt = 0.001;
  World w(def);
  CreatureModel m;
  m.parts = {bxtest::box_part({0.1, 0.1, 0.1}, 1, {-2, 0, 1}), bxtest::part(shape, size, mass, {0, 0, 1}, 0)};
  JointModel j;
  j.type = JointType::Hinge;
  j.parent = 0;
  j.child = 1;
  j.anchor = {0, 0, 1};  // the part's centre
  j.axis1 = axis;
  m.joints.push_back(j);
  EffectorModel e;
  e.joint = 0;
  e.cross_section = 0.01;
  m.effectors.push_back(e);
  w.add_creature(m, {{0, 0, 0}, Mat3::identity()});
  w.fix_part_to_world(0);
  const MotorDef motor = bxtest::torque_motor(1);
  const double s[1] = {1.0};
  while (w.time() < 1 - 1e-9) {
    w.apply_effectors(m, motor, s);
    w.step();
  }
  return std::abs(w.joint_rate(0, 0));
}

// the inertia the rate implies
double inertia(double rate) { return kTorque * 1.0 / rate; }

TEST(ShapeInertia, ABoxIsTheClosedForm) {
  const double m = 2, x = 0.6, y = 0.2, z = 0.4;
  EXPECT_NEAR(inertia(spun_rate(Shape::Box, {x, y, z}, m, {0, 0, 1})), m * (x * x + y * y) / 12, 1e-9);
  EXPECT_NEAR(inertia(spun_rate(Shape::Box, {x, y, z}, m, {1, 0, 0})), m * (y * y + z * z) / 12, 1e-9);
}

TEST(ShapeInertia, ASphereIsTwoFifthsMRSquared) {
  const double m = 3, r = 0.25;
  for (Vec3 axis : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}})
    EXPECT_NEAR(inertia(spun_rate(Shape::Sphere, {2 * r, 2 * r, 2 * r}, m, axis)), 0.4 * m * r * r, 1e-9);
}

TEST(ShapeInertia, ACapsuleIsItsCylinderAndTwoHemispheres) {
  // along the part's x: 1.0 m end to end, 0.2 m across: a 0.8 m cylinder
  // of radius 0.1 and a hemisphere at each end, the mass shared by volume
  const double m = 1.5, L = 1.0, r = 0.1, h = L - 2 * r;
  const double vc = kPi * r * r * h, vs = 4.0 / 3.0 * kPi * r * r * r;
  const double mc = m * vc / (vc + vs), ms = m * vs / (vc + vs);
  const double along = mc * r * r / 2 + ms * 2 * r * r / 5;
  const double across = mc * (r * r / 4 + h * h / 12) + ms * (2 * r * r / 5 + h * h / 4 + 3 * h * r / 8);
  EXPECT_NEAR(inertia(spun_rate(Shape::Capsule, {L, 2 * r, 2 * r}, m, {1, 0, 0})), along, 1e-9);
  EXPECT_NEAR(inertia(spun_rate(Shape::Capsule, {L, 2 * r, 2 * r}, m, {0, 1, 0})), across, 1e-9);
  EXPECT_NEAR(inertia(spun_rate(Shape::Capsule, {L, 2 * r, 2 * r}, m, {0, 0, 1})), across, 1e-9);
}

}  // namespace
}  // namespace bx
