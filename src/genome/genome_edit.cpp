// Reference-keeping edits of a genome (genome_edit.h).
#include "genome/genome_edit.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "genome/dialect.h"

namespace bx {

namespace {

int n_nodes(const Genome& g) { return static_cast<int>(g.nodes.size()); }

// how many neurons, sensors or muscles (muscle dialects' effectors) node n has
int count_of(const Genome& g, int n, SourceKind kind) {
  const NodeGene& node = g.nodes[n];
  switch (kind) {
    case SourceKind::Neuron: return static_cast<int>(node.neurons.size());
    case SourceKind::Sensor: return static_cast<int>(node.sensors.size());
    case SourceKind::Muscle:
      return dialect_rules(g.dialect).muscle_effectors ? static_cast<int>(node.effectors.size()) : 0;
  }
  return 0;
}

// whether node p has an edge to node c
bool has_edge(const Genome& g, int p, int c) {
  for (const EdgeGene& e : g.nodes[p].edges)
    if (e.to == c) return true;
  return false;
}

// Calls f(owner, inputs) for the inputs of every neuron and effector
// (owner: node index), of every global neuron (owner -1) and of a
// catapult's release (read as from the arm, node 0).
template <class G, class F>
void for_each_inputs(G& g, F f) {
  for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i) {
    for (auto& nr : g.nodes[i].neurons) f(i, nr.inputs);
    for (auto& ef : g.nodes[i].effectors) f(i, ef.inputs);
  }
  for (auto& nr : g.global_neurons) f(-1, nr.inputs);
  if (g.catapult && !g.nodes.empty()) f(0, g.catapult->release.inputs);
}

// whether input `in` of `owner` reads node `node` (global sources read no node)
bool reads_node(const Genome& g, int owner, const InputGene& in, int node) {
  switch (in.place) {
    case SourcePlace::Self:
      return owner == node;
    case SourcePlace::Parent:
      return owner >= 0 && has_edge(g, node, owner);
    case SourcePlace::Child: {
      if (owner < 0) return false;
      const auto& edges = g.nodes[owner].edges;
      return in.edge >= 0 && in.edge < static_cast<int>(edges.size()) && edges[in.edge].to == node;
    }
    case SourcePlace::Root:
      return node == 0;
    case SourcePlace::Global:
      return false;
  }
  return false;
}

// After removing element k of a list, an index that pointed at k becomes -1
// (to be fixed) and one past it moves down.
void shift_index(int& index, int k) {
  if (index == k)
    index = -1;
  else if (index > k)
    --index;
}

// Marks child sources on edge k (edge -1) and renumbers those on later edges.
void shift_child_sources(std::vector<InputGene>& inputs, int k) {
  for (InputGene& in : inputs)
    if (in.place == SourcePlace::Child) shift_index(in.edge, k);
}

// Within one node: drops edge k, marking child sources on it (edge -1) and
// renumbering those on later edges. Sources are not repaired.
void drop_edge_in_node(NodeGene& node, int k) {
  for (auto& nr : node.neurons) shift_child_sources(nr.inputs, k);
  for (auto& ef : node.effectors) shift_child_sources(ef.inputs, k);
  node.edges.erase(node.edges.begin() + k);
}

// Drops edge k of node n of g, as drop_edge_in_node; a catapult's release
// reads as from node 0, so its child sources follow the root's edges.
void drop_edge(Genome& g, int n, int k) {
  if (n == 0 && g.catapult) shift_child_sources(g.catapult->release.inputs, k);
  drop_edge_in_node(g.nodes[n], k);
}

// Removes the flagged nodes (never the root) without repairing sources;
// returns old index -> new index (-1 for removed nodes).
std::vector<int> remove_flagged(Genome& g, const std::vector<bool>& gone) {
  int n = n_nodes(g);
  assert(!gone[0]);
  for (int i = 0; i < n; ++i) {
    if (gone[i]) continue;
    auto& edges = g.nodes[i].edges;
    for (int k = static_cast<int>(edges.size()) - 1; k >= 0; --k)
      if (gone[edges[k].to]) drop_edge(g, i, k);
  }
  std::vector<int> map(n, -1);
  std::vector<NodeGene> kept;
  for (int i = 0; i < n; ++i)
    if (!gone[i]) {
      map[i] = static_cast<int>(kept.size());
      kept.push_back(std::move(g.nodes[i]));
    }
  for (NodeGene& node : kept)
    for (EdgeGene& e : node.edges) e.to = map[e.to];
  g.nodes = std::move(kept);
  return map;
}

// Tries to fix an input in place (Clamp, Reassign); false: remove it.
bool fix_input(const Genome& g, int owner, InputGene& in, SourceFix fix, Rng* rng) {
  if (fix == SourceFix::Remove) return false;
  if (fix == SourceFix::Clamp) {
    // how many elements of this kind the place has (every parent, for parent sources)
    int count = 0;
    switch (in.place) {
      case SourcePlace::Self:
        count = owner >= 0 ? count_of(g, owner, in.kind) : 0;
        break;
      case SourcePlace::Parent: {
        if (owner < 0) break;
        auto ps = parents_of(g, owner);
        if (ps.empty()) break;
        count = std::numeric_limits<int>::max();
        for (int p : ps) count = std::min(count, count_of(g, p, in.kind));
        break;
      }
      case SourcePlace::Child: {
        if (owner < 0) break;
        const auto& edges = g.nodes[owner].edges;
        if (in.edge >= 0 && in.edge < static_cast<int>(edges.size()))
          count = count_of(g, edges[in.edge].to, in.kind);
        break;
      }
      case SourcePlace::Root:
        count = count_of(g, 0, in.kind);
        break;
      case SourcePlace::Global:
        count = in.kind == SourceKind::Neuron ? static_cast<int>(g.global_neurons.size()) : 0;
        break;
    }
    // a removed element (index -1) has no nearest index: reassigned below
    if (count > 0 && in.index >= 0) {
      InputGene c = in;
      c.index = std::min(in.index, count - 1);
      if (source_exists(g, owner, c)) {
        in = c;
        return true;
      }
    }
  }
  if (!rng) return false;
  std::vector<InputGene> cands = source_candidates(g, owner);
  if (cands.empty()) return false;
  double w = in.weight;
  in = cands[rng->below(cands.size())];
  in.weight = w;
  return true;
}

}  // namespace

// ---------------------------------------------------------------- queries

std::vector<int> parents_of(const Genome& g, int n) {
  std::vector<int> ps;
  for (int i = 0; i < n_nodes(g); ++i)
    if (has_edge(g, i, n)) ps.push_back(i);
  return ps;
}

std::vector<int> subtree(const Genome& g, int from) {
  std::vector<int> order{from};
  std::vector<bool> seen(g.nodes.size(), false);
  seen[from] = true;
  for (std::size_t h = 0; h < order.size(); ++h)
    for (const EdgeGene& e : g.nodes[order[h]].edges)
      if (e.to >= 0 && e.to < n_nodes(g) && !seen[e.to]) {
        seen[e.to] = true;
        order.push_back(e.to);
      }
  return order;
}

std::vector<bool> reachable_from_root(const Genome& g) {
  std::vector<bool> r(g.nodes.size(), false);
  if (g.nodes.empty()) return r;
  for (int i : subtree(g, 0)) r[i] = true;
  return r;
}

int reachable_count(const Genome& g, int skip_node, int skip_edge_node, int skip_edge) {
  if (g.nodes.empty() || skip_node == 0) return 0;
  std::vector<bool> seen(g.nodes.size(), false);
  std::vector<int> todo{0};
  seen[0] = true;
  int count = 1;
  while (!todo.empty()) {
    int i = todo.back();
    todo.pop_back();
    const auto& edges = g.nodes[i].edges;
    for (int k = 0; k < static_cast<int>(edges.size()); ++k) {
      int to = edges[k].to;
      if ((i == skip_edge_node && k == skip_edge) || to == skip_node || seen[to]) continue;
      seen[to] = true;
      ++count;
      todo.push_back(to);
    }
  }
  return count;
}

int count_parts(const Genome& g, int cap) {
  if (g.nodes.empty()) return 0;
  // depth-first like develop()'s Grower: `path` holds the nodes from the root
  std::vector<int> path{0};
  int count = 1;
  auto occurrences = [&](int n) {
    return static_cast<int>(std::count(path.begin(), path.end(), n));
  };
  auto expand = [&](auto&& self) -> void {
    const NodeGene& node = g.nodes[path.back()];
    bool at_limit = occurrences(path.back()) >= node.recursive_limit;
    for (const EdgeGene& e : node.edges) {
      if (e.terminal_only && !at_limit) continue;
      if (occurrences(e.to) >= g.nodes[e.to].recursive_limit) continue;
      int copies = 1 << e.reflect.size();
      for (int c = 0; c < copies; ++c) {
        if (count > cap) return;
        ++count;
        path.push_back(e.to);
        self(self);
        path.pop_back();
      }
    }
  };
  expand(expand);
  return std::min(count, cap + 1);
}

bool source_exists(const Genome& g, int owner, const InputGene& in) {
  if (in.index < 0) return false;
  if (owner < 0 && in.place != SourcePlace::Root && in.place != SourcePlace::Global) return false;
  switch (in.place) {
    case SourcePlace::Self:
      return in.index < count_of(g, owner, in.kind);
    case SourcePlace::Parent:
      for (int p : parents_of(g, owner))
        if (in.index < count_of(g, p, in.kind)) return true;
      return false;
    case SourcePlace::Child: {
      const auto& edges = g.nodes[owner].edges;
      if (in.edge < 0 || in.edge >= static_cast<int>(edges.size())) return false;
      return in.index < count_of(g, edges[in.edge].to, in.kind);
    }
    case SourcePlace::Root:
      return in.index < count_of(g, 0, in.kind);
    case SourcePlace::Global:
      return dialect_rules(g.dialect).global_neurons && in.kind == SourceKind::Neuron &&
             in.index < static_cast<int>(g.global_neurons.size());
  }
  return false;
}

std::vector<InputGene> source_candidates(const Genome& g, int owner) {
  std::vector<InputGene> out;
  auto add = [&out](SourcePlace place, int neurons, int sensors, int muscles, int edge) {
    for (int k = 0; k < neurons; ++k) out.push_back({place, SourceKind::Neuron, k, edge, 1.0});
    for (int k = 0; k < sensors; ++k) out.push_back({place, SourceKind::Sensor, k, edge, 1.0});
    for (int k = 0; k < muscles; ++k) out.push_back({place, SourceKind::Muscle, k, edge, 1.0});
  };
  auto add_node = [&](SourcePlace place, int n, int edge) {
    add(place, count_of(g, n, SourceKind::Neuron), count_of(g, n, SourceKind::Sensor),
        count_of(g, n, SourceKind::Muscle), edge);
  };
  if (owner >= 0) {
    add_node(SourcePlace::Self, owner, 0);
    std::vector<int> ps = parents_of(g, owner);
    if (!ps.empty()) {
      int nn = std::numeric_limits<int>::max(), ns = nn, nm = nn;
      for (int p : ps) {
        nn = std::min(nn, count_of(g, p, SourceKind::Neuron));
        ns = std::min(ns, count_of(g, p, SourceKind::Sensor));
        nm = std::min(nm, count_of(g, p, SourceKind::Muscle));
      }
      add(SourcePlace::Parent, nn, ns, nm, 0);
    }
    const auto& edges = g.nodes[owner].edges;
    for (int e = 0; e < static_cast<int>(edges.size()); ++e)
      add_node(SourcePlace::Child, edges[e].to, e);
    bool root_only_parent = ps.size() == 1 && ps[0] == 0;
    if (owner != 0 && !root_only_parent) add_node(SourcePlace::Root, 0, 0);
  } else if (!g.nodes.empty()) {
    add_node(SourcePlace::Root, 0, 0);
  }
  if (dialect_rules(g.dialect).global_neurons)
    add(SourcePlace::Global, static_cast<int>(g.global_neurons.size()), 0, 0, 0);
  return out;
}

// ---------------------------------------------------------------- source repair

int repair_sources(Genome& g, SourceFix fix, Rng* rng) {
  int fixed = 0;
  for_each_inputs(g, [&](int owner, std::vector<InputGene>& inputs) {
    for (std::size_t k = 0; k < inputs.size();) {
      InputGene& in = inputs[k];
      if (in.place != SourcePlace::Child) in.edge = 0;
      if (source_exists(g, owner, in)) {
        ++k;
        continue;
      }
      ++fixed;
      if (fix_input(g, owner, in, fix, rng))
        ++k;
      else
        inputs.erase(inputs.begin() + static_cast<std::ptrdiff_t>(k));
    }
  });
  return fixed;
}

// ---------------------------------------------------------------- removals

namespace {

// Removes unit k of a node's `units` (neurons, sensors, or effectors, whose
// muscles' lengths are sources): readers of a later unit of that node are
// renumbered, readers of unit k fixed by `fix`.
template <class Unit>
void remove_read_unit(Genome& g, int node, int k, SourceKind kind, std::vector<Unit> NodeGene::*units,
                      SourceFix fix, Rng* rng) {
  assert(node >= 0 && node < n_nodes(g) && k >= 0 && k < static_cast<int>((g.nodes[node].*units).size()));
  for_each_inputs(g, [&](int owner, std::vector<InputGene>& inputs) {
    for (InputGene& in : inputs)
      if (in.kind == kind && reads_node(g, owner, in, node)) shift_index(in.index, k);
  });
  auto& us = g.nodes[node].*units;
  us.erase(us.begin() + k);
  repair_sources(g, fix, rng);
}

}  // namespace

void remove_neuron(Genome& g, int node, int k, SourceFix fix, Rng* rng) {
  remove_read_unit(g, node, k, SourceKind::Neuron, &NodeGene::neurons, fix, rng);
}

void remove_global_neuron(Genome& g, int k, SourceFix fix, Rng* rng) {
  assert(k >= 0 && k < static_cast<int>(g.global_neurons.size()));
  for_each_inputs(g, [&](int, std::vector<InputGene>& inputs) {
    for (InputGene& in : inputs) {
      if (in.place == SourcePlace::Global) shift_index(in.index, k);
      // a gate follows its switch (one removed leaves its wires ungated;
      // the operators never remove a switch: genome/locks.h)
      if (in.gate != InputGene::kNoGate) {
        shift_index(in.gate, k);
        if (in.gate < 0) in.gate = InputGene::kNoGate;
      }
    }
  });
  g.global_neurons.erase(g.global_neurons.begin() + k);
  repair_sources(g, fix, rng);
}

void remove_sensor(Genome& g, int node, int k, SourceFix fix, Rng* rng) {
  remove_read_unit(g, node, k, SourceKind::Sensor, &NodeGene::sensors, fix, rng);
}

void remove_effector(Genome& g, int node, int k, SourceFix fix, Rng* rng) {
  remove_read_unit(g, node, k, SourceKind::Muscle, &NodeGene::effectors, fix, rng);
}

void remove_edge(Genome& g, int node, int k, SourceFix fix, Rng* rng) {
  assert(node >= 0 && node < n_nodes(g) && k >= 0 &&
         k < static_cast<int>(g.nodes[node].edges.size()));
  drop_edge(g, node, k);
  repair_sources(g, fix, rng);
}

void remove_edges_to(Genome& g, int n, SourceFix fix, Rng* rng) {
  for (int i = 0; i < n_nodes(g); ++i)
    for (int k = static_cast<int>(g.nodes[i].edges.size()) - 1; k >= 0; --k)
      if (g.nodes[i].edges[k].to == n) remove_edge(g, i, k, fix, rng);
}

void move_edge(Genome& g, int from, int k, int to, SourceFix fix, Rng* rng) {
  assert(from >= 0 && from < n_nodes(g) && to >= 0 && to < n_nodes(g) && k >= 0 &&
         k < static_cast<int>(g.nodes[from].edges.size()));
  EdgeGene e = g.nodes[from].edges[k];
  drop_edge(g, from, k);
  g.nodes[to].edges.push_back(e);
  repair_sources(g, fix, rng);
}

void remove_nodes(Genome& g, const std::vector<int>& nodes, SourceFix fix, Rng* rng) {
  std::vector<bool> gone(g.nodes.size(), false);
  for (int n : nodes) {
    assert(n > 0 && n < n_nodes(g));
    gone[n] = true;
  }
  remove_flagged(g, gone);
  repair_sources(g, fix, rng);
}

void remove_node(Genome& g, int n, SourceFix fix, Rng* rng) { remove_nodes(g, {n}, fix, rng); }

int remove_unreachable(Genome& g, SourceFix fix, Rng* rng) {
  std::vector<bool> r = reachable_from_root(g);
  std::vector<bool> gone(r.size());
  int k = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    gone[i] = !r[i];
    k += gone[i];
  }
  if (k == 0) return 0;
  remove_flagged(g, gone);
  repair_sources(g, fix, rng);
  return k;
}

// ---------------------------------------------------------------- subgraphs

int append_subgraph(Genome& dst, const Genome& src_in, int src_root, int max_nodes) {
  // copying a genome into itself: read from a copy
  Genome self_copy;
  if (&dst == &src_in) self_copy = src_in;
  const Genome& s = &dst == &src_in ? self_copy : src_in;
  std::vector<int> order = subtree(s, src_root);
  if (static_cast<int>(order.size()) > std::max(1, max_nodes)) order.resize(std::max(1, max_nodes));
  int base = n_nodes(dst);
  std::vector<int> map(s.nodes.size(), -1);
  for (std::size_t j = 0; j < order.size(); ++j) map[order[j]] = base + static_cast<int>(j);
  for (int i : order) {
    NodeGene node = s.nodes[i];
    for (int k = static_cast<int>(node.edges.size()) - 1; k >= 0; --k) {
      int to = map[node.edges[k].to];
      if (to < 0)
        drop_edge_in_node(node, k);
      else
        node.edges[k].to = to;
    }
    dst.nodes.push_back(std::move(node));
  }
  return base;
}

int splice_subgraph(Genome& dst, int parent, int edge, const Genome& src, int src_root,
                    int max_nodes, SourceFix fix, Rng* rng) {
  int c = append_subgraph(dst, src, src_root, max_nodes);
  dst.nodes[parent].edges[edge].to = c;
  std::vector<bool> r = reachable_from_root(dst);
  std::vector<bool> gone(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) gone[i] = !r[i];
  std::vector<int> map = remove_flagged(dst, gone);
  repair_sources(dst, fix, rng);
  return map[c];
}

// ---------------------------------------------------------------- geometry

Mat3 face_frame(Face f) {
  int a = face_axis(f);
  Vec3 n, t1;
  n[a] = face_sign(f);
  t1[(a + 1) % 3] = 1;
  return Mat3::from_columns(n, t1, cross(n, t1));
}

Vec3 edge_direction(const EdgeGene& e) {
  return face_frame(e.face) * (euler_xyz(e.rotation) * Vec3{1, 0, 0});
}

namespace {

// (u, v) where the ray from the parent's centre along the edge's direction
// meets the plane of its face (clamped to the face); false if the child does
// not point out of its face.
bool set_at_from_direction(EdgeGene& e, Vec3 parent_size) {
  Vec3 d = edge_direction(e);
  int a = face_axis(e.face);
  double out = d[a] * face_sign(e.face);
  if (!(out > 1e-6)) return false;
  Vec3 q = (parent_size[a] / 2 / out) * d;
  int b = (a + 1) % 3, c = (a + 2) % 3;
  if (b > c) std::swap(b, c);
  e.u = std::clamp(q[b] / (parent_size[b] / 2), -1.0, 1.0);
  e.v = std::clamp(q[c] / (parent_size[c] / 2), -1.0, 1.0);
  return true;
}

}  // namespace

void place_edge(EdgeGene& e, Vec3 parent_size, Vec3 d, double roll, double step) {
  d = normalized(d);
  // the face through which the ray from the centre leaves the box
  int a = 0;
  double t = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    if (std::abs(d[i]) > 1e-12) {
      double ti = parent_size[i] / 2 / std::abs(d[i]);
      if (ti < t) {
        t = ti;
        a = i;
      }
    }
  e.face = make_face(a, d[a]);
  // polar angles of the direction in the face frame, after undoing the roll
  Vec3 w = Mat3::rotation({1, 0, 0}, -roll) * (face_frame(e.face).transposed() * d);
  double rz = std::asin(std::clamp(w.y, -1.0, 1.0));
  double ry = std::atan2(-w.z, w.x);
  if (step > 0) {
    ry = std::round(ry / step) * step;
    rz = std::round(rz / step) * step;
    roll = std::round(roll / step) * step;
  }
  e.rotation = {roll, ry, rz};
  // rounding tilts the direction by at most step/2 per angle: still outward
  if (!set_at_from_direction(e, parent_size)) e.u = e.v = 0;
}

void reseat_edge(EdgeGene& e, Vec3 parent_size, double step) {
  if (set_at_from_direction(e, parent_size)) return;
  place_edge(e, parent_size, edge_direction(e), e.rotation.x, step);
}

}  // namespace bx
