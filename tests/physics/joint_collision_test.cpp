// JointModel::parts_collide: a joint whose two parts collide is limited by
// their shapes (lessin2015 III-B), with no stops of its own; without it the
// parts pass through each other, as in the other dialects.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/world.h"
#include "support/parts.h"

namespace bx {
namespace {

// A fixed 1 m cube and a 1 x 0.2 x 0.2 m bar lying along +x on its top, its
// near end 1 cm past the cube's edge, hinged about y at that edge; a torque
// turns the bar down past the cube's side, which it meets when vertical.
// Returns the hinge's largest turn (rad) over `seconds`.
double largest_turn(bool parts_collide, bool self_collision, double seconds = 3) {
  PhysicsDef def;
  def.gravity = 0;
  def.dt = 0.001;
  def.self_collision = self_collision;
  World w(def);
  CreatureModel m;
  m.parts = {bxtest::box_part({1, 1, 1}, 10, {0, 0, 2}),
             bxtest::box_part({1, 0.2, 0.2}, 1, {1.01, 0, 2.6}, 0)};  // the bar: x 0.51..1.51, z 2.5..2.7
  JointModel j;
  j.type = JointType::Hinge;
  j.parent = 0;
  j.child = 1;
  j.anchor = {0.5, 0, 2.5};  // the cube's top edge
  j.axis1 = {0, 1, 0};       // turning +x towards -z
  j.parts_collide = parts_collide;
  m.joints.push_back(j);
  EffectorModel e;
  e.joint = 0;
  e.cross_section = 0.01;
  m.effectors.push_back(e);
  w.add_creature(m, {{0, 0, 0}, Mat3::identity()});
  w.fix_part_to_world(0);
  const MotorDef motor = bxtest::torque_motor(100);  // 1 N m
  const double s[1] = {1.0};
  double most = 0;
  while (w.time() < seconds) {
    w.apply_effectors(m, motor, s);
    w.step();
    EXPECT_EQ(w.check_explosion(), "");
    most = std::max(most, std::abs(w.joint_position(0, 0)));
  }
  return most;
}

TEST(JointCollision, ThePartsShapesStopTheJointWhereTheyMeet) {
  // the bar's lower face meets the cube's side when it hangs straight down
  const double stopped = largest_turn(true, true);
  EXPECT_GT(stopped, 0.48 * kPi);  // measured 0.516 pi: the contact yields a little
  EXPECT_LT(stopped, 0.53 * kPi);
  // a per-joint choice: unjoined parts that do not collide leave it so
  EXPECT_NEAR(largest_turn(true, false), stopped, 1e-9);
}

TEST(JointCollision, WithoutItTheBarTurnsThroughTheCube) {
  EXPECT_GT(largest_turn(false, true), 0.75 * kPi);
}

}  // namespace
}  // namespace bx
