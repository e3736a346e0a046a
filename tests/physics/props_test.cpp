// Props (World::add_prop): a box dropped on a fixed disc comes to rest on
// its top and is seen touching it; a prop stands in the ground without
// touching it; a spinning prop turns at its rate whatever rests on it and
// carries what rests on it round; a ray hits a prop and names it.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/world.h"
#include "support/parts.h"

namespace bx {
namespace {

// an upright disc (a cylinder whose axis, a prop's x, points up) of
// diameter `diameter` and height `height`, standing on the ground at (x, y)
Prop disc(double x, double y, double diameter, double height, double spin = 0) {
  Prop p;
  p.shape = Shape::Cylinder;
  p.size = {height, diameter, diameter};
  p.pose = {{x, y, height / 2}, Mat3::rotation({0, 1, 0}, -kPi / 2)};  // x up
  p.spin = spin;
  return p;
}

// a 0.2 m cube of 1 kg dropped from z, its centre over (x, y)
CreatureModel cube(double x, double y, double z) {
  CreatureModel m;
  m.parts.push_back(bxtest::box_part({0.2, 0.2, 0.2}, 1, {x, y, z}));
  return m;
}

TEST(Props, ACubeDroppedOnAFixedDiscRestsOnItsTopTouchingIt) {
  PhysicsDef def;
  World w(def);
  EXPECT_EQ(w.add_prop(disc(0, 0, 1, 0.3)), 0);
  EXPECT_EQ(w.n_props(), 1);
  w.add_creature(cube(0, 0, 1), {{0, 0, 0}, Mat3::identity()});
  bool touched = false;
  for (int k = 0; k < 2 / def.dt; ++k) {
    w.step();
    touched |= w.prop_touched(0);
  }
  EXPECT_TRUE(touched);
  EXPECT_TRUE(w.prop_touched(0));  // resting on it
  // its centre half its side above the disc's top (0.3 m), within the contacts' give
  EXPECT_NEAR(w.part_pose(0).p.z, 0.3 + 0.1, 5e-3);
  EXPECT_NEAR(w.part_pose(0).p.x, 0, 1e-6);
  // beside the disc it falls to the ground and touches nothing of it
  World beside(def);
  beside.add_prop(disc(0, 0, 1, 0.3));
  beside.add_creature(cube(2, 0, 1), {{0, 0, 0}, Mat3::identity()});
  for (int k = 0; k < 2 / def.dt; ++k) {
    beside.step();
    EXPECT_FALSE(beside.prop_touched(0));
  }
  EXPECT_NEAR(beside.part_pose(0).p.z, 0.1, 5e-3);
}

TEST(Props, APropInTheGroundStaysWhereItIsAndTouchesNothing) {
  PhysicsDef def;
  World w(def);
  Prop sunk = disc(0, 0, 1, 0.3);
  sunk.pose.p.z = 0;  // half in the ground
  w.add_prop(sunk);
  w.add_prop(disc(0.2, 0, 1, 0.3, 1.0));  // through the first, spinning
  w.add_creature(cube(3, 0, 0.1), {{0, 0, 0}, Mat3::identity()});
  for (int k = 0; k < 100; ++k) {
    w.step();
    EXPECT_FALSE(w.prop_touched(0));
    EXPECT_FALSE(w.prop_touched(1));
  }
  EXPECT_EQ(w.prop_pose(0).p, sunk.pose.p);
  EXPECT_NEAR(w.prop_pose(1).p.x, 0.2, 1e-12);
  EXPECT_NEAR(w.prop_pose(1).p.z, 0.15, 1e-12);
}

TEST(Props, ASpinningPropTurnsAtItsRateAndCarriesWhatRestsOnIt) {
  PhysicsDef def;
  World w(def);
  const double spin = 2.0;  // rad/s
  w.add_prop(disc(0, 0, 1.2, 0.3, spin));
  // a cube resting off the axis, 0.3 m out
  w.add_creature(cube(0.3, 0, 0.4), {{0, 0, 0}, Mat3::identity()});
  const int steps = static_cast<int>(std::lround(1.0 / def.dt));
  for (int k = 0; k < steps; ++k) w.step();
  const double t = steps * def.dt;
  // the disc's x axis still points up; its y axis has turned spin t about the vertical
  const Pose p = w.prop_pose(0);
  const Vec3 up = p.R * Vec3{1, 0, 0}, side = p.R * Vec3{0, 1, 0};
  EXPECT_NEAR(up.z, 1, 1e-9);
  EXPECT_NEAR(std::atan2(side.y, side.x), kPi / 2 + spin * t - 2 * kPi * (spin * t > kPi / 2 ? 1 : 0), 1e-6);
  EXPECT_NEAR(p.p.x, 0, 1e-12);
  EXPECT_NEAR(p.p.y, 0, 1e-12);
  // friction carried the cube round with it: 0.3 m out, near the same angle
  const Vec3 c = w.part_pose(0).p;
  EXPECT_NEAR(std::hypot(c.x, c.y), 0.3, 0.03);
  EXPECT_NEAR(std::atan2(c.y, c.x), spin * t, 0.15);
  EXPECT_TRUE(w.prop_touched(0));
}

TEST(Props, ARayHitsAPropAndNamesIt) {
  PhysicsDef def;
  World w(def);
  w.add_prop(disc(0, 0, 1, 0.3));
  w.add_prop(disc(5, 0, 1, 0.3, 1.0));
  w.add_creature(cube(0, 3, 0.1), {{0, 0, 0}, Mat3::identity()});
  const RayHit h = w.ray({-2, 0, 0.1}, {1, 0, 0}, 10);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 1.5, 1e-9);  // the disc's side, 0.5 m from its axis
  EXPECT_EQ(h.entity.kind, WorldEntity::Kind::Prop);
  EXPECT_EQ(h.entity.index, 0);
  EXPECT_NEAR(h.normal.x, -1, 1e-9);
  const RayHit far = w.ray({3, 0, 0.1}, {1, 0, 0}, 10);
  ASSERT_TRUE(far.hit);
  EXPECT_NEAR(far.distance, 1.5, 1e-9);
  EXPECT_EQ(far.entity.index, 1);
  // over them, nothing but the ground
  EXPECT_EQ(w.ray({0, 0, 1}, {0, 0, -1}, 10).entity.kind, WorldEntity::Kind::Prop);
  EXPECT_NEAR(w.ray({0, 0, 1}, {0, 0, -1}, 10).distance, 0.7, 1e-9);
}

}  // namespace
}  // namespace bx
