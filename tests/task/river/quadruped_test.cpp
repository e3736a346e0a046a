// The river crossing's quadruped (Stanton & Channon 2015, "Environment and
// Physical Model"; docs/rivercrossing.md, "The quadruped"): the body as the
// paper gives it, and, in real ODE physics with the paper's PD motors, that it
// stands on mid-range targets and comes to rest under constant ones. The
// QuadrupedScale tests are the measurements behind the unit and density.
#include "task/river/quadruped.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "core/rng.h"
#include "eval/check.h"  // kRestTravel: the rest law's bound
#include "physics/world.h"

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
  EXPECT_EQ(p.powered_stops, PoweredStops::Separate);  // the PD's implicit damper
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

// ---- in physics ----------------------------------------------------------

// what a drop measured, lengths in cell widths
struct Outcome {
  std::string failure;       // check_explosion's first message
  double torso_z = 0;        // torso's centre at the end
  double lowest_torso = 0;   // torso's centre, lowest from `stand_from` on
  double tilt = 0;           // largest angle of the torso's z from the vertical, from `stand_from` on
  double travel = 0;         // centre of mass, from `mark` to the end
  double speed = 0;          // fastest part over the last `still` seconds (u/s)
  double rate = 0;           // fastest joint over the last `still` seconds (rad/s)
  double gap = 0;            // joints' largest gap, whole run
};

struct Schedule {
  double seconds = 20;
  double mark = 10;
  double still = 5;
  double stand_from = 2;
};

// the quadruped dropped flat, its feet 0.01 u above the ground, every
// effector held at its signal from the first step
Outcome drop(const QuadrupedDef& def, const PhysicsDef& physics, std::span<const double> signals,
             const Schedule& sch = {}) {
  const double u = def.unit;
  const CreatureModel m = make_quadruped(def);
  World w(physics);
  w.add_creature(m, {{0, 0, quadruped_foot_depth(def) + 0.01 * u}, Mat3::identity()});
  const MotorDef motor = river_motor();
  Outcome o;
  o.lowest_torso = 1e300;
  Vec3 mark = w.centre_of_mass();
  const int steps = static_cast<int>(std::lround(sch.seconds / physics.dt));
  for (int i = 1; i <= steps; ++i) {
    w.apply_effectors(m, motor, signals);
    w.step();
    if (o.failure.empty()) o.failure = w.check_explosion();
    if (!std::isfinite(w.part_pose(kTorso).p.z)) break;
    const double t = i * physics.dt;
    if (std::abs(t - sch.mark) < physics.dt / 2) mark = w.centre_of_mass();
    const Pose torso = w.part_pose(kTorso);
    if (t >= sch.stand_from) {
      o.lowest_torso = std::min(o.lowest_torso, torso.p.z / u);
      o.tilt = std::max(o.tilt, std::acos(std::clamp(torso.R.m[2][2], -1.0, 1.0)));
    }
    if (t > sch.seconds - sch.still) {
      for (int p = 0; p < m.n_parts(); ++p) o.speed = std::max(o.speed, norm(w.part_velocity(p)) / u);
      for (const EffectorModel& e : m.effectors) o.rate = std::max(o.rate, std::abs(w.joint_rate(e.joint, e.dof)));
    }
  }
  o.torso_z = w.part_pose(kTorso).p.z / u;
  o.travel = norm(w.centre_of_mass() - mark) / u;
  o.gap = w.stats().max_joint_gap / u;
  return o;
}

std::vector<double> all(double s) { return std::vector<double>(kQuadrupedEffectors, s); }

// Standing: the torso's centre above this (u). The pose built has it at 0.525
// u (0.1 u of torso, then 0.425 u of leg below it); a body that has sunk onto
// its limbs has it at 0.2 u or less (the level upper limbs hang 0.1 u below
// the torso's bottom). Measured: 0.485.
constexpr double kStanding = 0.4;

TEST(Quadruped, TheBuiltPoseIsMidRangeAndPositiveLowersALimb) {
  // the torso held in the air, no gravity: each limb goes where its targets say
  const QuadrupedDef def;
  const double u = def.unit;
  const CreatureModel m = make_quadruped(def);
  PhysicsDef physics = river_physics(def);
  physics.gravity = 0;
  auto pose_at = [&](std::vector<double> signals) {
    World w(physics);
    w.add_creature(m, {{0, 0, 10 * u}, Mat3::identity()});
    w.fix_part_to_world(kTorso);
    for (int i = 0; i < 1000; ++i) {
      w.apply_effectors(m, river_motor(), signals);
      w.step();
    }
    std::vector<Pose> poses;
    for (int p = 0; p < m.n_parts(); ++p) poses.push_back(w.part_pose(p));
    std::vector<double> angles;
    for (const EffectorModel& e : m.effectors) angles.push_back(w.joint_position(e.joint, e.dof));
    return std::pair{poses, angles};
  };
  const Vec3 down{0, 0, -1};
  // 0: the pose built, every angle 0
  {
    auto [poses, angles] = pose_at(all(0));
    for (int e = 0; e < kQuadrupedEffectors; ++e) EXPECT_NEAR(angles[e], 0, 1e-6) << e;
    for (int leg = 0; leg < kLegs; ++leg)
      expect_near(poses[upper_limb(leg)].R.column(0), out_of(leg), 1e-6, "upper limb level");
  }
  // +1: upper limbs straight down, lower limbs at a right angle, pointing in
  {
    auto [poses, angles] = pose_at(all(1));
    for (int leg = 0; leg < kLegs; ++leg) {
      EXPECT_NEAR(angles[3 * leg + 1], kPi / 2, 1e-3) << leg;
      EXPECT_NEAR(angles[3 * leg + 2], kPi / 4, 1e-3) << leg;
      EXPECT_NEAR(dot(poses[upper_limb(leg)].R.column(0), down), 1, 1e-3) << leg;
      EXPECT_LT(poses[lower_limb(leg)].R.column(0).z, 1e-3) << leg;
      EXPECT_GT(poses[lower_limb(leg)].R.column(0).z, -1e-3) << leg;
    }
  }
  // -1: upper limbs straight up, lower limbs straight on
  {
    auto [poses, angles] = pose_at(all(-1));
    for (int leg = 0; leg < kLegs; ++leg) {
      EXPECT_NEAR(dot(poses[upper_limb(leg)].R.column(0), -1.0 * down), 1, 1e-3) << leg;
      EXPECT_NEAR(dot(poses[lower_limb(leg)].R.column(0), -1.0 * down), 1, 1e-3) << leg;
    }
  }
  // leg 0's yaw at +1 alone: it turns clockwise seen from above, onto +x
  {
    std::vector<double> s = all(0);
    s[0] = 1;
    auto [poses, angles] = pose_at(s);
    expect_near(poses[upper_limb(0)].R.column(0), {1, 0, 0}, 1e-3, "leg 0 turned to +x");
  }
}

TEST(Quadruped, StandsOnMidRangeTargetsAndComesToRest) {
  const QuadrupedDef def;
  Outcome o = drop(def, river_physics(def), all(0));
  EXPECT_EQ(o.failure, "");
  EXPECT_GT(o.lowest_torso, kStanding);  // measured 0.485
  EXPECT_LT(o.tilt, 0.01);               // level (symmetric): measured 0
  // at rest: in the last 5 of 20 s every part below 1e-5 u/s and every joint
  // below 1e-5 rad/s; the centre moves less than 1e-5 u in the last 10 s
  // (measured 2e-9 u/s, 2e-9 rad/s, 2e-8 u)
  EXPECT_LT(o.speed, 1e-5);
  EXPECT_LT(o.rate, 1e-5);
  EXPECT_LT(o.travel, 1e-5);
  EXPECT_LT(o.gap, 1e-3);  // measured 1e-6 u
}

TEST(Quadruped, ComesToRestUnderConstantTargetsOffTheMiddle) {
  // every effector at -1, -0.5, 0.5, 1, then 8 patterns of 12 signals drawn
  // uniformly in [-1, 1]; under both friction bounds. This light, slow body
  // (gravity's time scale sqrt(u / g) is 2 s) settles within 40 s where the
  // rest law's creatures take 5: measured from 40 to 60 s, at the rest law's
  // bound (kRestTravel of the body length; docs/physics.md)
  const QuadrupedDef def;
  const double bound = kRestTravel * make_quadruped(def).body_length() / def.unit;  // 0.049 u
  std::vector<std::vector<double>> patterns = {all(-1), all(-0.5), all(0.5), all(1)};
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    Rng rng(seed);
    std::vector<double> s(kQuadrupedEffectors);
    for (double& x : s) x = rng.uniform(-1, 1);
    patterns.push_back(s);
  }
  const Schedule sch{60, 40, 5, 2};
  for (FrictionBound fb : {FrictionBound::Lagged, FrictionBound::Ode}) {
    PhysicsDef physics = river_physics(def);
    physics.friction_bound = fb;
    for (std::size_t k = 0; k < patterns.size(); ++k) {
      const std::string what = "pattern " + std::to_string(k) + (fb == FrictionBound::Ode ? " (ode)" : " (lagged)");
      Outcome o = drop(def, physics, patterns[k], sch);
      EXPECT_EQ(o.failure, "") << what;
      EXPECT_LT(o.travel, bound) << what;  // measured at most 0.013 u
      EXPECT_LT(o.gap, 0.01) << what;      // measured at most 5e-4 u
    }
  }
}

// ---- the unit and density (docs/rivercrossing.md, "Unit and density") ----

TEST(QuadrupedScale, AtOneMetreAndDensityOneItSinksOntoItsLimbs) {
  // ODE's usual density and a 1 m cell: 0.36 kg, 1 kg m of weight product;
  // the hips would need 0.57 N m to hold it, 2.3 rad of ks's error
  const QuadrupedDef def{1, 1};
  Outcome o = drop(def, river_physics(def), all(0));
  EXPECT_EQ(o.failure, "");
  EXPECT_LT(o.torso_z, 0.25);  // measured 0.178
}

TEST(QuadrupedScale, FourTimesDenserItSinksOntoItsLimbs) {
  QuadrupedDef def;
  def.density *= 4;  // 0.4 kg m
  Outcome o = drop(def, river_physics(def), all(0));
  EXPECT_EQ(o.failure, "");
  EXPECT_LT(o.torso_z, 0.25);  // measured 0.191
  def.density /= 2;            // 0.2 kg m: still stands
  EXPECT_GT(drop(def, river_physics(def), all(0)).lowest_torso, kStanding);  // measured 0.442
}

TEST(QuadrupedScale, AOneMetreCellInAFortiethOfEarthsGravityStandsTheSame) {
  // only density x unit^4 x g and density x unit^5 matter: both the same
  const QuadrupedDef chosen;
  const QuadrupedDef metre{1, 4};
  PhysicsDef low = river_physics(metre);
  low.gravity = -9.81 / 40;
  const Outcome a = drop(chosen, river_physics(chosen), all(0));
  const Outcome b = drop(metre, low, all(0));
  EXPECT_EQ(b.failure, "");
  EXPECT_NEAR(a.torso_z, b.torso_z, 0.005);  // measured 0.4855 and 0.4857
}

}  // namespace
}  // namespace bx
