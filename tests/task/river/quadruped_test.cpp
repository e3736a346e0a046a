// The river crossing's quadruped (Stanton & Channon 2015, "Environment and
// Physical Model"; docs/rivercrossing.md, "The quadruped"): the body as the
// paper gives it, and, in real ODE physics with the paper's PD motors, that it
// stands on mid-range targets and comes to rest under constant ones. The
// QuadrupedScale tests are the measurements behind the unit and density.
// Measurements marked "measured" are at the defaults (a 0.1 m cell, 1000
// kg/m^3) unless they say otherwise.
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
  // the defaults: a 1 m cell at 0.1 kg/m^3, 0.1 kg m of weight product
  // (QuadrupedDef), a body of 0.036 kg
  EXPECT_EQ(def.unit, 1);
  EXPECT_EQ(def.density, 0.1);
  EXPECT_NEAR(def.density * std::pow(def.unit, 4), 0.1, 1e-12);
  EXPECT_NEAR(make_quadruped(def).total_mass(), 0.036, 1e-12);
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
// the torso's bottom). Measured: 0.485 at 20 s.
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
  EXPECT_GT(o.lowest_torso, kStanding);  // measured 0.485 (at 20 s)
  EXPECT_LT(o.tilt, 0.01);               // level (symmetric): measured 0
  // at rest but for the creep of its feet (ODE's CFM on the friction rows,
  // QuadrupedScale.ItCreepsAtTheWorldsCFMTimesItsFrictionForce): in the last
  // 5 of 20 s every part below 1e-3 u/s and every joint below 1e-3 rad/s; the
  // centre moves less than 0.01 u in the last 10 s (measured 3.0e-4 u/s,
  // 2.9e-4 rad/s, 2.3e-3 u, the torso sinking)
  EXPECT_LT(o.speed, 1e-3);
  EXPECT_LT(o.rate, 1e-3);
  EXPECT_LT(o.travel, 0.01);
  EXPECT_LT(o.gap, 1e-3);  // measured 2.8e-5 u
}

TEST(Quadruped, ComesToRestUnderConstantTargetsOffTheMiddle) {
  // every effector at -1, -0.5, 0.5, 1, then 8 patterns of 12 signals drawn
  // uniformly in [-1, 1]; under both friction bounds. Some patterns take up
  // to 20 s to fall into place (the PD's lag kd / ks is 0.7 s, and a leg
  // pushing sideways creeps: QuadrupedScale.ItCreepsAtTheWorldsCFMTimesIts-
  // FrictionForce) where the rest law's creatures take 5: measured from 40 to
  // 60 s, at the rest law's bound (kRestTravel of the body length;
  // docs/physics.md)
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
      EXPECT_LT(o.travel, bound) << what;  // measured at most 0.021 u (seed 1)
      EXPECT_LT(o.gap, 0.01) << what;      // measured at most 7.5e-4 u
    }
  }
}

TEST(Quadruped, AHipFollowsItsTargetAsALagOfKdOverKs) {
  // the torso held in the air, no gravity, every hip lift driven. A limb this
  // light (a leg's inertia about its hip is 1.2e-4 kg m^2, kd dt / I = 15) moves
  // as kd theta' = ks (theta_d - theta): a first-order lag of kd / ks = 0.7 s
  // whatever the body's size. A step of the target is 63% done at 0.7 s; a
  // 1 Hz target reaches 1 / sqrt(1 + (2 pi 0.7)^2) = 0.22 of its amplitude
  // (the pattern generator's rhythm swings a hip a fifth of its command)
  const QuadrupedDef def;
  const CreatureModel m = make_quadruped(def);
  PhysicsDef physics = river_physics(def);
  physics.gravity = 0;
  const MotorDef motor = river_motor();
  const double tau = motor.kd / motor.kp, w = 2 * kPi;
  // leg 0's lift under signal(t) on every hip lift, after 5 s at 0
  auto run = [&](auto signal, double seconds, auto probe) {
    World world(physics);
    world.add_creature(m, {{0, 0, 10 * def.unit}, Mat3::identity()});
    world.fix_part_to_world(kTorso);
    std::vector<double> s(kQuadrupedEffectors, 0.0);
    for (int i = 0; i < 500; ++i) {
      world.apply_effectors(m, motor, s);
      world.step();
    }
    for (int i = 1; i <= std::lround(seconds / physics.dt); ++i) {
      const double t = i * physics.dt;
      for (int leg = 0; leg < kLegs; ++leg) s[3 * leg + 1] = signal(t);
      world.apply_effectors(m, motor, s);
      world.step();
      probe(t, world.joint_position(hip_joint(0), 1));
    }
  };
  // a step to s = 0.5: pi/4 rad
  const double target = 0.5 * kPi / 2;
  double t63 = -1;
  run([](double) { return 0.5; }, 3, [&](double t, double x) {
    if (t63 < 0 && x >= (1 - std::exp(-1.0)) * target) t63 = t;
  });
  EXPECT_NEAR(t63, tau, 0.03);  // measured 0.70 s (90% at 1.60 s)
  // s = 0.5 sin(2 pi t): its swing over the last 5 of 15 s
  double hi = -1, lo = 1;
  run([&](double t) { return 0.5 * std::sin(w * t); }, 15, [&](double t, double x) {
    if (t > 10) {
      hi = std::max(hi, x);
      lo = std::min(lo, x);
    }
  });
  const double gain = 0.5 * (hi - lo) / target;
  EXPECT_NEAR(gain, 1 / std::hypot(1, w * tau), 0.01);  // 0.222; measured 0.223
}

TEST(Quadruped, AScriptedOneHertzGaitWalksUnderThePapersGains) {
  // The lag above does not stop the body walking at the pattern generator's
  // rhythm: every hip's yaw and lift at full command, s = sin(2 pi t + p_leg)
  // for the yaw and its negative for the lift (lift half a cycle from the
  // yaw), legs 0, 1 and 3 in phase and leg 2 half a cycle apart (pattern 36
  // of a scratch search over 256 such gaits; docs/rivercrossing.md, "What it
  // costs"), knees mid-range. The torso's travel in the plane from 5 s to 25
  // s, in cell widths per second: measured 0.146 at dt, 0.133 at dt/2 and
  // 0.133 at dt/4 (a cell in 7-8 s, the grid's 20 cells in under 3 minutes;
  // over a minute's walk 0.12, as fast in its second half), joints within
  // 0.2 mm
  const QuadrupedDef def;
  const CreatureModel m = make_quadruped(def);
  auto speed = [&](double div) {
    PhysicsDef physics = river_physics(def);
    physics.dt /= div;
    World w(physics);
    w.add_creature(m, {{0, 0, quadruped_foot_depth(def) + 0.01 * def.unit}, Mat3::identity()});
    std::vector<double> s(kQuadrupedEffectors, 0.0);
    Vec3 start{};
    const int steps = static_cast<int>(std::lround(25 / physics.dt));
    for (int i = 1; i <= steps; ++i) {
      const double t = i * physics.dt;
      for (int leg = 0; leg < kLegs; ++leg) {
        const double wave = std::sin(2 * kPi * t + (leg == 2 ? kPi : 0));
        s[3 * leg] = wave;
        s[3 * leg + 1] = -wave;
      }
      w.apply_effectors(m, river_motor(), s);
      w.step();
      EXPECT_EQ(w.check_explosion(), "") << "dt / " << div << " at " << t << " s";
      if (i == static_cast<int>(std::lround(5 / physics.dt))) start = w.part_pose(kTorso).p;
    }
    EXPECT_LT(w.stats().max_joint_gap / def.unit, 0.005) << "dt / " << div;  // measured 1.5e-3 u at dt
    const Vec3 end = w.part_pose(kTorso).p;
    return std::hypot(end.x - start.x, end.y - start.y) / def.unit / 20;
  };
  const double at_dt = speed(1), at_half = speed(2);
  EXPECT_GT(at_dt, 0.08);
  EXPECT_GT(at_half, 0.08);
  EXPECT_NEAR(at_half / at_dt, 1, 0.25);
}

// ---- the unit and density (docs/rivercrossing.md, "Unit and density") ----

TEST(QuadrupedScale, AtOneMetreAndDensityOneItSinksOntoItsLimbs) {
  // ODE's usual density and a 1 m cell: 0.36 kg, 1 kg m of weight product;
  // the hips would need 0.57 N m to hold it, 2.3 rad of ks's error
  const QuadrupedDef def{1, 1};
  Outcome o = drop(def, river_physics(def), all(0));
  EXPECT_EQ(o.failure, "");
  EXPECT_LT(o.torso_z, 0.25);  // measured 0.185
}

TEST(QuadrupedScale, TwiceAsDenseItStandsFourTimesItSinks) {
  // the weight product, density x unit^4, against ks: 0.2 kg m still stands,
  // 0.4 kg m sinks onto its limbs (0.3 kg m sags to 0.31 u)
  QuadrupedDef def;
  def.density *= 2;  // 0.2 kg m
  EXPECT_GT(drop(def, river_physics(def), all(0)).lowest_torso, kStanding);  // measured 0.430
  def.density *= 2;  // 0.4 kg m
  Outcome o = drop(def, river_physics(def), all(0));
  EXPECT_EQ(o.failure, "");
  EXPECT_LT(o.torso_z, 0.25);  // measured 0.186
}

TEST(QuadrupedScale, TheLimbsInertiaNoLongerMatters) {
  // the same weight product, 0.1 kg m, in cells of 0.1, 1, 10 and 40 m: the
  // limbs' inertia product density x unit^5 runs from 0.01 to 4 kg m^2 (kd dt
  // over a lower limb's inertia about its knee from 100 to 0.25). With World's
  // old explicit damper the 10 m body tore on mid-range targets and the 20 m
  // one with every leg pointing up, which forced a 40 m cell; with the
  // implicit damper none tears, and each stands at the same height
  std::vector<double> heights;
  for (double unit : {0.1, 1.0, 10.0, 40.0}) {
    const QuadrupedDef def{unit, 0.1 / std::pow(unit, 4)};
    const std::string what = "unit " + std::to_string(unit);
    const Outcome up = drop(def, river_physics(def), all(-1));
    EXPECT_EQ(up.failure, "") << what;
    const Outcome mid = drop(def, river_physics(def), all(0));
    EXPECT_EQ(mid.failure, "") << what;
    EXPECT_GT(mid.lowest_torso, kStanding) << what;
    heights.push_back(mid.torso_z);
  }
  // measured 0.485, 0.491, 0.491, 0.490 u after 20 s (the 0.1 m body lower
  // by its creep)
  for (double h : heights) EXPECT_NEAR(h, heights.back(), 0.01);
}

TEST(QuadrupedScale, ItCreepsAtTheWorldsCFMTimesItsFrictionForce) {
  // ODE gives a contact's friction rows the world's CFM: each slips at CFM
  // times the force it carries (m/s per N), a viscous creep under a standing
  // body's weight. In 0.1 m cells of water's density (3.5 N; the paper's CFM
  // 5e-5) the torso sinks 3e-4 u/s (3e-5 m/s; measured over 600 s: from
  // 0.485 to 0.331 u). A tenth of the CFM creeps a tenth as fast; so does the
  // same weight product in a cell 3.2 times larger: the creep in u/s goes as
  // CFM x density x unit^2 x g, so the default 1 m cell at 0.1 kg/m^3
  // creeps a hundredth as fast (measured 3e-6 u/s; 3e-8 at 10 m)
  const QuadrupedDef def{0.1, 1000};
  const Outcome paper = drop(def, river_physics(def), all(0));
  PhysicsDef stiffer = river_physics(def);
  stiffer.cfm /= 10;
  const Outcome tenth = drop(def, stiffer, all(0));
  EXPECT_GT(paper.speed, 1e-4);                       // measured 3.0e-4 u/s
  EXPECT_NEAR(tenth.speed / paper.speed, 0.1, 0.02);  // measured 0.100
  const Outcome metre = drop(QuadrupedDef{}, river_physics(QuadrupedDef{}), all(0));
  EXPECT_NEAR(metre.speed / paper.speed, 0.01, 0.003);  // measured 3.0e-6 u/s
}

}  // namespace
}  // namespace bx
