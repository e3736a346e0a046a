// Pandemonium groups in the genome (lessin2015 IV-C; NeuronGene::group):
// only a lessin2015 sigma may have one, validate() names the field; the file
// form writes "group" only when set; the operators copy groups and never
// make or change one.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "genome/dialect.h"
#include "genome/genome_json.h"
#include "genome/operators.h"

namespace bx {
namespace {

NeuronGene sigma(double bias, int group = NeuronGene::kNoGroup) {
  NeuronGene n;
  n.fn = "sigma";
  n.bias = bias;
  n.group = group;
  return n;
}

// a lessin2015 root and a reflected limb with a muscle: two sigmas of group
// 3 and one of group 1 on the root, a sigma of group 3 on the limb (grown
// twice), an ungrouped constant and a global sigma of group 1
Genome grouped() {
  Genome g;
  g.dialect = Dialect::Lessin2015;
  g.nodes.resize(2);
  g.nodes[0].size = {0.4, 0.2, 0.1};
  g.nodes[0].edges.push_back({1, Face::PosX, 0.5, 0, {0, 0, 0}, 1.0, {1}, false});
  g.nodes[0].neurons = {sigma(0.2, 3), sigma(0.9, 1), sigma(0.7, 3)};
  NeuronGene constant;
  constant.fn = "constant";
  constant.params = {0.5};
  g.nodes[0].neurons.push_back(constant);
  g.nodes[1].size = {0.3, 0.1, 0.1};
  g.nodes[1].neurons = {sigma(0.5, 3)};
  EffectorGene e;
  e.muscle = MuscleGene{{1, 0, 1}, {-1, 0, 1}, 2000};
  e.inputs = {{SourcePlace::Root, SourceKind::Neuron, 0, 0, 1.0}};
  g.nodes[1].effectors.push_back(e);
  g.global_neurons = {sigma(0.1, 1)};
  return g;
}

std::string error_of(const Genome& g) {
  Status s = validate(g);
  EXPECT_FALSE(s.ok());
  return s.ok() ? "" : s.error();
}

TEST(PandemoniumGenome, OnlyALessin2015SigmaMayHaveAGroup) {
  ASSERT_TRUE(validate(grouped()).ok()) << validate(grouped()).error();
  Genome g = grouped();
  g.nodes[0].neurons[3].group = 2;  // the constant
  EXPECT_EQ(error_of(g),
            "nodes[0].neurons[3].group: only a sigma neuron may belong to a pandemonium group in dialect "
            "lessin2015 (this is a constant), got 2");
  g = grouped();
  g.nodes[1].neurons[0].group = -2;
  EXPECT_EQ(error_of(g), "nodes[1].neurons[0].group: must be >= 0 (-1: none), got -2");
  g = grouped();
  g.global_neurons[0].fn = "sum";
  g.global_neurons[0].bias = 0;
  EXPECT_EQ(error_of(g),
            "global_neurons[0].group: only a sigma neuron may belong to a pandemonium group in dialect "
            "lessin2015 (this is a sum), got 1");
  // group 0 is a group like any other
  g = grouped();
  g.nodes[0].neurons[1].group = 0;
  EXPECT_TRUE(validate(g).ok());
  // the other dialects have no groups
  Genome c;
  c.dialect = Dialect::Chaumont2007;
  c.nodes.resize(1);
  NeuronGene sum;
  sum.fn = "sum";
  sum.group = 1;
  c.nodes[0].neurons.push_back(sum);
  EXPECT_EQ(error_of(c), "nodes[0].neurons[0].group: no pandemonium groups in dialect chaumont2007, got 1");
  EXPECT_EQ(dialect_rules(Dialect::Lessin2015).group_fn, "sigma");
  for (Dialect d : {Dialect::Sims1994, Dialect::Miconi2006, Dialect::Chaumont2007})
    EXPECT_TRUE(dialect_rules(d).group_fn.empty());
}

TEST(PandemoniumGenome, TheFileFormWritesAGroupOnlyWhenSet) {
  const Genome g = grouped();
  const std::string text = genome_to_string(g);
  EXPECT_NE(text.find("\"group\": 3"), std::string::npos);
  EXPECT_NE(text.find("\"group\": 1"), std::string::npos);
  auto back = genome_from_string(text, "t.json");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(*back, g);
  EXPECT_EQ(genome_to_string(*back), text);
  // no groups, no "group": files from before groups read and write as they did
  Genome none = g;
  for (NeuronGene& n : none.nodes[0].neurons) n.group = NeuronGene::kNoGroup;
  none.nodes[1].neurons[0].group = NeuronGene::kNoGroup;
  none.global_neurons[0].group = NeuronGene::kNoGroup;
  EXPECT_EQ(genome_to_string(none).find("\"group\""), std::string::npos);
  // read by name; a group that is not an integer names its path
  std::string bad = text;
  bad.replace(bad.find("\"group\": 3"), 10, "\"group\": \"left\"");
  auto err = genome_from_string(bad, "t.json");
  ASSERT_FALSE(err.ok());
  EXPECT_NE(err.error().find("t.json: nodes[0].neurons[0].group: expected an integer, got \"left\""),
            std::string::npos)
      << err.error();
  // read, then checked by validate()
  bad = text;
  bad.replace(bad.find("\"group\": 3"), 10, "\"group\": -7");
  err = genome_from_string(bad, "t.json");
  ASSERT_FALSE(err.ok());
  EXPECT_NE(err.error().find("nodes[0].neurons[0].group: must be >= 0 (-1: none), got -7"), std::string::npos)
      << err.error();
}

// every grouped neuron of `g`: its group id and its function must be sigma
std::multimap<int, std::string> groups_of(const Genome& g) {
  std::multimap<int, std::string> out;
  auto add = [&](const NeuronGene& n) {
    if (n.group != NeuronGene::kNoGroup) out.insert({n.group, n.fn});
  };
  for (const NodeGene& node : g.nodes)
    for (const NeuronGene& n : node.neurons) add(n);
  for (const NeuronGene& n : g.global_neurons) add(n);
  return out;
}

int grouped_count(const Genome& g) { return static_cast<int>(groups_of(g).size()); }

TEST(PandemoniumGenome, OperatorsNeverMakeOrChangeAGroup) {
  const OperatorDef def = default_operators(Dialect::Lessin2015);
  Rng rng(4152);
  for (int i = 0; i < 100; ++i) {
    // random genomes have none
    Genome r = random_genome(Dialect::Lessin2015, def, rng);
    EXPECT_EQ(grouped_count(r), 0);
    // add grouped sigmas to it, then mutate and cross it
    Genome g = r;
    g.nodes[0].neurons.push_back(sigma(0.3, 5));
    g.nodes.back().neurons.push_back(sigma(0.6, 2));
    ASSERT_TRUE(validate(g).ok()) << validate(g).error();
    Genome m = g;
    for (int k = 0; k < 5; ++k) {
      mutate(m, def, 0.5, rng);
      ASSERT_TRUE(validate(m).ok()) << validate(m).error();
    }
    // a removed neuron takes its group away; none is added, each stays a sigma
    EXPECT_LE(grouped_count(m), 2);
    for (const auto& [id, fn] : groups_of(m)) {
      EXPECT_TRUE(id == 5 || id == 2) << id;
      EXPECT_EQ(fn, "sigma");
    }
    Genome x = crossover(g, r, def, rng);
    ASSERT_TRUE(validate(x).ok()) << validate(x).error();
    for (const auto& [id, fn] : groups_of(x)) {
      EXPECT_TRUE(id == 5 || id == 2) << id;
      EXPECT_EQ(fn, "sigma");
    }
  }
}

// change_fn on a brain of grouped sigmas only: their functions stay (a group
// needs its sigma), while an ungrouped sigma beside them does change
TEST(PandemoniumGenome, ChangeFnLeavesAGroupedSigmaASigma) {
  OperatorDef def = default_operators(Dialect::Lessin2015);
  def.structure = StructuralRates{};
  def.structure.change_fn = 1;
  Genome g = grouped();
  g.nodes[0].neurons.pop_back();  // the constant: only sigmas are left
  ASSERT_TRUE(validate(g).ok());
  const auto before = groups_of(g);
  Rng rng(77);
  int changed = 0;
  for (int i = 0; i < 200; ++i) {
    Genome m = g;
    m.nodes[0].neurons.push_back(sigma(0.4));  // ungrouped
    mutate(m, def, 0, rng);
    ASSERT_TRUE(validate(m).ok()) << validate(m).error();
    EXPECT_EQ(groups_of(m), before);
    changed += m.nodes[0].neurons.back().fn != "sigma";
  }
  EXPECT_GT(changed, 20);
}

}  // namespace
}  // namespace bx
