// Dialect tables, names, and validate() on genomes built in code (as random
// creation and the operators build them: messages carry paths, no file name).
#include "genome/dialect.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

namespace bx {
namespace {

// A two-part genome valid in `d`: a root and one hinged limb.
Genome pair(Dialect d) {
  Genome g;
  g.dialect = d;
  g.nodes.resize(2);
  g.nodes[0].edges.push_back({1, Face::PosX, 0, 0, {0, 0, 0}, 1.0, {}, false});
  g.nodes[1].size = {1, 0.5, 0.5};
  g.nodes[1].effectors.push_back({0, 0, {}});
  return g;
}

std::string error_of(const Genome& g) {
  Status s = validate(g);
  EXPECT_FALSE(s.ok());
  return s.ok() ? "" : s.error();
}

TEST(Genome, JointDofs) {
  EXPECT_EQ(joint_dofs(JointType::Fixed), 0);
  EXPECT_EQ(joint_dofs(JointType::Hinge), 1);
  EXPECT_EQ(joint_dofs(JointType::Universal), 2);
  EXPECT_EQ(joint_dofs(JointType::Spherical), 3);
  EXPECT_EQ(joint_dofs(JointType::Slider), 1);
  EXPECT_EQ(joint_dofs(JointType::Cylindrical), 2);
}

TEST(Genome, Names) {
  EXPECT_EQ(to_string(Dialect::Sims1994), "sims1994");
  EXPECT_EQ(to_string(Dialect::Miconi2006), "miconi2006");
  EXPECT_EQ(to_string(Dialect::Chaumont2007), "chaumont2007");
  EXPECT_EQ(to_string(Shape::Box), "box");
  EXPECT_EQ(to_string(Shape::Sphere), "sphere");
  EXPECT_EQ(to_string(Shape::Capsule), "capsule");
  EXPECT_EQ(to_string(Shape::Cylinder), "cylinder");
  EXPECT_EQ(to_string(JointType::Fixed), "fixed");
  EXPECT_EQ(to_string(JointType::Hinge), "hinge");
  EXPECT_EQ(to_string(JointType::Universal), "universal");
  EXPECT_EQ(to_string(JointType::Spherical), "spherical");
  EXPECT_EQ(to_string(JointType::Slider), "slider");
  EXPECT_EQ(to_string(JointType::Cylindrical), "cylindrical");
  EXPECT_EQ(to_string(Face::PosX), "+x");
  EXPECT_EQ(to_string(Face::NegX), "-x");
  EXPECT_EQ(to_string(Face::PosY), "+y");
  EXPECT_EQ(to_string(Face::NegY), "-y");
  EXPECT_EQ(to_string(Face::PosZ), "+z");
  EXPECT_EQ(to_string(Face::NegZ), "-z");
  EXPECT_EQ(to_string(SourcePlace::Self), "self");
  EXPECT_EQ(to_string(SourcePlace::Parent), "parent");
  EXPECT_EQ(to_string(SourcePlace::Child), "child");
  EXPECT_EQ(to_string(SourcePlace::Root), "root");
  EXPECT_EQ(to_string(SourcePlace::Global), "global");
  EXPECT_EQ(to_string(SensorType::JointAngle), "joint_angle");
  EXPECT_EQ(to_string(SensorType::Contact), "contact");
}

TEST(Dialect, ParseNames) {
  for (Dialect d : {Dialect::Sims1994, Dialect::Miconi2006, Dialect::Chaumont2007}) {
    EXPECT_EQ(parse_dialect(to_string(d)), d);
    EXPECT_EQ(dialect_rules(d).dialect, d);
  }
  EXPECT_EQ(parse_dialect("Sims1994"), std::nullopt);
  EXPECT_EQ(parse_dialect(""), std::nullopt);
}

TEST(Dialect, Sims1994Rules) {
  const DialectRules& r = dialect_rules(Dialect::Sims1994);
  EXPECT_EQ(r.neuron_set, NeuronSetId::Sims1994);
  EXPECT_EQ(r.max_genes, 0);
  EXPECT_EQ(r.max_parts, 100);
  EXPECT_FALSE(r.tree_only);
  EXPECT_EQ(r.shapes.size(), 4u);
  EXPECT_EQ(r.joints.size(), 6u);
  EXPECT_EQ(r.angle_step, 0);
  EXPECT_EQ(r.max_neurons_per_part, 0);
  EXPECT_EQ(r.max_inputs_per_neuron, 0);
  EXPECT_EQ(r.mass_rule, MassRule::Density);
  EXPECT_EQ(r.default_hinge_limits, std::nullopt);
  EXPECT_TRUE(r.global_neurons);
}

TEST(Dialect, Miconi2006Rules) {
  const DialectRules& r = dialect_rules(Dialect::Miconi2006);
  EXPECT_EQ(r.neuron_set, NeuronSetId::Miconi2006);
  EXPECT_EQ(r.max_genes, 7);
  EXPECT_EQ(r.max_parts, 11);
  EXPECT_TRUE(r.tree_only);
  EXPECT_EQ(r.shapes, std::vector<Shape>{Shape::Box});
  EXPECT_EQ(r.joints, std::vector<JointType>{JointType::Hinge});
  EXPECT_TRUE(r.hinge_axis_y_or_z);
  EXPECT_DOUBLE_EQ(r.angle_step, kPi / 8);
  EXPECT_EQ(r.max_neurons_per_part, 6);
  EXPECT_EQ(r.max_inputs_per_neuron, 3);
  EXPECT_EQ(r.mass_rule, MassRule::TanhVolume);
  EXPECT_DOUBLE_EQ(r.mass_scale, 0.8);
  ASSERT_TRUE(r.default_hinge_limits.has_value());
  EXPECT_DOUBLE_EQ(r.default_hinge_limits->lo, -3 * kPi / 4);
  EXPECT_DOUBLE_EQ(r.default_hinge_limits->hi, 3 * kPi / 4);
  EXPECT_EQ(r.reflect_axes, std::vector<int>{1});
  EXPECT_DOUBLE_EQ(r.max_abs_bias, 1.5);
  EXPECT_DOUBLE_EQ(r.max_abs_weight, 1.0);
  EXPECT_FALSE(r.global_neurons);
}

TEST(Dialect, Chaumont2007Rules) {
  const DialectRules& r = dialect_rules(Dialect::Chaumont2007);
  EXPECT_EQ(r.neuron_set, NeuronSetId::Chaumont2007);
  EXPECT_EQ(r.max_genes, 20);
  EXPECT_EQ(r.max_parts, 100);
  EXPECT_FALSE(r.tree_only);
  EXPECT_EQ(r.shapes, std::vector<Shape>{Shape::Box});
  // 5.1: "each (ball and socket) joint has only one degree of freedom": no sliders
  EXPECT_EQ(r.joints, (std::vector<JointType>{JointType::Hinge}));
  EXPECT_EQ(r.sensors, std::vector<SensorType>{SensorType::Contact});
  EXPECT_EQ(r.mass_rule, MassRule::Density);
  EXPECT_EQ(r.default_hinge_limits, std::nullopt);
}

TEST(Validate, ValidPairsInEveryDialect) {
  for (Dialect d : {Dialect::Sims1994, Dialect::Miconi2006, Dialect::Chaumont2007}) {
    Status s = validate(pair(d));
    EXPECT_TRUE(s.ok()) << to_string(d) << ": " << s.error();
  }
}

TEST(Validate, EmptyGenome) {
  Genome g;
  EXPECT_EQ(error_of(g), "nodes: a genome needs at least one node, got []");
}

TEST(Validate, MessagesHavePathsAndValues) {
  Genome g = pair(Dialect::Sims1994);
  g.nodes[1].size.y = std::nan("");
  EXPECT_EQ(error_of(g), "nodes[1].size: each dimension must be > 0, got [1.0, nan, 0.5]");

  g = pair(Dialect::Sims1994);
  g.nodes[1].joint.axis1 = {0, 0, 2};
  EXPECT_EQ(error_of(g), "nodes[1].joint.axis1: must be a unit vector, got [0.0, 0.0, 2.0]");

  g = pair(Dialect::Sims1994);
  g.nodes[1].joint = {JointType::Universal, {0, 0, 1}, {0, 0, -1}, {}};
  EXPECT_EQ(error_of(g),
            "nodes[1].joint.axis2: must not be parallel to axis1 for a universal joint, "
            "got [0.0, 0.0, -1.0]");

  g = pair(Dialect::Sims1994);
  g.nodes[1].recursive_limit = 0;
  EXPECT_EQ(error_of(g), "nodes[1].recursive_limit: must be >= 1, got 0");

  g = pair(Dialect::Sims1994);
  g.nodes[1].joint.type = JointType::Fixed;
  EXPECT_EQ(
      error_of(g),
      "nodes[1].effectors[0].dof: no such degree of freedom of a fixed joint (it has 0), got 0");

  g = pair(Dialect::Sims1994);
  g.nodes[0].edges[0].reflect = {3};
  EXPECT_EQ(error_of(g),
            "nodes[0].edges[0].reflect: reflection axis not allowed in dialect sims1994 "
            "(expected one of x, y, z), got [3]");
}

// values ODE's asserts met (issue 13): refused by validation, naming the field and the value
TEST(Validate, PhysicalRangesKeepTheEngineInsideDoublePrecision) {
  Genome g = pair(Dialect::Sims1994);
  g.nodes[1].size.x = 1e-308;
  EXPECT_EQ(error_of(g), "nodes[1].size: each dimension must lie in [0.0001, 10000.0] m, got [1e-308, 0.5, 0.5]");
  g.nodes[1].size.x = 5e-324;
  EXPECT_EQ(error_of(g), "nodes[1].size: each dimension must lie in [0.0001, 10000.0] m, got [5e-324, 0.5, 0.5]");
  g.nodes[1].size.x = 1e308;
  EXPECT_EQ(error_of(g), "nodes[1].size: each dimension must lie in [0.0001, 10000.0] m, got [1e+308, 0.5, 0.5]");

  g = pair(Dialect::Sims1994);
  g.nodes[0].density = 1e200;
  EXPECT_EQ(error_of(g), "nodes[0].density: must lie in [0.001, 1000000.0] kg/m^3, got 1e+200");
  g.nodes[0].density = 5e-324;
  EXPECT_EQ(error_of(g), "nodes[0].density: must lie in [0.001, 1000000.0] kg/m^3, got 5e-324");

  g = pair(Dialect::Sims1994);
  g.nodes[0].edges[0].scale = 1e15;
  EXPECT_EQ(error_of(g), "nodes[0].edges[0].scale: must lie in [0.001, 1000.0], got 1e+15");

  // the ends of each range are fine
  g = pair(Dialect::Sims1994);
  g.nodes[1].size = {kMinPartSize, kMaxPartSize, 1};
  g.nodes[0].density = kMaxDensity;
  g.nodes[1].density = kMinDensity;
  g.nodes[0].edges[0].scale = kMaxEdgeScale;
  EXPECT_TRUE(validate(g).ok()) << validate(g).error();
}

TEST(Validate, SliderLimitsAreNotAngles) {
  Genome g = pair(Dialect::Sims1994);
  g.nodes[1].joint = {JointType::Slider, {1, 0, 0}, {0, 1, 0}, {{-5, 5}}};
  EXPECT_TRUE(validate(g).ok()) << validate(g).error();
  g.nodes[1].joint.type = JointType::Hinge;
  EXPECT_EQ(error_of(g),
            "nodes[1].joint.limits[0]: angular limits must lie within [-pi, pi], got [-5.0, 5.0]");
  g.dialect = Dialect::Sims1994;
  g.nodes[1].joint = {JointType::Cylindrical, {1, 0, 0}, {0, 1, 0}, {{-5, 5}, {-4, 1}}};
  EXPECT_EQ(error_of(g),
            "nodes[1].joint.limits[1]: angular limits must lie within [-pi, pi], got [-4.0, 1.0]");
}

TEST(Validate, ParamsByPosition) {
  Genome g = pair(Dialect::Chaumont2007);
  g.nodes[0].neurons.push_back({"mem", {}, 0, {}});
  EXPECT_EQ(error_of(g), "nodes[0].neurons[0].params: mem takes 1 parameter(s), got []");
  const NeuronFnSpec* mem = find_neuron_fn(NeuronSetId::Chaumont2007, "mem");
  ASSERT_NE(mem, nullptr);
  ASSERT_EQ(mem->params.size(), 1u);
  ASSERT_TRUE(mem->params[0].integer);
  g.nodes[0].neurons[0].params = {mem->params[0].min + 0.5};
  EXPECT_EQ(error_of(g), "nodes[0].neurons[0].params.n: must be an integer, got " +
                             nlohmann::json(mem->params[0].min + 0.5).dump());
  g.nodes[0].neurons[0].params = {mem->params[0].min};
  EXPECT_TRUE(validate(g).ok()) << validate(g).error();
}

TEST(Validate, ParentSourcesAreLeftToDevelopment) {
  // a parent source cannot be checked statically: a node may have several parents
  Genome g = pair(Dialect::Sims1994);
  g.nodes[1].effectors[0].inputs.push_back({SourcePlace::Parent, SourceKind::Neuron, 9, 0, 1.0});
  EXPECT_TRUE(validate(g).ok()) << validate(g).error();
  g.nodes[1].effectors[0].inputs[0].index = -1;
  EXPECT_EQ(error_of(g), "nodes[1].effectors[0].inputs[0].neuron: must be >= 0, got -1");
}

TEST(Validate, RootMayCarryJointSensorsAndEffectors) {
  // the root instance has no joint and reads 0, but a reflexive copy of it has one
  Genome g = pair(Dialect::Sims1994);
  g.nodes[0].sensors.push_back({SensorType::JointAngle, 0, Face::NegZ});
  g.nodes[0].effectors.push_back({0, 0.5, {{SourcePlace::Self, SourceKind::Sensor, 0, 0, 1.0}}});
  EXPECT_TRUE(validate(g).ok()) << validate(g).error();
}

TEST(Validate, MiconiTreeAndLimits) {
  Genome g = pair(Dialect::Miconi2006);
  // the fixed range, given explicitly, is accepted
  g.nodes[1].joint.limits = {*dialect_rules(Dialect::Miconi2006).default_hinge_limits};
  EXPECT_TRUE(validate(g).ok()) << validate(g).error();
  g.nodes[1].joint.axis1 = {0, -1, 0};
  EXPECT_TRUE(validate(g).ok()) << validate(g).error();
  // rotations: multiples of pi/8 in both polar angles
  g.nodes[0].edges[0].rotation = {0, -3 * kPi / 8, 5 * kPi / 8};
  EXPECT_TRUE(validate(g).ok()) << validate(g).error();
  // a second root-level edge to the same node breaks the tree
  g.nodes[0].edges.push_back(g.nodes[0].edges[0]);
  EXPECT_EQ(error_of(g),
            "nodes[0].edges[1].to: node 1 already has a parent (nodes[0].edges[0]); a tree "
            "genome in dialect miconi2006 allows one, got 1");
}

TEST(Validate, MiconiEffectorInputs) {
  Genome g = pair(Dialect::Miconi2006);
  g.nodes[1].neurons.push_back({"tanh", {}, 0, {}});
  for (int i = 0; i < 4; ++i)
    g.nodes[1].effectors[0].inputs.push_back({SourcePlace::Self, SourceKind::Neuron, 0, 0, 1.0});
  EXPECT_EQ(
      error_of(g),
      "nodes[1].effectors[0].inputs: too many inputs (at most 3) in dialect miconi2006, got 4");
  g.nodes[1].effectors.push_back({0, 0, {}});
  EXPECT_EQ(error_of(g),
            "nodes[1].effectors: at most 1 effector(s) per part in dialect miconi2006, got 2");
}

TEST(Validate, ChaumontGenesLimit) {
  Genome g = pair(Dialect::Chaumont2007);
  while (g.nodes.size() < 21) {
    g.nodes[0].edges.push_back(
        {static_cast<int>(g.nodes.size()), Face::PosX, 0, 0, {0, 0, 0}, 1.0, {}, false});
    g.nodes.push_back(NodeGene{});
  }
  EXPECT_EQ(error_of(g), "nodes: at most 20 genes in dialect chaumont2007, got 21");
  g.nodes.pop_back();
  g.nodes[0].edges.pop_back();
  EXPECT_TRUE(validate(g).ok()) << validate(g).error();
}

}  // namespace
}  // namespace bx

#include "genome/operators.h"

namespace bx {
namespace {

// The operators' dialect rules are table fields: what random genomes and
// mutated, crossed and grafted children look like follows the fields, for
// every dialect's row.
TEST(DialectRules, TheOperatorsFollowTheTablesFields) {
  for (Dialect d : {Dialect::Sims1994, Dialect::Miconi2006, Dialect::Chaumont2007}) {
    const DialectRules& r = dialect_rules(d);
    OperatorDef def = default_operators(d);
    Rng rng(42);
    int scaled = 0, terminal = 0, rolled = 0, edges = 0;
    for (int k = 0; k < 60; ++k) {
      Genome a = random_genome(d, def, rng), b = random_genome(d, def, rng);
      Genome c = k % 3 == 0 ? crossover(a, b, def, rng) : k % 3 == 1 ? graft(a, b, def, rng) : a;
      mutate(c, def, 0.2, rng);
      for (const Genome* g : {&a, &c}) {
        ASSERT_TRUE(validate(*g).ok()) << validate(*g).error();
        for (std::size_t i = 0; i < g->nodes.size(); ++i) {
          const NodeGene& n = g->nodes[i];
          if (r.limb_io) {
            // one joint-angle sensor and one actuator per limb, the root none
            EXPECT_EQ(n.sensors.size(), i == 0 ? 0u : 1u) << to_string(d);
            EXPECT_EQ(n.effectors.size(), i == 0 ? 0u : 1u) << to_string(d);
          }
          for (const EdgeGene& e : n.edges) {
            ++edges;
            scaled += e.scale != 1.0;
            terminal += e.terminal_only;
            rolled += e.rotation.x != 0.0;
          }
        }
      }
    }
    ASSERT_GT(edges, 50) << to_string(d);
    EXPECT_EQ(scaled > 0, r.edge_scale_free) << to_string(d);
    EXPECT_EQ(terminal > 0, r.edge_terminal_only) << to_string(d);
    EXPECT_EQ(rolled > 0, r.edge_roll_free) << to_string(d);
  }
}

}  // namespace
}  // namespace bx
