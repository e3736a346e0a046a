// Reference-keeping edits (genome_edit.h): after a removal every source and
// edge still points at the same logical neuron, sensor, edge or node.
#include "genome/genome_edit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "genome/dialect.h"
#include "genome/genome_json.h"

namespace bx {
namespace {

::testing::AssertionResult valid(const Genome& g) {
  Status s = validate(g);
  if (s.ok()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << s.error() << "\n" << genome_to_string(g);
}

// A sims1994 genome whose neurons and sensors carry markers: neuron k of node
// n is sum-threshold with T = -1.5 + 0.25 n + 0.05 k; node sizes (x) mark
// nodes. Node 0 -> 1 -> 2, 0 -> 3, and 2 -> 2 (recursion).
// Sensors: node n has contact sensors on faces +x, -x, +y (markers: face).
Genome marked_genome() {
  Genome g;
  g.dialect = Dialect::Sims1994;
  g.nodes.resize(4);
  for (int n = 0; n < 4; ++n) {
    g.nodes[n].size = {0.1 + 0.1 * n, 0.2, 0.2};
    for (int k = 0; k < 4; ++k)
      g.nodes[n].neurons.push_back({"sum-threshold", {-1.5 + 0.25 * n + 0.05 * k}, 0, {}});
    for (Face f : {Face::PosX, Face::NegX, Face::PosY})
      g.nodes[n].sensors.push_back({SensorType::Contact, 0, f});
  }
  auto edge = [](int to, Face f) {
    EdgeGene e;
    e.to = to;
    e.face = f;
    return e;
  };
  g.nodes[0].edges = {edge(1, Face::PosX), edge(3, Face::NegX)};
  g.nodes[1].edges = {edge(2, Face::PosX)};
  g.nodes[2].edges = {edge(2, Face::PosY)};
  g.nodes[2].recursive_limit = 2;
  using P = SourcePlace;
  using K = SourceKind;
  // inputs reading every place; weights number the inputs
  auto in = [](P p, K k, int index, int edge, double w) { return InputGene{p, k, index, edge, w}; };
  g.nodes[0].neurons[0].inputs = {in(P::Self, K::Neuron, 3, 0, 1),
                                  in(P::Child, K::Neuron, 2, 0, 2)};
  g.nodes[0].neurons[1].inputs = {in(P::Child, K::Neuron, 3, 1, 3),
                                  in(P::Child, K::Sensor, 2, 1, 4)};
  g.nodes[1].neurons[0].inputs = {in(P::Parent, K::Neuron, 1, 0, 5),
                                  in(P::Root, K::Neuron, 3, 0, 6)};
  g.nodes[1].neurons[2].inputs = {in(P::Child, K::Neuron, 1, 0, 7),
                                  in(P::Self, K::Sensor, 1, 0, 8)};
  g.nodes[2].neurons[0].inputs = {in(P::Parent, K::Neuron, 2, 0, 9),
                                  in(P::Child, K::Neuron, 3, 0, 10)};
  g.nodes[3].neurons[3].inputs = {in(P::Parent, K::Sensor, 2, 0, 11),
                                  in(P::Root, K::Neuron, 1, 0, 12)};
  g.nodes[3].effectors.push_back(
      {0, 0, {in(P::Root, K::Neuron, 2, 0, 13), in(P::Self, K::Neuron, 0, 0, 14)}});
  g.global_neurons.push_back(
      {"sum", {}, 0, {in(P::Root, K::Neuron, 1, 0, 15), in(P::Root, K::Sensor, 0, 0, 16)}});
  return g;
}

// What an input reads, as markers: the node (by size), the neuron (by its
// parameter) or the sensor (by its face). Parent sources name every parent's
// element; the first is enough here.
struct Target {
  double node = 0;
  std::optional<double> neuron;
  std::optional<Face> sensor;
  friend bool operator==(const Target&, const Target&) = default;
};

std::optional<int> node_read(const Genome& g, int owner, const InputGene& in) {
  switch (in.place) {
    case SourcePlace::Self:
      return owner;
    case SourcePlace::Parent: {
      auto ps = parents_of(g, owner);
      // the tree parent (not the node's own recursion)
      for (int p : ps)
        if (p != owner) return p;
      if (!ps.empty()) return ps[0];
      return std::nullopt;
    }
    case SourcePlace::Child:
      return g.nodes[owner].edges[in.edge].to;
    case SourcePlace::Root:
      return 0;
    case SourcePlace::Global:
      return std::nullopt;
  }
  return std::nullopt;
}

Target target(const Genome& g, int owner, const InputGene& in) {
  Target t;
  auto n = node_read(g, owner, in);
  if (!n) return t;
  const NodeGene& node = g.nodes[*n];
  t.node = node.size.x;
  if (in.kind == SourceKind::Neuron)
    t.neuron = node.neurons[in.index].params[0];
  else
    t.sensor = node.sensors[in.index].face;
  return t;
}

// input weight -> what it reads, over the whole genome
std::map<double, Target> targets(const Genome& g) {
  std::map<double, Target> out;
  auto add = [&](int owner, const std::vector<InputGene>& ins) {
    for (const InputGene& in : ins)
      out[in.weight] = owner >= 0 || in.place == SourcePlace::Root
                           ? target(g, std::max(owner, 0), in)
                           : Target{};
  };
  for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i) {
    for (const auto& nr : g.nodes[i].neurons) add(i, nr.inputs);
    for (const auto& ef : g.nodes[i].effectors) add(i, ef.inputs);
  }
  for (const auto& nr : g.global_neurons) add(-1, nr.inputs);
  return out;
}

TEST(GenomeEdit, MarkedGenomeIsValid) { EXPECT_TRUE(valid(marked_genome())); }

TEST(GenomeEdit, Queries) {
  Genome g = marked_genome();
  EXPECT_EQ(parents_of(g, 0), std::vector<int>{});
  EXPECT_EQ(parents_of(g, 2), (std::vector<int>{1, 2}));
  EXPECT_EQ(subtree(g, 0), (std::vector<int>{0, 1, 3, 2}));  // breadth-first
  EXPECT_EQ(subtree(g, 1), (std::vector<int>{1, 2}));
  EXPECT_EQ(reachable_count(g), 4);
  EXPECT_EQ(reachable_count(g, 1), 2);         // without node 1: 0 and 3
  EXPECT_EQ(reachable_count(g, -1, 0, 0), 2);  // without the edge 0 -> 1
  EXPECT_EQ(reachable_count(g, -1, 2, 0), 4);  // the recursion reaches nothing new
  auto r = reachable_from_root(g);
  EXPECT_EQ(r, (std::vector<bool>{true, true, true, true}));
}

TEST(GenomeEdit, CountParts) {
  Genome g = marked_genome();
  // 0, 1, 2, 2 (recursion limit 2), 3
  EXPECT_EQ(count_parts(g, 100), 5);
  g.nodes[0].edges[0].reflect = {1};  // 1 -> 2 -> 2 twice
  EXPECT_EQ(count_parts(g, 100), 8);
  g.nodes[0].edges[0].reflect = {1, 2};
  EXPECT_EQ(count_parts(g, 100), 14);
  EXPECT_EQ(count_parts(g, 6), 7);           // counting stops above the cap
  g.nodes[2].edges[0].terminal_only = true;  // the recursion itself never reaches its limit
  g.nodes[0].edges[0].reflect.clear();
  EXPECT_EQ(count_parts(g, 100), 4);
}

TEST(GenomeEdit, RemoveNeuronKeepsReferences) {
  for (int node = 0; node < 4; ++node)
    for (int k = 0; k < 4; ++k) {
      Genome g = marked_genome();
      auto before = targets(g);
      double gone = g.nodes[node].neurons[k].params[0];
      // the removed neuron's own inputs go with it
      for (const InputGene& in : g.nodes[node].neurons[k].inputs) before.erase(in.weight);
      remove_neuron(g, node, k);
      ASSERT_TRUE(valid(g)) << node << " " << k;
      EXPECT_EQ(g.nodes[node].neurons.size(), 3u);
      auto after = targets(g);
      for (const auto& [w, t] : before) {
        // node 2's parent source (weight 9) reads node 1 or, through the
        // recursion, node 2: renumbered for node 2's sake (genome_edit.h)
        if (w == 9 && (node == 1 || node == 2)) continue;
        if (t.neuron && *t.neuron == gone && t.node == 0.1 + 0.1 * node) {
          EXPECT_EQ(after.count(w), 0u) << "input " << w << " read the removed neuron";
        } else {
          ASSERT_EQ(after.count(w), 1u) << "input " << w << " was lost";
          EXPECT_EQ(after[w], t) << "input " << w << " reads another neuron";
        }
      }
    }
}

TEST(GenomeEdit, RemoveNeuronReassignOrClamp) {
  Genome g = marked_genome();
  Rng rng(3);
  remove_neuron(g, 0, 3, SourceFix::Reassign, &rng);
  ASSERT_TRUE(valid(g));
  EXPECT_EQ(targets(g).size(), targets(marked_genome()).size());  // nothing lost
  Genome h = marked_genome();
  remove_neuron(h, 0, 3, SourceFix::Clamp, &rng);
  ASSERT_TRUE(valid(h));
  // self neuron 3 (weight 1) read the removed neuron: reassigned, not lost
  EXPECT_EQ(targets(h).size(), targets(marked_genome()).size());
  EXPECT_EQ(h.nodes[0].neurons[0].inputs[0].weight, 1);
}

TEST(GenomeEdit, RemoveSensorKeepsReferences) {
  for (int node = 0; node < 4; ++node)
    for (int k = 0; k < 3; ++k) {
      Genome g = marked_genome();
      auto before = targets(g);
      Face gone = g.nodes[node].sensors[k].face;
      remove_sensor(g, node, k);
      ASSERT_TRUE(valid(g));
      auto after = targets(g);
      for (const auto& [w, t] : before) {
        if (t.sensor && *t.sensor == gone && t.node == 0.1 + 0.1 * node)
          EXPECT_EQ(after.count(w), 0u);
        else
          EXPECT_EQ(after[w], t) << "input " << w;
      }
    }
}

TEST(GenomeEdit, RemoveGlobalNeuron) {
  Genome g = marked_genome();
  g.global_neurons.push_back({"abs", {}, 0, {}});
  g.nodes[1].neurons[1].inputs = {{SourcePlace::Global, SourceKind::Neuron, 1, 0, 30},
                                  {SourcePlace::Global, SourceKind::Neuron, 0, 0, 31}};
  ASSERT_TRUE(valid(g));
  remove_global_neuron(g, 0);
  ASSERT_TRUE(valid(g));
  EXPECT_EQ(g.nodes[1].neurons[1].inputs,
            (std::vector<InputGene>{{SourcePlace::Global, SourceKind::Neuron, 0, 0, 30}}));
}

TEST(GenomeEdit, RemoveEdgeRenumbersChildSources) {
  Genome g = marked_genome();
  auto before = targets(g);
  remove_edge(g, 0, 0);  // 0 -> 1; node 1 and 2 now unreachable
  // child sources of node 0 on edge 1 (node 3) now say edge 0
  EXPECT_EQ(g.nodes[0].neurons[1].inputs[0].edge, 0);
  EXPECT_EQ(g.nodes[0].neurons[0].inputs.size(), 1u);  // the one on the removed edge went
  auto after = targets(g);
  EXPECT_EQ(after[3.0], before[3.0]);
  EXPECT_EQ(after[4.0], before[4.0]);
  EXPECT_EQ(remove_unreachable(g), 2);
  ASSERT_TRUE(valid(g));
  EXPECT_EQ(g.nodes.size(), 2u);
  EXPECT_DOUBLE_EQ(g.nodes[1].size.x, 0.4);  // node 3 is now node 1
  EXPECT_EQ(g.nodes[0].edges[0].to, 1);
  EXPECT_EQ(targets(g)[11.0], before[11.0]);  // its parent source still reads the root's sensor
}

TEST(GenomeEdit, RemoveNodeRenumbersEdges) {
  Genome g = marked_genome();
  auto before = targets(g);
  remove_node(g, 1);  // node 2 unreachable (only 1 and itself lead to it)
  EXPECT_EQ(g.nodes.size(), 3u);
  EXPECT_EQ(g.nodes[0].edges.size(), 1u);
  EXPECT_DOUBLE_EQ(g.nodes[g.nodes[0].edges[0].to].size.x, 0.4);  // still node "3"
  EXPECT_EQ(g.nodes[1].edges[0].to, 1);  // "2" is now 1, and its recursion follows it
  remove_unreachable(g);
  ASSERT_TRUE(valid(g));
  EXPECT_EQ(g.nodes.size(), 2u);
  auto after = targets(g);
  for (double w : {1.0, 3.0, 4.0, 11.0, 12.0, 13.0, 14.0, 15.0, 16.0})
    EXPECT_EQ(after[w], before[w]) << w;
}

TEST(GenomeEdit, MoveEdge) {
  Genome g = marked_genome();
  Rng rng(5);
  // move the branch at 1 (edge 0 of the root) under node 3
  move_edge(g, 0, 0, 3, SourceFix::Clamp, &rng);
  ASSERT_TRUE(valid(g));
  EXPECT_EQ(parents_of(g, 1), std::vector<int>{3});
  // node 1's parent source (neuron 1) now reads node 3's neuron 1
  EXPECT_EQ(g.nodes[1].neurons[0].inputs[0].place, SourcePlace::Parent);
  EXPECT_DOUBLE_EQ(target(g, 1, g.nodes[1].neurons[0].inputs[0]).node, 0.4);
  EXPECT_EQ(g.nodes[0].neurons[1].inputs[0].edge, 0);  // root's edge to 3 moved up
}

TEST(GenomeEdit, SourceCandidates) {
  Genome g = marked_genome();
  auto has = [](const std::vector<InputGene>& c, SourcePlace p, SourceKind k, int index, int edge) {
    for (const InputGene& in : c)
      if (in.place == p && in.kind == k && in.index == index && in.edge == edge) return true;
    return false;
  };
  auto c = source_candidates(g, 2);
  EXPECT_TRUE(has(c, SourcePlace::Self, SourceKind::Neuron, 3, 0));
  EXPECT_TRUE(has(c, SourcePlace::Parent, SourceKind::Sensor, 2, 0));
  EXPECT_TRUE(has(c, SourcePlace::Child, SourceKind::Neuron, 0, 0));
  EXPECT_TRUE(has(c, SourcePlace::Root, SourceKind::Neuron, 0, 0));
  EXPECT_TRUE(has(c, SourcePlace::Global, SourceKind::Neuron, 0, 0));
  EXPECT_EQ(c.size(), 4u * 7u + 1);  // self, parents, the child through the recursion, root, global
  // the root's only parent is none; a child of the root does not list "root" (it is its parent)
  auto c1 = source_candidates(g, 1);
  for (const InputGene& in : c1) EXPECT_NE(in.place, SourcePlace::Root);
  // global neurons read only the root and global neurons
  for (const InputGene& in : source_candidates(g, -1))
    EXPECT_TRUE(in.place == SourcePlace::Root || in.place == SourcePlace::Global);
  for (const InputGene& in : c) EXPECT_TRUE(source_exists(g, 2, in));
}

TEST(GenomeEdit, RepairSources) {
  Genome g = marked_genome();
  g.nodes[1].neurons[3] = {"if", {}, 0, {}};  // three arguments
  g.nodes[1].neurons[3].inputs = {{SourcePlace::Self, SourceKind::Neuron, 9, 0, 40},
                                  {SourcePlace::Child, SourceKind::Neuron, 0, 5, 41},
                                  {SourcePlace::Root, SourceKind::Sensor, 1, 3, 42}};
  Genome removed = g, clamped = g, reassigned = g;
  EXPECT_EQ(repair_sources(removed, SourceFix::Remove, nullptr), 2);
  EXPECT_EQ(
      removed.nodes[1].neurons[3].inputs,
      (std::vector<InputGene>{{SourcePlace::Root, SourceKind::Sensor, 1, 0, 42}}));  // edge reset
  Rng rng(7);
  repair_sources(clamped, SourceFix::Clamp, &rng);
  EXPECT_EQ(clamped.nodes[1].neurons[3].inputs[0],
            (InputGene{SourcePlace::Self, SourceKind::Neuron, 3, 0, 40}));
  repair_sources(reassigned, SourceFix::Reassign, &rng);
  EXPECT_EQ(reassigned.nodes[1].neurons[3].inputs.size(), 3u);
  for (Genome* x : {&removed, &clamped, &reassigned}) EXPECT_TRUE(valid(*x));
}

TEST(GenomeEdit, AppendAndSpliceSubgraph) {
  Genome g = marked_genome();
  Genome src = marked_genome();
  for (NodeGene& n : src.nodes) n.size.y = 0.3;  // mark the copies
  // copy of src's subgraph at 1 (nodes 1, 2) cut to one node: the recursion
  // edge to 2 is dropped with the child source on it
  int c = append_subgraph(g, src, 1, 1);
  EXPECT_EQ(c, 4);
  EXPECT_EQ(g.nodes.size(), 5u);
  EXPECT_TRUE(g.nodes[4].edges.empty());
  EXPECT_EQ(g.nodes[4].neurons[2].inputs[0].edge, -1);
  // splice: the root's edge to 3 now leads to a copy of src's 1 -> 2 -> 2
  Genome h = marked_genome();
  Rng rng(9);
  int root = splice_subgraph(h, 0, 1, src, 1, 10, SourceFix::Clamp, &rng);
  ASSERT_TRUE(valid(h));
  EXPECT_EQ(h.nodes.size(), 5u);  // 0, 1, 2, and copies of 1, 2 (3 dropped)
  EXPECT_EQ(h.nodes[root].size.y, 0.3);
  EXPECT_EQ(h.nodes[0].edges[1].to, root);
  EXPECT_EQ(h.nodes[h.nodes[root].edges[0].to].size.y, 0.3);
  // the root's sources on edge 1 read the new child at the same index
  EXPECT_EQ(h.nodes[0].neurons[1].inputs[0],
            (InputGene{SourcePlace::Child, SourceKind::Neuron, 3, 1, 3}));
  EXPECT_EQ(target(h, 0, h.nodes[0].neurons[1].inputs[0]).node, 0.2);
}

TEST(GenomeEdit, PlaceEdgeAlongADirection) {
  Vec3 P{0.6, 0.3, 0.2};
  for (Vec3 d : {Vec3{1, 0, 0}, Vec3{0.2, 1, 0.1}, Vec3{-0.3, -0.2, -1}, Vec3{1, 1, 0.5}}) {
    d = normalized(d);
    EdgeGene e;
    place_edge(e, P, d, 0.3, 0);
    Vec3 got = edge_direction(e);
    EXPECT_NEAR(dot(got, d), 1.0, 1e-12);
    EXPECT_NEAR(e.rotation.x, 0.3, 1e-15);
    // the face the ray leaves through, at the point it leaves
    int a = face_axis(e.face);
    double t = P[a] / 2 / std::abs(d[a]);
    for (int i = 0; i < 3; ++i) EXPECT_LE(std::abs(t * d[i]), P[i] / 2 + 1e-12);
    EXPECT_GT(d[a] * face_sign(e.face), 0);
    EdgeGene f = e;
    reseat_edge(f, P, 0);
    EXPECT_EQ(f, e);  // already fitted: unchanged
  }
  // on the pi/8 lattice: angles are exact multiples, reseating changes nothing
  EdgeGene e;
  place_edge(e, P, normalized(Vec3{0.9, 0.35, -0.2}), 0, kPi / 8);
  for (int a = 1; a < 3; ++a)
    EXPECT_EQ(e.rotation[a], std::round(e.rotation[a] / (kPi / 8)) * (kPi / 8));
  EdgeGene f = e;
  reseat_edge(f, P, kPi / 8);
  EXPECT_EQ(f, e);
  // a longer parent: same face and angles, the point moves along the ray
  reseat_edge(f, {1.2, 0.3, 0.2}, kPi / 8);
  EXPECT_EQ(f.face, e.face);
  EXPECT_EQ(f.rotation, e.rotation);
}

}  // namespace
}  // namespace bx
