// A creature's ODE evaluation replayed open loop in MuJoCo (io/mujoco_replay.h).
#include <gtest/gtest.h>

#include <cmath>

#include "brain/controller.h"
#include "io/mujoco_replay.h"
#include "support/creatures.h"

namespace bx {
namespace {

// miconi_stroke's servos swing its limbs to their stops within a second; in
// the air (no gravity, held clear of the ground) the replayed motors must move
// MuJoCo's joints as ODE's moved: every joint within 0.1 rad (the stops'
// softness differs by about 0.05 rad). Motors solved one at a time, blind to
// how the stops and the other motors respond, miss by 0.5-1 rad.
TEST(MujocoReplay, ServoMotorsDriveTheJointsAsInOdeInTheAir) {
  auto c = bxtest::develop_creature("miconi_stroke");
  ASSERT_TRUE(c.dev.viable());
  SimConfig cfg = c.cfg.sim;
  cfg.physics.gravity = 0;
  const CreatureModel& m = *c.dev.model;
  auto r = crosscheck_mujoco(m, GraphBrain(m.brain), cfg, 1, 2.0);
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_NEAR(r->seconds, 2.0, 1e-9);
  EXPECT_GT(r->steps, 0);
  ASSERT_EQ(r->variants.size(), 4u);
  for (const CrossSimVariant& v : r->variants) EXPECT_LT(v.first_second_angle_gap, 0.1) << v.name;
}

// A torque motor's no-load speed is a velocity motor too: a hinged pair's
// oscillator swings its hinge alike in both (to its stops at +-1 rad, which
// MuJoCo's softer limits let it pass by about 0.05 rad), and the report's
// span is the task's whole run when it marks none.
TEST(MujocoReplay, AHingedPairSwingsAlikeAndTheSpanIsTheRun) {
  auto c = bxtest::develop_creature("hinged_pair");
  ASSERT_TRUE(c.dev.viable());
  SimConfig cfg = c.cfg.sim;
  cfg.physics.gravity = 0;
  const CreatureModel& m = *c.dev.model;
  auto r = crosscheck_mujoco(m, GraphBrain(m.brain), cfg, 3, 1.0);
  ASSERT_TRUE(r.ok()) << r.error();
  for (const CrossSimVariant& v : r->variants) EXPECT_LT(v.first_second_angle_gap, 0.1) << v.name;
  EXPECT_LE(r->from, r->to);
  EXPECT_LE(r->to, r->seconds + 1e-9);
}

// What MJCF cannot carry is refused with the reason, not replayed wrong.
TEST(MujocoReplay, MusclesAreRefusedWithTheReason) {
  auto c = bxtest::develop_creature("lessin_crawler");
  ASSERT_TRUE(c.dev.viable());
  const CreatureModel& m = *c.dev.model;
  auto r = crosscheck_mujoco(m, GraphBrain(m.brain), c.cfg.sim, 1, 1.0);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("muscles"), std::string::npos) << r.error();
}

}  // namespace
}  // namespace bx
