// Development of lessin2015 creatures (III-B to III-E): muscles between
// adjacent parts at the points where their directions leave the parts'
// surfaces, a length node per muscle, photoreceptors, reflection of both,
// and joints whose parts collide (a child starts off its parent's face).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "develop/develop.h"
#include "genome/dialect.h"
#include "genome/genome_json.h"
#include "support/creatures.h"

namespace bx {
namespace {

Genome load(const std::string& name) { return bxtest::load_creature(name); }

CreatureModel grow(const Genome& g, const DevelopDef& def = {}) {
  Development d = develop(g, def);
  EXPECT_TRUE(d.viable()) << d.reason;
  return d.viable() ? *d.model : CreatureModel{};
}

void expect_near(Vec3 a, Vec3 b, const std::string& what) {
  EXPECT_NEAR(a.x, b.x, 1e-12) << what;
  EXPECT_NEAR(a.y, b.y, 1e-12) << what;
  EXPECT_NEAR(a.z, b.z, 1e-12) << what;
}

// lessin_pair.json: a 0.4 x 0.2 x 0.1 m root and a 0.3 x 0.1 x 0.1 m limb on
// its +x face at u = 0.5 (y = +0.05), reflected across y; two muscles per
// limb (over its top and under it), a photoreceptor on each limb
TEST(Lessin2015Develop, AChildStartsItsHalfThicknessOffItsParentAndTheirJointCollides) {
  CreatureModel m = grow(load("lessin_pair.json"));
  ASSERT_EQ(m.n_parts(), 3);
  // the limb's -x end 0.05 m (half its 0.1 m thickness) off the root's face at x = 0.2
  expect_near(m.parts[1].pose.p, {0.2 + 0.05 + 0.15, 0.05, 0}, "limb");
  expect_near(m.parts[2].pose.p, {0.2 + 0.05 + 0.15, -0.05, 0}, "mirrored limb");
  ASSERT_EQ(m.joints.size(), 2u);
  for (const JointModel& j : m.joints) {
    EXPECT_TRUE(j.parts_collide);
    EXPECT_NEAR(j.anchor.x, 0.2, 1e-12);  // on the parent's surface
  }
  // the gap is a config value: 0 puts the limb flush, as Sims
  DevelopDef flush;
  flush.collide_gap = 0;
  EXPECT_NEAR(grow(load("lessin_pair.json"), flush).parts[1].pose.p.x, 0.35, 1e-12);
}

// collisions stop a slide into the parent, never away from it: a slider or
// a cylindrical joint without limits in its gene slides at most
// slide_range x its child's half-thickness either way
TEST(Lessin2015Develop, ASliderWithoutLimitsSlidesAtMostItsChildsHalfThickness) {
  for (JointType type : {JointType::Slider, JointType::Cylindrical, JointType::Hinge}) {
    Genome g = load("lessin_pair.json");
    g.nodes[1].joint.type = type;
    g.nodes[1].joint.limits.clear();
    CreatureModel m = grow(g);
    ASSERT_EQ(m.joints.size(), 2u);
    for (const JointModel& j : m.joints) {
      if (type == JointType::Hinge) {
        EXPECT_TRUE(j.limits.empty());  // collisions limit a turn both ways
        continue;
      }
      ASSERT_EQ(j.limits.size(), 1u) << to_string(type);  // the slide; a cylinder's turn stays free
      EXPECT_NEAR(j.limits[0].lo, -0.05, 1e-12);  // the limb's 0.1 m thickness, halved
      EXPECT_NEAR(j.limits[0].hi, 0.05, 1e-12);
    }
    DevelopDef wide;
    wide.slide_range = 3;
    if (type != JointType::Hinge) {
      EXPECT_NEAR(grow(g, wide).joints[0].limits[0].hi, 0.15, 1e-12);
    }
    // limits a genome gives are kept
    g.nodes[1].joint.limits = {{-0.01, 0.02}};
    if (type != JointType::Hinge) {
      EXPECT_EQ(grow(g).joints[0].limits[0].hi, 0.02);
    }
  }
}

TEST(Lessin2015Develop, MusclesJoinTheSurfacePointsOfTheirDirections) {
  CreatureModel m = grow(load("lessin_pair.json"));
  ASSERT_EQ(m.muscles.size(), 4u);
  // muscle 0: root along (1, 0, 1) leaves its 0.2 x 0.1 x 0.05 half-box at
  // (0.05, 0, 0.05); the limb (centre (0.4, 0.05, 0)) along (-1, 0, 1) at
  // (-0.05, 0, 0.05) from its centre
  const MuscleModel& a = m.muscles[0];
  EXPECT_EQ(a.part_a, 0);
  EXPECT_EQ(a.part_b, 1);
  expect_near(a.anchor_a, {0.05, 0, 0.05}, "root anchor");
  expect_near(a.anchor_b, {0.35, 0.05, 0.05}, "limb anchor");
  EXPECT_NEAR(a.length, std::hypot(0.30, 0.05), 1e-12);
  EXPECT_NEAR(a.rest_length, 0.5 * a.length, 1e-12);  // DevelopDef::muscle_rest_fraction
  EXPECT_EQ(a.strength, 2000);
  // the mirrored limb's muscles are mirror images across y
  for (int k = 0; k < 2; ++k) {
    const MuscleModel &p = m.muscles[k], &q = m.muscles[2 + k];
    EXPECT_EQ(q.part_b, 2);
    expect_near(q.anchor_a, {p.anchor_a.x, -p.anchor_a.y, p.anchor_a.z}, "mirrored root anchor");
    expect_near(q.anchor_b, {p.anchor_b.x, -p.anchor_b.y, p.anchor_b.z}, "mirrored limb anchor");
  }
  // each muscle is an effector: the activation node (III-E)
  ASSERT_EQ(m.effectors.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(m.effectors[k].muscle, k);
    EXPECT_EQ(m.effectors[k].joint, k / 2);
  }
}

TEST(Lessin2015Develop, EachMuscleAddsALengthNodeThatSourcesRead) {
  CreatureModel m = grow(load("lessin_pair.json"));
  // per limb: its photoreceptor, then its muscles' lengths
  ASSERT_EQ(m.sensors.size(), 6u);
  const SensorType want[] = {SensorType::Photoreceptor, SensorType::MuscleLength, SensorType::MuscleLength,
                             SensorType::Photoreceptor, SensorType::MuscleLength, SensorType::MuscleLength};
  const int muscle[] = {-1, 0, 1, -1, 2, 3};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(m.sensors[i].type, want[i]) << i;
    EXPECT_EQ(m.sensors[i].muscle, muscle[i]) << i;
    EXPECT_EQ(m.sensors[i].part, 1 + i / 3) << i;
  }
  // the root's scale node reads {"from": "child", "edge": 0, "muscle": 1}:
  // the unreflected limb's second muscle, value slot 2
  const BrainModel& b = m.brain;
  ASSERT_EQ(b.n_sensors, 6);
  ASSERT_EQ(b.n_neurons(), 3);
  ASSERT_EQ(b.input_begin[3] - b.input_begin[2], 1u);
  EXPECT_EQ(b.input_src[b.input_begin[2]], 2);
  EXPECT_TRUE(m.warnings.empty());
}

TEST(Lessin2015Develop, AMirroredPartsPhotoreceptorLooksTheMirroredWay) {
  CreatureModel m = grow(load("lessin_pair.json"));
  // the genome's direction (0, 1, 1) in each limb's frame, to the creature frame
  const Vec3 a = m.parts[1].pose.R * m.sensors[0].direction;
  const Vec3 b = m.parts[2].pose.R * m.sensors[3].direction;
  expect_near(b, {a.x, -a.y, a.z}, "mirrored eye");
  EXPECT_GT(a.y, 0.5);
  EXPECT_GT(a.z, 0.5);
}

TEST(Lessin2015Develop, AChildTurnedIntoItsParentIsNotViable) {
  // turned 1.2 rad about z, the limb's near corner sinks into the root's
  // face: fine where joined parts pass through each other, not here
  Genome g = load("lessin_pair.json");
  g.nodes[0].edges[0].rotation = {0, 0, 1.2};
  g.nodes[0].edges[0].u = 0;  // mid-face, so the turned limb's corner is in front of it
  g.nodes[0].edges[0].reflect.clear();
  Development d = develop(g);
  EXPECT_FALSE(d.viable());
  EXPECT_EQ(d.reason, "self-intersection: parts 0 (gene 0) and 1 (gene 1) overlap");
  // a quarter of that keeps clear of it
  g.nodes[0].edges[0].rotation = {0, 0, 0.3};
  EXPECT_TRUE(develop(g).viable());
}

TEST(Lessin2015Develop, AMuscleTooShortToHaveADirectionIsNotViable) {
  Genome g = load("lessin_pair.json");
  g.nodes[0].edges[0].reflect.clear();
  // both anchors where the limb meets the root's face, with no gap between them
  g.nodes[1].effectors[0].muscle->parent_dir = {1, 0.25, 0};
  g.nodes[1].effectors[0].muscle->child_dir = {-1, 0, 0};
  DevelopDef flush;
  flush.collide_gap = 0;
  Development d = develop(g, flush);
  EXPECT_FALSE(d.viable());
  EXPECT_EQ(d.reason.rfind("nodes[1].effectors[0].muscle: ", 0), 0u) << d.reason;
  EXPECT_NE(d.reason.find(" m long as built, below 0.001 m"), std::string::npos) << d.reason;
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

// Sims' example topologies (lessin2015 Fig. 4) as lessin2015 creatures, each
// limb with an antagonistic pair of muscles: they grow as the sims1994 ones do
struct Topology {
  const char* file;
  int parts, muscles;
};

class Lessin2015Topologies : public ::testing::TestWithParam<Topology> {};

TEST_P(Lessin2015Topologies, DevelopAsDrawnWithAPairOfMusclesPerJoint) {
  CreatureModel m = grow(bxtest::load_creature(GetParam().file));
  EXPECT_EQ(m.n_parts(), GetParam().parts);
  EXPECT_EQ(static_cast<int>(m.muscles.size()), GetParam().muscles);
  for (const MuscleModel& mm : m.muscles) {
    EXPECT_EQ(m.parts[mm.part_b].parent, mm.part_a);
    EXPECT_GT(mm.length, 0.01);
    // each end on its own part's half towards the other: the parent's end was
    // given in the growing edge's frame, so every copy pulls from its own side
    const Vec3 towards = m.parts[mm.part_b].pose.p - m.parts[mm.part_a].pose.p;
    EXPECT_GT(dot(mm.anchor_a - m.parts[mm.part_a].pose.p, towards), 0) << GetParam().file;
  }
  for (const JointModel& j : m.joints) EXPECT_TRUE(j.parts_collide);
}

INSTANTIATE_TEST_SUITE_P(Fig4, Lessin2015Topologies,
                         ::testing::Values(Topology{"lessin_simple.json", 4, 6},       // (a)
                                           Topology{"lessin_multi_edge.json", 9, 16},  // (b) four legs, each with a foot
                                           Topology{"lessin_recursive.json", 6, 8},    // (c) four recursive copies have a parent
                                           Topology{"lessin_both.json", 9, 16}),       // (d) 2 segments + 6 legs
                         [](const auto& info) {
                           std::string s = info.param.file;
                           return s.substr(0, s.find('.'));
                         });

}  // namespace
}  // namespace bx
