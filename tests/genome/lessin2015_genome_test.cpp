// The lessin2015 dialect's genome (III): muscles as its only effectors, each
// with anchors and a strength; photoreceptors with a direction; a muscle's
// length as a source. validate(), the file format, the edits that keep
// muscle sources pointing at the same muscle, and the operators.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "genome/dialect.h"
#include "genome/genome_edit.h"
#include "genome/genome_json.h"
#include "genome/operators.h"

namespace bx {
namespace {

// a root and one hinged limb with a muscle to the root, whose length the
// root's neuron reads
Genome pair_with_muscle() {
  Genome g;
  g.dialect = Dialect::Lessin2015;
  g.nodes.resize(2);
  g.nodes[0].size = {0.4, 0.2, 0.1};
  g.nodes[0].edges.push_back({1, Face::PosX, 0, 0, {0, 0, 0}, 1.0, {}, false});
  NeuronGene n;
  n.fn = "scale";
  n.params = {1};
  n.inputs = {{SourcePlace::Child, SourceKind::Muscle, 0, 0, 1.0}};
  g.nodes[0].neurons.push_back(n);
  g.nodes[1].size = {0.3, 0.1, 0.1};
  EffectorGene e;
  e.muscle = MuscleGene{{1, 0, 1}, {-1, 0, 1}, 2000};
  g.nodes[1].effectors.push_back(e);
  return g;
}

std::string error_of(const Genome& g) {
  Status s = validate(g);
  EXPECT_FALSE(s.ok());
  return s.ok() ? "" : s.error();
}

TEST(Lessin2015Genome, TheDialectsRow) {
  const DialectRules& r = dialect_rules(Dialect::Lessin2015);
  EXPECT_EQ(to_string(Dialect::Lessin2015), "lessin2015");
  EXPECT_EQ(parse_dialect("lessin2015"), Dialect::Lessin2015);
  EXPECT_EQ(r.neuron_set, NeuronSetId::Lessin2015);
  EXPECT_TRUE(r.muscle_effectors);
  EXPECT_TRUE(r.joined_parts_collide);
  EXPECT_FALSE(r.tree_only);  // III-B: reflexive and multiple edges
  EXPECT_EQ(r.shapes, (std::vector<Shape>{Shape::Box, Shape::Sphere, Shape::Capsule}));
  EXPECT_EQ(r.joints, (std::vector<JointType>{JointType::Fixed, JointType::Hinge, JointType::Spherical,
                                              JointType::Slider, JointType::Cylindrical}));
  EXPECT_EQ(r.sensors, std::vector<SensorType>{SensorType::Photoreceptor});
  // the other dialects keep joint effectors and flush joints
  for (Dialect d : {Dialect::Sims1994, Dialect::Miconi2006, Dialect::Chaumont2007}) {
    EXPECT_FALSE(dialect_rules(d).muscle_effectors);
    EXPECT_FALSE(dialect_rules(d).joined_parts_collide);
  }
}

TEST(Lessin2015Genome, AMuscleCreatureIsValid) { EXPECT_TRUE(validate(pair_with_muscle()).ok()); }

TEST(Lessin2015Genome, ValidateNamesTheMuscleField) {
  Genome g = pair_with_muscle();
  g.nodes[1].effectors[0].muscle.reset();
  EXPECT_EQ(error_of(g), "nodes[1].effectors[0].muscle: every effector is a muscle in dialect lessin2015, got null");
  g = pair_with_muscle();
  g.nodes[1].effectors[0].muscle->strength = 0;
  EXPECT_EQ(error_of(g), "nodes[1].effectors[0].muscle.strength: must lie in (0, 10000000.0] N/m, got 0.0");
  g.nodes[1].effectors[0].muscle->strength = NAN;
  EXPECT_NE(error_of(g).find("muscle.strength: must lie in"), std::string::npos);
  g = pair_with_muscle();
  g.nodes[1].effectors[0].muscle->child_dir = {0, 0, 0};
  EXPECT_EQ(error_of(g), "nodes[1].effectors[0].muscle.child_dir: a direction must be finite and not zero, got [0.0, 0.0, 0.0]");
  g = pair_with_muscle();
  g.nodes[1].effectors[0].dof = 1;
  EXPECT_EQ(error_of(g), "nodes[1].effectors[0].dof: a muscle has no degree of freedom (0), got 1");
  // a muscle source reads an existing muscle
  g = pair_with_muscle();
  g.nodes[0].neurons[0].inputs[0].index = 1;
  EXPECT_EQ(error_of(g), "nodes[0].neurons[0].inputs[0].muscle: no such muscle in the child node 1 (it has 1), got 1");
}

TEST(Lessin2015Genome, OtherDialectsHaveNoMusclesNorMuscleSources) {
  Genome g = pair_with_muscle();
  g.dialect = Dialect::Sims1994;
  g.nodes[1].effectors[0].muscle.reset();
  g.nodes[0].neurons[0].fn = "sum";  // sims1994's set has no scale
  g.nodes[0].neurons[0].params.clear();
  EXPECT_EQ(error_of(g), "nodes[0].neurons[0].inputs[0].muscle: no muscles in dialect sims1994, got 0");
  g.nodes[0].neurons.clear();
  g.nodes[1].effectors[0].muscle = MuscleGene{};
  EXPECT_EQ(error_of(g), "nodes[1].effectors[0].muscle: no muscles in dialect sims1994 (effectors drive joints), got true");
}

TEST(Lessin2015Genome, PhotoreceptorsNeedADirection) {
  Genome g = pair_with_muscle();
  SensorGene eye;
  eye.type = SensorType::Photoreceptor;
  eye.direction = {0, 0, 0};
  g.nodes[0].sensors.push_back(eye);
  EXPECT_EQ(error_of(g), "nodes[0].sensors[0].direction: a direction must be finite and not zero, got [0.0, 0.0, 0.0]");
  g.nodes[0].sensors[0].direction = {0, 1, 1};
  EXPECT_TRUE(validate(g).ok());
  // a joint-angle sensor is not lessin2015's
  g.nodes[0].sensors[0].type = SensorType::JointAngle;
  EXPECT_NE(error_of(g).find("sensor type not allowed in dialect lessin2015 (expected photoreceptor)"),
            std::string::npos);
}

TEST(Lessin2015Genome, TheFileFormatRoundTripsMusclesEyesAndMuscleSources) {
  Genome g = pair_with_muscle();
  SensorGene eye;
  eye.type = SensorType::Photoreceptor;
  eye.direction = {0.1, 0.7, -0.3};
  g.nodes[1].sensors.push_back(eye);
  std::string text = genome_to_string(g);
  EXPECT_NE(text.find("\"muscle\": {"), std::string::npos);
  EXPECT_NE(text.find("\"parent_dir\""), std::string::npos);
  EXPECT_NE(text.find("\"direction\""), std::string::npos);
  EXPECT_NE(text.find("\"muscle\": 0"), std::string::npos);  // the neuron's source
  auto back = genome_from_string(text, "t.json");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(*back, g);
}

TEST(Lessin2015Genome, TheFileFormatNamesMisplacedFields) {
  const std::string base = genome_to_string(pair_with_muscle());
  auto err = [](const std::string& text) {
    auto r = genome_from_string(text, "t.json");
    EXPECT_FALSE(r.ok());
    return r.ok() ? std::string() : r.error();
  };
  auto edit = [&](const std::string& from, const std::string& to) {
    std::string s = base;
    auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
    return s;
  };
  EXPECT_NE(err(edit("\"strength\": 2000.0", "\"force\": 2000.0")).find("nodes[1].effectors[0].muscle.force: unknown field"),
            std::string::npos);
  EXPECT_NE(err(edit("\"strength\": 2000.0", "\"strength\": \"strong\"")).find("nodes[1].effectors[0].muscle.strength"),
            std::string::npos);
  EXPECT_NE(err(edit("\"muscle\": 0", "\"muscle\": 0, \"neuron\": 0"))
                .find("a source names exactly one of \"neuron\", \"sensor\" and \"muscle\""),
            std::string::npos);
}

TEST(Lessin2015Genome, RemovingAMuscleRenumbersAndFixesItsReaders) {
  Genome g = pair_with_muscle();
  EffectorGene second;
  second.muscle = MuscleGene{{1, 0, -1}, {-1, 0, -1}, 1000};
  g.nodes[1].effectors.push_back(second);
  g.nodes[0].neurons[0].inputs[0].index = 1;  // reads the second muscle
  ASSERT_TRUE(validate(g).ok());
  remove_effector(g, 1, 0);  // the first: the reader now reads index 0, the same muscle
  ASSERT_EQ(g.nodes[1].effectors.size(), 1u);
  EXPECT_EQ(g.nodes[1].effectors[0].muscle->strength, 1000);
  ASSERT_EQ(g.nodes[0].neurons[0].inputs.size(), 1u);
  EXPECT_EQ(g.nodes[0].neurons[0].inputs[0].index, 0);
  remove_effector(g, 1, 0);  // its muscle gone: the input is removed
  EXPECT_TRUE(g.nodes[0].neurons[0].inputs.empty());
  EXPECT_TRUE(validate(g).ok());
}

TEST(Lessin2015Genome, SourceCandidatesIncludeMuscleLengths) {
  Genome g = pair_with_muscle();
  bool child_muscle = false;
  for (const InputGene& in : source_candidates(g, 0))
    child_muscle |= in.place == SourcePlace::Child && in.kind == SourceKind::Muscle && in.index == 0;
  EXPECT_TRUE(child_muscle);
  // not in a dialect without muscles
  g.dialect = Dialect::Sims1994;
  g.nodes[1].effectors[0].muscle.reset();
  for (const InputGene& in : source_candidates(g, 0)) EXPECT_NE(in.kind, SourceKind::Muscle);
}

TEST(Lessin2015Genome, RandomCreaturesCarryMusclesAndMutationMovesThem) {
  const OperatorDef def = default_operators(Dialect::Lessin2015);
  Rng rng(20151);
  int muscles = 0, eyes = 0, moved = 0;
  for (int i = 0; i < 100; ++i) {
    Genome g = random_genome(Dialect::Lessin2015, def, rng);
    ASSERT_TRUE(validate(g).ok()) << validate(g).error();
    for (const NodeGene& n : g.nodes) {
      for (const EffectorGene& e : n.effectors) {
        ASSERT_TRUE(e.muscle.has_value());
        EXPECT_GE(e.muscle->strength, def.muscle_strength_range.lo);
        EXPECT_LE(e.muscle->strength, def.muscle_strength_range.hi);
        ++muscles;
      }
      for (const SensorGene& s : n.sensors) eyes += s.type == SensorType::Photoreceptor;
    }
    Genome m = g;
    mutate(m, def, 0.5, rng);
    ASSERT_TRUE(validate(m).ok()) << validate(m).error();
    for (std::size_t k = 0; k < std::min(m.nodes.size(), g.nodes.size()); ++k)
      for (std::size_t e = 0; e < std::min(m.nodes[k].effectors.size(), g.nodes[k].effectors.size()); ++e)
        moved += !(m.nodes[k].effectors[e].muscle == g.nodes[k].effectors[e].muscle);
  }
  EXPECT_GT(muscles, 100);
  EXPECT_GT(eyes, 20);
  EXPECT_GT(moved, 20);
}

}  // namespace
}  // namespace bx
