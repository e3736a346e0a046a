// Locks (genome/locks.h): no operator changes a locked gene, on many random
// genomes with random locks; locks_kept() sees every kind of change; the
// rules of lock_problem(); the JSON form.
#include "genome/locks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "genome/dialect.h"
#include "genome/genome_json.h"
#include "genome/operators.h"

namespace bx {
namespace {

Rng rng_for(Dialect d, std::uint64_t tag) { return Rng(stream_seed({static_cast<std::uint64_t>(d) + 7, tag})); }

// Random locks on a valid genome: each node locked with probability 1/2,
// with random bits; units locked (the node's, or a prefix of its neurons,
// sensors and effectors) where the rules allow. Each step keeps the genome
// valid, so the result is too.
Genome with_random_locks(Genome g, Rng& rng) {
  for (NodeGene& n : g.nodes) {
    if (!rng.chance(0.5)) continue;
    n.lock = static_cast<unsigned>(rng.below(kLockAll + 1)) & ~static_cast<unsigned>(kLockUnits);
    if (!validate(g).ok()) n.lock = 0;
    NodeGene before = n;
    if (rng.chance(0.3)) {
      n.lock |= kLockUnits;
    } else {
      auto prefix = [&](auto& units) {
        if (units.empty()) return;
        int k = static_cast<int>(rng.below(units.size() + 1));
        for (int j = 0; j < k; ++j) units[j].locked = true;
      };
      prefix(n.sensors);
      prefix(n.neurons);
      prefix(n.effectors);
    }
    if (!validate(g).ok()) n = before;  // a locked unit read an unlocked one
  }
  return g;
}

::testing::AssertionResult valid(const Genome& g) {
  Status s = validate(g);
  if (s.ok()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << s.error() << "\n" << genome_to_string(g);
}

::testing::AssertionResult kept(const Genome& parent, const Genome& child) {
  Status s = locks_kept(parent, child);
  if (s.ok()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << s.error() << "\nparent:\n"
                                       << genome_to_string(parent) << "\nchild:\n"
                                       << genome_to_string(child);
}

class Locks : public ::testing::TestWithParam<Dialect> {};

// Every operator's child keeps its first parent's locks, and evolution is
// not frozen: most children still differ from their parent.
TEST_P(Locks, NoOperatorChangesALockedGene) {
  const Dialect d = GetParam();
  const OperatorDef def = default_operators(d);
  Rng rng = rng_for(d, 1);
  int locked = 0, mutated = 0, crossed = 0, grafted = 0, can_cross = 0;
  const int n = 300;
  for (int i = 0; i < n; ++i) {
    Genome a = with_random_locks(random_genome(d, def, rng), rng);
    Genome b = with_random_locks(random_genome(d, def, rng), rng);
    ASSERT_TRUE(valid(a));
    locked += has_locks(a);
    Genome m = a;
    mutate(m, def, 0.2, rng);
    ASSERT_TRUE(valid(m));
    ASSERT_TRUE(kept(a, m));
    mutated += !(m == a);
    Genome c = crossover(a, b, def, rng);
    ASSERT_TRUE(valid(c));
    ASSERT_TRUE(kept(a, c));
    // a's kept nodes come whole: b gives something where both go on past them
    if (last_kept_node(a) + 1 < static_cast<int>(std::min(a.nodes.size(), b.nodes.size()))) {
      ++can_cross;
      crossed += !(c == a);
    }
    Genome t = graft(a, b, def, rng);
    ASSERT_TRUE(valid(t));
    ASSERT_TRUE(kept(a, t));
    grafted += !(t == a);
  }
  EXPECT_GT(locked, n / 2);
  EXPECT_GT(mutated, n * 8 / 10);
  EXPECT_GT(can_cross, n / 4);
  // (some fall back to a copy of a: a locked edge went to a node b replaced)
  EXPECT_GT(crossed, can_cross * 6 / 10);
  EXPECT_GT(grafted, n / 2);
}

// A genome whose nodes and global neurons are all locked keeps its nodes
// through every operator (mutation may still add a global neuron).
TEST_P(Locks, AFullyLockedGenomeNeverChanges) {
  const Dialect d = GetParam();
  const OperatorDef def = default_operators(d);
  Rng rng = rng_for(d, 2);
  for (int i = 0; i < 100; ++i) {
    Genome a = random_genome(d, def, rng);
    for (NodeGene& node : a.nodes) node.lock = kLockAll;
    for (NeuronGene& nr : a.global_neurons) nr.locked = true;
    ASSERT_TRUE(valid(a));
    Genome m = a;
    mutate(m, def, 0.5, rng);
    EXPECT_EQ(m.nodes, a.nodes);
    EXPECT_TRUE(kept(a, m));
    EXPECT_EQ(crossover(a, random_genome(d, def, rng), def, rng), a);
    EXPECT_EQ(graft(a, random_genome(d, def, rng), def, rng), a);
  }
}

INSTANTIATE_TEST_SUITE_P(GraphDialects, Locks, ::testing::Values(Dialect::Sims1994, Dialect::Chaumont2007, Dialect::Lessin2015),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// a two-node chaumont2007 genome: root box with a neuron, one limb on a hinge
Genome two_nodes() {
  const OperatorDef def = default_operators(Dialect::Chaumont2007);
  Rng rng(stream_seed({42}));
  for (;;) {
    Genome g = random_genome(Dialect::Chaumont2007, def, rng);
    if (g.nodes.size() >= 2 && !g.nodes[0].edges.empty() && !g.nodes[1].sensors.empty() &&
        !g.nodes[1].effectors.empty())
      return g;
  }
}

TEST(LocksKept, SeesEveryKindOfChange) {
  Genome p = two_nodes();
  const int c = p.nodes[0].edges[0].to;
  p.nodes[c].lock = kLockBody | kLockJoint | kLockInEdges | kLockOutEdges;
  p.nodes[c].sensors[0].locked = true;
  ASSERT_TRUE(valid(p));
  ASSERT_TRUE(locks_kept(p, p).ok());
  auto expect_broken = [&](const Genome& child, const std::string& what) {
    Status s = locks_kept(p, child);
    ASSERT_FALSE(s.ok()) << what;
    EXPECT_NE(s.error().find(what), std::string::npos) << s.error();
  };
  Genome g = p;
  g.nodes[c].size.x *= 1.5;
  expect_broken(g, "its body");
  g = p;
  g.nodes[c].joint.limits.at(0).hi *= 0.5;
  expect_broken(g, "its joint");
  g = p;
  g.nodes[0].edges[0].u = -g.nodes[0].edges[0].u + 0.1;
  expect_broken(g, "the edges into it");
  g = p;
  g.nodes[0].edges.push_back(p.nodes[0].edges[0]);
  expect_broken(g, "the edges into it");
  g = p;
  g.nodes[c].sensors[0].face = g.nodes[c].sensors[0].face == Face::PosX ? Face::NegX : Face::PosX;
  g.nodes[c].sensors[0].type = SensorType::Contact;
  expect_broken(g, "a locked sensor");
  g = p;
  g.nodes[c].lock &= ~static_cast<unsigned>(kLockBody);
  expect_broken(g, "its lock");
  g = p;
  g.nodes[c].lock = 0;
  g.nodes[c].sensors[0].locked = false;
  expect_broken(g, "kept nodes");
  // what is not locked may change
  g = p;
  if (!g.nodes[c].effectors.empty()) g.nodes[c].effectors[0].bias += 0.1;
  g.nodes[0].size.y *= 1.1;
  EXPECT_TRUE(locks_kept(p, g).ok());
}

TEST(LockProblem, NamesTheRuleBroken) {
  Genome g = two_nodes();
  const int c = g.nodes[0].edges[0].to;
  // a locked effector reading an unlocked source
  g.nodes[c].effectors[0].locked = true;
  g.nodes[c].effectors[0].inputs = {InputGene{SourcePlace::Self, SourceKind::Sensor, 0, 0, 1.0}};
  Status s = validate(g);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("effectors[0].inputs[0]: a locked unit reads only locked units"), std::string::npos)
      << s.error();
  g.nodes[c].sensors[0].locked = true;
  EXPECT_TRUE(valid(g));
  // locked units first
  if (g.nodes[c].sensors.size() < 2) g.nodes[c].sensors.push_back(g.nodes[c].sensors[0]);
  g.nodes[c].sensors[0].locked = false;
  g.nodes[c].sensors[1].locked = true;
  s = validate(g);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("sensors[1].locked: locked units come before unlocked ones"), std::string::npos)
      << s.error();
}

TEST(LockProblem, Miconi2006GenomesHaveNoLocks) {
  const OperatorDef def = default_operators(Dialect::Miconi2006);
  Rng rng(stream_seed({3}));
  Genome g = random_genome(Dialect::Miconi2006, def, rng);
  g.nodes[0].lock = kLockBody;
  Status s = validate(g);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("limb-tree"), std::string::npos) << s.error();
}

TEST(LocksJson, RoundTripAndBadNames) {
  Genome g = two_nodes();
  const int c = g.nodes[0].edges[0].to;
  g.nodes[c].lock = kLockJoint | kLockOutEdges;
  g.nodes[c].sensors[0].locked = true;
  ASSERT_TRUE(valid(g));
  nlohmann::json j = genome_to_json(g);
  EXPECT_EQ(j["nodes"][c]["lock"], nlohmann::json::parse(R"(["joint", "out_edges"])"));
  EXPECT_EQ(j["nodes"][c]["sensors"][0]["locked"], true);
  EXPECT_FALSE(j["nodes"][0].contains("lock"));  // written only when set
  auto back = genome_from_json(j, "g.json");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back.value(), g);

  j["nodes"][c]["lock"] = nlohmann::json::parse(R"(["joint", "bones"])");
  auto bad = genome_from_json(j, "g.json");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("nodes[" + std::to_string(c) + "].lock[1]"), std::string::npos) << bad.error();
  EXPECT_NE(bad.error().find("bones"), std::string::npos) << bad.error();
  j["nodes"][c]["lock"] = nlohmann::json::parse(R"(["joint", "joint"])");
  bad = genome_from_json(j, "g.json");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("repeated lock"), std::string::npos) << bad.error();
}

}  // namespace
}  // namespace bx
