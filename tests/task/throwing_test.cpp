// Throwing scores (chaumont2007 4.2): D_p from release to rest, the rest
// test, and D_t, the least distance from a target to the projectile's path,
// against closed forms.
#include "task/throwing.h"

#include "develop/creature_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bx {
namespace {

constexpr double g = 9.81;

// an observation the value methods' tests do not read
struct Nowhere : Observation {
  double time() const override { return 0; }
  Vec3 centre_of_mass() const override { return {}; }
  int n_parts() const override { return 0; }
  Pose part_pose(int) const override { return {}; }
  bool touches_part(int) const override { return false; }
};

// a projectile released at p0 with velocity v flies until it lands, then lies still
void fly(ThrowingTask& t, const ThrowingDef& def, Vec3 p0, Vec3 v, double dt) {
  t.release(0, p0);
  Vec3 p = p0;
  double s = 0;
  while (true) {
    s += dt;
    p = {p0.x + v.x * s, p0.y + v.y * s, p0.z + v.z * s - 0.5 * g * s * s};
    if (p.z <= 0) break;
    t.observe(s, p);
  }
  p.z = 0;
  for (int k = 0; k * dt <= def.rest_seconds + dt; ++k) t.observe(s += dt, p);
}

TEST(Throwing, PointSegmentDistance) {
  EXPECT_DOUBLE_EQ(point_segment_distance({0, 1, 0}, {-1, 0, 0}, {1, 0, 0}), 1.0);
  EXPECT_DOUBLE_EQ(point_segment_distance({3, 4, 0}, {-1, 0, 0}, {0, 0, 0}), 5.0);  // past the end
  EXPECT_DOUBLE_EQ(point_segment_distance({0, 0, 2}, {1, 1, 1}, {1, 1, 1}), std::sqrt(3.0));
}

// D_p of a ballistic throw is the closed-form range; D_t of a target straight
// above the apex, closer than the apex's radius of curvature v_x^2 / g, is
// its height above the apex; one beside the apex, its offset
TEST(Throwing, AimOfABallisticThrowMatchesItsClosedForm) {
  const double dt = 1e-4, vx = 4, vz = 3, h = 0.5;
  const double t_land = (vz + std::sqrt(vz * vz + 2 * g * h)) / g;
  const Vec3 apex{vx * vz / g, 0, h + vz * vz / (2 * g)};
  ASSERT_LT(0.3, vx * vx / g);
  for (Vec3 target : {apex + Vec3{0, 0, 0.3}, apex + Vec3{0, 1.5, 0}, apex}) {
    ThrowingDef def;
    def.fitness = ThrowFitness::Aim;
    def.target = target;
    ThrowingTask t(def, dt);
    fly(t, def, {0, 0, h}, {vx, 0, vz}, dt);
    EXPECT_TRUE(t.done());
    EXPECT_NEAR(t.distance(), vx * t_land, vx * dt);
    double expected_miss = norm(target - apex);
    EXPECT_NEAR(t.target_miss(), expected_miss, 1e-6);
    EXPECT_NEAR(t.fitness(), vx * t_land - expected_miss, vx * dt + 1e-6);
  }
}

TEST(Throwing, DistanceIsHorizontalFromTheReleasePoint) {
  ThrowingDef def;
  ThrowingTask t(def, 0.01);
  t.release(0.5, {1, 1, 2});
  t.observe(0.51, {4, 5, 0.1});
  EXPECT_DOUBLE_EQ(t.distance(), 5.0);  // the fall from 2 m does not count
  EXPECT_DOUBLE_EQ(t.fitness(), 5.0);
  EXPECT_DOUBLE_EQ(t.release_time(), 0.5);
}

// throwing.touch_seconds: a push or carry is not a throw
TEST(Throwing, ATouchLaterThanTouchSecondsAfterTheReleaseEndsTheThrowWhereTheProjectileIs) {
  ThrowingDef def;
  def.touch_seconds = 0.5;
  const double dt = 0.1;
  ThrowingTask t(def, dt);
  t.release(1.0, {0, 0, 0});
  double x = 0;
  for (int k = 1; k <= 5; ++k) t.observe(1.0 + k * dt, {x += 0.2, 0, 0}, true);  // pushed within 0.5 s
  EXPECT_FALSE(t.done());
  t.observe(1.6, {x += 0.2, 0, 0}, false);  // free
  EXPECT_FALSE(t.done());
  t.observe(1.7, {x += 0.2, 0, 0}, true);  // touched 0.7 s after the release: the throw ends
  EXPECT_TRUE(t.done());
  EXPECT_NEAR(t.distance(), 1.4, 1e-12);
  EXPECT_DOUBLE_EQ(t.late_touch_time(), 1.7);
  SceneRecord scene;
  t.record(Nowhere{}, scene);
  EXPECT_EQ(scene.marker("touch end"), 1.7);
  t.observe(1.8, {x + 5, 0, 0}, false);  // nothing counts after
  EXPECT_NEAR(t.distance(), 1.4, 1e-12);

  // negative: no limit (the paper's way)
  def.touch_seconds = -1;
  ThrowingTask u(def, dt);
  u.release(0, {0, 0, 0});
  for (int k = 1; k <= 50; ++k) u.observe(k * dt, {0.2 * k, 0, 0}, true);
  EXPECT_FALSE(u.done());
  EXPECT_NEAR(u.distance(), 10, 1e-9);
  EXPECT_EQ(u.late_touch_time(), -1);
}

// the replay's scene: the projectile and the aim task's target once, then
// each moment once, at its own time, however often it is asked
TEST(Throwing, ItsSceneNamesTheProjectileTheTargetAndEachMomentOnce) {
  ThrowingDef def;
  def.fitness = ThrowFitness::Aim;
  def.target = {3, 1, 0.075};
  ThrowingTask t(def, 0.01, 2, 1);
  SceneRecord scene;
  t.record(Nowhere{}, scene);
  ASSERT_EQ(scene.parts.size(), 1u);
  EXPECT_EQ(scene.parts[0], (ScenePart{"projectile", 2, "#ffc61a", true}));  // its path is scored
  ASSERT_EQ(scene.points.size(), 1u);
  EXPECT_EQ(scene.points[0], (ScenePoint{"target", {3, 1, 0.075}, 0.12, "#d6336c"}));
  // at the drop the throw begins at 0; nothing is released yet
  ASSERT_EQ(scene.markers.size(), 1u);
  EXPECT_EQ(scene.markers[0], (SceneMarker{"begin", 0}));
  t.release(0.5, {0, 0, 1});
  t.observe(0.51, {0.1, 0, 1});
  t.record(Nowhere{}, scene);
  t.record(Nowhere{}, scene);
  // the scored span begins with the release
  EXPECT_EQ(scene.markers, (std::vector<SceneMarker>{{"begin", 0}, {"release", 0.5}, {"scored from", 0.5}}));
  // and ends when the projectile rests (rest_seconds of stillness)
  for (int k = 2; k <= 60 && !t.done(); ++k) t.observe(0.5 + k * 0.01, {0.1, 0, 1});
  ASSERT_TRUE(t.done());
  t.record(Nowhere{}, scene);
  t.record(Nowhere{}, scene);
  ASSERT_EQ(scene.markers.size(), 4u);
  EXPECT_EQ(scene.markers[3].name, "scored to");
  EXPECT_NEAR(scene.markers[3].t, 0.51 + def.rest_seconds, 0.011);
  EXPECT_EQ(scene.parts.size(), 1u);
  EXPECT_EQ(scene.points.size(), 1u);
  EXPECT_TRUE(scene.events.empty());
  // the distance task has no target
  ThrowingTask d(ThrowingDef{}, 0.01, 2, 1);
  SceneRecord plain;
  d.record(Nowhere{}, plain);
  EXPECT_TRUE(plain.points.empty());
  EXPECT_EQ(plain.marker("release"), std::nullopt);
}

TEST(Throwing, ComesToRestAfterRestSecondsOfStillness) {
  ThrowingDef def;
  const double dt = 0.01;
  def.rest_speed = 0.1;
  def.rest_seconds = 5 * dt;  // five steps
  ThrowingTask t(def, dt);
  t.observe(0, {0, 0, 0});
  EXPECT_FALSE(t.done()) << "not released: nothing to wait for";
  t.release(0, {0, 0, 0});
  double x = 0;
  for (int k = 0; k < 10; ++k) t.observe(0, {x += 0.01, 0, 0});  // 1 m/s: moving
  for (int k = 0; k < 4; ++k) t.observe(0, {x += 0.0009, 0, 0});  // 0.09 m/s: still
  EXPECT_FALSE(t.done());
  t.observe(0, {x += 0.0009, 0, 0});
  EXPECT_TRUE(t.done());
  EXPECT_NEAR(t.distance(), x, 1e-12);
  t.observe(0, {x + 5, 0, 0});  // nothing counts once at rest
  EXPECT_NEAR(t.distance(), x, 1e-12);
}

TEST(Throwing, RestIsASpeedHeldForRestSecondsWhateverTheStep) {
  // rolling at 0.02 m/s, under rest_speed 0.05 m/s: at rest after
  // rest_seconds, 0.5 s = 30 steps at 60 Hz, 60 at 120 Hz, 120 at 240 Hz
  for (int hz : {60, 120, 240}) {
    const double dt = 1.0 / hz;
    ThrowingDef def;
    ThrowingTask t(def, dt);
    t.release(0, {0, 0, 0});
    long steps = 0;
    while (!t.done() && steps < 10 * hz) {
      ++steps;
      t.observe(static_cast<double>(steps) * dt, {0.02 * static_cast<double>(steps) * dt, 0, 0});
    }
    EXPECT_EQ(steps, hz / 2) << hz << " Hz";
  }
}

TEST(Throwing, NeverReleasedScoresZeroWithANote) {
  ThrowingDef def;
  def.fitness = ThrowFitness::Aim;
  ThrowingTask t(def, 0.01);
  t.observe(1, {5, 0, 0});
  EXPECT_FALSE(t.released());
  EXPECT_EQ(t.fitness(), 0.0);
  EXPECT_EQ(t.target_miss(), -1.0);
  EXPECT_EQ(t.release_time(), -1.0);
  EXPECT_NE(t.note().find("never released"), std::string::npos);
}

}  // namespace
}  // namespace bx
