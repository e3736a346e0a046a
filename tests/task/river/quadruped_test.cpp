// The river crossing's quadruped (Stanton & Channon 2015, "Environment and
// Physical Model"; docs/rivercrossing.md, "The quadruped"): the body as the
// paper gives it.
#include "task/river/quadruped.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace bx {
namespace {

constexpr double kEps = 1e-12;

// leg k's outward diagonal and hip (torso's lower corner), in cell widths
Vec3 out_of(int leg) {
  const double sx = (leg == 0 || leg == 3) ? 1 : -1, sy = leg < 2 ? 1 : -1;
  return normalized({sx, sy, 0});
}
Vec3 hip_of(int leg) {
  const Vec3 o = out_of(leg);
  return {0.5 * (o.x > 0 ? 1 : -1), 0.5 * (o.y > 0 ? 1 : -1), -0.1};
}

void expect_near(Vec3 a, Vec3 b, double tol, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, tol) << what;
  EXPECT_NEAR(a.y, b.y, tol) << what;
  EXPECT_NEAR(a.z, b.z, tol) << what;
}

// the lowest z of a part's box at its pose
double lowest_z(const PartModel& p) {
  double z = 1e300;
  for (int i = 0; i < 8; ++i) {
    const Vec3 c{(i & 1 ? 0.5 : -0.5) * p.size.x, (i & 2 ? 0.5 : -0.5) * p.size.y, (i & 4 ? 0.5 : -0.5) * p.size.z};
    z = std::min(z, p.pose.apply(c).z);
  }
  return z;
}

TEST(Quadruped, HasThePapersBody) {
  const QuadrupedDef def{2, 3};  // not the defaults, so that both scale the body
  const double u = def.unit;
  CreatureModel m = make_quadruped(def);
  ASSERT_EQ(m.n_parts(), 9);
  ASSERT_EQ(m.joints.size(), 8u);
  ASSERT_EQ(m.effectors.size(), 12u);
  EXPECT_TRUE(m.sensors.empty());
  EXPECT_TRUE(m.brain.fn.empty());
  EXPECT_EQ(m.projectile, -1);

  // torso 1 x 1 x 0.2 at the origin, limbs 0.5 x 0.2 x 0.2; mass = density x volume
  const PartModel& torso = m.parts[kTorso];
  expect_near(torso.size, {u, u, 0.2 * u}, kEps, "torso size");
  expect_near(torso.pose.p, {0, 0, 0}, kEps, "torso centre");
  EXPECT_EQ(torso.parent, -1);
  EXPECT_NEAR(torso.mass, 3 * (2 * 2 * 0.4), 1e-12);
  for (int p = 1; p < 9; ++p) {
    expect_near(m.parts[p].size, {0.5 * u, 0.2 * u, 0.2 * u}, kEps, "limb size");
    EXPECT_NEAR(m.parts[p].mass, 3 * (1.0 * 0.4 * 0.4), 1e-12) << p;
  }
  EXPECT_NEAR(m.total_mass(), 3 * (0.2 + 8 * 0.02) * u * u * u, 1e-12);

  for (int leg = 0; leg < kLegs; ++leg) {
    const std::string l = "leg " + std::to_string(leg);
    const Vec3 out = out_of(leg), up{0, 0, 1};
    const Vec3 hip = u * hip_of(leg), knee = hip + 0.5 * u * out;
    const PartModel& upper = m.parts[upper_limb(leg)];
    const PartModel& lower = m.parts[lower_limb(leg)];
    EXPECT_EQ(upper.parent, kTorso) << l;
    EXPECT_EQ(lower.parent, upper_limb(leg)) << l;
    // the upper limb points out along the diagonal, level, from the hip;
    // the lower limb 45 degrees down from the knee
    expect_near(upper.pose.R.column(0), out, kEps, l + " upper limb's length");
    expect_near(upper.pose.p, hip + 0.25 * u * out, kEps, l + " upper limb's centre");
    const Vec3 along = std::cos(kPi / 4) * out - std::sin(kPi / 4) * up;
    expect_near(lower.pose.R.column(0), along, kEps, l + " lower limb's length");
    expect_near(lower.pose.p, knee + 0.25 * u * along, kEps, l + " lower limb's centre");
    EXPECT_NEAR(upper.pose.R.det(), 1, kEps) << l;
    EXPECT_NEAR(lower.pose.R.det(), 1, kEps) << l;
    EXPECT_NEAR(lowest_z(lower), -quadruped_foot_depth(def), kEps) << l;

    // hip: 2 axes at the torso's lower corner, pi/2 about the vertical, pi
    // about the level line across the diagonal
    const JointModel& h = m.joints[hip_joint(leg)];
    EXPECT_EQ(h.type, JointType::Universal) << l;
    EXPECT_EQ(h.parent, kTorso) << l;
    EXPECT_EQ(h.child, upper_limb(leg)) << l;
    expect_near(h.anchor, hip, kEps, l + " hip anchor");
    expect_near(h.axis1, up, kEps, l + " hip's first axis");
    EXPECT_NEAR(norm(h.axis2), 1, kEps) << l;
    EXPECT_NEAR(h.axis2.z, 0, kEps) << l;
    EXPECT_NEAR(dot(h.axis2, out), 0, kEps) << l;
    ASSERT_EQ(h.limits.size(), 2u) << l;
    EXPECT_NEAR(h.limits[0].hi - h.limits[0].lo, kPi / 2, kEps) << l;
    EXPECT_NEAR(h.limits[1].hi - h.limits[1].lo, kPi, kEps) << l;
    EXPECT_NEAR(h.limits[0].hi + h.limits[0].lo, 0, kEps) << l;
    EXPECT_NEAR(h.limits[1].hi + h.limits[1].lo, 0, kEps) << l;

    // knee: pi/2 about the limbs' y, the same line as the hip's lift
    const JointModel& k = m.joints[knee_joint(leg)];
    EXPECT_EQ(k.type, JointType::Hinge) << l;
    EXPECT_EQ(k.parent, upper_limb(leg)) << l;
    EXPECT_EQ(k.child, lower_limb(leg)) << l;
    expect_near(k.anchor, knee, kEps, l + " knee anchor");
    expect_near(k.axis1, h.axis2, kEps, l + " knee axis");
    EXPECT_NEAR(std::abs(dot(k.axis1, upper.pose.R.column(1))), 1, kEps) << l;
    ASSERT_EQ(k.limits.size(), 1u) << l;
    EXPECT_NEAR(k.limits[0].hi - k.limits[0].lo, kPi / 2, kEps) << l;
    EXPECT_NEAR(k.limits[0].hi + k.limits[0].lo, 0, kEps) << l;

    // effectors 3 leg + 0, 1, 2: hip yaw, hip lift, knee
    EXPECT_EQ(m.effectors[3 * leg].joint, hip_joint(leg));
    EXPECT_EQ(m.effectors[3 * leg].dof, 0);
    EXPECT_EQ(m.effectors[3 * leg + 1].joint, hip_joint(leg));
    EXPECT_EQ(m.effectors[3 * leg + 1].dof, 1);
    EXPECT_EQ(m.effectors[3 * leg + 2].joint, knee_joint(leg));
    EXPECT_EQ(m.effectors[3 * leg + 2].dof, 0);
  }
  // the body's lowest points are the feet, 0.525 u below the torso's centre
  double lowest = 1e300;
  for (const PartModel& p : m.parts) lowest = std::min(lowest, lowest_z(p));
  EXPECT_NEAR(lowest, -0.525 * u, 1e-3 * u);
  EXPECT_NEAR(m.min_z(), lowest, 1e-9);
}

TEST(Quadruped, SensorsAreTheCentresOfTheTorsosSideFaces) {
  const QuadrupedDef def{3, 1};
  const auto s = quadruped_sensor_points(def);
  expect_near(s[0], {1.5, 0, 0}, kEps, "+x");
  expect_near(s[1], {0, 1.5, 0}, kEps, "+y");
  expect_near(s[2], {-1.5, 0, 0}, kEps, "-x");
  expect_near(s[3], {0, -1.5, 0}, kEps, "-y");
}

TEST(Quadruped, CheckNamesABadUnitOrDensity) {
  EXPECT_TRUE(check_quadruped_def(QuadrupedDef{}).ok());
  Status s = check_quadruped_def({0, 1});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "quadruped: unit is 0, must be a finite number above 0");
  s = check_quadruped_def({1, -2});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "quadruped: density is -2, must be a finite number above 0");
  EXPECT_FALSE(check_quadruped_def({INFINITY, 1}).ok());
  EXPECT_FALSE(check_quadruped_def({1, NAN}).ok());
}

TEST(Quadruped, PhysicsAndMotorsAreThePapers) {
  const QuadrupedDef def;
  const PhysicsDef p = river_physics(def);
  EXPECT_EQ(p.dt, 0.01);
  EXPECT_EQ(p.erp, 0.2);
  EXPECT_EQ(p.cfm, 5e-5);
  EXPECT_EQ(p.friction, 10);
  EXPECT_EQ(p.gravity, -9.81);
  // the explosion tests per cell width as the defaults are per metre
  EXPECT_EQ(p.max_joint_gap, PhysicsDef{}.max_joint_gap * def.unit);
  EXPECT_EQ(p.max_speed, PhysicsDef{}.max_speed * def.unit);
  EXPECT_EQ(p.max_step_jump, PhysicsDef{}.max_step_jump * def.unit);
  const MotorDef m = river_motor();
  EXPECT_EQ(m.model, MotorModel::PD);
  EXPECT_EQ(m.kp, 0.25);
  EXPECT_EQ(m.kd, 0.175);
  EXPECT_EQ(m.response_time, 0);
  // the defaults' weight and inertia products (QuadrupedDef)
  EXPECT_NEAR(def.density * std::pow(def.unit, 4), 0.1, 1e-12);
  EXPECT_NEAR(def.density * std::pow(def.unit, 5), 4, 1e-12);
}

}  // namespace
}  // namespace bx
