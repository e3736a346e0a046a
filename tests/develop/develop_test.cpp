// Development: the four Sims topologies, reflection, recursion, scale,
// viability and brain compilation.
#include "develop/develop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "genome/dialect.h"
#include "genome/genome_json.h"
#include "support/creatures.h"

namespace bx {
namespace {

Genome load(const std::string& name) { return bxtest::load_creature(name); }

CreatureModel grow(const std::string& name) {
  Development d = develop(load(name));
  EXPECT_TRUE(d.viable()) << name << ": " << d.reason;
  return d.viable() ? *d.model : CreatureModel{};
}

struct Counts {
  const char* file;
  int parts, joints;
};

class CanonicalCreatures : public ::testing::TestWithParam<Counts> {};

TEST_P(CanonicalCreatures, DevelopToTheirPartAndJointCounts) {
  CreatureModel m = grow(GetParam().file);
  EXPECT_EQ(m.n_parts(), GetParam().parts);
  EXPECT_EQ(static_cast<int>(m.joints.size()), GetParam().joints);
  // parents precede children and each non-root part has exactly one joint
  for (int i = 1; i < m.n_parts(); ++i) EXPECT_LT(m.parts[i].parent, i);
  for (std::size_t j = 0; j < m.joints.size(); ++j)
    EXPECT_EQ(m.parts[m.joints[j].child].parent, m.joints[j].parent);
}

INSTANTIATE_TEST_SUITE_P(
    All, CanonicalCreatures,
    ::testing::Values(Counts{"box.json", 1, 0}, Counts{"hinged_pair.json", 2, 1},
                      Counts{"snake.json", 6, 5},
                      // Sims' example topologies (lessin2015 Fig. 4)
                      Counts{"sims_simple.json", 4, 3},       // (a) simple
                      Counts{"sims_multi_edge.json", 9, 8},   // (b) one node, four edges, each with a foot
                      Counts{"sims_recursive.json", 6, 5},    // (c) reflexive edge, limit 5, terminal tip
                      Counts{"sims_both.json", 9, 8},         // (d) both: 3 segments x (1 + 2 legs)
                      Counts{"walker.json", 5, 4}),
    [](const auto& info) {
      std::string s = info.param.file;
      return s.substr(0, s.find('.'));
    });

TEST(Develop, ReflectionMirrorsGeometryAxesAndFaces) {
  CreatureModel m = grow("walker.json");
  // parts 1 and 2 are a leg and its mirror image across the body's xz plane
  const PartModel &a = m.parts[1], &b = m.parts[2];
  EXPECT_EQ(a.gene, b.gene);
  EXPECT_FALSE(a.mirrored);
  EXPECT_TRUE(b.mirrored);
  EXPECT_NEAR(a.pose.p.x, b.pose.p.x, 1e-12);
  EXPECT_NEAR(a.pose.p.y, -b.pose.p.y, 1e-12);
  EXPECT_NEAR(a.pose.p.z, b.pose.p.z, 1e-12);
  EXPECT_GT(b.pose.R.det(), 0.999);  // physics gets a proper rotation
  // every local axis of b is the mirror image of a's, up to sign (same box)
  for (int k = 0; k < 3; ++k) {
    Vec3 ca = a.pose.R.column(k), cb = b.pose.R.column(k);
    Vec3 mirrored{ca.x, -ca.y, ca.z};
    EXPECT_NEAR(std::abs(dot(mirrored, cb)), 1.0, 1e-12) << "axis " << k;
  }
  // joint axes are pseudovectors: mirror image negated
  const JointModel &ja = m.joints[0], &jb = m.joints[1];
  EXPECT_EQ(ja.child, 1);
  EXPECT_EQ(jb.child, 2);
  for (auto [va, vb] : {std::pair{ja.axis1, jb.axis1}, std::pair{ja.axis2, jb.axis2}}) {
    EXPECT_NEAR(vb.x, -va.x, 1e-12);
    EXPECT_NEAR(vb.y, va.y, 1e-12);
    EXPECT_NEAR(vb.z, -va.z, 1e-12);
  }
  EXPECT_NEAR(ja.anchor.y, -jb.anchor.y, 1e-12);
  // the contact sensor on each leg's +x face (its tip) points the mirrored way
  const SensorModel* sa = nullptr;
  const SensorModel* sb = nullptr;
  for (const auto& s : m.sensors) {
    if (s.type != SensorType::Contact) continue;
    if (s.part == 1) sa = &s;
    if (s.part == 2) sb = &s;
  }
  ASSERT_TRUE(sa && sb);
  Vec3 na = a.pose.R.column(face_axis(sa->face)) * face_sign(sa->face);
  Vec3 nb = b.pose.R.column(face_axis(sb->face)) * face_sign(sb->face);
  EXPECT_NEAR(na.x, nb.x, 1e-12);
  EXPECT_NEAR(na.y, -nb.y, 1e-12);
  EXPECT_NEAR(na.z, nb.z, 1e-12);
}

TEST(Develop, RecursionScalesEachLevelAndEndsWithTheTerminalOnlyPart) {
  CreatureModel m = grow("sims_recursive.json");
  // five segments of gene 0, each 0.85 of its parent, then the tip (gene 1)
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(m.parts[i].gene, 0);
    EXPECT_EQ(m.parts[i].parent, i - 1);
    EXPECT_NEAR(m.parts[i].size.x, 0.3 * std::pow(0.85, i), 1e-12);
  }
  EXPECT_EQ(m.parts[5].gene, 1);
  EXPECT_EQ(m.parts[5].parent, 4);  // only the last segment grows the terminal-only edge
  EXPECT_EQ(m.joints[4].type, JointType::Fixed);
  // segments chain along +x, touching end to end
  for (int i = 1; i < 5; ++i) {
    double gap = (m.parts[i].pose.p.x - m.parts[i].size.x / 2) -
                 (m.parts[i - 1].pose.p.x + m.parts[i - 1].size.x / 2);
    EXPECT_NEAR(gap, 0, 1e-12);
  }
}

TEST(Develop, SelfIntersectionIsNotViableAndNamesTheParts) {
  Genome g = load("sims_multi_edge.json");
  // a fifth leg on top of the first one
  g.nodes[0].edges.push_back(g.nodes[0].edges[0]);
  g.nodes[0].edges.back().u = 0.65;
  Development d = develop(g);
  EXPECT_FALSE(d.viable());
  EXPECT_NE(d.reason.find("self-intersection: parts"), std::string::npos) << d.reason;
}

// evolved (chaumont2007-catapult-small seed 2): the projectile sits inside the
// body it hangs from; released, the contact pushed it out at the solver's
// correcting speed, and the throw grew as the step shrank
TEST(Develop, ACatapultsProjectileMayNotStartInsideTheBodyItIsReleasedFrom) {
  Genome g = load("embedded_projectile.json");
  Development d = develop(g);
  EXPECT_FALSE(d.viable());
  EXPECT_EQ(d.reason, "self-intersection: parts 0 (gene 0) and 5 (gene 5) overlap");
  // the same body without the release: parts joined for good may overlap
  g.catapult.reset();
  EXPECT_TRUE(develop(g).viable());
  // a projectile that rests on its arm is fine
  EXPECT_TRUE(develop(load("catapult.json")).viable());
}

TEST(Develop, TooManyPartsIsNotViable) {
  Genome g = load("sims_recursive.json");
  g.nodes[0].recursive_limit = 40;
  DevelopDef def;
  def.max_parts = 10;
  Development d = develop(g, def);
  EXPECT_FALSE(d.viable());
  EXPECT_EQ(d.reason, "too many parts: more than 10");
}

// A node with an edge to itself: a chain as long as max_parts allows. At the
// largest max_parts (100,000) the recursive growth overflowed the stack and
// the path scan made refusing quadratic in the limit (issue 13)
TEST(Develop, ASelfChainGrowsWithoutRecursionUpToMaxParts) {
  Genome g;
  g.dialect = Dialect::Sims1994;
  NodeGene n;
  n.size = {0.1, 0.1, 0.1};
  n.recursive_limit = 1000000000;
  n.edges.push_back(EdgeGene{});
  g.nodes = {n};
  ASSERT_TRUE(validate(g).ok()) << validate(g).error();
  DevelopDef def;
  def.max_parts = 100000;
  Development d = develop(g, def);
  EXPECT_FALSE(d.viable());
  EXPECT_EQ(d.reason, "too many parts: more than 100000");
  // a limit the chain meets: 99,999 parts in a line, viable
  g.nodes[0].recursive_limit = 99999;
  d = develop(g, def);
  ASSERT_TRUE(d.viable()) << d.reason;
  EXPECT_EQ(d.model->n_parts(), 99999);
  EXPECT_EQ(d.model->parts.back().parent, 99997);
  EXPECT_NEAR(d.model->parts.back().pose.p.x, 0.1 * 99998, 1e-6);
}

// Edge scales compound: genes within range can grow parts that are not
TEST(Develop, PartsOutsideThePhysicalRangesAreNotViable) {
  Genome g = load("sims_recursive.json");
  g.nodes[0].edges[0].scale = 0.01;  // 0.3 m, 3 mm, 0.03 mm: below 0.1 mm
  ASSERT_TRUE(validate(g).ok()) << validate(g).error();
  Development d = develop(g);
  EXPECT_FALSE(d.viable());
  EXPECT_EQ(d.reason,
            "part 2 (gene 0): size [3e-05, 2e-05, 1.5e-05] m, each extent must lie in [0.0001, 10000] m "
            "(edge scales compound along the body)");
  g.nodes[0].edges[0].scale = 100;  // 0.3 m, 30 m, 3 km, 300 km
  d = develop(g);
  EXPECT_FALSE(d.viable());
  EXPECT_EQ(d.reason.rfind("part 3 (gene 0): size [300000, ", 0), 0u) << d.reason;
}

// Mass is checked too, for any mass rule: a genome that skipped validation
// (density 1e-25) grows a part ODE's mass check would assert on
TEST(Develop, AMassOutsideItsRangeIsNotViable) {
  Genome g = load("box.json");
  g.nodes[0].density = 1e-25;  // 0.064 m^3: 6.4e-27 kg
  Development d = develop(g);
  EXPECT_FALSE(d.viable());
  EXPECT_EQ(d.reason, "part 0 (gene 0): mass 6.4e-27 kg, must lie in [1e-20, 1e+20] kg");
  g.nodes[0].density = 1e25;
  EXPECT_EQ(develop(g).reason, "part 0 (gene 0): mass 6.4e+23 kg, must lie in [1e-20, 1e+20] kg");
  g.nodes[0].density = kMaxDensity;
  EXPECT_TRUE(develop(g).viable());
}

// A recursive edge that scales by 1.5 grows giants: the body-length limit
// makes them non-viable, and leaves creatures within it alone.
TEST(Develop, BodyLongerThanTheLimitIsNotViable) {
  Genome g = load("sims_recursive.json");
  double base = grow("sims_recursive.json").body_length();
  DevelopDef def;
  def.max_body_length = base * 1.01;
  EXPECT_TRUE(develop(g, def).viable());
  for (auto& node : g.nodes)
    for (auto& e : node.edges)
      if (e.to == &node - g.nodes.data()) e.scale = 1.5;
  Development big = develop(g);
  ASSERT_TRUE(big.viable()) << big.reason;
  ASSERT_GT(big.model->body_length(), base * 1.2);
  Development d = develop(g, def);
  EXPECT_FALSE(d.viable());
  EXPECT_EQ(d.reason.rfind("too large: body length ", 0), 0u) << d.reason;
  EXPECT_NE(d.reason.find("above develop.max_body_length"), std::string::npos) << d.reason;
}

TEST(Develop, MiconiMassIsScaledTanhOfVolume) {
  Genome g;
  g.dialect = Dialect::Miconi2006;
  NodeGene root;
  root.size = {1.0, 0.5, 0.2};
  NodeGene limb;
  limb.size = {0.6, 0.3, 0.2};
  limb.joint.axis1 = {0, 0, 1};
  root.edges.push_back(EdgeGene{});
  root.edges[0].to = 1;
  g.nodes = {root, limb};
  ASSERT_TRUE(validate(g).ok()) << validate(g).error();
  CreatureModel m = *develop(g).model;
  EXPECT_NEAR(m.parts[0].mass, 0.8 * std::tanh(1.0 * 0.5 * 0.2), 1e-12);
  EXPECT_NEAR(m.parts[1].mass, 0.8 * std::tanh(0.6 * 0.3 * 0.2), 1e-12);
  // Table 1's joint range fills an empty hinge limit
  ASSERT_EQ(m.joints[0].limits.size(), 1u);
  EXPECT_NEAR(m.joints[0].limits[0].hi, 3 * kPi / 4, 1e-12);
}

TEST(Develop, BrainWiringResolvesPlacesAndWarnsOfMissingSources) {
  CreatureModel m = grow("snake.json");
  // head: 1 neuron, 5 segments: 1 neuron each; sensors: 2 per segment
  EXPECT_EQ(m.brain.n_neurons(), 6);
  EXPECT_EQ(m.brain.n_sensors, 10);
  EXPECT_EQ(m.brain.n_effectors(), 5);
  // segment k's smooth neuron reads its parent's neuron 0: slot n_sensors + (k-1)
  for (int k = 1; k < 6; ++k) {
    int src = m.brain.input_src[m.brain.input_begin[k]];
    EXPECT_EQ(src, m.brain.n_sensors + (k - 1)) << "segment " << k;
    EXPECT_EQ(m.brain.neuron_part[k], k);
  }
  // every source exists in this body
  EXPECT_TRUE(m.warnings.empty());

  // the same segment gene as root would read a parent it does not have
  Genome g = load("snake.json");
  g.nodes[0] = g.nodes[1];
  g.nodes[0].edges[0].to = 1;
  Development d = develop(g);
  ASSERT_TRUE(d.viable()) << d.reason;
  ASSERT_EQ(d.model->warnings.size(), 1u);
  EXPECT_EQ(d.model->warnings[0],
            "nodes[0].neurons[0].inputs[0]: its source does not exist in this body; it reads 0");
}

}  // namespace
}  // namespace bx
