// World::ray against geometry: the ground, a box's face, a sphere, which
// surface is nearest (occlusion), and rays too short to reach anything.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/world.h"
#include "support/parts.h"

namespace bx {
namespace {

PartModel part(Shape shape, Vec3 size, Vec3 pos) { return bxtest::part(shape, size, 1, pos); }

// a world of the ground and the given parts (unjoined; nothing is stepped)
struct Scene {
  PhysicsDef def;
  World w{def};
  explicit Scene(std::vector<PartModel> parts) {
    CreatureModel m;
    m.parts = std::move(parts);
    for (std::size_t i = 1; i < m.parts.size(); ++i) m.parts[i].parent = 0;
    w.add_creature(m, {{0, 0, 0}, Mat3::identity()});
  }
};

void expect_vec(Vec3 a, Vec3 b, double tol = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Ray, StrikesTheGroundWhereTheLineMeetsIt) {
  Scene s({part(Shape::Box, {0.4, 0.4, 0.4}, {10, 10, 1})});
  RayHit h = s.w.ray({1, 2, 3}, {0, 0, -1}, 10);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 3, 1e-9);
  expect_vec(h.point, {1, 2, 0});
  expect_vec(h.normal, {0, 0, 1});
  EXPECT_EQ(h.entity, (WorldEntity{WorldEntity::Kind::Ground, 0}));
  // slanted, its direction not of unit length: 2 sqrt 2 to (2, 0, 0)
  h = s.w.ray({0, 0, 2}, {5, 0, -5}, 10);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 2 * std::sqrt(2.0), 1e-9);
  expect_vec(h.point, {2, 0, 0});
}

TEST(Ray, StrikesABoxOnTheFaceItMeetsAndNamesThePart) {
  Scene s({part(Shape::Box, {0.4, 0.4, 0.4}, {5, 5, 1}), part(Shape::Box, {0.4, 0.4, 0.4}, {0, 0, 1})});
  RayHit h = s.w.ray({-2, 0.1, 1.1}, {1, 0, 0}, 10);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 1.8, 1e-9);
  expect_vec(h.point, {-0.2, 0.1, 1.1});
  expect_vec(h.normal, {-1, 0, 0});
  EXPECT_EQ(h.entity, (WorldEntity{WorldEntity::Kind::Part, 1}));
  // too short to reach it, and the ground is not in the way: nothing
  EXPECT_FALSE(s.w.ray({-2, 0.1, 1.1}, {1, 0, 0}, 1.7).hit);
  // parallel to the ground, past every part: nothing
  EXPECT_FALSE(s.w.ray({-2, 3, 1.1}, {1, 0, 0}, 100).hit);
}

TEST(Ray, AStraightDownRayStopsAtTheBoxNotTheGroundBelowIt) {
  Scene s({part(Shape::Box, {0.4, 0.4, 0.4}, {0, 0, 1})});
  RayHit h = s.w.ray({0.1, -0.1, 3}, {0, 0, -1}, 10);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 1.8, 1e-9);  // the top face at z = 1.2
  expect_vec(h.normal, {0, 0, 1});
  EXPECT_EQ(h.entity.kind, WorldEntity::Kind::Part);
  // beside the box the ground is what it meets
  h = s.w.ray({0.5, 0, 3}, {0, 0, -1}, 10);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 3, 1e-9);
  EXPECT_EQ(h.entity.kind, WorldEntity::Kind::Ground);
}

TEST(Ray, OfTwoPartsOnItsLineTheNearerOccludesTheFarther) {
  Scene s({part(Shape::Box, {0.4, 0.4, 0.4}, {2, 0, 1}), part(Shape::Box, {0.2, 0.2, 0.2}, {1, 0, 1})});
  RayHit h = s.w.ray({0, 0, 1}, {1, 0, 0}, 10);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 0.9, 1e-9);
  EXPECT_EQ(h.entity.index, 1);
  // from the far side, the other one first
  h = s.w.ray({4, 0, 1}, {-1, 0, 0}, 10);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.distance, 1.8, 1e-9);
  EXPECT_EQ(h.entity.index, 0);
}

TEST(Ray, StrikesASphereWhereTheLineFirstMeetsItsSurface) {
  const double r = 0.3, off = 0.1;
  Scene s({part(Shape::Sphere, {2 * r, 2 * r, 2 * r}, {0, 0, 1})});
  RayHit h = s.w.ray({-2, off, 1}, {1, 0, 0}, 10);
  ASSERT_TRUE(h.hit);
  const double x = -std::sqrt(r * r - off * off);
  EXPECT_NEAR(h.distance, 2 + x, 1e-9);
  expect_vec(h.point, {x, off, 1});
  expect_vec(h.normal, {x / r, off / r, 0});
}

}  // namespace
}  // namespace bx
