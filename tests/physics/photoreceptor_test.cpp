// Photoreceptors against geometry (lessin2015 III-D): a receptor on a box's
// face reads a light in front of it by distance and angle, nothing behind it
// or through a body, and two lights together.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "physics/world.h"
#include "support/parts.h"

namespace bx {
namespace {

PartModel box(Vec3 size, Vec3 pos) { return bxtest::box_part(size, 1, pos); }

// A 0.4 m cube at (0, 0, 1) whose photoreceptor looks along `direction`
// (the cube's frame), and any other parts (unjoined, for occlusion); its
// reading under `lights`.
double reading(std::vector<Light> lights, Vec3 direction = {1, 0, 0}, std::vector<PartModel> others = {},
               Mat3 turn = Mat3::identity()) {
  PhysicsDef def;
  World w(def);
  CreatureModel m;
  m.parts.push_back(box({0.4, 0.4, 0.4}, {0, 0, 1}));
  m.parts[0].pose.R = turn;
  for (PartModel& o : others) {
    o.parent = 0;
    m.parts.push_back(o);
  }
  SensorModel s;
  s.type = SensorType::Photoreceptor;
  s.part = 0;
  s.direction = direction;
  m.sensors.push_back(s);
  w.add_creature(m, {{0, 0, 0}, Mat3::identity()});
  w.set_lights(std::move(lights));
  double out[1];
  w.read_sensors(m, out);
  return out[0];
}

// the reading of one light of strength 1 and range 1 at distance d, angle a off the receptor
double expected(double d, double a = 0) { return std::cos(a) / (1 + d * d); }

// the receptor on the +x face sits 0.2 m from the centre (the geom is a hair smaller)
constexpr double kFace = 0.2;
constexpr double kTol = 2e-3;

TEST(Photoreceptor, FacingALightItReadsItsStrengthOverOnePlusDistanceSquared) {
  EXPECT_NEAR(reading({{{kFace + 1, 0, 1}}}), expected(1), kTol);  // 0.5
  EXPECT_NEAR(reading({{{kFace + 0.5, 0, 1}}}), expected(0.5), kTol);
  // farther is dimmer
  EXPECT_NEAR(reading({{{kFace + 3, 0, 1}}}), expected(3), kTol);
  EXPECT_LT(reading({{{kFace + 3, 0, 1}}}), reading({{{kFace + 1, 0, 1}}}));
  // a light's range: where it reads half
  EXPECT_NEAR(reading({{{kFace + 2, 0, 1}, 1, 2}}), 0.5, kTol);
}

TEST(Photoreceptor, OffItsAxisByTheCosineAndBehindItNothing) {
  const double a = kPi / 3, d = 1;
  EXPECT_NEAR(reading({{{kFace + d * std::cos(a), d * std::sin(a), 1}}}), expected(d, a), kTol);
  EXPECT_EQ(reading({{{-2, 0, 1}}}), 0.0);       // behind the cube
  EXPECT_EQ(reading({{{kFace, 2, 1}}}), 0.0);     // square to its direction
}

TEST(Photoreceptor, ItTurnsWithItsPart) {
  // the cube turned a quarter about z: its +x receptor now faces +y
  const Mat3 quarter = Mat3::rotation({0, 0, 1}, kPi / 2);
  EXPECT_NEAR(reading({{{0, kFace + 1, 1}}}, {1, 0, 0}, {}, quarter), expected(1), kTol);
  EXPECT_EQ(reading({{{kFace + 1, 0, 1}}}, {1, 0, 0}, {}, quarter), 0.0);
}

TEST(Photoreceptor, ABodyInTheWayHidesTheLight) {
  const Light light{{kFace + 2, 0, 1}};
  EXPECT_NEAR(reading({light}), expected(2), kTol);
  EXPECT_EQ(reading({light}, {1, 0, 0}, {box({0.2, 0.2, 0.2}, {kFace + 1, 0, 1})}), 0.0);
  // beside the line it hides nothing
  EXPECT_NEAR(reading({light}, {1, 0, 0}, {box({0.2, 0.2, 0.2}, {kFace + 1, 0.5, 1})}), expected(2), kTol);
}

TEST(Photoreceptor, TwoLightsAddAndTheSumIsHeldAtOne) {
  const Light front{{kFace + 1, 0, 1}}, side{{kFace + 0.5, 0.5 * std::sqrt(3.0), 1}};
  EXPECT_NEAR(reading({front, side}), expected(1) + expected(1, kPi / 3), kTol);
  EXPECT_EQ(reading({front, {{kFace + 0.1, 0, 1}, 5}}), 1.0);  // held at 1
  EXPECT_EQ(reading({}), 0.0);                                   // no light: dark
}

}  // namespace
}  // namespace bx

#include "support/creatures.h"

namespace bx {
namespace {

// creatures/lessin_eyes.json: a 0.4 x 0.3 x 0.15 m box with two eyes
// looking forward, 26.6 degrees to the left (+y) and to the right; their
// readings under one light at the body's height, the body turned by `yaw`
std::vector<double> eyes(Vec3 light, double yaw = 0) {
  Development d = develop(bxtest::load_creature("lessin_eyes.json"), DevelopDef{});
  EXPECT_TRUE(d.viable()) << d.reason;
  const CreatureModel& m = *d.model;
  EXPECT_EQ(m.sensors.size(), 2u);
  World w(PhysicsDef{});
  w.add_creature(m, {{0, 0, 0.075 - m.min_z()}, Mat3::rotation({0, 0, 1}, yaw)});
  w.set_lights({{light}});
  std::vector<double> out(m.sensors.size());
  w.read_sensors(m, out);
  return out;
}

TEST(Photoreceptor, TwoEyesFacingALightSeeItAlikeAndTellItsSide) {
  const double z = 0.075;
  const std::vector<double> ahead = eyes({3, 0, z});
  EXPECT_GT(ahead[0], 0.05);
  EXPECT_NEAR(ahead[0], ahead[1], 1e-9);  // straight ahead: both alike
  // ahead and to the left: the left eye sees more; to the right, the right
  const std::vector<double> left = eyes({3, 1.5, z}), right = eyes({3, -1.5, z});
  EXPECT_GT(left[0], left[1] + 0.02);
  EXPECT_GT(right[1], right[0] + 0.02);
  EXPECT_NEAR(left[0], right[1], 1e-9);  // mirror images
  // behind: dark; turned about to face it: it sees it again
  const std::vector<double> behind = eyes({-3, 0, z});
  EXPECT_EQ(behind[0], 0.0);
  EXPECT_EQ(behind[1], 0.0);
  const std::vector<double> turned = eyes({-3, 0, z}, kPi);
  EXPECT_NEAR(turned[0], ahead[0], 1e-9);
  EXPECT_NEAR(turned[1], ahead[1], 1e-9);
}

}  // namespace
}  // namespace bx
