// Encapsulation (lessin2015 IV-B, genome/encapsulate.h) as genes, on the
// muscle crawler of creatures: the skill frozen, its wires gated by a
// new switch, the bias a gated wire; mutation and crossover keep every
// frozen gene; validation names a bad gate or switch. Its behaviour (the
// skill alone exactly as before, silent when off) is
// tests/eval/encapsulated_skill_test.cpp.
#include "genome/encapsulate.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "genome/dialect.h"
#include "genome/genome_json.h"
#include "genome/locks.h"
#include "genome/operators.h"
#include "genome/reconcile.h"

namespace bx {
namespace {

Genome crawler() {
  auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/lessin_crawler.json");
  EXPECT_TRUE(g.ok()) << g.error();
  return g.ok() ? *g : Genome{};
}

Genome encapsulated(const Genome& g, const std::string& name, int group = NeuronGene::kNoGroup) {
  auto e = encapsulate(g, {name, group});
  EXPECT_TRUE(e.ok()) << e.error();
  return e.ok() ? *e : g;
}

TEST(Encapsulate, FreezesTheSkillAndGatesEveryWireLeavingIt) {
  const Genome g = crawler();
  const Genome e = encapsulated(g, "crawl", 3);
  ASSERT_TRUE(validate(e).ok()) << validate(e).error();
  // the switch: a closed global sigma of the skill's name and group
  const std::vector<std::string> skills = skills_of(e);
  ASSERT_EQ(skills, std::vector<std::string>{"crawl"});
  const int sw = static_cast<int>(e.global_neurons.size()) - 1;
  EXPECT_EQ(e.global_neurons[sw].fn, "sigma");
  EXPECT_EQ(e.global_neurons[sw].group, 3);
  EXPECT_TRUE(e.global_neurons[sw].locked);
  for (std::size_t i = 0; i < e.nodes.size(); ++i) {
    for (const NeuronGene& nr : e.nodes[i].neurons) EXPECT_TRUE(nr.locked);
    for (const SensorGene& s : e.nodes[i].sensors) EXPECT_TRUE(s.locked);
    for (std::size_t k = 0; k < e.nodes[i].effectors.size(); ++k) {
      const EffectorGene &was = g.nodes[i].effectors[k], &is = e.nodes[i].effectors[k];
      EXPECT_EQ(is.bias, 0);
      EXPECT_EQ(is.muscle, was.muscle);
      // the bias leads as a gated wire from a constant 1, then the wires as they were
      const std::size_t lead = was.bias != 0 ? 1 : 0;
      ASSERT_EQ(is.inputs.size(), was.inputs.size() + lead);
      if (lead) {
        EXPECT_EQ(is.inputs[0].place, SourcePlace::Global);
        EXPECT_EQ(is.inputs[0].weight, was.bias);
        const NeuronGene& one = e.global_neurons[is.inputs[0].index];
        EXPECT_EQ(one.fn, "constant");
        EXPECT_EQ(one.params, std::vector{1.0});
      }
      for (std::size_t q = 0; q < is.inputs.size(); ++q) EXPECT_EQ(is.inputs[q].gate, sw);
      for (std::size_t q = 0; q < was.inputs.size(); ++q) {
        InputGene ungated = is.inputs[q + lead];
        ungated.gate = InputGene::kNoGate;
        EXPECT_EQ(ungated, was.inputs[q]);
      }
    }
  }
  // a genome and its JSON read back alike
  auto back = genome_from_json(genome_to_json(e), "test");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(*back, e);
  // a name once
  EXPECT_FALSE(encapsulate(e, {"crawl"}).ok());
  EXPECT_FALSE(encapsulate(g, {""}).ok());
}

TEST(Encapsulate, AThousandMutationsChangeNoFrozenGene) {
  Genome e = encapsulated(crawler(), "crawl");
  open_switches(e, {"crawl"});  // open: mutation may wire into it
  OperatorDef def = default_operators(Dialect::Lessin2015);
  def.structure.add_input = 0.5;
  def.structure.remove_input = 0.2;
  Rng rng(7);
  Genome g = e;
  int grew = 0;  // mutants whose effectors or switch took a wire of their own
  for (int k = 0; k < 1000; ++k) {
    mutate(g, def, 0.2, rng);
    ASSERT_TRUE(validate(g).ok()) << "mutation " << k << ": " << validate(g).error();
    Status kept = locks_kept(e, g);
    ASSERT_TRUE(kept.ok()) << "mutation " << k << ": " << kept.error();
    bool own = false;
    for (const NodeGene& n : g.nodes)
      for (const EffectorGene& ef : n.effectors)
        if (static_cast<int>(ef.inputs.size()) > gated_prefix(ef.inputs)) own = true;
    grew += own;
  }
  EXPECT_GT(grew, 100);
  // crossover with the mutant keeps them too
  Genome child = crossover(e, g, rng);
  EXPECT_TRUE(locks_kept(e, child).ok()) << locks_kept(e, child).error();
}

// how many inputs of units other than neuron k of `owner` (-1: global) read it
int readers_of(const Genome& g, int owner, int k) {
  int n = 0;
  const NeuronGene* self = &(owner < 0 ? g.global_neurons : g.nodes[owner].neurons)[k];
  auto count = [&](int reader, const std::vector<InputGene>& ins) {
    if (!ins.empty() && &ins == &self->inputs) return;
    for (const InputGene& in : ins) {
      if (in.kind != SourceKind::Neuron || in.index != k) continue;
      if (owner < 0 ? in.place == SourcePlace::Global : (in.place == SourcePlace::Self && reader == owner)) ++n;
    }
  };
  for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i) {
    for (const NeuronGene& nr : g.nodes[i].neurons) count(i, nr.inputs);
    for (const EffectorGene& ef : g.nodes[i].effectors) count(i, ef.inputs);
  }
  for (const NeuronGene& nr : g.global_neurons) count(-1, nr.inputs);
  return n;
}

TEST(Encapsulate, AWiredNewNeuronIsReadByAMuscleOrAnOpenSwitch) {
  Genome e = encapsulated(crawler(), "crawl");
  open_switches(e, {"crawl"});
  OperatorDef def = default_operators(Dialect::Lessin2015);
  def.structure = {};
  def.structure.add_neuron = 1;  // each mutation adds one neuron, and nothing else changes (rate 0)
  for (double wired : {0.0, 1.0}) {
    def.p_wired_neuron = wired;
    Rng rng(11);
    int read = 0, effectors = 0, switches = 0;
    for (int k = 0; k < 200; ++k) {
      Genome g = e;
      mutate(g, def, 0, rng);
      ASSERT_TRUE(validate(g).ok()) << validate(g).error();
      ASSERT_TRUE(locks_kept(e, g).ok()) << locks_kept(e, g).error();
      // the one new neuron: the last of its node's or of the global ones
      int owner = -2, at = -1;
      for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i)
        if (g.nodes[i].neurons.size() == e.nodes[i].neurons.size() + 1) owner = i, at = static_cast<int>(e.nodes[i].neurons.size());
      if (g.global_neurons.size() == e.global_neurons.size() + 1) owner = -1, at = static_cast<int>(e.global_neurons.size());
      ASSERT_NE(owner, -2) << "mutation " << k << " added no neuron";
      ASSERT_FALSE((owner < 0 ? g.global_neurons : g.nodes[owner].neurons)[at].locked);
      if (readers_of(g, owner, at) == 0) continue;
      ++read;
      // its reader: a muscle's free input or the open switch's (the only
      // units that may take one), never a frozen unit's
      for (const NodeGene& n : g.nodes)
        for (const EffectorGene& ef : n.effectors)
          effectors += ef.inputs.size() > static_cast<std::size_t>(gated_prefix(ef.inputs));
      for (const NeuronGene& nr : g.global_neurons)
        switches += nr.skill == "crawl" && !nr.inputs.empty();
    }
    if (wired == 0) {
      EXPECT_EQ(read, 0);  // Sims' add_neuron: a neuron no unit reads yet
    } else {
      EXPECT_EQ(read, 200);
      EXPECT_EQ(effectors + switches, 200);
      EXPECT_GT(effectors, 100);  // two muscles, one switch: 133 and 67 expected
      EXPECT_GT(switches, 40);
    }
  }
}

// reconciliation (genome/reconcile.h): only the named skill's wires move
TEST(Reconcile, MutationMovesOnlyTheSkillsWiresAndCrossoverMixesThem) {
  Genome e = encapsulated(crawler(), "crawl");
  // a second skill: a wire of its own on the first muscle, then encapsulated
  e.nodes[1].effectors[0].inputs.push_back({SourcePlace::Self, SourceKind::Neuron, 0, 0, 0.4});
  Genome two = encapsulated(e, "twitch");
  const int crawl = skill_switch(two, "crawl"), twitch = skill_switch(two, "twitch");
  ASSERT_GE(crawl, 0);
  ASSERT_GT(twitch, crawl);
  EXPECT_EQ(skill_wire_count(two, "twitch"), 1);
  EXPECT_GT(skill_wire_count(two, "crawl"), 2);
  OperatorDef def = default_operators(Dialect::Lessin2015);
  Rng rng(5);
  Genome g = two;
  for (int k = 0; k < 50; ++k) mutate_skill_wires(g, "crawl", def, 0.3, rng);
  int moved = 0;
  Genome back = g;
  for (std::size_t n = 0; n < g.nodes.size(); ++n)
    for (std::size_t f = 0; f < g.nodes[n].effectors.size(); ++f)
      for (std::size_t i = 0; i < g.nodes[n].effectors[f].inputs.size(); ++i) {
        const InputGene &now = g.nodes[n].effectors[f].inputs[i], &was = two.nodes[n].effectors[f].inputs[i];
        if (now.weight != was.weight) {
          EXPECT_EQ(now.gate, crawl);
          ++moved;
        }
        back.nodes[n].effectors[f].inputs[i].weight = was.weight;
      }
  EXPECT_EQ(back, two);  // nothing but the weights of crawl's wires
  EXPECT_EQ(moved, skill_wire_count(two, "crawl"));
  // crossover: each of crawl's weights from one parent or the other, both seen
  Genome child = cross_skill_wires(two, g, "crawl", rng);
  int from_a = 0, from_b = 0;
  for (std::size_t n = 0; n < g.nodes.size(); ++n)
    for (std::size_t f = 0; f < g.nodes[n].effectors.size(); ++f)
      for (std::size_t i = 0; i < g.nodes[n].effectors[f].inputs.size(); ++i) {
        const double w = child.nodes[n].effectors[f].inputs[i].weight;
        if (two.nodes[n].effectors[f].inputs[i].gate != crawl) continue;
        from_a += w == two.nodes[n].effectors[f].inputs[i].weight;
        from_b += w == g.nodes[n].effectors[f].inputs[i].weight;
      }
  EXPECT_EQ(from_a + from_b, skill_wire_count(two, "crawl"));
  EXPECT_GT(from_a, 0);
  EXPECT_GT(from_b, 0);
}

TEST(Encapsulate, ValidationNamesABadGateOrSwitch) {
  const Genome e = encapsulated(crawler(), "crawl");
  auto problem = [](const Genome& g) {
    Status s = validate(g);
    return s.ok() ? std::string() : s.error();
  };
  Genome g = e;
  for (NodeGene& n : g.nodes)
    if (!n.effectors.empty() && !n.effectors[0].inputs.empty()) {
      n.effectors[0].inputs[0].gate = 0;  // global neuron 0 is no switch
      break;
    }
  EXPECT_NE(problem(g).find(".gate"), std::string::npos) << problem(g);
  g = e;
  for (NodeGene& n : g.nodes)
    if (!n.neurons.empty()) {
      n.neurons[0].skill = "walk";  // a switch is global
      break;
    }
  EXPECT_NE(problem(g).find(".skill"), std::string::npos) << problem(g);
  g = e;
  for (NodeGene& n : g.nodes)
    if (!n.effectors.empty() && !n.effectors[0].inputs.empty()) {
      std::vector<InputGene>& ins = n.effectors[0].inputs;
      InputGene gated = ins[0], free = ins[0];
      free.gate = InputGene::kNoGate;
      ins.push_back(free);
      ins.push_back(gated);  // a gated one after an ungated one
      break;
    }
  EXPECT_NE(problem(g).find("gated inputs come before"), std::string::npos) << problem(g);
}

}  // namespace
}  // namespace bx
