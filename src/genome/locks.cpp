#include "genome/locks.h"

#include <algorithm>
#include <tuple>
#include <vector>

#include "genome/dialect.h"

namespace bx {

namespace {

// a unit's frozen part (genome/locks.h): all of a locked unit; of a switch or
// an effector carrying an encapsulated skill's wires, what stays as the skill
// left it (the free rest cleared)
NeuronGene frozen(const NeuronGene& n) {
  if (n.locked || n.skill.empty()) return n;
  NeuronGene f = n;
  f.inputs.resize(gated_prefix(n.inputs));
  return f;
}
const SensorGene& frozen(const SensorGene& s) { return s; }
EffectorGene frozen(const EffectorGene& e) {
  if (e.locked) return e;
  EffectorGene f = e;
  f.bias = 0;
  f.inputs.resize(gated_prefix(e.inputs));
  return f;
}

template <class U>
int locked_prefix(const std::vector<U>& units) {
  int k = 0;
  while (k < static_cast<int>(units.size()) && is_fixed(units[k])) ++k;
  return k;
}

template <class U>
bool any_locked(const std::vector<U>& units) {
  return std::any_of(units.begin(), units.end(), [](const U& u) { return is_fixed(u); });
}

std::vector<int> kept_nodes(const Genome& g) {
  std::vector<int> out;
  for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i)
    if (is_kept(g.nodes[i])) out.push_back(i);
  return out;
}

std::string node_path(int i) { return "nodes[" + std::to_string(i) + "]"; }

// an edge without its target, for comparing placements
EdgeGene placement(EdgeGene e) {
  e.to = 0;
  return e;
}

// the edges into node `n`: each as (who grows it, its placement); the grower
// is named by its kept ordinal, or as the root, or as another node
std::vector<std::pair<std::string, EdgeGene>> in_edges(const Genome& g, int n, const std::vector<int>& kept) {
  std::vector<std::pair<std::string, EdgeGene>> out;
  for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i)
    for (const EdgeGene& e : g.nodes[i].edges) {
      if (e.to != n) continue;
      auto k = std::find(kept.begin(), kept.end(), i);
      std::string who = k != kept.end() ? "kept " + std::to_string(k - kept.begin())
                                        : i == 0 ? "root" : "other";
      out.push_back({who, placement(e)});
    }
  auto key = [](const std::pair<std::string, EdgeGene>& x) {
    const EdgeGene& e = x.second;
    return std::tuple(x.first, static_cast<int>(e.face), e.u, e.v, e.rotation.x, e.rotation.y, e.rotation.z,
                      e.scale, e.reflect, e.terminal_only);
  };
  std::sort(out.begin(), out.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
  return out;
}

template <class U>
bool same_prefix(const std::vector<U>& a, const std::vector<U>& b, int n) {
  if (static_cast<int>(b.size()) < n || locked_prefix(b) != n) return false;
  for (int k = 0; k < n; ++k)
    if (!(frozen(a[k]) == frozen(b[k]))) return false;
  return true;
}

}  // namespace

int gated_prefix(const std::vector<InputGene>& inputs) {
  int k = 0;
  while (k < static_cast<int>(inputs.size()) && inputs[k].gate != InputGene::kNoGate) ++k;
  return k;
}

bool is_fixed(const NeuronGene& n) { return n.locked || !n.skill.empty(); }
bool is_fixed(const SensorGene& s) { return s.locked; }
bool is_fixed(const EffectorGene& e) { return e.locked || gated_prefix(e.inputs) > 0; }

bool has_locked_unit(const NodeGene& n) {
  return (n.lock & kLockUnits) || any_locked(n.neurons) || any_locked(n.sensors) || any_locked(n.effectors);
}

bool is_kept(const NodeGene& n) { return n.lock != 0 || has_locked_unit(n); }

bool has_locks(const Genome& g) {
  return any_locked(g.global_neurons) || std::any_of(g.nodes.begin(), g.nodes.end(), is_kept);
}

int last_kept_node(const Genome& g) {
  for (int i = static_cast<int>(g.nodes.size()) - 1; i >= 0; --i)
    if (is_kept(g.nodes[i])) return i;
  return -1;
}

void unlock(NodeGene& n) {
  n.lock = 0;
  for (auto& u : n.neurons) u.locked = false;
  for (auto& u : n.sensors) u.locked = false;
  for (auto& u : n.effectors) {
    u.locked = false;
    for (InputGene& in : u.inputs) in.gate = InputGene::kNoGate;  // its skill's switch is not this genome's
  }
}

Status locks_kept(const Genome& parent, const Genome& child) {
  const std::vector<int> p = kept_nodes(parent), c = kept_nodes(child);
  if (p.size() != c.size())
    return Error{"kept nodes: " + std::to_string(p.size()) + " locked in the parent, " + std::to_string(c.size()) +
                 " in the child"};
  for (std::size_t k = 0; k < p.size(); ++k) {
    const NodeGene &a = parent.nodes[p[k]], &b = child.nodes[c[k]];
    auto changed = [&](const std::string& what) {
      return Error{"kept node " + std::to_string(k) + " (" + node_path(p[k]) + " in the parent, " + node_path(c[k]) +
                   " in the child): " + what + " changed"};
    };
    if (a.lock != b.lock) return changed("its lock");
    if (a.lock & kLockBody)
      if (a.shape != b.shape || a.size != b.size || a.density != b.density || a.recursive_limit != b.recursive_limit)
        return changed("its body");
    if ((a.lock & kLockJoint) && !(a.joint == b.joint)) return changed("its joint");
    if (a.lock & kLockUnits) {
      if (a.neurons != b.neurons || a.sensors != b.sensors || a.effectors != b.effectors) return changed("its units");
    } else {
      if (!same_prefix(a.neurons, b.neurons, locked_prefix(a.neurons))) return changed("a locked neuron");
      if (!same_prefix(a.sensors, b.sensors, locked_prefix(a.sensors))) return changed("a locked sensor");
      if (!same_prefix(a.effectors, b.effectors, locked_prefix(a.effectors))) return changed("a locked effector");
    }
    if (a.lock & kLockOutEdges) {
      if (a.edges.size() != b.edges.size()) return changed("its edges");
      for (std::size_t e = 0; e < a.edges.size(); ++e) {
        if (!(placement(a.edges[e]) == placement(b.edges[e]))) return changed("its edges");
        // a kept target is the kept node of the same rank; another stays where it was
        auto t = std::find(p.begin(), p.end(), a.edges[e].to);
        int want = t != p.end() ? c[t - p.begin()] : a.edges[e].to;
        if (b.edges[e].to != want || (t == p.end() && is_kept(child.nodes[want]))) return changed("its edges");
      }
    }
    if ((a.lock & kLockInEdges) && in_edges(parent, p[k], p) != in_edges(child, c[k], c))
      return changed("the edges into it");
  }
  if (!same_prefix(parent.global_neurons, child.global_neurons, locked_prefix(parent.global_neurons)))
    return Error{"a locked global neuron changed"};
  return Ok{};
}

std::optional<std::string> lock_problem(const Genome& g) {
  if (!has_locks(g)) return std::nullopt;
  if (dialect_rules(g.dialect).operators == OperatorScheme::LimbTree)
    return "nodes: locks are not honoured by the limb-tree operators of dialect " + std::string(to_string(g.dialect)) +
           ", got a genome with locks";
  const int n = static_cast<int>(g.nodes.size());
  // locked units first in their lists
  auto prefix = [](const auto& units, const std::string& path) -> std::optional<std::string> {
    int k = locked_prefix(units);
    for (int j = k; j < static_cast<int>(units.size()); ++j)
      if (is_fixed(units[j]))
        return path + "[" + std::to_string(j) + "]" + (units[j].locked ? ".locked" : "") +
               ": locked units come before unlocked ones (skills' switches and effectors with gated inputs " +
               "count as locked; the first unlocked one is [" + std::to_string(k) + "]), got " +
               (units[j].locked ? "true" : "a fixed one");
    return std::nullopt;
  };
  if (auto p = prefix(g.global_neurons, "global_neurons")) return p;
  for (int i = 0; i < n; ++i) {
    const NodeGene& node = g.nodes[i];
    if (node.lock & ~kLockAll)
      return node_path(i) + ".lock: unknown lock bits, got " + std::to_string(node.lock);
    if (auto p = prefix(node.neurons, node_path(i) + ".neurons")) return p;
    if (auto p = prefix(node.sensors, node_path(i) + ".sensors")) return p;
    if (auto p = prefix(node.effectors, node_path(i) + ".effectors")) return p;
  }
  // a locked unit reads only locked units
  auto unit_locked = [&](int node, const InputGene& in) {
    const NodeGene& s = g.nodes[node];
    if (s.lock & kLockUnits) return true;
    if (in.kind == SourceKind::Neuron)
      return in.index >= 0 && in.index < static_cast<int>(s.neurons.size()) && s.neurons[in.index].locked;
    if (in.kind == SourceKind::Muscle)  // a muscle's length: its effector
      return in.index >= 0 && in.index < static_cast<int>(s.effectors.size()) && is_fixed(s.effectors[in.index]);
    return in.index >= 0 && in.index < static_cast<int>(s.sensors.size()) && s.sensors[in.index].locked;
  };
  auto source_locked = [&](int owner, const InputGene& in) -> bool {
    switch (in.place) {
      case SourcePlace::Self: return unit_locked(owner, in);
      case SourcePlace::Root: return unit_locked(0, in);
      case SourcePlace::Global:
        // a skill's switch counts as locked: later skills drive it, as IV-B means them to
        return in.index >= 0 && in.index < static_cast<int>(g.global_neurons.size()) &&
               is_fixed(g.global_neurons[in.index]);
      case SourcePlace::Child: {
        const NodeGene& o = g.nodes[owner];
        return (o.lock & kLockOutEdges) && in.edge >= 0 && in.edge < static_cast<int>(o.edges.size()) &&
               unit_locked(o.edges[in.edge].to, in);
      }
      case SourcePlace::Parent: {
        if (!(g.nodes[owner].lock & kLockInEdges)) return false;
        for (int i = 0; i < n; ++i)
          for (const EdgeGene& e : g.nodes[i].edges)
            if (e.to == owner && !unit_locked(i, in)) return false;
        return true;
      }
    }
    return false;
  };
  // only the first `n` of `ins` (all: a locked unit's; the gated prefix: a
  // switch's or an effector's, the wires of encapsulated skills)
  auto inputs = [&](int owner, const std::vector<InputGene>& ins, const std::string& path,
                    std::size_t n = static_cast<std::size_t>(-1)) -> std::optional<std::string> {
    for (std::size_t k = 0; k < ins.size() && k < n; ++k)
      if (!source_locked(owner, ins[k]))
        return path + ".inputs[" + std::to_string(k) + "]: a locked unit reads only locked units (through a " +
               "parent only with in_edges locked, a child only with out_edges locked), got a source from " +
               std::string(to_string(ins[k].place)) + " " + (ins[k].kind == SourceKind::Neuron   ? "neuron "
                                                                 : ins[k].kind == SourceKind::Sensor ? "sensor "
                                                                                                      : "muscle ") +
               std::to_string(ins[k].index);
    return std::nullopt;
  };
  // gated inputs come first in their lists (new ones are appended after them)
  auto gated_first = [](const std::vector<InputGene>& ins, const std::string& path) -> std::optional<std::string> {
    const int k = gated_prefix(ins);
    for (int j = k; j < static_cast<int>(ins.size()); ++j)
      if (ins[j].gate != InputGene::kNoGate)
        return path + ".inputs[" + std::to_string(j) + "].gate: gated inputs come before ungated ones (the first " +
               "ungated one is [" + std::to_string(k) + "]), got " + std::to_string(ins[j].gate);
    return std::nullopt;
  };
  for (int j = 0; j < static_cast<int>(g.global_neurons.size()); ++j) {
    const NeuronGene& nr = g.global_neurons[j];
    const std::string path = "global_neurons[" + std::to_string(j) + "]";
    if (auto p = gated_first(nr.inputs, path)) return p;
    if (is_fixed(nr))
      if (auto p = inputs(-1, nr.inputs, path, nr.locked ? nr.inputs.size() : gated_prefix(nr.inputs))) return p;
  }
  for (int i = 0; i < n; ++i) {
    const NodeGene& node = g.nodes[i];
    const bool all = node.lock & kLockUnits;
    for (int j = 0; j < static_cast<int>(node.neurons.size()); ++j)
      if (all || node.neurons[j].locked)
        if (auto p = inputs(i, node.neurons[j].inputs, node_path(i) + ".neurons[" + std::to_string(j) + "]")) return p;
    for (int j = 0; j < static_cast<int>(node.effectors.size()); ++j) {
      const EffectorGene& ef = node.effectors[j];
      const std::string path = node_path(i) + ".effectors[" + std::to_string(j) + "]";
      if (auto p = gated_first(ef.inputs, path)) return p;
      if (all || is_fixed(ef))
        if (auto p = inputs(i, ef.inputs, path, all || ef.locked ? ef.inputs.size() : gated_prefix(ef.inputs)))
          return p;
    }
  }
  return std::nullopt;
}

std::string_view lock_name(NodeLock bit) {
  switch (bit) {
    case kLockBody: return "body";
    case kLockJoint: return "joint";
    case kLockInEdges: return "in_edges";
    case kLockOutEdges: return "out_edges";
    case kLockUnits: return "units";
  }
  return "?";
}

std::vector<std::string> lock_names(unsigned bits) {
  std::vector<std::string> out;
  for (NodeLock b : kLockBits)
    if (bits & b) out.emplace_back(lock_name(b));
  return out;
}

std::optional<NodeLock> parse_lock(std::string_view name) {
  for (NodeLock b : kLockBits)
    if (lock_name(b) == name) return b;
  return std::nullopt;
}

}  // namespace bx
