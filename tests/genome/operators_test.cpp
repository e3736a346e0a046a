// Genetic operators (operators.h): every output passes validate(), for every
// dialect, on many random genomes and children (fixed seeds); determinism;
// miconi2006's mutation steps one at a time; crossover's prefix and suffix;
// grafting keeps the trunk's root; the canonical JSON round trip.
#include "genome/operators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "genome/dialect.h"
#include "genome/genome_edit.h"
#include "genome/genome_json.h"

namespace bx {
namespace {

// how an evolutionary loop mixes the operators (EvolutionDef's defaults per dialect)
struct Mix {
  double rate_asexual, rate_after_mating, p_mutate_after_mating;
  int asexual_mutations;
  double p_asexual, p_crossover;
};
Mix mix_for(Dialect d) {
  switch (d) {
    case Dialect::Miconi2006: return {0.04, 0.04, 1.0, 4, 1.0 / 3, 1.0 / 3};  // 5.1, 5.2
    case Dialect::Chaumont2007: return {0.10, 0.05, 0.10, 1, 0.4, 0.3};      // 5.7
    case Dialect::Sims1994: break;
    case Dialect::Lessin2015: return {0.10, 0.05, 0.10, 1, 0.4, 0.3};  // default_evolution's (chaumont2007's)
  }
  return {0.05, 0.05, 1.0, 1, 0.4, 0.3};
}


constexpr int kMany = 1000;

std::string name_of(Dialect d) { return std::string(to_string(d)); }

Rng rng_for(Dialect d, std::uint64_t tag) {
  return Rng(stream_seed({static_cast<std::uint64_t>(d) + 1, tag}));
}

// a pool of random genomes to draw parents from
std::vector<Genome> pool(Dialect d, int n, std::uint64_t tag) {
  OperatorDef def = default_operators(d);
  Rng rng = rng_for(d, tag);
  std::vector<Genome> out;
  for (int i = 0; i < n; ++i) out.push_back(random_genome(d, def, rng));
  return out;
}

// validate() with the genome in the failure message
::testing::AssertionResult valid(const Genome& g) {
  Status s = validate(g);
  if (s.ok()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << s.error() << "\n" << genome_to_string(g);
}

int most_genes(Dialect d) {
  OperatorDef def = default_operators(d);
  int r = dialect_rules(d).max_genes;
  return r > 0 ? std::min(r, def.max_genes) : def.max_genes;
}

class Operators : public ::testing::TestWithParam<Dialect> {};

INSTANTIATE_TEST_SUITE_P(Dialects, Operators,
                         ::testing::Values(Dialect::Sims1994, Dialect::Miconi2006,
                                           Dialect::Chaumont2007, Dialect::Lessin2015),
                         [](const auto& info) { return name_of(info.param); });

// ---------------------------------------------------------------- validity

TEST_P(Operators, RandomGenomesValidate) {
  Dialect d = GetParam();
  OperatorDef def = default_operators(d);
  Rng rng = rng_for(d, 1);
  const DialectRules& rules = dialect_rules(d);
  for (int i = 0; i < kMany; ++i) {
    Genome g = random_genome(d, def, rng);
    ASSERT_TRUE(valid(g)) << "random genome " << i;
    EXPECT_EQ(g.dialect, d);
    EXPECT_GE(static_cast<int>(g.nodes.size()), def.genes_at_creation.lo);
    EXPECT_LE(static_cast<int>(g.nodes.size()), def.genes_at_creation.hi);
    // not too many parts to develop
    EXPECT_LE(count_parts(g, rules.max_parts), rules.max_parts);
  }
}

TEST_P(Operators, MutationChildrenValidate) {
  Dialect d = GetParam();
  OperatorDef def = default_operators(d);
  std::vector<Genome> parents = pool(d, 100, 2);
  for (double rate : {0.04, 0.1, 1.0}) {
    Rng rng = rng_for(d, 3 + static_cast<std::uint64_t>(rate * 100));
    for (int i = 0; i < kMany; ++i) {
      Genome g = parents[i % parents.size()];
      mutate(g, def, rate, rng);
      ASSERT_TRUE(valid(g)) << "rate " << rate << ", child " << i;
      EXPECT_GE(static_cast<int>(g.nodes.size()), 1);
      EXPECT_LE(static_cast<int>(g.nodes.size()), most_genes(d));
    }
  }
}

TEST_P(Operators, LongMutationChainsStayValid) {
  // edits pile up: one lineage mutated again and again
  Dialect d = GetParam();
  OperatorDef def = default_operators(d);
  Rng rng = rng_for(d, 4);
  for (int lineage = 0; lineage < 10; ++lineage) {
    Genome g = random_genome(d, def, rng);
    for (int step = 0; step < 100; ++step) {
      mutate(g, def, step % 10 == 0 ? 0.5 : mix_for(d).rate_asexual, rng);
      ASSERT_TRUE(valid(g)) << "lineage " << lineage << ", step " << step;
    }
  }
}

TEST_P(Operators, CrossoverChildrenValidate) {
  Dialect d = GetParam();
  std::vector<Genome> parents = pool(d, 100, 5);
  Rng rng = rng_for(d, 6);
  for (int i = 0; i < kMany; ++i) {
    const Genome& a = parents[rng.below(parents.size())];
    const Genome& b = parents[rng.below(parents.size())];
    Genome c = crossover(a, b, rng);
    ASSERT_TRUE(valid(c)) << "child " << i;
    EXPECT_LE(c.nodes.size(), std::max(a.nodes.size(), b.nodes.size()));
    if (d == Dialect::Miconi2006) {
      EXPECT_GE(c.nodes.size(), 2u);  // a tree loses no node
    }
  }
}

TEST_P(Operators, GraftChildrenValidate) {
  Dialect d = GetParam();
  std::vector<Genome> parents = pool(d, 100, 7);
  Rng rng = rng_for(d, 8);
  for (int i = 0; i < kMany; ++i) {
    const Genome& a = parents[rng.below(parents.size())];
    const Genome& b = parents[rng.below(parents.size())];
    Genome c = graft(a, b, rng);
    ASSERT_TRUE(valid(c)) << "child " << i;
    EXPECT_LE(static_cast<int>(c.nodes.size()), most_genes(d));
    // the trunk's root (its body; its edges and wiring may change)
    EXPECT_EQ(c.nodes[0].shape, a.nodes[0].shape);
    EXPECT_EQ(c.nodes[0].size, a.nodes[0].size);
    EXPECT_EQ(c.nodes[0].joint, a.nodes[0].joint);
    EXPECT_EQ(c.nodes[0].neurons.size(), a.nodes[0].neurons.size());
  }
}

TEST_P(Operators, EvolutionLoopStaysValid) {
  // the operators as an evolutionary loop uses them, children of children
  Dialect d = GetParam();
  OperatorDef def = default_operators(d);
  std::vector<Genome> pop = pool(d, 40, 9);
  Rng rng = rng_for(d, 10);
  const Mix mix = mix_for(d);
  for (int i = 0; i < 3000; ++i) {
    const Genome& a = pop[rng.below(pop.size())];
    const Genome& b = pop[rng.below(pop.size())];
    double r = rng.uniform();
    Genome c;
    if (r < mix.p_asexual) {
      c = a;
      for (int k = 0; k < mix.asexual_mutations; ++k) mutate(c, def, mix.rate_asexual, rng);
    } else {
      c = r < mix.p_asexual + mix.p_crossover ? crossover(a, b, def, rng) : graft(a, b, def, rng);
      if (rng.chance(mix.p_mutate_after_mating)) mutate(c, def, mix.rate_after_mating, rng);
    }
    ASSERT_TRUE(valid(c)) << "child " << i;
    pop[rng.below(pop.size())] = std::move(c);
  }
}

// ---------------------------------------------------------------- determinism

TEST_P(Operators, SameSeedSameOutput) {
  Dialect d = GetParam();
  OperatorDef def = default_operators(d);
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    Rng r1 = rng_for(d, 100 + seed), r2 = rng_for(d, 100 + seed);
    Genome a1 = random_genome(d, def, r1), a2 = random_genome(d, def, r2);
    Genome b1 = random_genome(d, def, r1), b2 = random_genome(d, def, r2);
    EXPECT_EQ(a1, a2);
    EXPECT_EQ(b1, b2);
    Genome m1 = a1, m2 = a2;
    mutate(m1, def, 0.2, r1);
    mutate(m2, def, 0.2, r2);
    EXPECT_EQ(m1, m2);
    EXPECT_EQ(crossover(a1, b1, r1), crossover(a2, b2, r2));
    EXPECT_EQ(graft(a1, b1, r1), graft(a2, b2, r2));
    EXPECT_EQ(r1.next(), r2.next());  // the same number of draws
  }
  // different seeds give different genomes
  Rng r1 = rng_for(d, 200), r2 = rng_for(d, 201);
  EXPECT_NE(random_genome(d, def, r1), random_genome(d, def, r2));
}

// ---------------------------------------------------------------- canonical form

TEST_P(Operators, JsonRoundTrip) {
  Dialect d = GetParam();
  OperatorDef def = default_operators(d);
  std::vector<Genome> parents = pool(d, 50, 11);
  Rng rng = rng_for(d, 12);
  std::vector<Genome> all = parents;
  for (int i = 0; i < 150; ++i) {
    const Genome& a = parents[rng.below(parents.size())];
    const Genome& b = parents[rng.below(parents.size())];
    Genome m = a;
    mutate(m, def, 0.3, rng);
    all.push_back(m);
    all.push_back(crossover(a, b, rng));
    all.push_back(graft(a, b, rng));
  }
  for (const Genome& g : all) {
    std::string text = genome_to_string(g);
    Result<Genome> back = genome_from_string(text, "round-trip");
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_EQ(*back, g) << text;
    EXPECT_EQ(genome_to_string(*back), text);
  }
}

// ---------------------------------------------------------------- graph dialects

class GraphOperators : public ::testing::TestWithParam<Dialect> {};

INSTANTIATE_TEST_SUITE_P(Dialects, GraphOperators,
                         ::testing::Values(Dialect::Sims1994, Dialect::Chaumont2007, Dialect::Lessin2015),
                         [](const auto& info) { return name_of(info.param); });

// gives each node a size that names its origin: parent p (1 or 2), position i
Genome marked(Genome g, int p) {
  for (std::size_t i = 0; i < g.nodes.size(); ++i)
    g.nodes[i].size = {0.1 + 0.01 * static_cast<double>(i), 0.1 * p, 0.1};
  return g;
}

TEST_P(GraphOperators, CrossoverNodesComeFromPrefixAndSuffix) {
  Dialect d = GetParam();
  std::vector<Genome> parents = pool(d, 60, 13);
  Rng rng = rng_for(d, 14);
  for (int i = 0; i < 300; ++i) {
    Genome a = marked(parents[rng.below(parents.size())], 1);
    Genome b = marked(parents[rng.below(parents.size())], 2);
    int na = static_cast<int>(a.nodes.size()), nb = static_cast<int>(b.nodes.size());
    int cut = 1 + static_cast<int>(rng.below(std::max(na, nb)));
    Genome c = crossover_at(a, b, cut, default_operators(d), rng);
    ASSERT_TRUE(valid(c));
    EXPECT_EQ(c.nodes[0].size, a.nodes[0].size);  // the root is a's
    // every node is a's before the cut or b's from the cut, a's first, each in order
    bool in_b = false;
    int last = -1;
    for (const NodeGene& n : c.nodes) {
      int pos = static_cast<int>(std::lround((n.size.x - 0.1) / 0.01));
      bool from_b = n.size.y > 0.15;
      if (from_b && !in_b) {
        in_b = true;
        last = -1;
      }
      EXPECT_EQ(from_b, in_b) << "a node of a after one of b";
      if (from_b)
        EXPECT_TRUE(pos >= cut && pos < nb) << "b's node " << pos << ", cut " << cut;
      else
        EXPECT_TRUE(pos < cut && pos < na) << "a's node " << pos << ", cut " << cut;
      EXPECT_GT(pos, last);
      last = pos;
    }
  }
}

TEST_P(GraphOperators, NothingToMutateChangesNothing) {
  Dialect d = GetParam();
  OperatorDef def = default_operators(d);
  def.structure = {};
  std::vector<Genome> parents = pool(d, 100, 15);
  Rng rng = rng_for(d, 16);
  for (const Genome& p : parents) {
    Genome g = p;
    mutate(g, def, 0.0, rng);
    EXPECT_EQ(g, p);
  }
}

TEST_P(GraphOperators, EveryStructuralMutationAloneStaysValid) {
  Dialect d = GetParam();
  std::vector<Genome> parents = pool(d, 50, 17);
  Rng rng = rng_for(d, 18);
  double StructuralRates::*kinds[] = {
      &StructuralRates::add_node,        &StructuralRates::remove_node,
      &StructuralRates::add_edge,        &StructuralRates::remove_edge,
      &StructuralRates::retarget_edge,   &StructuralRates::add_neuron,
      &StructuralRates::remove_neuron,   &StructuralRates::add_sensor,
      &StructuralRates::remove_sensor,   &StructuralRates::add_effector,
      &StructuralRates::remove_effector, &StructuralRates::change_fn};
  for (auto kind : kinds) {
    OperatorDef def = default_operators(d);
    def.structure = {};
    def.structure.*kind = 1.0;
    int changed = 0;
    for (int i = 0; i < 200; ++i) {
      Genome g = parents[i % parents.size()];
      mutate(g, def, 0.0, rng);
      ASSERT_TRUE(valid(g));
      changed += !(g == parents[i % parents.size()]);
    }
    EXPECT_GT(changed, 20);  // the mutation does something
  }
}

TEST_P(GraphOperators, StructuralMutationsDoWhatTheySay) {
  Dialect d = GetParam();
  std::vector<Genome> parents = pool(d, 50, 19);
  Rng rng = rng_for(d, 20);
  auto only = [d](double StructuralRates::*kind) {
    OperatorDef def = default_operators(d);
    def.structure = {};
    def.structure.*kind = 1.0;
    return def;
  };
  auto neurons = [](const Genome& g) {
    std::size_t n = g.global_neurons.size();
    for (const NodeGene& x : g.nodes) n += x.neurons.size();
    return n;
  };
  auto sensors = [](const Genome& g) {
    std::size_t n = 0;
    for (const NodeGene& x : g.nodes) n += x.sensors.size();
    return n;
  };
  for (const Genome& p : parents) {
    Genome g = p;
    mutate(g, only(&StructuralRates::add_node), 0, rng);
    EXPECT_EQ(g.nodes.size(), std::min<std::size_t>(p.nodes.size() + 1, most_genes(d)));
    g = p;
    mutate(g, only(&StructuralRates::add_neuron), 0, rng);
    EXPECT_EQ(neurons(g), neurons(p) + 1);
    g = p;
    mutate(g, only(&StructuralRates::remove_neuron), 0, rng);
    EXPECT_EQ(neurons(g), std::max<std::size_t>(neurons(p), 1) - 1);
    g = p;
    mutate(g, only(&StructuralRates::add_sensor), 0, rng);
    EXPECT_EQ(sensors(g), sensors(p) + 1);
    g = p;
    mutate(g, only(&StructuralRates::remove_node), 0, rng);
    EXPECT_LE(g.nodes.size(), p.nodes.size());
    EXPECT_GE(g.nodes.size(), std::min<std::size_t>(p.nodes.size(), 2));
  }
}

TEST(GraphOperators, RandomGenomesUseTheWholeDialect) {
  // variety: recursion, reflection, extra edges, global neurons, shapes, joints
  OperatorDef def = default_operators(Dialect::Sims1994);
  Rng rng = rng_for(Dialect::Sims1994, 21);
  std::map<std::string, int> seen;
  for (int i = 0; i < kMany; ++i) {
    Genome g = random_genome(Dialect::Sims1994, def, rng);
    if (!g.global_neurons.empty()) seen["global"]++;
    for (int n = 0; n < static_cast<int>(g.nodes.size()); ++n) {
      const NodeGene& node = g.nodes[n];
      seen[std::string(to_string(node.shape))]++;
      seen[std::string(to_string(node.joint.type))]++;
      for (const EdgeGene& e : node.edges) {
        if (e.to == n) seen["reflexive"]++;
        if (!e.reflect.empty()) seen["reflect"]++;
        if (e.terminal_only) seen["terminal_only"]++;
      }
      for (const SensorGene& s : node.sensors) seen[std::string(to_string(s.type))]++;
    }
  }
  for (const char* k : {"global", "box", "sphere", "capsule", "cylinder", "hinge", "universal",
                        "spherical", "fixed", "slider", "cylindrical", "reflexive", "reflect",
                        "terminal_only", "joint_angle", "contact"})
    EXPECT_GT(seen[k], 5) << k;
}

TEST(GraphOperators, ChaumontBodies) {
  OperatorDef def = default_operators(Dialect::Chaumont2007);
  Rng rng = rng_for(Dialect::Chaumont2007, 22);
  for (int i = 0; i < 300; ++i) {
    Genome g = random_genome(Dialect::Chaumont2007, def, rng);
    for (int k = 0; k < 3; ++k) mutate(g, def, 0.3, rng);
    ASSERT_TRUE(valid(g));
    for (const NodeGene& n : g.nodes) {
      EXPECT_EQ(n.shape, Shape::Box);
      EXPECT_TRUE(n.joint.type == JointType::Hinge || n.joint.type == JointType::Slider);
      for (const SensorGene& s : n.sensors) EXPECT_EQ(s.type, SensorType::Contact);
    }
    EXPECT_LE(g.nodes.size(), 20u);
  }
}

// ---------------------------------------------------------------- constants

TEST(OperatorDefaults, PapersConstants) {
  OperatorDef m = default_operators(Dialect::Miconi2006);
  EXPECT_EQ(m.dialect, Dialect::Miconi2006);
  EXPECT_DOUBLE_EQ(m.p_reflect, 0.1);
  EXPECT_DOUBLE_EQ(m.connection_fraction, 0.75);
  EXPECT_DOUBLE_EQ(m.bias_step, 0.33);
  EXPECT_DOUBLE_EQ(m.weight_step, 0.33);
  EXPECT_DOUBLE_EQ(m.angle_step, kPi / 8);
  EXPECT_DOUBLE_EQ(m.angle_mutation_range, kPi / 2);
  EXPECT_EQ(m.max_genes, 7);
  EXPECT_EQ(m.min_genes, 2);
  EXPECT_EQ(m.neuron_slots, 6);
  EXPECT_EQ(m.connection_slots, 3);
  EXPECT_EQ(m.bias_range, (Range{-1.5, 1.5}));
  EXPECT_EQ(m.weight_range, (Range{-1, 1}));

  OperatorDef c = default_operators(Dialect::Chaumont2007);
  EXPECT_EQ(c.max_genes, 20);

  OperatorDef s = default_operators(Dialect::Sims1994);
  EXPECT_GT(s.structure.add_node, 0);
}

// ---------------------------------------------------------------- miconi2006

constexpr Dialect kMiconi = Dialect::Miconi2006;

bool axis_y_or_z(Vec3 a) { return a == Vec3{0, 1, 0} || a == Vec3{0, 0, 1}; }

bool on_lattice(double x) {
  double k = x / (kPi / 8);
  return std::abs(x - std::round(k) * (kPi / 8)) < 1e-12;
}

TEST(MiconiOperators, RandomLimbs) {
  OperatorDef def = default_operators(kMiconi);
  Rng rng = rng_for(kMiconi, 30);
  int reflected = 0, limbs = 0;
  for (int i = 0; i < kMany; ++i) {
    Genome g = random_genome(kMiconi, def, rng);
    // Fig. 1: the root has no sensor or actuator, every limb one of each
    EXPECT_TRUE(g.nodes[0].sensors.empty());
    EXPECT_TRUE(g.nodes[0].effectors.empty());
    for (std::size_t n = 0; n < g.nodes.size(); ++n) {
      const NodeGene& node = g.nodes[n];
      if (n > 0) {
        ASSERT_EQ(node.sensors.size(), 1u);
        EXPECT_EQ(node.sensors[0].type, SensorType::JointAngle);
        ASSERT_EQ(node.effectors.size(), 1u);
        ++limbs;
      }
      EXPECT_EQ(node.joint.type, JointType::Hinge);
      EXPECT_TRUE(axis_y_or_z(node.joint.axis1));
      EXPECT_TRUE(node.joint.limits.empty());
      EXPECT_LE(node.neurons.size(), 6u);
      for (const NeuronGene& nr : node.neurons) EXPECT_LE(nr.inputs.size(), 3u);
      for (const EdgeGene& e : node.edges) {
        EXPECT_EQ(e.rotation.x, 0);
        EXPECT_TRUE(on_lattice(e.rotation.y) && on_lattice(e.rotation.z));
        if (!e.reflect.empty()) {
          ++reflected;
          EXPECT_EQ(e.reflect, std::vector<int>{1});
          // off the mirror plane: on the parent's +-y face
          EXPECT_EQ(face_axis(e.face), 1);
        }
      }
    }
  }
  // P_ref = 0.1
  EXPECT_NEAR(static_cast<double>(reflected) / limbs, 0.1, 0.03);
}

TEST(MiconiOperators, InitialConnectionFraction) {
  // Table 1: 75% of connection slots assigned
  OperatorDef def = default_operators(kMiconi);
  Rng rng = rng_for(kMiconi, 31);
  double slots = 0, used = 0;
  for (int i = 0; i < kMany; ++i) {
    Genome g = random_genome(kMiconi, def, rng);
    for (const NodeGene& n : g.nodes) {
      for (const NeuronGene& nr : n.neurons) slots += 3, used += nr.inputs.size();
      for (const EffectorGene& ef : n.effectors) slots += 3, used += ef.inputs.size();
    }
  }
  EXPECT_NEAR(used / slots, 0.75, 0.02);
}

TEST(MiconiOperators, RateZeroChangesNothing) {
  OperatorDef def = default_operators(kMiconi);
  std::vector<Genome> parents = pool(kMiconi, 200, 32);
  Rng rng = rng_for(kMiconi, 33);
  for (const Genome& p : parents) {
    Genome g = p;
    mutate(g, def, 0.0, rng);
    EXPECT_EQ(g, p);
  }
}

// miconi mutation with only `steps` on, at probability p
Genome miconi_step(const Genome& p, unsigned steps, double prob, Rng& rng) {
  OperatorDef def = default_operators(kMiconi);
  def.miconi_steps = steps;
  Genome g = p;
  mutate(g, def, prob, rng);
  EXPECT_TRUE(valid(g));
  return g;
}

// the genome with every threshold, weight and activation function blanked
Genome without_values(Genome g) {
  for (NodeGene& n : g.nodes) {
    for (NeuronGene& nr : n.neurons) {
      nr.bias = 0;
      nr.fn = "";
      for (InputGene& in : nr.inputs) in.weight = 0;
    }
    for (EffectorGene& ef : n.effectors) {
      ef.bias = 0;
      for (InputGene& in : ef.inputs) in.weight = 0;
    }
  }
  return g;
}

double torus_distance(double a, double b, double span) {
  double d = std::abs(a - b);
  return std::min(d, span - d);
}

TEST(MiconiOperators, ThresholdStepAlone) {
  std::vector<Genome> parents = pool(kMiconi, 100, 34);
  Rng rng = rng_for(kMiconi, 35);
  for (const Genome& p : parents) {
    Genome g = miconi_step(p, kMiconiThresholds, 1.0, rng);
    EXPECT_EQ(without_values(g), without_values(p));
    for (std::size_t n = 0; n < g.nodes.size(); ++n) {
      for (std::size_t k = 0; k < g.nodes[n].neurons.size(); ++k) {
        double a = p.nodes[n].neurons[k].bias, b = g.nodes[n].neurons[k].bias;
        EXPECT_LE(torus_distance(a, b, 3.0), 0.33 + 1e-12);
        EXPECT_EQ(g.nodes[n].neurons[k].fn, p.nodes[n].neurons[k].fn);
      }
      for (std::size_t k = 0; k < g.nodes[n].effectors.size(); ++k)
        EXPECT_LE(torus_distance(p.nodes[n].effectors[k].bias, g.nodes[n].effectors[k].bias, 3.0),
                  0.33 + 1e-12);
    }
  }
}

TEST(MiconiOperators, ActivationStepAlone) {
  std::vector<Genome> parents = pool(kMiconi, 100, 36);
  Rng rng = rng_for(kMiconi, 37);
  for (const Genome& p : parents) {
    Genome g = miconi_step(p, kMiconiActivation, 1.0, rng);
    EXPECT_EQ(without_values(g), without_values(p));
    for (std::size_t n = 0; n < g.nodes.size(); ++n)
      for (std::size_t k = 0; k < g.nodes[n].neurons.size(); ++k) {
        EXPECT_NE(g.nodes[n].neurons[k].fn, p.nodes[n].neurons[k].fn);  // sigmoid <-> tanh
        EXPECT_EQ(g.nodes[n].neurons[k].bias, p.nodes[n].neurons[k].bias);
      }
  }
}

TEST(MiconiOperators, WeightStepAlone) {
  std::vector<Genome> parents = pool(kMiconi, 100, 38);
  Rng rng = rng_for(kMiconi, 39);
  for (const Genome& p : parents) {
    Genome g = miconi_step(p, kMiconiWeights, 1.0, rng);
    EXPECT_EQ(without_values(g), without_values(p));
    for (std::size_t n = 0; n < g.nodes.size(); ++n)
      for (std::size_t k = 0; k < g.nodes[n].neurons.size(); ++k)
        for (std::size_t i = 0; i < g.nodes[n].neurons[k].inputs.size(); ++i)
          EXPECT_LE(torus_distance(p.nodes[n].neurons[k].inputs[i].weight,
                                   g.nodes[n].neurons[k].inputs[i].weight, 2.0),
                    0.33 + 1e-12);
  }
}

TEST(MiconiOperators, NeuronSlotStepAlone) {
  // at p = 1 every slot flips: n neurons become 6 - n
  std::vector<Genome> parents = pool(kMiconi, 100, 40);
  Rng rng = rng_for(kMiconi, 41);
  for (const Genome& p : parents) {
    Genome g = miconi_step(p, kMiconiNeuronSlots, 1.0, rng);
    ASSERT_EQ(g.nodes.size(), p.nodes.size());
    for (std::size_t n = 0; n < g.nodes.size(); ++n) {
      EXPECT_EQ(g.nodes[n].neurons.size(), 6 - p.nodes[n].neurons.size());
      EXPECT_EQ(g.nodes[n].size, p.nodes[n].size);
    }
  }
}

TEST(MiconiOperators, ConnectionSlotStepAlone) {
  // at p = 1 every connection slot flips: k inputs become 3 - k
  std::vector<Genome> parents = pool(kMiconi, 100, 42);
  Rng rng = rng_for(kMiconi, 43);
  for (const Genome& p : parents) {
    Genome g = miconi_step(p, kMiconiConnSlots, 1.0, rng);
    for (std::size_t n = 0; n < g.nodes.size(); ++n) {
      ASSERT_EQ(g.nodes[n].neurons.size(), p.nodes[n].neurons.size());
      for (std::size_t k = 0; k < g.nodes[n].neurons.size(); ++k) {
        EXPECT_EQ(g.nodes[n].neurons[k].inputs.size(), 3 - p.nodes[n].neurons[k].inputs.size());
        EXPECT_EQ(g.nodes[n].neurons[k].bias, p.nodes[n].neurons[k].bias);
      }
      for (std::size_t k = 0; k < g.nodes[n].effectors.size(); ++k)
        EXPECT_EQ(g.nodes[n].effectors[k].inputs.size(), 3 - p.nodes[n].effectors[k].inputs.size());
    }
  }
}

TEST(MiconiOperators, SourceStepAlone) {
  std::vector<Genome> parents = pool(kMiconi, 100, 44);
  Rng rng = rng_for(kMiconi, 45);
  int moved = 0, total = 0;
  for (const Genome& p : parents) {
    Genome g = miconi_step(p, kMiconiSources, 1.0, rng);
    for (std::size_t n = 0; n < g.nodes.size(); ++n)
      for (std::size_t k = 0; k < g.nodes[n].neurons.size(); ++k) {
        const auto& a = p.nodes[n].neurons[k].inputs;
        const auto& b = g.nodes[n].neurons[k].inputs;
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
          EXPECT_EQ(a[i].weight, b[i].weight);
          ++total;
          moved += !(a[i] == b[i]);
        }
      }
  }
  EXPECT_GT(moved, total / 2);  // most draw another source
}

TEST(MiconiOperators, LimbStepsAlone) {
  std::vector<Genome> parents = pool(kMiconi, 200, 46);
  Rng rng = rng_for(kMiconi, 47);
  for (const Genome& p : parents) {
    std::size_t n = p.nodes.size();
    // (1) delete a limb and its sub-limbs, never below 2
    Genome g = miconi_step(p, kMiconiDeleteLimb, 1.0, rng);
    if (n > 2) {
      EXPECT_LT(g.nodes.size(), n);
    } else {
      EXPECT_EQ(g, p);
    }
    EXPECT_GE(g.nodes.size(), 2u);
    // (2) add a random limb, at most 7 genes
    g = miconi_step(p, kMiconiAddLimb, 1.0, rng);
    EXPECT_EQ(g.nodes.size(), std::min<std::size_t>(n + 1, 7));
    // (9) morphology: the brain's shape stays
    g = miconi_step(p, kMiconiMorphology, 1.0, rng);
    ASSERT_EQ(g.nodes.size(), n);
    for (std::size_t i = 0; i < n; ++i)
      EXPECT_EQ(g.nodes[i].neurons.size(), p.nodes[i].neurons.size());
  }
}

TEST(MiconiOperators, MorphologyMovesAndTurnsLimbs) {
  // over many mutations every kind of morphological change shows up
  std::vector<Genome> parents = pool(kMiconi, 300, 48);
  Rng rng = rng_for(kMiconi, 49);
  int moved = 0, resized = 0, turned = 0, hinge = 0, reflect = 0;
  for (const Genome& p : parents) {
    Genome g = miconi_step(p, kMiconiMorphology, 1.0, rng);
    for (std::size_t i = 1; i < p.nodes.size(); ++i) {
      auto pp = parents_of(p, static_cast<int>(i)), gp = parents_of(g, static_cast<int>(i));
      moved += pp != gp;
      resized += !(p.nodes[i].size == g.nodes[i].size);
      hinge += !(p.nodes[i].joint.axis1 == g.nodes[i].joint.axis1);
    }
    for (std::size_t i = 0; i < p.nodes.size(); ++i)
      for (const EdgeGene& e : p.nodes[i].edges)
        for (std::size_t j = 0; j < g.nodes.size(); ++j)
          for (const EdgeGene& f : g.nodes[j].edges)
            if (f.to == e.to) {
              turned += !(f.rotation == e.rotation);
              reflect += f.reflect != e.reflect;
            }
  }
  EXPECT_GT(moved, 20);
  EXPECT_GT(resized, 20);
  EXPECT_GT(turned, 20);
  EXPECT_GT(hinge, 20);
  EXPECT_GT(reflect, 20);
}

TEST(MiconiOperators, OrientationMutationStaysWithinRange) {
  // a turned limb keeps its face or moves to the face its new direction leaves
  // through; its direction moves by at most pi/2 (plus the lattice rounding)
  std::vector<Genome> parents = pool(kMiconi, 300, 50);
  Rng rng = rng_for(kMiconi, 51);
  for (const Genome& p : parents) {
    Genome g = miconi_step(p, kMiconiMorphology, 1.0, rng);
    for (std::size_t i = 0; i < p.nodes.size(); ++i)
      for (std::size_t k = 0; k < p.nodes[i].edges.size() && k < g.nodes[i].edges.size(); ++k) {
        const EdgeGene& e = p.nodes[i].edges[k];
        const EdgeGene& f = g.nodes[i].edges[k];
        if (e.to != f.to || e.rotation == f.rotation) continue;
        double angle = std::acos(std::clamp(dot(edge_direction(e), edge_direction(f)), -1.0, 1.0));
        EXPECT_LE(angle, kPi / 2 + kPi / 8 + 1e-9);
      }
  }
}

TEST(MiconiOperators, MeanChangesAtPmut) {
  // statistics at P_mut = 0.04: each threshold and weight moves with 4%
  std::vector<Genome> parents = pool(kMiconi, 300, 52);
  OperatorDef def = default_operators(kMiconi);
  Rng rng = rng_for(kMiconi, 53);
  double units = 0, biases = 0, inputs = 0, weights = 0;
  for (int rep = 0; rep < 10; ++rep)
    for (const Genome& p : parents) {
      Genome g = miconi_step(p, kMiconiThresholds | kMiconiWeights, 0.04 /* P_mut, 5.1 */, rng);
      for (std::size_t n = 0; n < g.nodes.size(); ++n)
        for (std::size_t k = 0; k < g.nodes[n].neurons.size(); ++k) {
          ++units;
          biases += g.nodes[n].neurons[k].bias != p.nodes[n].neurons[k].bias;
          for (std::size_t i = 0; i < g.nodes[n].neurons[k].inputs.size(); ++i) {
            ++inputs;
            weights +=
                g.nodes[n].neurons[k].inputs[i].weight != p.nodes[n].neurons[k].inputs[i].weight;
          }
        }
    }
  EXPECT_NEAR(biases / units, 0.04, 0.008);
  EXPECT_NEAR(weights / inputs, 0.04, 0.008);
  // the full sequence: about 0.04 * 6 neuron slots flipped per limb
  double flips = 0, limbs = 0;
  for (int rep = 0; rep < 10; ++rep)
    for (const Genome& p : parents) {
      Genome g = miconi_step(p, kMiconiNeuronSlots, 0.04 /* P_mut, 5.1 */, rng);
      for (std::size_t n = 0; n < g.nodes.size(); ++n) {
        ++limbs;
        flips += std::abs(static_cast<double>(g.nodes[n].neurons.size()) -
                          static_cast<double>(p.nodes[n].neurons.size()));
      }
    }
  // |added - deleted| is at most the flips (0.24 per limb) and rarely less
  EXPECT_GT(flips / limbs, 0.18);
  EXPECT_LT(flips / limbs, 0.26);
}

TEST(MiconiOperators, CrossoverSplicesAlignedNodeLists) {
  // sec. 5.1: child = a's nodes before the cut, then b's from the cut; a tree
  // loses no node, so the sequence is exact
  std::vector<Genome> parents = pool(kMiconi, 60, 54);
  OperatorDef def = default_operators(kMiconi);
  Rng rng = rng_for(kMiconi, 55);
  for (int i = 0; i < 300; ++i) {
    Genome a = marked(parents[rng.below(parents.size())], 1);
    Genome b = marked(parents[rng.below(parents.size())], 2);
    int na = static_cast<int>(a.nodes.size()), nb = static_cast<int>(b.nodes.size());
    int cut = 1 + static_cast<int>(rng.below(std::max(na, nb)));
    Genome c = crossover_at(a, b, cut, def, rng);
    ASSERT_TRUE(valid(c));
    std::vector<Vec3> want;
    for (int p = 0; p < std::min(cut, na); ++p) want.push_back(a.nodes[p].size);
    for (int p = cut; p < nb; ++p) want.push_back(b.nodes[p].size);
    std::vector<Vec3> got;
    for (const NodeGene& n : c.nodes) got.push_back(n.size);
    EXPECT_EQ(got, want) << "cut " << cut;
    // each node keeps its neurons (the brain travels with the node)
    for (int p = 0; p < std::min(cut, na); ++p)
      EXPECT_EQ(c.nodes[p].neurons.size(), a.nodes[p].neurons.size());
  }
}

// A root with neurons and one limb; the root's neuron 0 reads the limb's
// neuron `k`, the limb's neuron 0 reads the root (as parent) neuron 1.
Genome two_limbs(double limb_x, int limb_neurons) {
  Genome g;
  g.dialect = kMiconi;
  g.nodes.resize(2);
  g.nodes[0].size = {0.5, 0.3, 0.3};
  g.nodes[1].size = {limb_x, 0.2, 0.2};
  g.nodes[1].sensors.push_back({SensorType::JointAngle, 0, Face::NegZ});
  g.nodes[1].effectors.push_back({0, 0.1, {}});
  EdgeGene e;
  e.to = 1;
  g.nodes[0].edges.push_back(e);
  for (int k = 0; k < 3; ++k) g.nodes[0].neurons.push_back({"tanh", {}, 0.1 * k, {}});
  for (int k = 0; k < limb_neurons; ++k)
    g.nodes[1].neurons.push_back({"sigmoid", {}, -0.1 * k, {}});
  return g;
}

TEST(MiconiOperators, GraftKeepsConnectivity) {
  // sec. 5.1: the trunk's neurons read the new branch as they read the old
  // one, and the new branch reads its new trunk as it read its old one
  Genome trunk = two_limbs(0.4, 3);
  trunk.nodes[0].neurons[0].inputs.push_back({SourcePlace::Child, SourceKind::Neuron, 2, 0, 0.5});
  trunk.nodes[0].neurons[1].inputs.push_back({SourcePlace::Child, SourceKind::Sensor, 0, 0, -0.5});
  Genome branch = two_limbs(0.7, 4);
  branch.nodes[1].neurons[3].inputs.push_back(
      {SourcePlace::Parent, SourceKind::Neuron, 1, 0, 0.25});
  branch.nodes[1].neurons[2].inputs.push_back({SourcePlace::Self, SourceKind::Neuron, 3, 0, 0.75});
  ASSERT_TRUE(valid(trunk));
  ASSERT_TRUE(valid(branch));
  Rng rng(1);
  Genome c = graft(trunk, branch, rng);
  ASSERT_TRUE(valid(c));
  ASSERT_EQ(c.nodes.size(), 2u);
  EXPECT_EQ(c.nodes[0].size, trunk.nodes[0].size);
  EXPECT_EQ(c.nodes[1].size, branch.nodes[1].size);   // the new branch
  EXPECT_EQ(c.nodes[0].edges, trunk.nodes[0].edges);  // attached by the old branch's edge
  // trunk -> new branch, same indices
  EXPECT_EQ(c.nodes[0].neurons[0].inputs,
            (std::vector<InputGene>{{SourcePlace::Child, SourceKind::Neuron, 2, 0, 0.5}}));
  EXPECT_EQ(c.nodes[0].neurons[1].inputs,
            (std::vector<InputGene>{{SourcePlace::Child, SourceKind::Sensor, 0, 0, -0.5}}));
  // new branch -> trunk, and inside the branch
  EXPECT_EQ(c.nodes[1].neurons[3].inputs,
            (std::vector<InputGene>{{SourcePlace::Parent, SourceKind::Neuron, 1, 0, 0.25}}));
  EXPECT_EQ(c.nodes[1].neurons[2].inputs,
            (std::vector<InputGene>{{SourcePlace::Self, SourceKind::Neuron, 3, 0, 0.75}}));
}

TEST(MiconiOperators, GraftClampsIndicesThatDoNotExist) {
  Genome trunk = two_limbs(0.4, 3);
  trunk.nodes[0].neurons[0].inputs.push_back({SourcePlace::Child, SourceKind::Neuron, 2, 0, 0.5});
  Genome branch = two_limbs(0.7, 2);  // the new branch has neurons 0 and 1 only
  branch.nodes[0].neurons.resize(1);
  branch.nodes[1].neurons[1].inputs.push_back(
      {SourcePlace::Parent, SourceKind::Neuron, 0, 0, 0.25});
  // and a trunk whose root has a single neuron: the branch's parent source 2 clamps to 0
  Genome small_trunk = trunk;
  small_trunk.nodes[0].neurons.resize(1);
  Genome branch2 = two_limbs(0.7, 2);
  branch2.nodes[1].neurons[1].inputs.push_back(
      {SourcePlace::Parent, SourceKind::Neuron, 2, 0, 0.25});
  Rng rng(2);
  Genome c = graft(trunk, branch, rng);
  ASSERT_TRUE(valid(c));
  EXPECT_EQ(c.nodes[0].neurons[0].inputs,
            (std::vector<InputGene>{{SourcePlace::Child, SourceKind::Neuron, 1, 0, 0.5}}));
  Genome c2 = graft(small_trunk, branch2, rng);
  ASSERT_TRUE(valid(c2));
  EXPECT_EQ(c2.nodes[1].neurons[1].inputs,
            (std::vector<InputGene>{{SourcePlace::Parent, SourceKind::Neuron, 0, 0, 0.25}}));
}

}  // namespace
}  // namespace bx
