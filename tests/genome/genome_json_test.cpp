// The genome file form: round trips, canonical text, defaults, and the exact
// error line for malformed input.
#include "genome/genome_json.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "genome/dialect.h"

namespace bx {
namespace {

using nlohmann::json;

// A small valid sims1994 genome: a body with one limb.
constexpr const char* kSims = R"({
  "format": "bestiary-genome", "version": 1, "dialect": "sims1994",
  "nodes": [
    {"size": [2, 1, 1],
     "neurons": [{"fn": "sum", "inputs": [{"from": "self", "sensor": 0}, {"from": "child", "edge": 0, "neuron": 0}]}],
     "sensors": [{"type": "contact", "face": "-z"}],
     "edges": [{"to": 1, "face": "+x"}]},
    {"shape": "box", "size": [1, 0.5, 0.5],
     "joint": {"type": "hinge", "axis1": [0, 0, 1], "limits": [[-1, 1]]},
     "neurons": [{"fn": "oscillate-wave", "params": {"freq": 2}}],
     "effectors": [{"dof": 0, "inputs": [{"from": "self", "neuron": 0}]}]}
  ]
})";

// A small valid miconi2006 genome: a root and one reflected limb.
constexpr const char* kMiconi = R"({
  "format": "bestiary-genome", "version": 1, "dialect": "miconi2006",
  "nodes": [
    {"size": [1, 1, 1],
     "neurons": [{"fn": "tanh", "bias": 0.5, "inputs": [{"from": "child", "edge": 0, "sensor": 0, "weight": -0.5}]}],
     "edges": [{"to": 1, "rotation": [0, 0.39269908169872414, 0], "reflect": ["y"]}]},
    {"size": [2, 0.5, 0.5],
     "joint": {"type": "hinge", "axis1": [0, 1, 0], "limits": [[-2.356194490192345, 2.356194490192345]]},
     "neurons": [{"fn": "sigmoid", "inputs": [{"from": "self", "sensor": 0}, {"from": "parent", "neuron": 0}, {"from": "root", "neuron": 0}]}],
     "sensors": [{"type": "joint_angle", "dof": 0}],
     "effectors": [{"dof": 0, "bias": -1.5, "inputs": [{"from": "self", "neuron": 0, "weight": 1}]}]}
  ]
})";

// A small valid chaumont2007 genome.
constexpr const char* kChaumont = R"({
  "format": "bestiary-genome", "version": 1, "dialect": "chaumont2007",
  "nodes": [
    {"size": [1, 1, 1],
     "neurons": [{"fn": "sumT", "params": {"T": 0.5}, "inputs": [{"from": "self", "sensor": 0}]},
                 {"fn": "mem", "params": {"n": 3}, "inputs": [{"from": "self", "neuron": 0}]}],
     "sensors": [{"type": "contact", "face": "-z"}],
     "edges": [{"to": 1}]},
    {"size": [1, 0.5, 0.5], "joint": {"type": "hinge", "axis1": [1, 0, 0]},
     "effectors": [{"inputs": [{"from": "parent", "neuron": 1}]}]}
  ]
})";

// `text` with its only occurrence of `from` replaced by `to`.
std::string edit(std::string text, const std::string& from, const std::string& to) {
  auto p = text.find(from);
  EXPECT_NE(p, std::string::npos) << "fixture lacks: " << from;
  if (p == std::string::npos) return text;
  EXPECT_EQ(text.find(from, p + 1), std::string::npos) << "fixture has twice: " << from;
  return text.replace(p, from.size(), to);
}

// The error line for `text`, which must fail.
std::string err(const std::string& text) {
  auto r = genome_from_string(text, "t.json");
  EXPECT_FALSE(r.ok()) << "unexpectedly parsed:\n" << text;
  return r.ok() ? "" : r.error();
}

// A sims1994 document with the given nodes.
std::string sims_nodes(const std::string& nodes) {
  return R"({"format": "bestiary-genome", "version": 1, "dialect": "sims1994", "nodes": )" + nodes +
         "}";
}

std::string num(double v) { return json(v).dump(); }

// A genome using every shape, joint type, source place, reflection,
// terminal-only edges, recursion and global neurons.
Genome rich_genome() {
  Genome g;
  g.dialect = Dialect::Sims1994;
  g.nodes.resize(6);

  NodeGene& root = g.nodes[0];
  root.size = {2, 1, 0.5};
  root.density = 1.5;
  root.recursive_limit = 2;
  root.neurons.push_back({"oscillate-wave", {2.0, 0.5}, 0, {}});
  root.neurons.push_back({"sum",
                          {},
                          0,
                          {{SourcePlace::Self, SourceKind::Sensor, 0, 0, 1.0},
                           {SourcePlace::Child, SourceKind::Neuron, 0, 0, 0.5}}});
  root.sensors.push_back({SensorType::Contact, 0, Face::NegZ});
  root.sensors.push_back({SensorType::JointAngle, 0, Face::NegZ});
  root.effectors.push_back({0, 0.25, {{SourcePlace::Global, SourceKind::Neuron, 0, 0, -1.0}}});
  root.edges.push_back({1, Face::PosX, 0.5, -0.25, {0.1, 0.2, 0.3}, 0.8, {1}, false});
  root.edges.push_back({2, Face::NegY, 0, 0, {0, 0, 0}, 1.0, {0, 2}, false});
  root.edges.push_back({0, Face::PosZ, 0, 0, {0, 0, kPi / 2}, 0.5, {}, true});

  NodeGene& n1 = g.nodes[1];
  n1.shape = Shape::Sphere;
  n1.size = {0.6, 0.6, 0.6};
  n1.joint = {JointType::Universal, {1, 0, 0}, {0, 1, 0}, {{-1, 1}, {-0.5, 0.5}}};
  n1.neurons.push_back({"sum-threshold",
                        {0.3},
                        0,
                        {{SourcePlace::Parent, SourceKind::Neuron, 1, 0, 1.0},
                         {SourcePlace::Root, SourceKind::Sensor, 0, 0, 2.0}}});
  n1.sensors.push_back({SensorType::JointAngle, 1, Face::NegZ});
  n1.effectors.push_back({1, 0, {{SourcePlace::Self, SourceKind::Neuron, 0, 0, 1.0}}});
  n1.edges.push_back({3, Face::PosZ, 0, 0, {0, 0, 0}, 1.0, {}, true});

  NodeGene& n2 = g.nodes[2];
  n2.shape = Shape::Capsule;
  n2.size = {1.5, 0.3, 0.3};
  n2.joint = {JointType::Spherical, {0, 0, 1}, {1, 0, 0}, {{-1, 1}, {-0.5, 0.5}, {-3, 3}}};
  n2.neurons.push_back(
      {"smooth", {0.2}, 0, {{SourcePlace::Global, SourceKind::Neuron, 1, 0, 0.75}}});

  NodeGene& n3 = g.nodes[3];
  n3.shape = Shape::Cylinder;
  n3.size = {1, 0.4, 0.4};
  n3.joint = {JointType::Slider, {0, 1, 0}, {0, 1, 0}, {{-0.2, 0.2}}};
  n3.edges.push_back({4, Face::NegX, 1, -1, {0, 0, 0}, 1.0, {}, false});

  NodeGene& n4 = g.nodes[4];
  n4.joint.type = JointType::Fixed;
  n4.edges.push_back({5, Face::PosY, 0, 0, {0, 0, 0}, 2.0, {2}, false});

  NodeGene& n5 = g.nodes[5];
  n5.size = {0.5, 0.5, 0.5};
  n5.joint = {JointType::Cylindrical, {0, 0, 1}, {0, 1, 0}, {{-0.1, 0.1}, {-2, 2}}};

  g.global_neurons.push_back({"sin", {}, 0, {{SourcePlace::Root, SourceKind::Neuron, 0, 0, 1.0}}});
  g.global_neurons.push_back({"max",
                              {},
                              0,
                              {{SourcePlace::Global, SourceKind::Neuron, 0, 0, 1.0},
                               {SourcePlace::Root, SourceKind::Sensor, 1, 0, 1.0}}});
  return g;
}

// ---------------------------------------------------------------- round trips

TEST(GenomeJson, RichGenomeRoundTrips) {
  Genome g = rich_genome();
  ASSERT_TRUE(validate(g).ok()) << validate(g).error();
  auto back = genome_from_json(genome_to_json(g), "rich");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(*back, g);
  auto again = genome_from_string(genome_to_string(g), "rich");
  ASSERT_TRUE(again.ok()) << again.error();
  EXPECT_EQ(*again, g);
}

TEST(GenomeJson, CanonicalStringIsStable) {
  for (const char* text : {kSims, kMiconi, kChaumont}) {
    auto g = genome_from_string(text, "t.json");
    ASSERT_TRUE(g.ok()) << g.error();
    std::string s = genome_to_string(*g);
    auto back = genome_from_string(s, "t.json");
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_EQ(*back, *g);
    EXPECT_EQ(genome_to_string(*back), s);
  }
  std::string s = genome_to_string(rich_genome());
  EXPECT_EQ(genome_to_string(*genome_from_string(s, "rich")), s);
}

TEST(GenomeJson, CanonicalStringLayout) {
  auto g = genome_from_string(kChaumont, "t.json");
  ASSERT_TRUE(g.ok()) << g.error();
  std::string s = genome_to_string(*g);
  EXPECT_EQ(s.rfind("{\n  \"format\": \"bestiary-genome\",\n  \"version\": 1,\n  \"dialect\": "
                    "\"chaumont2007\",\n",
                    0),
            0u)
      << s;
  EXPECT_EQ(s.substr(s.size() - 2), "}\n");
  // short arrays stay on one line, integer parameters stay integers
  EXPECT_NE(s.find("\"size\": [1.0, 0.5, 0.5]"), std::string::npos) << s;
  EXPECT_NE(s.find("\"params\": {\"n\": 3}"), std::string::npos) << s;
  for (std::size_t p = 0, q; (q = s.find('\n', p)) != std::string::npos; p = q + 1)
    EXPECT_LE(q - p, 100u) << s.substr(p, q - p);
}

TEST(GenomeJson, CanonicalJsonWritesEveryField) {
  auto g =
      genome_from_string(sims_nodes(R"([{"size": [1, 1, 1], "edges": [{"to": 0}]}])"), "t.json");
  ASSERT_TRUE(g.ok()) << g.error();
  json j = genome_to_json(*g);
  const json& node = j["nodes"][0];
  for (const char* k : {"shape", "size", "density", "joint", "recursive_limit", "neurons",
                        "sensors", "effectors", "edges"})
    EXPECT_TRUE(node.contains(k)) << k;
  for (const char* k : {"type", "axis1", "axis2", "limits"})
    EXPECT_TRUE(node["joint"].contains(k)) << k;
  for (const char* k : {"to", "face", "at", "rotation", "scale", "reflect", "terminal_only"})
    EXPECT_TRUE(node["edges"][0].contains(k)) << k;
  EXPECT_EQ(j["format"], "bestiary-genome");
  EXPECT_EQ(j["version"], 1);
  EXPECT_TRUE(j["global_neurons"].is_array());
}

// ---------------------------------------------------------------- defaults

TEST(GenomeJson, DefaultsAndNormalization) {
  auto g = genome_from_string(sims_nodes(R"([
    {"size": [1, 2, 3],
     "joint": {"type": "universal", "axis1": [0, 0, 2], "axis2": [3, 4, 0]},
     "neurons": [{"fn": "oscillate-saw", "params": {"phase": 0.5}}],
     "sensors": [{"type": "contact"}, {"type": "joint_angle"}],
     "effectors": [{}],
     "edges": [{"to": 0}]}])"),
                              "t.json");
  ASSERT_TRUE(g.ok()) << g.error();
  const NodeGene& n = g->nodes[0];
  EXPECT_EQ(n.shape, Shape::Box);
  EXPECT_EQ(n.size, (Vec3{1, 2, 3}));
  EXPECT_EQ(n.density, NodeGene{}.density);
  EXPECT_EQ(n.recursive_limit, 1);
  EXPECT_EQ(n.joint.axis1, (Vec3{0, 0, 1}));
  EXPECT_NEAR(n.joint.axis2.x, 0.6, 1e-15);
  EXPECT_NEAR(n.joint.axis2.y, 0.8, 1e-15);
  EXPECT_TRUE(n.joint.limits.empty());
  // parameters by position; the missing one takes its default
  const NeuronFnSpec* spec = find_neuron_fn(NeuronSetId::Sims1994, "oscillate-saw");
  ASSERT_NE(spec, nullptr);
  ASSERT_EQ(spec->params.size(), 2u);
  ASSERT_EQ(n.neurons[0].params.size(), 2u);
  int phase = spec->params[0].name == "phase" ? 0 : 1;
  EXPECT_EQ(n.neurons[0].params[phase], 0.5);
  EXPECT_EQ(n.neurons[0].params[1 - phase], spec->params[1 - phase].default_value);
  EXPECT_EQ(n.sensors[0].face, Face::NegZ);
  EXPECT_EQ(n.sensors[1].dof, 0);
  EXPECT_EQ(n.effectors[0], EffectorGene{});
  const EdgeGene& e = n.edges[0];
  EXPECT_EQ(e, (EdgeGene{0, Face::PosX, 0, 0, {0, 0, 0}, 1.0, {}, false}));
  EXPECT_TRUE(g->global_neurons.empty());
}

TEST(GenomeJson, ValidFixturesParse) {
  for (const char* text : {kSims, kMiconi, kChaumont}) {
    auto g = genome_from_string(text, "t.json");
    EXPECT_TRUE(g.ok()) << g.error();
  }
  auto m = genome_from_string(kMiconi, "t.json");
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m->nodes[0].edges[0].reflect, std::vector<int>{1});
  EXPECT_EQ(m->nodes[0].neurons[0].inputs[0].place, SourcePlace::Child);
  EXPECT_EQ(m->nodes[0].neurons[0].inputs[0].kind, SourceKind::Sensor);
  EXPECT_EQ(m->nodes[0].neurons[0].inputs[0].weight, -0.5);
}

// ---------------------------------------------------------------- errors: form

TEST(GenomeJsonErrors, WrongType) {
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, "2", 1]}])")),
            "t.json: nodes[0].size[1]: expected a number, got \"2\"");
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, 1]}])")),
            "t.json: nodes[0].size: expected an array of 3 numbers, got [1, 1]");
  EXPECT_EQ(err(sims_nodes(R"({"size": [1, 1, 1]})")),
            "t.json: nodes: expected an array, got {\"size\": [1, 1, 1]}");
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, 1, 1], "edges": [{"to": 0, "terminal_only": 1}]}])")),
            "t.json: nodes[0].edges[0].terminal_only: expected true or false, got 1");
  EXPECT_EQ(err("[1, 2]"), "t.json: expected a genome object, got [1, 2]");
}

TEST(GenomeJsonErrors, IntegersMustBeIntegers) {
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, 1, 1], "recursive_limit": 2.0}])")),
            "t.json: nodes[0].recursive_limit: expected an integer, got 2.0");
  EXPECT_EQ(err(edit(kChaumont, R"({"n": 3})", R"({"n": 2.5})")),
            "t.json: nodes[0].neurons[1].params.n: expected an integer, got 2.5");
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, 1, 1], "edges": [{"to": 4294967296}]}])")),
            "t.json: nodes[0].edges[0].to: integer out of range, got 4294967296");
}

TEST(GenomeJsonErrors, MissingField) {
  EXPECT_EQ(err(sims_nodes(R"([{"shape": "box"}])")),
            "t.json: nodes[0]: missing required field \"size\", got {\"shape\": \"box\"}");
  EXPECT_EQ(err(R"({"format": "bestiary-genome", "version": 1, "nodes": []})"),
            "t.json: missing required field \"dialect\", got {\"format\": \"bestiary-genome\", "
            "\"nodes\": [], \"version\": 1}");
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, 1, 1], "edges": [{"face": "+x"}]}])")),
            "t.json: nodes[0].edges[0]: missing required field \"to\", got {\"face\": \"+x\"}");
}

TEST(GenomeJsonErrors, BadEnum) {
  EXPECT_EQ(
      err(sims_nodes(R"([{"shape": "cube", "size": [1, 1, 1]}])")),
      "t.json: nodes[0].shape: unknown shape (expected one of box, sphere, capsule, cylinder), "
      "got \"cube\"");
  EXPECT_EQ(
      err(edit(kSims, R"("type": "hinge")", R"("type": "ball")")),
      "t.json: nodes[1].joint.type: unknown joint type (expected one of fixed, hinge, universal, "
      "spherical, slider, cylindrical), got \"ball\"");
  EXPECT_EQ(err(edit(kSims, R"("face": "+x")", R"("face": "x")")),
            "t.json: nodes[0].edges[0].face: unknown face (expected one of +x, -x, +y, -y, +z, "
            "-z), got \"x\"");
  EXPECT_EQ(
      err(edit(kSims, R"("from": "self", "sensor": 0)", R"("from": "sibling", "sensor": 0)")),
      "t.json: nodes[0].neurons[0].inputs[0].from: unknown source place (expected one of self, "
      "parent, child, root, global), got \"sibling\"");
  EXPECT_EQ(
      err(edit(kSims, R"("dialect": "sims1994")", R"("dialect": "sims")")),
      "t.json: dialect: unknown dialect (expected one of sims1994, miconi2006, chaumont2007, lessin2015), "
      "got \"sims\"");
  EXPECT_EQ(
      err(edit(kSims, R"("face": "+x")", R"("face": "+x", "reflect": ["w"])")),
      "t.json: nodes[0].edges[0].reflect[0]: unknown axis (expected one of x, y, z), got \"w\"");
}

TEST(GenomeJsonErrors, UnknownField) {
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, 1, 1], "sise": 2}])")),
            "t.json: nodes[0].sise: unknown field (expected one of shape, size, density, joint, "
            "recursive_limit, neurons, sensors, effectors, edges, lock), got 2");
  EXPECT_EQ(err(edit(kSims, R"("face": "+x")", R"("face": "+x", "scael": 2)")),
            "t.json: nodes[0].edges[0].scael: unknown field (expected one of to, face, at, "
            "rotation, scale, "
            "reflect, terminal_only), got 2");
  EXPECT_EQ(err(edit(kSims, R"("version": 1,)", R"("version": 1, "author": "me",)")),
            "t.json: author: unknown field (expected one of format, version, dialect, nodes, "
            "global_neurons, catapult, provenance), got \"me\"");
}

TEST(GenomeJsonErrors, SourceForm) {
  EXPECT_EQ(err(edit(kSims, R"({"from": "self", "sensor": 0})",
                     R"({"from": "self", "sensor": 0, "neuron": 0})")),
            "t.json: nodes[0].neurons[0].inputs[0]: a source names exactly one of \"neuron\", "
            "\"sensor\" and \"muscle\", "
            "got {\"from\": \"self\", \"neuron\": 0, \"sensor\": 0}");
  EXPECT_EQ(err(edit(kSims, R"("edge": 0, "neuron": 0)", R"("neuron": 0)")),
            "t.json: nodes[0].neurons[0].inputs[1]: missing required field \"edge\", got "
            "{\"from\": \"child\", "
            "\"neuron\": 0}");
  EXPECT_EQ(
      err(edit(kSims, R"({"from": "self", "sensor": 0})",
               R"({"from": "self", "sensor": 0, "edge": 0})")),
      "t.json: nodes[0].neurons[0].inputs[0].edge: only \"child\" sources take an edge, got 0");
  EXPECT_EQ(
      err(edit(kSims, R"({"type": "contact", "face": "-z"})", R"({"type": "contact", "dof": 0})")),
      "t.json: nodes[0].sensors[0].dof: only joint_angle sensors have a dof, got 0");
}

TEST(GenomeJsonErrors, NonFiniteNumber) {
  json j = json::parse(kSims);
  j["nodes"][0]["density"] = std::nan("");
  auto r = genome_from_json(j, "t.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), "t.json: nodes[0].density: expected a finite number, got nan");
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, 1, 1e999]}])")),
            "t.json: invalid JSON: number overflow parsing '1e999'");
}

TEST(GenomeJsonErrors, VersionAndFormat) {
  EXPECT_EQ(err(edit(kSims, R"("version": 1)", R"("version": 2)")),
            "t.json: version: unsupported version 2 (this build reads 1), got 2");
  EXPECT_EQ(err(edit(kSims, R"("version": 1)", R"("version": "1")")),
            "t.json: version: expected an integer, got \"1\"");
  EXPECT_EQ(
      err(edit(kSims, R"("format": "bestiary-genome")", R"("format": "bestiary-replay")")),
      "t.json: format: not a genome file (expected \"bestiary-genome\"), got \"bestiary-replay\"");
  // a newer version is reported as such even if it has fields this build does not know
  EXPECT_EQ(err(edit(kSims, R"("version": 1,)", R"("version": 3, "colour": "red",)")),
            "t.json: version: unsupported version 3 (this build reads 1), got 3");
}

TEST(GenomeJsonErrors, JsonSyntax) {
  EXPECT_EQ(
      err("{\"format\": \"bestiary-genome\",\n  , }"),
      "t.json: line 2, column 3 (byte 33): invalid JSON: syntax error while parsing object key - "
      "unexpected ','; expected string literal");
  EXPECT_EQ(err(""),
            "t.json: line 1, column 1 (byte 1): invalid JSON: syntax error while parsing value - "
            "unexpected end of input; expected '[', '{', or a literal");
}

TEST(GenomeJsonErrors, DuplicateField) {
  EXPECT_EQ(
      err(edit(kSims, R"("effectors": [{"dof": 0,)", R"("effectors": [{"dof": 0, "dof": 1,)")),
      "t.json: nodes[1].effectors[0].dof: field given twice");
  EXPECT_EQ(err(edit(kSims, R"("version": 1,)", R"("version": 1, "version": 1,)")),
            "t.json: version: field given twice");
  // equal keys in different objects are fine
  EXPECT_TRUE(genome_from_string(kSims, "t.json").ok());
}

// ---------------------------------------------------------------- hostile input (issue 13)

// `depth` nested arrays as a field's value: [[[...]]]
std::string nested(int depth) { return std::string(depth, '[') + std::string(depth, ']'); }

TEST(GenomeJsonLimits, DeepNestingIsRefusedBeforeAnythingRecurses) {
  // 10,000 deep crashed the error printer (20 KB of text); a document 64
  // levels deep passes the reader (a genome needs 6), 65 do not. Here the
  // genome object, "nodes" and the node take 3 levels
  std::string deep = sims_nodes(R"([{"size": [1, 1, 1], "shape": )" + nested(10000) + "}]");
  std::string at = "t.json: nodes[0].shape";
  for (int i = 0; i < kMaxGenomeDepth - 3; ++i) at += "[0]";
  EXPECT_EQ(err(deep), at + ": nested deeper than 64 levels of arrays and objects (a genome needs 6)");
  std::string ok_depth = err(sims_nodes(R"([{"size": [1, 1, 1], "shape": )" + nested(kMaxGenomeDepth - 3) + "}]"));
  EXPECT_EQ(ok_depth.rfind("t.json: nodes[0].shape: expected a string, got [[[[[[", 0), 0u) << ok_depth;
  EXPECT_EQ(err(nested(100000)).substr(0, 15), "t.json: [0][0][");
}

TEST(GenomeJsonLimits, QuotedValuesAreBoundedInLengthAndDepth) {
  // a 100,000-element array where a string belongs: the message quotes its start
  std::string many = "[";
  for (int i = 0; i < 100000; ++i) many += (i ? ", " : "") + std::to_string(i);
  many += "]";
  std::string e = err(sims_nodes(R"([{"size": [1, 1, 1], "shape": )" + many + "}]"));
  EXPECT_LT(e.size(), 200u) << e;
  EXPECT_EQ(e.substr(e.size() - 3), "...");
  // json_one_line on a value deeper than the reader allows (built in code)
  json v = json::array();
  for (int i = 0; i < 100000; ++i) v = json::array({std::move(v)});
  std::string line = json_one_line(v);
  EXPECT_NE(line.find("[...]"), std::string::npos);
  EXPECT_LT(line.size(), 200u);
  EXPECT_EQ(json_one_line(v, 20), "[[[[[[[[[[[[[[[[[...");
}

// found by fuzz_genome: a key with an escaped newline made a message of two lines
TEST(GenomeJsonLimits, KeysAreQuotedOnOneLine) {
  EXPECT_EQ(err(edit(kSims, R"("version": 1,)", R"("version": 1, "dia\nlect": 1,)")),
            "t.json: dia\\nlect: unknown field (expected one of format, version, dialect, nodes, "
            "global_neurons, catapult, provenance), got 1");
  EXPECT_EQ(err(edit(kSims, R"("version": 1,)", R"("version": 1, "a\tb": 1, "a\tb": 2,)")),
            "t.json: a\\tb: field given twice");
  std::string e = err(edit(kSims, R"("version": 1,)", R"("version": 1, ")" + std::string(100000, 'k') + R"(": 1,)"));
  EXPECT_LT(e.size(), 300u);
}

TEST(GenomeJsonLimits, TextAboveTheSizeLimitIsRefusedUnread) {
  std::string text(kMaxGenomeBytes + 1, ' ');
  EXPECT_EQ(err(text), "t.json: too large for a genome: " + std::to_string(kMaxGenomeBytes + 1) +
                           " bytes, above " + std::to_string(kMaxGenomeBytes));
}

TEST(GenomeJsonLimits, ALongArrayParsesInOnePass) {
  // 300,000 global neurons (9 MB) took 12.5 s: the parser's callback mode scanned
  // the whole array at each element's end. Read now in one pass; a duplicate key
  // at the end of the array is still found and named
  const int n = 300000;
  std::string neurons;
  neurons.reserve(n * 32);
  for (int i = 0; i < n; ++i) neurons += std::string(i ? "," : "") + R"({"fn": "sum", "inputs": []})";
  std::string text = R"({"format": "bestiary-genome", "version": 1, "dialect": "sims1994",
    "nodes": [{"size": [1, 1, 1]}], "global_neurons": [)" + neurons + "]}";
  auto g = genome_from_string(text, "t.json");
  ASSERT_TRUE(g.ok()) << g.error();
  EXPECT_EQ(g->global_neurons.size(), static_cast<std::size_t>(n));
  text.insert(text.size() - 3, R"(, "fn": "sum")");
  EXPECT_EQ(err(text), "t.json: global_neurons[299999].fn: field given twice");
}

// ---------------------------------------------------------------- errors: values and structure

TEST(GenomeJsonErrors, BadValues) {
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, -2, 1]}])")),
            "t.json: nodes[0].size: each dimension must be > 0, got [1.0, -2.0, 1.0]");
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, 1, 1], "density": 0}])")),
            "t.json: nodes[0].density: must be > 0, got 0.0");
  EXPECT_EQ(err(edit(kSims, R"("limits": [[-1, 1]])", R"("limits": [[1.2, -0.3]])")),
            "t.json: nodes[1].joint.limits[0]: lower limit above upper limit, got [1.2, -0.3]");
  EXPECT_EQ(err(edit(kSims, R"("limits": [[-1, 1]])", R"("limits": [[-4, 1]])")),
            "t.json: nodes[1].joint.limits[0]: angular limits must lie within [-pi, pi], got "
            "[-4.0, 1.0]");
  EXPECT_EQ(
      err(edit(kSims, R"("limits": [[-1, 1]])", R"("limits": [[-1, 1], [-1, 1]])")),
      "t.json: nodes[1].joint.limits: a hinge joint needs 1 limits (one per degree of freedom) or "
      "none, got [[-1.0, 1.0], [-1.0, 1.0]]");
  EXPECT_EQ(err(edit(kSims, R"("axis1": [0, 0, 1])", R"("axis1": [0, 0, 0])")),
            "t.json: nodes[1].joint.axis1: axis must be non-zero, got [0, 0, 0]");
  EXPECT_EQ(err(edit(kSims, R"("face": "+x")", R"("face": "+x", "at": [0, 1.5])")),
            "t.json: nodes[0].edges[0].at: must lie in [-1, 1] x [-1, 1], got [0.0, 1.5]");
  EXPECT_EQ(err(edit(kSims, R"("face": "+x")", R"("face": "+x", "scale": -1)")),
            "t.json: nodes[0].edges[0].scale: must be > 0, got -1.0");
  EXPECT_EQ(err(edit(kSims, R"("face": "+x")", R"("face": "+x", "reflect": ["y", "y"])")),
            "t.json: nodes[0].edges[0].reflect: repeated axis, got [\"y\", \"y\"]");
  EXPECT_EQ(err(edit(kSims, R"("effectors": [{"dof": 0,)", R"("effectors": [{"dof": 1,)")),
            "t.json: nodes[1].effectors[0].dof: no such degree of freedom of a hinge joint (it has "
            "1), got 1");
}

TEST(GenomeJsonErrors, EdgeTargetOutOfRange) {
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, 1, 1], "edges": [{"to": 3}]}])")),
            "t.json: nodes[0].edges[0].to: no such node (the genome has 1), got 3");
}

TEST(GenomeJsonErrors, BadSourceIndex) {
  EXPECT_EQ(
      err(edit(kSims, R"({"from": "self", "sensor": 0})", R"({"from": "self", "sensor": 1})")),
      "t.json: nodes[0].neurons[0].inputs[0].sensor: no such sensor in this node (it has 1), got "
      "1");
  EXPECT_EQ(err(edit(kSims, R"("edge": 0, "neuron": 0)", R"("edge": 0, "neuron": 1)")),
            "t.json: nodes[0].neurons[0].inputs[1].neuron: no such neuron in the child node 1 (it "
            "has 1), got 1");
  EXPECT_EQ(
      err(edit(kSims, R"("edge": 0, "neuron": 0)", R"("edge": 1, "neuron": 0)")),
      "t.json: nodes[0].neurons[0].inputs[1].edge: no such edge in this node (it has 1), got 1");
  EXPECT_EQ(
      err(edit(kSims, R"({"from": "self", "sensor": 0})", R"({"from": "global", "neuron": 0})")),
      "t.json: nodes[0].neurons[0].inputs[0].neuron: no such global neuron (there are 0), got 0");
}

TEST(GenomeJsonErrors, GlobalNeuronSources) {
  std::string text = edit(
      kSims, R"("version": 1,)",
      R"("version": 1, "global_neurons": [{"fn": "abs", "inputs": [{"from": "self", "neuron": 0}]}],)");
  EXPECT_EQ(
      err(text),
      "t.json: global_neurons[0].inputs[0].from: global neurons read only root and global sources, "
      "got \"self\"");
  text = edit(
      kSims, R"("version": 1,)",
      R"("version": 1, "global_neurons": [{"fn": "abs", "inputs": [{"from": "global", "sensor": 0}]}],)");
  EXPECT_EQ(err(text),
            "t.json: global_neurons[0].inputs[0].sensor: global sources read neurons only, got 0");
}

TEST(GenomeJsonErrors, UnknownFunction) {
  EXPECT_EQ(
      err(edit(kMiconi, R"("fn": "tanh")", R"("fn": "sum")")),
      "t.json: nodes[0].neurons[0].fn: unknown function for dialect miconi2006 (expected one of "
      "sigmoid, tanh), got \"sum\"");
}

TEST(GenomeJsonErrors, BadParamName) {
  EXPECT_EQ(err(edit(kChaumont, R"({"T": 0.5})", R"({"t": 0.5})")),
            "t.json: nodes[0].neurons[0].params.t: unknown parameter of sumT (expected one of T), "
            "got 0.5");
  EXPECT_EQ(err(edit(kMiconi, R"("fn": "tanh",)", R"("fn": "tanh", "params": {"T": 1},)")),
            "t.json: nodes[0].neurons[0].params.T: unknown parameter of tanh (it has none), got 1");
}

TEST(GenomeJsonErrors, ParamOutOfRange) {
  const NeuronFnSpec* spec = find_neuron_fn(NeuronSetId::Chaumont2007, "sumT");
  ASSERT_NE(spec, nullptr);
  ASSERT_EQ(spec->params.size(), 1u);
  const ParamSpec& t = spec->params[0];
  ASSERT_TRUE(std::isfinite(t.max));
  double bad = t.max + 1;
  EXPECT_EQ(err(edit(kChaumont, R"({"T": 0.5})", "{\"T\": " + num(bad) + "}")),
            "t.json: nodes[0].neurons[0].params.T: out of range [" + num(t.min) + ", " +
                num(t.max) + "] for sumT, got " + num(bad));
}

TEST(GenomeJsonErrors, TooManyInputs) {
  const NeuronFnSpec* abs = find_neuron_fn(NeuronSetId::Sims1994, "abs");
  ASSERT_NE(abs, nullptr);
  std::string inputs;
  for (int i = 0; i <= abs->max_inputs; ++i)
    inputs += std::string(i ? ", " : "") + R"({"from": "self", "sensor": 0})";
  EXPECT_EQ(
      err(sims_nodes(
          R"([{"size": [1, 1, 1], "sensors": [{"type": "contact"}], "neurons": [{"fn": "abs", "inputs": [)" +
          inputs + "]}]}]")),
      "t.json: nodes[0].neurons[0].inputs: too many inputs for abs (at most " +
          std::to_string(abs->max_inputs) + "), got " + std::to_string(abs->max_inputs + 1));
  // miconi2006: three connections per neuron
  EXPECT_EQ(err(edit(kMiconi, R"({"from": "root", "neuron": 0}]})",
                     R"({"from": "root", "neuron": 0}, {"from": "self", "neuron": 0}]})")),
            "t.json: nodes[1].neurons[0].inputs: too many inputs for sigmoid (at most 3), got 4");
}

TEST(GenomeJsonErrors, PositionalBias) {
  EXPECT_EQ(
      err(edit(kChaumont, R"("fn": "sumT",)", R"("fn": "sumT", "bias": 0.5,)")),
      "t.json: nodes[0].neurons[0].bias: function sumT takes no bias (it must be 0), got 0.5");
}

TEST(GenomeJsonErrors, UnreachableNode) {
  EXPECT_EQ(err(sims_nodes(R"([{"size": [1, 1, 1], "edges": [{"to": 1}]}, {"size": [1, 1, 1]}, )"
                           R"({"size": [1, 1, 1], "edges": [{"to": 2}]}])")),
            "t.json: nodes[2]: not reachable from the root");
  EXPECT_EQ(err(sims_nodes("[]")), "t.json: nodes: a genome needs at least one node, got []");
}

// ---------------------------------------------------------------- errors: dialects

TEST(GenomeJsonErrors, MiconiTooManyGenes) {
  std::string nodes = R"({"size": [1, 1, 1], "edges": [)";
  for (int i = 1; i < 8; ++i)
    nodes += std::string(i > 1 ? ", " : "") + "{\"to\": " + std::to_string(i) + "}";
  nodes += "]}";
  for (int i = 1; i < 8; ++i) nodes += R"(, {"size": [1, 1, 1]})";
  std::string text =
      R"({"format": "bestiary-genome", "version": 1, "dialect": "miconi2006", "nodes": [)" + nodes +
      "]}";
  EXPECT_EQ(err(text), "t.json: nodes: at most 7 genes in dialect miconi2006, got 8");
}

TEST(GenomeJsonErrors, MiconiNotATree) {
  EXPECT_EQ(err(edit(kMiconi, R"("reflect": ["y"]})", R"("reflect": ["y"]}, {"to": 1})")),
            "t.json: nodes[0].edges[1].to: node 1 already has a parent (nodes[0].edges[0]); a tree "
            "genome in "
            "dialect miconi2006 allows one, got 1");
  EXPECT_EQ(err(edit(kMiconi, R"("sensors": [{"type": "joint_angle", "dof": 0}],)",
                     R"("sensors": [{"type": "joint_angle", "dof": 0}], "edges": [{"to": 1}],)")),
            "t.json: nodes[1].edges[0].to: reflexive edge not allowed in a tree genome in dialect "
            "miconi2006, got 1");
  EXPECT_EQ(err(edit(kMiconi, R"("sensors": [{"type": "joint_angle", "dof": 0}],)",
                     R"("sensors": [{"type": "joint_angle", "dof": 0}], "edges": [{"to": 0}],)")),
            "t.json: nodes[1].edges[0].to: no edge may lead to the root in a tree genome in "
            "dialect miconi2006, "
            "got 0");
}

TEST(GenomeJsonErrors, MiconiJointRules) {
  EXPECT_EQ(
      err(edit(kMiconi, R"("type": "hinge")", R"("type": "universal")")),
      "t.json: nodes[1].joint.type: joint type not allowed in dialect miconi2006 (expected hinge), "
      "got \"universal\"");
  EXPECT_EQ(err(edit(kMiconi, R"("axis1": [0, 1, 0])", R"("axis1": [1, 0, 0])")),
            "t.json: nodes[1].joint.axis1: hinge axis must be the part's y or z axis in dialect "
            "miconi2006, "
            "got [1.0, 0.0, 0.0]");
  EXPECT_EQ(err(edit(kMiconi, R"([[-2.356194490192345, 2.356194490192345]])", "[[-1, 1]]")),
            "t.json: nodes[1].joint.limits: hinge limits are fixed at [[-2.356194490192345, "
            "2.356194490192345]] "
            "in dialect miconi2006 (give exactly these or none), got [[-1.0, 1.0]]");
  EXPECT_EQ(err(edit(kMiconi, R"("size": [2, 0.5, 0.5],)",
                     R"("shape": "sphere", "size": [2, 0.5, 0.5],)")),
            "t.json: nodes[1].shape: shape not allowed in dialect miconi2006 (expected box), got "
            "\"sphere\"");
}

TEST(GenomeJsonErrors, MiconiOrientationRules) {
  EXPECT_EQ(err(edit(kMiconi, "[0, 0.39269908169872414, 0]", "[0, 0.3, 0]")),
            "t.json: nodes[0].edges[0].rotation: each angle must be a multiple of pi/8 in dialect "
            "miconi2006, "
            "got [0.0, 0.3, 0.0]");
  EXPECT_EQ(err(edit(kMiconi, "[0, 0.39269908169872414, 0]", "[0.39269908169872414, 0, 0]")),
            "t.json: nodes[0].edges[0].rotation: roll (x) must be 0 in dialect miconi2006, "
            "got [0.39269908169872414, 0.0, 0.0]");
  EXPECT_EQ(err(edit(kMiconi, R"("reflect": ["y"])", R"("reflect": ["x"])")),
            "t.json: nodes[0].edges[0].reflect: reflection axis not allowed in dialect miconi2006 "
            "(expected y), "
            "got [\"x\"]");
}

TEST(GenomeJsonErrors, MiconiBrainRules) {
  EXPECT_EQ(err(edit(kMiconi, R"("weight": -0.5)", R"("weight": 1.5)")),
            "t.json: nodes[0].neurons[0].inputs[0].weight: out of range [-1.0, 1.0] in dialect "
            "miconi2006, got 1.5");
  EXPECT_EQ(
      err(edit(kMiconi, R"("bias": 0.5)", R"("bias": 1.6)")),
      "t.json: nodes[0].neurons[0].bias: out of range [-1.5, 1.5] in dialect miconi2006, got 1.6");
  EXPECT_EQ(err(edit(kMiconi, R"("bias": -1.5)", R"("bias": -2)")),
            "t.json: nodes[1].effectors[0].bias: out of range [-1.5, 1.5] in dialect miconi2006, "
            "got -2.0");
  EXPECT_EQ(err(edit(kMiconi, R"([{"type": "joint_angle", "dof": 0}])",
                     R"([{"type": "joint_angle", "dof": 0}, {"type": "joint_angle", "dof": 0}])")),
            "t.json: nodes[1].sensors: at most 1 sensor(s) per part in dialect miconi2006, got 2");
  EXPECT_EQ(
      err(edit(kMiconi, R"([{"type": "joint_angle", "dof": 0}])", R"([{"type": "contact"}])")),
      "t.json: nodes[1].sensors[0].type: sensor type not allowed in dialect miconi2006 (expected "
      "joint_angle), got \"contact\"");
  EXPECT_EQ(err(edit(kMiconi, R"("version": 1,)",
                     R"("version": 1, "global_neurons": [{"fn": "tanh"}],)")),
            "t.json: global_neurons: no global neurons in dialect miconi2006, got 1");
  std::string six;
  for (int i = 0; i < 6; ++i) six += R"({"fn": "tanh"}, )";
  EXPECT_EQ(err(edit(kMiconi, R"("neurons": [{"fn": "tanh",)",
                     R"("neurons": [)" + six + R"({"fn": "tanh",)")),
            "t.json: nodes[0].neurons: at most 6 neurons per part in dialect miconi2006, got 7");
}

TEST(GenomeJsonErrors, ChaumontRules) {
  EXPECT_EQ(err(edit(kChaumont, R"("type": "hinge", "axis1": [1, 0, 0])", R"("type": "universal", "axis1": [1, 0, 0])")),
            "t.json: nodes[1].joint.type: joint type not allowed in dialect chaumont2007 (expected "
            "hinge), got \"universal\"");
  EXPECT_EQ(
      err(edit(kChaumont, R"({"type": "contact", "face": "-z"})", R"({"type": "joint_angle"})")),
      "t.json: nodes[0].sensors[0].type: sensor type not allowed in dialect chaumont2007 (expected "
      "contact), got \"joint_angle\"");
}

// ---------------------------------------------------------------- files

std::filesystem::path temp_dir() {
  auto dir = std::filesystem::temp_directory_path() /
             ("bestiary-genome-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(GenomeFile, MissingFile) {
  auto r = load_genome("/nonexistent-bestiary-dir/walker.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(),
            "/nonexistent-bestiary-dir/walker.json: cannot open file (No such file or directory)");
}

TEST(GenomeFile, SaveThenLoad) {
  auto dir = temp_dir();
  std::string path = (dir / "rich.json").string();
  Genome g = rich_genome();
  ASSERT_TRUE(save_genome(path, g).ok());
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  auto back = load_genome(path);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(*back, g);
  // overwrite in place
  Genome small = *genome_from_string(kMiconi, "t.json");
  ASSERT_TRUE(save_genome(path, small).ok());
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  back = load_genome(path);
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(*back, small);
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, genome_to_string(small));
  std::filesystem::remove_all(dir);
}

TEST(GenomeFile, ErrorsNameThePath) {
  auto dir = temp_dir();
  std::string path = (dir / "bad.json").string();
  {
    std::ofstream out(path);
    out << edit(kSims, R"("version": 1)", R"("version": 7)");
  }
  auto r = load_genome(path);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error(), path + ": version: unsupported version 7 (this build reads 1), got 7");
  EXPECT_FALSE(save_genome((dir / "no-such-dir" / "x.json").string(), rich_genome()).ok());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace bx
