// Catapults (chaumont2007 section 4): the "catapult" field of the file form,
// every rule validate() adds for it, random catapults, and mutation,
// crossover and grafting keeping one arm and one projectile through the
// mechanism's locks (genome/locks.h), with the first parent's projectile and
// mechanism and release inputs that stay valid.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "genome/dialect.h"
#include "genome/genome_edit.h"
#include "genome/genome_json.h"
#include "genome/locks.h"
#include "genome/operators.h"

namespace bx {
namespace {

// A small valid catapult: the arm (node 0) holds a body part through edge 0
// and the projectile (node 2) through edge 1. The release reads the arm's
// neuron 1, the body part's neuron 0 and a global neuron.
constexpr const char* kCatapult = R"({
  "format": "bestiary-genome", "version": 1, "dialect": "chaumont2007",
  "nodes": [
    {"size": [0.8, 0.1, 0.05],
     "neurons": [{"fn": "cst", "params": {"V": 1}},
                 {"fn": "mem", "params": {"n": 3}, "inputs": [{"from": "self", "neuron": 0}]}],
     "sensors": [{"type": "contact", "face": "-z"}],
     "edges": [{"to": 1, "face": "-x"}, {"to": 2, "face": "+z", "at": [0.8, 0]}]},
    {"size": [0.8, 0.6, 0.12],
     "joint": {"type": "hinge", "axis1": [0, 1, 0], "limits": [[-2.5, 2.5]]},
     "neurons": [{"fn": "wav", "inputs": [{"from": "parent", "neuron": 0}]}],
     "effectors": [{"dof": 0, "inputs": [{"from": "self", "neuron": 0, "weight": -1}]}]},
    {"size": [0.15, 0.15, 0.15], "joint": {"type": "fixed"}}
  ],
  "global_neurons": [{"fn": "cst", "params": {"V": 0.5}}],
  "catapult": {"projectile": 2, "release": {"delay_steps": 30, "inputs": [
    {"from": "self", "neuron": 1, "weight": 0.5},
    {"from": "child", "edge": 0, "neuron": 0},
    {"from": "global", "neuron": 0, "weight": -0.25}]}}
})";

// The same creature with the projectile as node 1 on the arm's edge 0 (as
// random catapults have it, but on the arm's first edge).
constexpr const char* kProjectileFirst = R"({
  "format": "bestiary-genome", "version": 1, "dialect": "chaumont2007",
  "nodes": [
    {"size": [0.8, 0.1, 0.05],
     "neurons": [{"fn": "cst", "params": {"V": 1}},
                 {"fn": "mem", "params": {"n": 3}, "inputs": [{"from": "self", "neuron": 0}]}],
     "edges": [{"to": 1, "face": "+z", "at": [0.8, 0]}, {"to": 2, "face": "-x"}]},
    {"size": [0.15, 0.15, 0.15], "joint": {"type": "fixed"}},
    {"size": [0.8, 0.6, 0.12],
     "joint": {"type": "hinge", "axis1": [0, 1, 0], "limits": [[-2.5, 2.5]]},
     "neurons": [{"fn": "wav", "inputs": [{"from": "parent", "neuron": 0}]}],
     "effectors": [{"dof": 0, "inputs": [{"from": "self", "neuron": 0, "weight": -1}]}]}
  ],
  "catapult": {"projectile": 1, "release": {"delay_steps": 30, "inputs": [
    {"from": "child", "edge": 1, "neuron": 0, "weight": 0.75}]}}
})";

Genome parse(const std::string& text) {
  auto g = genome_from_string(text, "t.json");
  EXPECT_TRUE(g.ok()) << (g.ok() ? "" : g.error());
  return g.ok() ? *g : Genome{};
}

std::string parse_error(const std::string& text) {
  auto g = genome_from_string(text, "t.json");
  EXPECT_FALSE(g.ok());
  return g.ok() ? "" : g.error();
}

std::string error_of(const Genome& g) {
  Status s = validate(g);
  EXPECT_FALSE(s.ok());
  return s.ok() ? "" : s.error();
}

// text with its only occurrence of `from` replaced by `to`
std::string edit(std::string text, const std::string& from, const std::string& to) {
  auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// kCatapult with its "catapult" field replaced by `field` (JSON text)
std::string with_catapult(const std::string& field) {
  std::string text = kCatapult;
  return text.substr(0, text.find(R"("catapult": )")) + R"("catapult": )" + field + "\n}";
}

// A valid catapult with one arm and one projectile: validate() passes, and
// exactly one node is held by a fixed joint, carries nothing, and is the
// projectile.
::testing::AssertionResult one_arm_one_projectile(const Genome& g) {
  auto fail = [&g](const std::string& why) {
    return ::testing::AssertionFailure() << why << "\n" << genome_to_string(g);
  };
  if (Status s = validate(g); !s.ok()) return fail(s.error());
  if (!is_catapult(g)) return fail("not a catapult");
  int fixed = 0, at = -1;
  for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i) {
    const NodeGene& n = g.nodes[i];
    if (n.joint.type != JointType::Fixed) continue;
    ++fixed;
    at = i;
    if (!n.neurons.empty() || !n.sensors.empty() || !n.effectors.empty() || !n.edges.empty())
      return fail("a fixed node carries something");
  }
  if (fixed != 1 || at != g.catapult->projectile) return fail("not exactly one projectile");
  int holders = 0;
  for (const NodeGene& n : g.nodes)
    for (const EdgeGene& e : n.edges) {
      if (e.to == 0) return fail("an edge leads to the arm");
      holders += e.to == at;
    }
  if (holders != 1) return fail("the projectile is held by " + std::to_string(holders) + " edges");
  return ::testing::AssertionSuccess();
}

// a random catapult's form: the projectile is node 1, on the arm's last edge
bool canonical(const Genome& g) {
  return g.catapult->projectile == 1 && g.nodes[0].edges.back().to == 1;
}

// the arm's edge that holds the projectile
const EdgeGene& projectile_edge(const Genome& g) {
  for (const EdgeGene& e : g.nodes[0].edges)
    if (e.to == g.catapult->projectile) return e;
  static const EdgeGene none{};
  ADD_FAILURE() << "no projectile edge";
  return none;
}

const NodeGene& projectile_of(const Genome& g) { return g.nodes[g.catapult->projectile]; }

OperatorDef catapult_def() {
  OperatorDef def = default_operators(Dialect::Chaumont2007);
  def.catapult.enabled = true;
  return def;
}

Rng rng_for(std::uint64_t tag) { return Rng(stream_seed({0xca7a, tag})); }

std::vector<Genome> pool(int n, std::uint64_t tag, const OperatorDef& def = catapult_def()) {
  Rng rng = rng_for(tag);
  std::vector<Genome> out;
  for (int i = 0; i < n; ++i) out.push_back(random_genome(Dialect::Chaumont2007, def, rng));
  return out;
}

constexpr int kMany = 1000;

// ---------------------------------------------------------------- file form

TEST(CatapultJson, ReadsTheField) {
  Genome g = parse(kCatapult);
  ASSERT_TRUE(g.catapult.has_value());
  EXPECT_EQ(g.catapult->projectile, 2);
  EXPECT_EQ(g.catapult->release.delay_steps, 30);
  ASSERT_EQ(g.catapult->release.inputs.size(), 3u);
  EXPECT_EQ(g.catapult->release.inputs[0],
            (InputGene{SourcePlace::Self, SourceKind::Neuron, 1, 0, 0.5}));
  EXPECT_EQ(g.catapult->release.inputs[1],
            (InputGene{SourcePlace::Child, SourceKind::Neuron, 0, 0, 1.0}));
  EXPECT_EQ(g.catapult->release.inputs[2],
            (InputGene{SourcePlace::Global, SourceKind::Neuron, 0, 0, -0.25}));
  EXPECT_TRUE(one_arm_one_projectile(g));
}

TEST(CatapultJson, RoundTripsExactly) {
  for (const char* text : {kCatapult, kProjectileFirst}) {
    Genome g = parse(text);
    std::string out = genome_to_string(g);
    EXPECT_NE(out.find(R"("catapult": {)"), std::string::npos) << out;
    EXPECT_NE(out.find(R"("release": {)"), std::string::npos) << out;
    EXPECT_NE(out.find(R"("delay_steps": 30)"), std::string::npos) << out;
    Genome back = parse(out);
    EXPECT_EQ(back, g);
    EXPECT_EQ(genome_to_string(back), out);
    EXPECT_EQ(genome_from_json(genome_to_json(g), "").value(), g);
  }
}

TEST(CatapultJson, WrittenOnlyWhenPresent) {
  Genome g = parse(kCatapult);
  g.catapult.reset();
  g.nodes.pop_back();
  g.nodes[0].edges.pop_back();
  ASSERT_TRUE(validate(g).ok());
  EXPECT_EQ(genome_to_string(g).find("catapult"), std::string::npos);
  EXPECT_FALSE(parse(genome_to_string(g)).catapult.has_value());
}

TEST(CatapultJson, ReleaseDefaults) {
  Genome g = parse(with_catapult(R"({"projectile": 2})"));
  ASSERT_TRUE(g.catapult.has_value());
  EXPECT_EQ(g.catapult->release, ReleaseGene{});
  EXPECT_EQ(g.catapult->release.delay_steps, 30);
  EXPECT_TRUE(g.catapult->release.inputs.empty());
  EXPECT_EQ(parse(with_catapult(R"({"projectile": 2, "release": {}})")), g);
  Genome h = parse(with_catapult(R"({"projectile": 2, "release": {"delay_steps": 7}})"));
  EXPECT_EQ(h.catapult->release.delay_steps, 7);
  EXPECT_TRUE(h.catapult->release.inputs.empty());
}

TEST(CatapultJson, FormErrorsNameTheField) {
  EXPECT_EQ(parse_error(with_catapult(R"({"projectile": 2, "arm": 0})")),
            "t.json: catapult.arm: unknown field (expected one of projectile, release), got 0");
  EXPECT_EQ(parse_error(with_catapult(R"({"projectile": 2, "release": {"delay": 30}})")),
            "t.json: catapult.release.delay: unknown field (expected one of delay_steps, inputs), "
            "got 30");
  EXPECT_EQ(parse_error(with_catapult(R"({"release": {}})")),
            "t.json: catapult: missing required field \"projectile\", got {\"release\": {}}");
  EXPECT_EQ(parse_error(with_catapult(R"({"projectile": 2.0})")),
            "t.json: catapult.projectile: expected an integer, got 2.0");
  EXPECT_EQ(parse_error(with_catapult(R"({"projectile": 2, "release": {"delay_steps": "30"}})")),
            "t.json: catapult.release.delay_steps: expected an integer, got \"30\"");
  EXPECT_EQ(parse_error(with_catapult(R"({"projectile": 2, "release": [30]})")),
            "t.json: catapult.release: expected an object, got [30]");
  EXPECT_EQ(parse_error(with_catapult(R"({"projectile": 2, "release": {"inputs": {}}})")),
            "t.json: catapult.release.inputs: expected an array, got {}");
  EXPECT_EQ(parse_error(with_catapult(
                R"({"projectile": 2, "release": {"inputs": [{"from": "self", "edge": 0, "neuron": 1}]}})")),
            "t.json: catapult.release.inputs[0].edge: only \"child\" sources take an edge, got 0");
  EXPECT_EQ(parse_error(with_catapult(
                R"({"projectile": 2, "release": {"inputs": [{"from": "arm", "neuron": 1}]}})")),
            "t.json: catapult.release.inputs[0].from: unknown source place (expected one of self, "
            "parent, child, root, global), got \"arm\"");
  EXPECT_EQ(parse_error(with_catapult(
                R"({"projectile": 2, "release": {"inputs": [{"from": "root", "neuron": 0, "weigth": 1}]}})")),
            "t.json: catapult.release.inputs[0].weigth: unknown field (expected one of from, "
            "neuron, sensor, muscle, edge, weight, gate), got 1");
  EXPECT_EQ(parse_error(with_catapult(R"(2)")), "t.json: catapult: expected an object, got 2");
  EXPECT_EQ(parse_error(with_catapult(R"({"projectile": 2, "projectile": 1})")),
            "t.json: catapult.projectile: field given twice");
}

TEST(CatapultJson, FileErrorsCarryTheValidationMessage) {
  EXPECT_EQ(parse_error(edit(kCatapult, R"("delay_steps": 30)", R"("delay_steps": 0)")),
            "t.json: catapult.release.delay_steps: must be in [2, 1001], got 0");
}

// ---------------------------------------------------------------- validation, one rule each

class CatapultRules : public ::testing::Test {
 protected:
  Genome g = parse(kCatapult);
};

TEST_F(CatapultRules, TheExamplesAreValid) {
  EXPECT_TRUE(validate(g).ok());
  EXPECT_TRUE(validate(parse(kProjectileFirst)).ok());
}

// A file without locks on its mechanism (written before locks existed) is
// read with the locks random catapults get; one that gives locks keeps them.
TEST_F(CatapultRules, AFileWithoutLocksGetsTheMechanismsLocks) {
  EXPECT_EQ(g.nodes[0].lock, kLockInEdges);
  EXPECT_EQ(g.nodes[2].lock, catapult_projectile_lock(false));
  EXPECT_EQ(g.nodes[1].lock, 0u);
  std::string text = edit(kCatapult, R"({"size": [0.15, 0.15, 0.15], "joint": {"type": "fixed"}})",
                          R"({"size": [0.15, 0.15, 0.15], "joint": {"type": "fixed"},
                              "lock": ["joint", "in_edges", "out_edges", "units"]})");
  // a file that gives some locks gives them all
  EXPECT_EQ(parse_error(text), "t.json: nodes[0].lock: a catapult's arm has its in_edges locked (one arm), got []");
  Genome h = parse(edit(text, R"("size": [0.8, 0.1, 0.05],)", R"("size": [0.8, 0.1, 0.05], "lock": ["in_edges"],)"));
  EXPECT_EQ(h.nodes[2].lock, catapult_projectile_lock(true));
  EXPECT_EQ(h.nodes[0].lock, 0u + kLockInEdges);
}

TEST_F(CatapultRules, TheMechanismIsLocked) {
  g.nodes[0].lock = 0;
  EXPECT_EQ(error_of(g), "nodes[0].lock: a catapult's arm has its in_edges locked (one arm), got []");
  g.nodes[0].lock = kLockInEdges;
  g.nodes[2].lock = kLockJoint | kLockUnits | kLockInEdges;
  EXPECT_EQ(error_of(g),
            "nodes[2].lock: a catapult's projectile has its joint, in_edges, out_edges and units locked "
            "(and its body, unless its size may mutate), got [\"joint\", \"in_edges\", \"units\"]");
}

TEST_F(CatapultRules, OnlyChaumont2007) {
  g.dialect = Dialect::Sims1994;
  EXPECT_EQ(error_of(g),
            "catapult: catapults belong to dialect chaumont2007 (section 4), got \"sims1994\"");
  // (miconi2006 has no global neurons: leave them out to reach the rule)
  g.dialect = Dialect::Miconi2006;
  g.global_neurons.clear();
  g.catapult->release.inputs.pop_back();
  EXPECT_EQ(error_of(g),
            "catapult: catapults belong to dialect chaumont2007 (section 4), got \"miconi2006\"");
}

TEST_F(CatapultRules, ProjectileIsANodeOtherThanTheRoot) {
  g.catapult->projectile = 0;
  EXPECT_EQ(error_of(g),
            "catapult.projectile: must name a node other than the root (the arm), in [1, 3), got 0");
  g.catapult->projectile = 3;
  EXPECT_EQ(error_of(g),
            "catapult.projectile: must name a node other than the root (the arm), in [1, 3), got 3");
  g.catapult->projectile = -1;
  EXPECT_EQ(error_of(g),
            "catapult.projectile: must name a node other than the root (the arm), in [1, 3), got "
            "-1");
}

TEST_F(CatapultRules, ProjectileIsABox) {
  g.nodes[2].shape = Shape::Sphere;
  EXPECT_EQ(error_of(g), "nodes[2].shape: a catapult's projectile must be a box, got \"sphere\"");
}

TEST_F(CatapultRules, ProjectileHangsByAFixedJoint) {
  g.nodes[2].joint.type = JointType::Hinge;
  EXPECT_EQ(error_of(g),
            "nodes[2].joint.type: a catapult's projectile is held by a fixed joint, got \"hinge\"");
}

TEST_F(CatapultRules, FixedJointsElsewhereStayForbidden) {
  g.nodes[1].joint = JointGene{JointType::Fixed, {0, 0, 1}, {0, 1, 0}, {}};
  g.nodes[1].effectors.clear();
  EXPECT_EQ(error_of(g),
            "nodes[1].joint.type: joint type not allowed in dialect chaumont2007 (expected hinge), "
            "got \"fixed\"");
}

TEST_F(CatapultRules, ProjectileHasNoNeurons) {
  g.nodes[2].neurons.push_back({"cst", {0.5}, 0, {}});
  EXPECT_EQ(error_of(g), "nodes[2].neurons: a catapult's projectile has no neurons, got 1");
}

TEST_F(CatapultRules, ProjectileHasNoSensors) {
  g.nodes[2].sensors.push_back({SensorType::Contact, 0, Face::NegZ});
  g.nodes[2].sensors.push_back({SensorType::Contact, 0, Face::PosZ});
  EXPECT_EQ(error_of(g), "nodes[2].sensors: a catapult's projectile has no sensors, got 2");
}

TEST_F(CatapultRules, ProjectileHasNoEffectors) {
  g.nodes[2].effectors.push_back({0, 0, {}});
  EXPECT_EQ(error_of(g), "nodes[2].effectors: a catapult's projectile has no effectors, got 1");
}

TEST_F(CatapultRules, ProjectileHasNoEdges) {
  g.nodes[2].edges.push_back({1, Face::PosX, 0, 0, {0, 0, 0}, 1.0, {}, false});
  EXPECT_EQ(error_of(g), "nodes[2].edges: a catapult's projectile has no edges, got 1");
}

TEST_F(CatapultRules, ProjectileGrowsOnce) {
  g.nodes[2].recursive_limit = 2;
  EXPECT_EQ(error_of(g),
            "nodes[2].recursive_limit: a catapult's projectile grows once (it must be 1), got 2");
}

TEST_F(CatapultRules, SomeEdgeOfTheArmHoldsTheProjectile) {
  g.nodes[0].edges.pop_back();
  EXPECT_EQ(error_of(g),
            "catapult.projectile: no edge of the arm (node 0) holds the projectile node, got 2");
}

TEST_F(CatapultRules, OneEdgeHoldsTheProjectile) {
  g.nodes[0].edges.push_back(g.nodes[0].edges[1]);
  EXPECT_EQ(error_of(g),
            "nodes[0].edges[2].to: a catapult's projectile is held by one edge only (already "
            "nodes[0].edges[1]), got 2");
}

TEST_F(CatapultRules, OnlyTheArmHoldsTheProjectile) {
  g.nodes[1].edges.push_back({2, Face::PosX, 0, 0, {0, 0, 0}, 1.0, {}, false});
  EXPECT_EQ(error_of(g),
            "nodes[1].edges[0].to: only the arm (node 0) may hold a catapult's projectile, got 2");
  // held by the body only
  g.nodes[0].edges.pop_back();
  EXPECT_EQ(error_of(g),
            "nodes[1].edges[0].to: only the arm (node 0) may hold a catapult's projectile, got 2");
}

TEST_F(CatapultRules, ProjectileEdgeDoesNotReflect) {
  g.nodes[0].edges[1].reflect = {1};
  EXPECT_EQ(error_of(g),
            "nodes[0].edges[1].reflect: the projectile's edge must not reflect (one projectile), "
            "got [\"y\"]");
}

TEST_F(CatapultRules, ProjectileEdgeIsNotTerminalOnly) {
  g.nodes[0].edges[1].terminal_only = true;
  EXPECT_EQ(error_of(g),
            "nodes[0].edges[1].terminal_only: must be false on the projectile's edge, got true");
}

TEST_F(CatapultRules, ProjectileEdgeHasScaleOne) {
  g.nodes[0].edges[1].scale = 0.5;
  EXPECT_EQ(error_of(g),
            "nodes[0].edges[1].scale: must be 1 on the projectile's edge (its node gives the "
            "projectile's size), got 0.5");
}

TEST_F(CatapultRules, NoEdgeLeadsToTheArm) {
  Genome h = g;
  h.nodes[1].edges.push_back({0, Face::PosX, 0, 0, {0, 0, 0}, 1.0, {}, false});
  EXPECT_EQ(error_of(h),
            "nodes[1].edges[0].to: no edge may lead to a catapult's arm (node 0): the arm exists "
            "once, got 0");
  // recursion of the arm: a reflexive edge
  g.nodes[0].edges.push_back({0, Face::PosX, 0, 0, {0, 0, 0}, 1.0, {}, false});
  g.nodes[0].recursive_limit = 2;
  EXPECT_EQ(error_of(g),
            "nodes[0].edges[2].to: no edge may lead to a catapult's arm (node 0): the arm exists "
            "once, got 0");
}

TEST_F(CatapultRules, DelayWithinRange) {
  for (int ok : {2, 30, 1001}) {
    g.catapult->release.delay_steps = ok;
    EXPECT_TRUE(validate(g).ok()) << ok;
  }
  g.catapult->release.delay_steps = 1;
  EXPECT_EQ(error_of(g), "catapult.release.delay_steps: must be in [2, 1001], got 1");
  g.catapult->release.delay_steps = 1002;
  EXPECT_EQ(error_of(g), "catapult.release.delay_steps: must be in [2, 1001], got 1002");
}

TEST_F(CatapultRules, ReleaseReadsNoParent) {
  g.catapult->release.inputs[0].place = SourcePlace::Parent;
  g.catapult->release.inputs[0].index = 0;
  EXPECT_EQ(error_of(g),
            "catapult.release.inputs[0].from: the release reads as from the arm, the root: it has "
            "no parent, got \"parent\"");
}

TEST_F(CatapultRules, ReleaseIndicesExist) {
  g.catapult->release.inputs[0].index = 7;
  EXPECT_EQ(error_of(g),
            "catapult.release.inputs[0].neuron: no such neuron in this node (it has 2), got 7");
  g.catapult->release.inputs[0] = {SourcePlace::Root, SourceKind::Sensor, 1, 0, 1.0};
  EXPECT_EQ(error_of(g),
            "catapult.release.inputs[0].sensor: no such sensor in the root node (it has 1), got 1");
  g.catapult->release.inputs[0].index = 0;
  g.catapult->release.inputs[2].index = 3;
  EXPECT_EQ(error_of(g),
            "catapult.release.inputs[2].neuron: no such global neuron (there are 1), got 3");
}

TEST_F(CatapultRules, ReleaseChildEdgesExist) {
  g.catapult->release.inputs[1].edge = 5;
  EXPECT_EQ(error_of(g),
            "catapult.release.inputs[1].edge: no such edge in this node (it has 2), got 5");
  g.catapult->release.inputs[1].edge = 0;
  g.catapult->release.inputs[1].index = 1;
  EXPECT_EQ(error_of(g),
            "catapult.release.inputs[1].neuron: no such neuron in the child node 1 (it has 1), got "
            "1");
}

TEST_F(CatapultRules, ReleaseDoesNotReadThroughTheProjectilesEdge) {
  g.catapult->release.inputs[1].edge = 1;
  EXPECT_EQ(error_of(g),
            "catapult.release.inputs[1].edge: reads through the projectile's edge (the projectile "
            "has no neurons or sensors), got 1");
}

TEST_F(CatapultRules, ReleaseWeightsFinite) {
  g.catapult->release.inputs[2].weight = std::nan("");
  EXPECT_EQ(error_of(g), "catapult.release.inputs[2].weight: must be finite, got nan");
}

TEST_F(CatapultRules, ProjectileCountsTowardsMaxGenes) {
  // a chain of 19 body parts after the arm: 20 genes with the projectile...
  Genome h = g;
  h.nodes.resize(2);
  h.nodes[0].edges.resize(1);
  h.nodes[1].effectors[0].inputs.clear();
  h.catapult->release.inputs.clear();
  while (h.nodes.size() < 19) {
    int last = static_cast<int>(h.nodes.size()) - 1;
    h.nodes[last].edges.push_back({last + 1, Face::PosX, 0, 0, {0, 0, 0}, 1.0, {}, false});
    h.nodes.push_back(h.nodes[1]);
    h.nodes.back().edges.clear();
  }
  Genome p = g;
  h.nodes.push_back(p.nodes[2]);
  h.nodes[0].edges.push_back(p.nodes[0].edges[1]);
  h.nodes[0].edges.back().to = 19;
  h.catapult->projectile = 19;
  ASSERT_EQ(h.nodes.size(), 20u);
  EXPECT_TRUE(validate(h).ok()) << validate(h).error();
  // ... and one more is too many
  NodeGene extra = h.nodes[1];
  h.nodes.insert(h.nodes.end() - 1, extra);
  h.nodes[18].edges.push_back({19, Face::PosX, 0, 0, {0, 0, 0}, 1.0, {}, false});
  h.nodes[0].edges.back().to = 20;
  h.catapult->projectile = 20;
  EXPECT_EQ(error_of(h), "nodes: at most 20 genes in dialect chaumont2007, got 21");
}

// ---------------------------------------------------------------- genome edits

TEST(CatapultEdits, ReleaseInputsAreTheArmsInputs) {
  Genome g = parse(kCatapult);
  // removing the arm's neuron 0: the release's read of neuron 1 follows it
  remove_neuron(g, 0, 0, SourceFix::Remove);
  EXPECT_EQ(g.catapult->release.inputs[0].index, 0);
  EXPECT_EQ(g.catapult->release.inputs[0].place, SourcePlace::Self);
  // and the neuron it read is gone: the input is removed
  remove_neuron(g, 0, 0, SourceFix::Remove);
  ASSERT_EQ(g.catapult->release.inputs.size(), 2u);
  EXPECT_EQ(g.catapult->release.inputs[0].place, SourcePlace::Child);
  // a global neuron removed: its readers go too
  remove_global_neuron(g, 0, SourceFix::Remove);
  EXPECT_EQ(g.catapult->release.inputs.size(), 1u);
}

TEST(CatapultEdits, ReleaseChildSourcesFollowTheArmsEdges) {
  Genome g = parse(kProjectileFirst);
  ASSERT_EQ(g.catapult->release.inputs[0].edge, 1);
  // the projectile's edge (edge 0) goes: the release's child source moves to edge 0
  remove_edge(g, 0, 0, SourceFix::Remove);
  ASSERT_EQ(g.catapult->release.inputs.size(), 1u);
  EXPECT_EQ(g.catapult->release.inputs[0].edge, 0);
  EXPECT_EQ(g.nodes[0].edges[0].to, 2);
  // the body part goes: nothing is left to read
  remove_node(g, 2, SourceFix::Remove);
  EXPECT_TRUE(g.catapult->release.inputs.empty());
}

TEST(CatapultEdits, RepairReassignsReleaseInputs) {
  Genome g = parse(kCatapult);
  g.catapult->release.inputs[1].index = 9;
  Rng rng = rng_for(1);
  EXPECT_EQ(repair_sources(g, SourceFix::Reassign, &rng), 1);
  EXPECT_TRUE(validate(g).ok()) << validate(g).error();
  EXPECT_EQ(g.catapult->release.inputs.size(), 3u);
  EXPECT_EQ(g.catapult->release.inputs[1].weight, 1.0);  // kept
}

// ---------------------------------------------------------------- random creation

TEST(CatapultRandom, ThousandAreValidCatapults) {
  OperatorDef def = catapult_def();
  Rng rng = rng_for(2);
  int inputs_seen[3] = {0, 0, 0};
  int largest = 0;
  for (int i = 0; i < kMany; ++i) {
    Genome g = random_genome(Dialect::Chaumont2007, def, rng);
    ASSERT_TRUE(one_arm_one_projectile(g)) << "catapult " << i;
    EXPECT_TRUE(canonical(g));
    EXPECT_EQ(g.nodes[0].lock, kLockInEdges);
    EXPECT_EQ(projectile_of(g).lock, kLockBody | kLockJoint | kLockInEdges | kLockOutEdges | kLockUnits);
    const NodeGene& p = projectile_of(g);
    EXPECT_EQ(p.size, def.catapult.projectile_size);
    EXPECT_EQ(p.density, def.catapult.projectile_density);
    EXPECT_TRUE(p.joint.limits.empty());
    const EdgeGene& e = g.nodes[0].edges.back();
    EXPECT_EQ(e.scale, 1.0);
    EXPECT_TRUE(e.reflect.empty());
    EXPECT_FALSE(e.terminal_only);
    EXPECT_EQ(g.catapult->release.delay_steps, 30);
    int k = static_cast<int>(g.catapult->release.inputs.size());
    ASSERT_LE(k, 2);
    ++inputs_seen[k];
    // the body: genes_at_creation for the arm and body, one gene more in all
    int n = static_cast<int>(g.nodes.size());
    EXPECT_GE(n - 1, def.genes_at_creation.lo);
    EXPECT_LE(n - 1, def.genes_at_creation.hi);
    largest = std::max(largest, n);
    EXPECT_LE(count_parts(g, 100), 100);
    EXPECT_EQ(parse(genome_to_string(g)), g);
  }
  for (int k = 0; k <= 2; ++k) EXPECT_GT(inputs_seen[k], 50) << k << " release inputs";
  EXPECT_EQ(largest, def.genes_at_creation.hi + 1);
}

TEST(CatapultRandom, FollowsTheDef) {
  OperatorDef def = catapult_def();
  def.catapult.projectile_size = {0.3, 0.2, 0.1};
  def.catapult.projectile_density = 500;
  def.catapult.release_delay_steps = 45;
  def.catapult.release_inputs_at_creation = {3, 3};
  def.genes_at_creation = {20, 20};  // clamped: 19 for the arm and body
  Rng rng = rng_for(3);
  int full = 0;
  for (int i = 0; i < 200; ++i) {
    Genome g = random_genome(Dialect::Chaumont2007, def, rng);
    ASSERT_TRUE(one_arm_one_projectile(g)) << "catapult " << i;
    EXPECT_EQ(g.nodes.size(), 20u);
    EXPECT_EQ(projectile_of(g).size, (Vec3{0.3, 0.2, 0.1}));
    EXPECT_EQ(projectile_of(g).density, 500);
    EXPECT_EQ(g.catapult->release.delay_steps, 45);
    EXPECT_LE(g.catapult->release.inputs.size(), 3u);
    full += g.catapult->release.inputs.size() == 3u;
  }
  EXPECT_GT(full, 180);  // fewer only when the arm has nothing to read
}

TEST(CatapultRandom, OnlyWhenEnabledAndChaumont) {
  Rng rng = rng_for(4);
  OperatorDef plain = default_operators(Dialect::Chaumont2007);
  for (int i = 0; i < 50; ++i)
    EXPECT_FALSE(random_genome(Dialect::Chaumont2007, plain, rng).catapult.has_value());
  for (Dialect d : {Dialect::Sims1994, Dialect::Miconi2006}) {
    OperatorDef def = default_operators(d);
    def.catapult.enabled = true;
    for (int i = 0; i < 50; ++i) {
      Genome g = random_genome(d, def, rng);
      EXPECT_FALSE(g.catapult.has_value());
      EXPECT_TRUE(validate(g).ok());
    }
  }
}

TEST(CatapultRandom, ProjectileClearOfTheArmsOtherChildren) {
  // the projectile's edge is placed as a new limb: mostly away from its siblings
  OperatorDef def = catapult_def();
  std::vector<Genome> gs = pool(300, 5, def);
  int apart = 0;
  for (const Genome& g : gs) {
    Vec3 d = edge_direction(g.nodes[0].edges.back());
    double closest = kPi;
    for (std::size_t k = 0; k + 1 < g.nodes[0].edges.size(); ++k)
      closest = std::min(closest, std::acos(std::clamp(
                                      dot(d, edge_direction(g.nodes[0].edges[k])), -1.0, 1.0)));
    apart += closest >= def.min_sibling_angle - 1e-9;
  }
  EXPECT_GT(apart, 270);
}

// ---------------------------------------------------------------- mutation

// The evolution loop's chaumont2007 rates (5.7): asexual 0.1; and a high one.
class CatapultMutation : public ::testing::TestWithParam<double> {};

INSTANTIATE_TEST_SUITE_P(Rates, CatapultMutation, ::testing::Values(0.1, 0.5),
                         [](const auto& info) { return info.param < 0.2 ? "Rate10" : "Rate50"; });

TEST_P(CatapultMutation, ThousandChildrenKeepArmProjectileAndDelay) {
  double rate = GetParam();
  OperatorDef def = catapult_def();
  std::vector<Genome> parents = pool(100, 6);
  for (Genome& p : parents) p.catapult->release.delay_steps = 17;  // not the def's
  Rng rng = rng_for(7 + static_cast<std::uint64_t>(rate * 100));
  int wiring = 0, attachment = 0, body = 0, count_changed = 0;
  for (int i = 0; i < kMany; ++i) {
    const Genome& parent = parents[i % parents.size()];
    Genome g = parent;
    mutate(g, def, rate, rng);
    ASSERT_TRUE(one_arm_one_projectile(g)) << "rate " << rate << ", child " << i;
    EXPECT_LE(g.nodes.size(), 20u);
    EXPECT_EQ(projectile_of(g), projectile_of(parent));
    EXPECT_EQ(g.catapult->release.delay_steps, 17);
    EXPECT_TRUE(locks_kept(parent, g).ok()) << locks_kept(parent, g).error();
    EdgeGene e = projectile_edge(g), pe = projectile_edge(parent);
    e.to = pe.to;
    attachment += !(e == pe);
    wiring += g.catapult->release.inputs != parent.catapult->release.inputs;
    count_changed += g.catapult->release.inputs.size() != parent.catapult->release.inputs.size();
    body += g.nodes.size() != parent.nodes.size() || !(g.nodes[0].size == parent.nodes[0].size);
  }
  // the mechanism's wiring and the body mutate; the projectile's attachment
  // is the mechanism's (its in-edges locked)
  EXPECT_GT(wiring, 50);
  EXPECT_GT(count_changed, 20);
  EXPECT_EQ(attachment, 0);
  EXPECT_GT(body, 100);
}

TEST_P(CatapultMutation, ProjectileSizeMutatesOnlyWhenAllowed) {
  double rate = GetParam();
  OperatorDef def = catapult_def();
  def.catapult.mutate_projectile = true;  // random catapults' projectiles without a body lock
  std::vector<Genome> parents = pool(100, 8, def);
  Rng rng = rng_for(9 + static_cast<std::uint64_t>(rate * 100));
  int changed = 0;
  for (int i = 0; i < kMany; ++i) {
    const Genome& parent = parents[i % parents.size()];
    Genome g = parent;
    mutate(g, def, rate, rng);
    ASSERT_TRUE(one_arm_one_projectile(g)) << "child " << i;
    const NodeGene& p = projectile_of(g);
    const NodeGene& q = projectile_of(parent);
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(p.size[a], def.size_min[a]);
      EXPECT_LE(p.size[a], def.size_max[a]);
    }
    changed += !(p.size == q.size);
    // only the size
    NodeGene same = p;
    same.size = q.size;
    EXPECT_EQ(same, q);
  }
  EXPECT_GT(changed, rate * kMany);  // 1 - (1 - rate)^3 of them, about
  EXPECT_LT(changed, kMany);
}

TEST(CatapultMutationChains, StayCatapults) {
  OperatorDef def = catapult_def();
  def.catapult.mutate_projectile = true;
  Rng rng = rng_for(10);
  for (int lineage = 0; lineage < 20; ++lineage) {
    Genome g = random_genome(Dialect::Chaumont2007, def, rng);
    for (int step = 0; step < 100; ++step) {
      mutate(g, def, step % 10 == 0 ? 0.5 : 0.1, rng);
      ASSERT_TRUE(one_arm_one_projectile(g)) << "lineage " << lineage << ", step " << step;
      EXPECT_EQ(g.catapult->release.delay_steps, 30);
    }
  }
}

TEST(CatapultMutationChains, NothingToMutateChangesNothing) {
  OperatorDef def = catapult_def();
  def.structure = {};
  def.catapult.mutate_projectile = true;
  Rng rng = rng_for(11);
  // even a catapult not in canonical form is left exactly as it was
  for (const char* text : {kCatapult, kProjectileFirst}) {
    Genome g = parse(text);
    Genome before = g;
    mutate(g, def, 0, rng);
    EXPECT_EQ(g, before);
  }
}

TEST(CatapultMutationChains, ReleaseFollowsTheNeuronItReads) {
  // the arm has neurons cst, cst, wav, cst; the release reads the wav. Only
  // neurons are removed: while the wav lives, the release reads it.
  Genome g0 = parse(kCatapult);
  std::vector<NeuronGene>& ns = g0.nodes[0].neurons;
  ns = {{"cst", {0.1}, 0, {}}, {"cst", {0.2}, 0, {}}, {"wav", {}, 0, {}}, {"cst", {0.3}, 0, {}}};
  g0.catapult->release.inputs = {{SourcePlace::Self, SourceKind::Neuron, 2, 0, 0.5}};
  ASSERT_TRUE(validate(g0).ok()) << validate(g0).error();
  OperatorDef def = catapult_def();
  def.structure = {};
  def.structure.remove_neuron = 1;
  int moved = 0, lost = 0;
  for (std::uint64_t seed = 0; seed < 300; ++seed) {
    Rng rng = rng_for(1000 + seed);
    Genome g = g0;
    for (int k = 0; k < 3; ++k) {
      mutate(g, def, 0, rng);
      ASSERT_TRUE(one_arm_one_projectile(g));
    }
    const auto& arm = g.nodes[0].neurons;
    auto wav = std::find_if(arm.begin(), arm.end(), [](const NeuronGene& n) { return n.fn == "wav"; });
    const auto& ins = g.catapult->release.inputs;
    if (wav == arm.end()) {
      ++lost;
      continue;
    }
    ASSERT_EQ(ins.size(), 1u) << genome_to_string(g);
    EXPECT_EQ(ins[0].place, SourcePlace::Self);
    EXPECT_EQ(ins[0].index, wav - arm.begin()) << "seed " << seed;
    EXPECT_EQ(ins[0].weight, 0.5);
    moved += ins[0].index != 2;
  }
  EXPECT_GT(moved, 50);  // the wav moved down in many lineages...
  EXPECT_GT(lost, 10);   // ... and was removed in some (its reader reassigned: still valid)
}

TEST(CatapultMutationChains, ReleaseFollowsTheChildItReads) {
  // the release reads the body part through the arm's edge 1; new edges of
  // the arm come after it, and the projectile's edge 0 stays
  Genome g0 = parse(kProjectileFirst);
  OperatorDef def = catapult_def();
  def.structure = {};
  def.structure.add_neuron = 1;
  def.structure.add_edge = 1;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    Rng rng = rng_for(2000 + seed);
    Genome g = g0;
    mutate(g, def, 0, rng);
    ASSERT_TRUE(one_arm_one_projectile(g));
    ASSERT_EQ(g.catapult->release.inputs.size(), 1u);
    const InputGene& in = g.catapult->release.inputs[0];
    EXPECT_EQ(in.place, SourcePlace::Child);
    EXPECT_EQ(in.edge, 1);
    EXPECT_EQ(in.weight, 0.75);
    EXPECT_EQ(g.nodes[g.nodes[0].edges[in.edge].to].size, g0.nodes[2].size);
    EXPECT_EQ(projectile_of(g), g0.nodes[1]);
    EXPECT_EQ(g.nodes[0].edges[0], g0.nodes[0].edges[0]);
  }
}

// ---------------------------------------------------------------- crossover and grafting

// Parents whose mechanisms and projectiles tell them apart.
struct Parents {
  std::vector<Genome> first, second;
};
Parents marked_parents(std::uint64_t tag) {
  Parents p{pool(60, tag), pool(60, tag + 1)};
  for (std::size_t i = 0; i < p.first.size(); ++i) {
    Genome& a = p.first[i];
    a.catapult->release.delay_steps = 20 + static_cast<int>(i);
    a.nodes[a.catapult->projectile].size = {0.1 + 0.001 * i, 0.1, 0.2};
  }
  for (Genome& b : p.second) {
    b.catapult->release.delay_steps = 99;
    b.nodes[b.catapult->projectile].size = {0.5, 0.3, 0.3};
    b.nodes[b.catapult->projectile].density = 700;
  }
  return p;
}

TEST(CatapultCrossover, ThousandChildrenTakeTheFirstParentsMechanism) {
  Parents ps = marked_parents(20);
  Rng rng = rng_for(21);
  OperatorDef def = catapult_def();
  int from_b = 0;
  for (int i = 0; i < kMany; ++i) {
    const Genome& a = ps.first[rng.below(ps.first.size())];
    const Genome& b = ps.second[rng.below(ps.second.size())];
    Genome c = i % 2 ? crossover(a, b, def, rng) : crossover(a, b, rng);
    ASSERT_TRUE(one_arm_one_projectile(c)) << "child " << i;
    EXPECT_TRUE(locks_kept(a, c).ok()) << locks_kept(a, c).error();
    EXPECT_EQ(projectile_of(c), projectile_of(a));
    EXPECT_EQ(projectile_edge(c).face, projectile_edge(a).face);
    EXPECT_EQ(c.catapult->release.delay_steps, a.catapult->release.delay_steps);
    EXPECT_EQ(c.nodes[0].size, a.nodes[0].size);  // a's arm
    // the arms' bodies cross: no more genes than the longer parent
    EXPECT_LE(c.nodes.size(), std::max(a.nodes.size(), b.nodes.size()));
    // some of b's body parts come along (told apart by their random sizes)
    for (std::size_t j = 1; j < c.nodes.size(); ++j)
      if (std::any_of(b.nodes.begin() + 1, b.nodes.end(),
                      [&](const NodeGene& n) { return n.size == c.nodes[j].size; })) {
        ++from_b;
        break;
      }
  }
  EXPECT_GT(from_b, kMany / 4);
}

TEST(CatapultCrossover, TheCutFallsAfterTheMechanism) {
  // a: arm, projectile, body part; b: arm, body part, projectile. A cut at 1
  // would fall inside a's mechanism: it moves to 2, after a's kept nodes,
  // and b's node 2 (its projectile) comes unlocked, as a body part.
  Genome a = parse(kProjectileFirst), b = parse(kCatapult);
  b.nodes[2].size = {0.5, 0.5, 0.5};
  OperatorDef def = catapult_def();
  Rng rng = rng_for(22);
  Genome c = crossover_at(a, b, 1, def, rng);
  ASSERT_TRUE(one_arm_one_projectile(c));
  ASSERT_EQ(c.nodes.size(), 3u);
  EXPECT_EQ(c.nodes[0].size, a.nodes[0].size);
  EXPECT_EQ(c.nodes[1], a.nodes[1]);
  EXPECT_EQ(c.nodes[2].size, (Vec3{0.5, 0.5, 0.5}));
  EXPECT_EQ(c.nodes[2].lock, 0u);
  EXPECT_NE(c.nodes[2].joint.type, JointType::Fixed);
}

TEST(CatapultGraft, ThousandChildrenTakeTheTrunksMechanism) {
  Parents ps = marked_parents(30);
  Rng rng = rng_for(31);
  OperatorDef def = catapult_def();
  // the branch parents' arms are marked: no child may contain one
  for (Genome& b : ps.second) b.nodes[0].size = {0.123, 0.0456, 0.0789};
  for (int i = 0; i < kMany; ++i) {
    const Genome& t = ps.first[rng.below(ps.first.size())];
    const Genome& b = ps.second[rng.below(ps.second.size())];
    Genome c = i % 2 ? graft(t, b, def, rng) : graft(t, b, rng);
    ASSERT_TRUE(one_arm_one_projectile(c)) << "child " << i;
    EXPECT_TRUE(locks_kept(t, c).ok()) << locks_kept(t, c).error();
    EXPECT_LE(c.nodes.size(), 20u);
    EXPECT_EQ(projectile_of(c), projectile_of(t));
    EXPECT_EQ(c.catapult->release.delay_steps, t.catapult->release.delay_steps);
    EXPECT_EQ(c.nodes[0].size, t.nodes[0].size);  // the trunk's arm
    for (const NodeGene& n : c.nodes) EXPECT_NE(n.size, b.nodes[0].size) << "child " << i;
  }
}

// A catapult crossed or grafted with a walker: the child is what its first
// parent is (locks are the first parent's; the paper never mixes them).
TEST(CatapultMixedParents, TheFirstParentGivesTheKind) {
  OperatorDef def = catapult_def();
  OperatorDef plain_def = default_operators(Dialect::Chaumont2007);
  plain_def.genes_at_creation = {15, 20};  // some at the gene limit
  std::vector<Genome> cats = pool(40, 40), plains = pool(40, 41, plain_def);
  Rng rng = rng_for(42);
  for (int i = 0; i < 400; ++i) {
    const Genome& cat = cats[rng.below(cats.size())];
    const Genome& plain = plains[rng.below(plains.size())];
    Genome children[4] = {crossover(cat, plain, def, rng), crossover(plain, cat, def, rng),
                          graft(cat, plain, def, rng), graft(plain, cat, def, rng)};
    for (int k = 0; k < 4; ++k) {
      const Genome& c = children[k];
      // the root is the first parent's
      EXPECT_EQ(c.nodes[0].size, (k % 2 == 0 ? cat : plain).nodes[0].size);
      if (k % 2 == 0) {
        ASSERT_TRUE(one_arm_one_projectile(c)) << "child " << i << ", form " << k;
        EXPECT_EQ(projectile_of(c), projectile_of(cat));
        EXPECT_EQ(c.catapult->release.delay_steps, cat.catapult->release.delay_steps);
      } else {
        Status s = validate(c);
        ASSERT_TRUE(s.ok()) << s.error() << "\n" << genome_to_string(c);
        EXPECT_FALSE(c.catapult.has_value());
        EXPECT_FALSE(has_locks(c));
      }
    }
  }
}

// ---------------------------------------------------------------- together

TEST(CatapultOperators, EvolutionLoopStaysCatapults) {
  // chaumont2007 5.7's mix: asexual 0.4 at 0.1; crossover 0.3, graft 0.3,
  // then mutation at 0.05 with chance 0.1
  OperatorDef def = catapult_def();
  def.catapult.mutate_projectile = true;
  std::vector<Genome> pop = pool(40, 50);
  Rng rng = rng_for(51);
  for (int i = 0; i < 3000; ++i) {
    const Genome& a = pop[rng.below(pop.size())];
    const Genome& b = pop[rng.below(pop.size())];
    double r = rng.uniform();
    Genome c;
    if (r < 0.4) {
      c = a;
      mutate(c, def, 0.1, rng);
    } else {
      c = r < 0.7 ? crossover(a, b, def, rng) : graft(a, b, def, rng);
      if (rng.chance(0.1)) mutate(c, def, 0.05, rng);
    }
    ASSERT_TRUE(one_arm_one_projectile(c)) << "child " << i;
    ASSERT_EQ(parse(genome_to_string(c)), c);
    EXPECT_EQ(c.catapult->release.delay_steps, 30);
    pop[rng.below(pop.size())] = std::move(c);
  }
}

TEST(CatapultOperators, SameSeedSameOutput) {
  OperatorDef def = catapult_def();
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    Rng r1 = rng_for(100 + seed), r2 = rng_for(100 + seed);
    Genome a1 = random_genome(Dialect::Chaumont2007, def, r1);
    Genome a2 = random_genome(Dialect::Chaumont2007, def, r2);
    Genome b1 = random_genome(Dialect::Chaumont2007, def, r1);
    Genome b2 = random_genome(Dialect::Chaumont2007, def, r2);
    EXPECT_EQ(a1, a2);
    Genome m1 = a1, m2 = a2;
    mutate(m1, def, 0.3, r1);
    mutate(m2, def, 0.3, r2);
    EXPECT_EQ(m1, m2);
    EXPECT_EQ(crossover(a1, b1, def, r1), crossover(a2, b2, def, r2));
    EXPECT_EQ(graft(a1, b1, def, r1), graft(a2, b2, def, r2));
    EXPECT_EQ(r1.next(), r2.next());
  }
}

TEST(CatapultOperators, NormalizeKeepsACatapult) {
  OperatorDef def = catapult_def();
  Rng rng = rng_for(60);
  Genome g = parse(kProjectileFirst);
  // out of the rules: a hinge joint on the projectile's edge? no: a sphere
  // body part, and an edge back to the arm
  g.nodes[2].shape = Shape::Sphere;
  g.nodes[2].edges.push_back({0, Face::PosX, 0, 0, {0, 0, 0}, 1.0, {}, false});
  normalize(g, def, rng);
  ASSERT_TRUE(one_arm_one_projectile(g));
  EXPECT_EQ(g.nodes[2].shape, Shape::Box);
  EXPECT_EQ(g.catapult->release.inputs[0].edge, 1);  // still the body part
}

}  // namespace
}  // namespace bx
