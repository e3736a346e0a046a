// Muscles (MotorModel::Muscle, lessin2015 III-E): a spring between two
// parts whose stiffness the activation sets, integrated as ODE's soft
// distance constraint. Against the implicit spring law for one step, silent
// when not activated, holding a limb against gravity, and at rest under a
// constant activation.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/world.h"
#include "support/parts.h"

namespace bx {
namespace {

using bxtest::box_part;

// Two free 0.1 m cubes of masses m1 and m2 on the x axis, 2 m up, centres
// `gap` apart, joined by a muscle between their centres of rest length L0
// and strength k, driven by effector 0.
CreatureModel pair(double m1, double m2, double gap, double L0, double k) {
  CreatureModel c;
  c.parts = {box_part({0.1, 0.1, 0.1}, m1, {0, 0, 2}), box_part({0.1, 0.1, 0.1}, m2, {gap, 0, 2})};
  c.parts[1].parent = 0;
  c.muscles.push_back({0, 1, {0, 0, 2}, {gap, 0, 2}, k, L0});
  EffectorModel e;
  e.muscle = 0;
  c.effectors.push_back(e);
  return c;
}

MotorDef muscles(double damping) {
  MotorDef m;
  m.model = MotorModel::Muscle;
  m.muscle_damping = damping;
  return m;
}

TEST(Muscle, OneStepFollowsTheImplicitSpringLaw) {
  // stretched by x beyond its rest length, activation a: the spring a k and
  // the damper c, solved with the end-of-step velocity (ODE's ERP and CFM
  // as the manual derives them): relative velocity after one step of h
  //   v = h (a k) x / (mu + h c + h^2 (a k)),  mu the reduced mass
  const double m1 = 2, m2 = 0.5, L0 = 0.5, x = 0.1, k = 400, c = 3, h = 0.001;
  for (double a : {1.0, 0.5, 0.25}) {
    PhysicsDef def;
    def.gravity = 0;
    def.dt = h;
    World w(def);
    CreatureModel cm = pair(m1, m2, L0 + x, L0, k);
    w.add_creature(cm, {{0, 0, 0}, Mat3::identity()});
    const double s[1] = {a};
    w.apply_effectors(cm, muscles(c), s);
    w.step();
    const double mu = m1 * m2 / (m1 + m2), kp = a * k;
    const double closing = w.part_velocity(0).x - w.part_velocity(1).x;
    EXPECT_NEAR(closing, h * kp * x / (mu + h * c + h * h * kp), 1e-9) << "activation " << a;
    // momentum: equal and opposite forces
    EXPECT_NEAR(m1 * w.part_velocity(0).x + m2 * w.part_velocity(1).x, 0, 1e-12);
  }
}

TEST(Muscle, SilentItPullsNothingAndAtItsRestLengthActiveNeither) {
  PhysicsDef def;
  def.gravity = 0;
  World w(def);
  CreatureModel cm = pair(1, 1, 0.6, 0.5, 400);
  w.add_creature(cm, {{0, 0, 0}, Mat3::identity()});
  const double silent[1] = {0};
  for (int i = 0; i < 100; ++i) {
    w.apply_effectors(cm, muscles(0), silent);
    w.step();
  }
  EXPECT_EQ(w.part_velocity(1).x, 0.0);
  // at rest length, fully active: no force
  World v(def);
  CreatureModel rest = pair(1, 1, 0.5, 0.5, 400);
  v.add_creature(rest, {{0, 0, 0}, Mat3::identity()});
  const double full[1] = {1};
  for (int i = 0; i < 100; ++i) {
    v.apply_effectors(rest, muscles(5), full);
    v.step();
  }
  EXPECT_NEAR(v.part_velocity(1).x, 0.0, 1e-9);
}

// A fixed 0.8 m tall post and a 0.6 m limb sticking out of its side,
// hinged about y where they meet, which gravity pulls down; a muscle from
// the post's top corner to the limb's far end at its built length (a lever
// arm of 0.31 m about the hinge), driven by effector 0.
CreatureModel limb_on_post() {
  CreatureModel cm;
  cm.parts = {box_part({0.2, 0.2, 0.8}, 5, {0, 0, 1}), box_part({0.6, 0.1, 0.1}, 0.5, {0.4, 0, 1.05})};
  cm.parts[1].parent = 0;
  JointModel j;
  j.type = JointType::Hinge;
  j.parent = 0;
  j.child = 1;
  j.anchor = {0.1, 0, 1.05};
  j.axis1 = {0, 1, 0};
  cm.joints.push_back(j);
  const Vec3 top{0.1, 0, 1.4}, tip{0.7, 0, 1.1};
  cm.muscles.push_back({0, 1, top, tip, 2000, norm(tip - top)});
  EffectorModel e;
  e.muscle = 0;
  cm.effectors.push_back(e);
  return cm;
}

// limb_on_post()'s limb: its turn (rad) after `seconds` under a constant
// activation, and its largest joint speed over the last second.
struct Held {
  double turn, speed;
};
Held hold(double activation, double seconds = 5) {
  PhysicsDef def;
  def.dt = 0.005;
  World w(def);
  CreatureModel cm = limb_on_post();
  w.add_creature(cm, {{0, 0, 0}, Mat3::identity()});
  w.fix_part_to_world(0);
  const double s[1] = {activation};
  double speed = 0;
  while (w.time() < seconds) {
    w.apply_effectors(cm, muscles(20), s);
    w.step();
    EXPECT_EQ(w.check_explosion(), "");
    if (w.time() > seconds - 1) speed = std::max(speed, std::abs(w.joint_rate(0, 0)));
  }
  return {std::abs(w.joint_position(0, 0)), speed};
}

TEST(Muscle, ActiveItHoldsALimbUpAgainstGravitySilentTheLimbFalls) {
  const Held active = hold(1), half = hold(0.5), silent = hold(0);
  // the small sag where the spring's torque k r^2 theta holds the limb's
  // weight m g l about the hinge: r = 0.313 m (the lever arm), l = 0.3 m
  const double r = 0.35 * 0.6 / std::sqrt(0.6 * 0.6 + 0.3 * 0.3), sag = 0.5 * 9.81 * 0.3 / (2000 * r * r);
  EXPECT_NEAR(active.turn, sag, 0.02 * sag);  // 0.0075 rad
  EXPECT_NEAR(half.turn, 2 * sag, 0.04 * sag);  // half the stiffness, twice the sag
  EXPECT_GT(silent.turn, 1.0);  // hanging down
  // under a constant activation the limb comes to rest
  EXPECT_LT(active.speed, 1e-3);
  EXPECT_LT(half.speed, 1e-3);
}

TEST(Muscle, ABrakeHoldsItWhereItWasThenReleasedItPullsToItsRestLength) {
  // stretched 0.1 m past its rest length: braked, it holds that length (no
  // force, where the old brake pulled it to its rest length: a contraction);
  // driven again, it pulls by the implicit spring law from where it is
  PhysicsDef def;
  def.gravity = 0;
  def.dt = 0.001;
  World w(def);
  CreatureModel cm = pair(2, 0.5, 0.6, 0.5, 400);
  w.add_creature(cm, {{0, 0, 0}, Mat3::identity()});
  for (int i = 0; i < 100; ++i) {
    w.brake_effectors(cm, muscles(0), 0.5);
    w.step();
  }
  EXPECT_NEAR(w.part_velocity(0).x - w.part_velocity(1).x, 0, 1e-12);
  EXPECT_NEAR(w.part_pose(1).p.x - w.part_pose(0).p.x, 0.6, 1e-9);
  const double full[1] = {1};
  w.apply_effectors(cm, muscles(0), full);
  w.step();
  const double mu = 2 * 0.5 / 2.5, kp = 400, h = 0.001;
  EXPECT_NEAR(w.part_velocity(0).x - w.part_velocity(1).x, h * kp * 0.1 / (mu + h * h * kp), 1e-9);
}

TEST(Muscle, ABrakeHoldsADroopingLimbAtItsAngleNotAtItsRestLength) {
  // limb_on_post()'s limb, silent for 0.3 s (it droops), then braked with all its
  // strength: it stays where it drooped to, within the sag of its spring;
  // pulling to its rest length (its built length) would lift it back to 0
  PhysicsDef def;
  def.dt = 0.005;
  World w(def);
  CreatureModel cm = limb_on_post();
  w.add_creature(cm, {{0, 0, 0}, Mat3::identity()});
  w.fix_part_to_world(0);
  const double silent[1] = {0};
  while (w.time() < 0.3) {
    w.apply_effectors(cm, muscles(20), silent);
    w.step();
  }
  const double drooped = std::abs(w.joint_position(0, 0));
  ASSERT_GT(drooped, 0.2);
  while (w.time() < 3.3) {
    w.brake_effectors(cm, muscles(20), 1);
    w.step();
  }
  // the drooping limb's swing is caught within a few of the active sag (0.0075 rad)
  EXPECT_NEAR(std::abs(w.joint_position(0, 0)), drooped, 0.1);
  EXPECT_LT(std::abs(w.joint_rate(0, 0)), 1e-2);
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

// A muscle's length node (SensorType::MuscleLength, lessin2015 III-E): its
// anchors' distance over twice its built length, so 0.5 as built.
TEST(Muscle, ItsLengthNodeReadsHalfAsBuiltAndFollowsTheStretch) {
  PhysicsDef def;
  def.gravity = 0;
  World w(def);
  CreatureModel cm = pair(1, 1, 0.6, 0.3, 400);  // built 0.6 m apart, rest length 0.3 m
  cm.muscles[0].length = 0.6;
  SensorModel s;
  s.type = SensorType::MuscleLength;
  s.part = 1;
  s.muscle = 0;
  cm.sensors.push_back(s);
  w.add_creature(cm, {{0, 0, 0}, Mat3::identity()});
  double reading[1] = {-1};
  w.read_sensors(cm, reading);
  EXPECT_NEAR(reading[0], 0.5, 1e-12);
  // fully active, it contracts towards its rest length: the node follows the distance
  const double full[1] = {1};
  for (int i = 0; i < 600; ++i) {
    w.apply_effectors(cm, muscles(20), full);
    w.step();
  }
  w.read_sensors(cm, reading);
  const double apart = w.part_pose(1).p.x - w.part_pose(0).p.x;
  EXPECT_NEAR(reading[0], apart / (2 * 0.6), 1e-9);
  EXPECT_NEAR(reading[0], 0.25, 0.01);  // at its rest length, half as long as built
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

// The muscles' work meter (World::muscle_work, lessin2015's efficiency):
// without gravity or damping a stretched muscle's spring turns its energy
// into the two cubes' kinetic energy. Until the cubes are fastest (the
// muscle passes its rest length) it only pulls them together, so the
// metered |power| dt is that kinetic energy; silent, it meters nothing.
TEST(Muscle, ItsWorkIsTheKineticEnergyItGives) {
  PhysicsDef def;
  def.gravity = 0;
  def.dt = 0.0005;
  World w(def);
  const double m1 = 2, m2 = 0.5;
  CreatureModel cm = pair(m1, m2, 0.6, 0.5, 400);
  w.add_creature(cm, {{0, 0, 0}, Mat3::identity()});
  auto kinetic = [&] {
    const double v0 = norm(w.part_velocity(0)), v1 = norm(w.part_velocity(1));
    return 0.5 * m1 * v0 * v0 + 0.5 * m2 * v1 * v1;
  };
  const double full[1] = {1};
  double peak = 0, work_at_peak = 0;
  for (int i = 0; i < 2000; ++i) {
    w.apply_effectors(cm, muscles(0), full);
    w.step();
    if (kinetic() < peak) break;  // past its rest length: it brakes them now
    peak = kinetic();
    work_at_peak = w.muscle_work();
  }
  // the spring's energy at the start, 1/2 k x^2, less what the implicit
  // step's damping takes
  EXPECT_GT(peak, 0.9 * 0.5 * 400 * 0.1 * 0.1);
  // force x each step's displacement: 1.25% above at this step (the
  // step's end velocity moves the anchors), an error that shrinks with it
  EXPECT_NEAR(work_at_peak, peak, 0.02 * peak);
  EXPECT_GT(w.muscle_work(), work_at_peak);  // braking them costs work too

  World silent(def);
  silent.add_creature(cm, {{0, 0, 0}, Mat3::identity()});
  const double off[1] = {0};
  for (int i = 0; i < 100; ++i) {
    silent.apply_effectors(cm, muscles(0), off);
    silent.step();
  }
  EXPECT_EQ(silent.muscle_work(), 0.0);
}

}  // namespace
}  // namespace bx
