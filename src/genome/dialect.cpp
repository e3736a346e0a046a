// Dialect tables (one per paper) and validate(): the checks every genome must
// pass, whatever its source (a file, random creation, an operator).
#include "genome/dialect.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "genome/genome_json.h"
#include "genome/locks.h"
#include "genome/operators.h"

namespace bx {

namespace {

// The tables are built on first use (function-local statics), so that other
// files' static initializers may already call dialect_rules().

// sims1994 (Sims, "Evolving virtual creatures", 1994): the open graph genome.
DialectRules sims1994_rules() {
  return {
      .dialect = Dialect::Sims1994,
      .neuron_set = NeuronSetId::Sims1994,
      .max_genes = 0,      // no limit on genes: the graph grows and shrinks by mutation
      .max_parts = 100,    // our default; Sims discarded creatures above a configured maximum
                           // number of parts (as chaumont2007 sec. 5.5 recounts)
      .tree_only = false,  // graph with multiple and reflexive edges (docs/papers.md S0)
      // Sims used boxes only; spheres, capsules and cylinders are our extension
      .shapes = {Shape::Box, Shape::Sphere, Shape::Capsule, Shape::Cylinder},
      // Sims' rigid, revolute, twist, universal, bend-twist, twist-bend and spherical
      // joints map onto these six types; slider and cylindrical are our extension
      .joints = {JointType::Fixed, JointType::Hinge, JointType::Universal, JointType::Spherical,
                 JointType::Slider, JointType::Cylindrical},
      .hinge_axis_y_or_z = false,
      .angle_step = 0,  // orientations are continuous
      .max_neurons_per_part = 0,
      .max_inputs_per_neuron = 0,  // each function's own arity
      .mass_rule = MassRule::Density,
      .mass_scale = 0,
      .edge_roll_free = true,
      .reflect_axes = {0, 1, 2},  // reflection across any of the parent's planes
      .default_hinge_limits = std::nullopt,
      .hinge_limits_fixed = false,
      .max_abs_bias = 0,
      .max_abs_weight = 0,
      .sensors = {SensorType::JointAngle, SensorType::Contact},
      .max_sensors_per_part = 0,
      .max_effectors_per_part = 0,
      .global_neurons = true,  // Sims' neurons outside any part
      .group_fn = "",
      .operators = OperatorScheme::Graph,
      .edge_lattice = false,
      .edge_scale_free = true,
      .edge_terminal_only = true,
      .limb_io = false,
      .slot_wiring = false,
      .muscle_effectors = false,
      .joined_parts_collide = false,
  };
}

// miconi2006 (Miconi & Channon, ALIFE X, 2006).
DialectRules miconi2006_rules() {
  return {
      .dialect = Dialect::Miconi2006,
      .neuron_set = NeuronSetId::Miconi2006,
      .max_genes = 7,                // Table 1: max. number of genes
      .max_parts = 11,               // Table 1: max. number of limbs after development
      .tree_only = true,             // sec. 2: "may not contain any loop, including self-loops"
      .shapes = {Shape::Box},        // sec. 2: rigid 3D blocks
      .joints = {JointType::Hinge},  // sec. 2: each limb hangs from its parent by a hinge
      .hinge_axis_y_or_z = true,     // sec. 2: hinge axis along the limb's y or z axis
      .angle_step = kPi / 8,         // sec. 2: polar angles are multiples of pi/8
      .max_neurons_per_part = 6,     // Table 1: max. number of neurons per limb
      .max_inputs_per_neuron = 3,    // sec. 3 and Table 1: max. connections per neuron
      .mass_rule = MassRule::TanhVolume,
      .mass_scale = 0.8,        // Table 1: mass 0.8 * tanh(x*y*z)
      .edge_roll_free = false,  // sec. 2: orientation is two polar angles, no roll
      .reflect_axes = {1},      // sec. 4.1: symmetry across the parent's xz plane only
      .default_hinge_limits = Limit{-3 * kPi / 4, 3 * kPi / 4},  // Table 1: joint angle range
      .hinge_limits_fixed = true,           // Table 1: the range is a constant, not evolved
      .max_abs_bias = 1.5,                  // sec. 3 and Table 1: thresholds in [-3/2, 3/2]
      .max_abs_weight = 1.0,                // sec. 3 and Table 1: weights in [-1, 1]
      .sensors = {SensorType::JointAngle},  // sec. 3.1: the only sensor is the joint angle
      .max_sensors_per_part = 1,            // sec. 3.1: one sensor per limb
      .max_effectors_per_part = 1,          // sec. 3.1: one actuator per limb
      .global_neurons = false,              // sec. 3: sources are adjacent limbs or the root only
      .group_fn = "",
      .operators = OperatorScheme::LimbTree,  // sec. 5.1
      .edge_lattice = true,                 // sec. 2: a face and two polar angles
      .edge_scale_free = false,             // sec. 2: a limb's size is its own gene
      .edge_terminal_only = false,
      .limb_io = true,                      // sec. 3.1, Fig. 1
      .slot_wiring = true,                  // sec. 3: connection slots
      .muscle_effectors = false,            // sec. 3.1: one actuator per hinge
      .joined_parts_collide = false,        // sec. 2: limits are the fixed joint range
  };
}

// chaumont2007 (Chaumont, Egli & Adami, Artificial Life 13, 2007).
DialectRules chaumont2007_rules() {
  return {
      .dialect = Dialect::Chaumont2007,
      .neuron_set = NeuronSetId::Chaumont2007,
      .max_genes = 20,         // sec. 5.5: n_max = 20 genes
      .max_parts = 100,        // our safety cap: the paper bounds genes, not blocks (sec. 5.5)
      .tree_only = false,      // Sims' graph genome (sec. 3.1)
      .shapes = {Shape::Box},  // sec. 3.1: cuboids
      .joints = {JointType::Hinge},  // sec. 5.1: "each (ball and socket) joint has only one degree of freedom": rotational
      .hinge_axis_y_or_z = false,
      .angle_step = 0,
      .max_neurons_per_part = 0,
      .max_inputs_per_neuron = 0,  // Table I: each function's own inputs
      .mass_rule = MassRule::Density,
      .mass_scale = 0,
      .edge_roll_free = true,
      .reflect_axes = {0, 1, 2},
      .default_hinge_limits = std::nullopt,
      .hinge_limits_fixed = false,
      .max_abs_bias = 0,
      .max_abs_weight = 0,
      .sensors = {SensorType::Contact},  // Table I: "sen", contact on one face of a block
      .max_sensors_per_part = 0,
      .max_effectors_per_part = 0,
      .global_neurons = true,
      .group_fn = "",
      .operators = OperatorScheme::Graph,  // sec. 3.1: Sims' genome and operators
      .edge_lattice = false,
      .edge_scale_free = true,
      .edge_terminal_only = true,
      .limb_io = false,
      .slot_wiring = false,
      .muscle_effectors = false,
      .joined_parts_collide = false,
  };
}

// lessin2015 (Lessin, Fussell & Miikkulainen, IEEE TEVC, 2015), section III:
// Sims' graph genome with round shapes, muscles and photoreceptors.
DialectRules lessin2015_rules() {
  return {
      .dialect = Dialect::Lessin2015,
      .neuron_set = NeuronSetId::Lessin2015,  // III-C: outputs in [0, 1]
      .max_genes = 20,   // our bound (the paper gives none), as chaumont2007's n_max
      .max_parts = 50,   // our safety cap; Fig. 3's creatures have up to about 15 segments
      .tree_only = false,  // III-B: reflexive and multiple edges allowed (Fig. 4)
      .shapes = {Shape::Box, Shape::Sphere, Shape::Capsule},  // III-B: "all PhysX primitives"
      // III-B: "fixed, revolute, spherical, prismatic, and cylindrical"
      .joints = {JointType::Fixed, JointType::Hinge, JointType::Spherical, JointType::Slider,
                 JointType::Cylindrical},
      .hinge_axis_y_or_z = false,
      .angle_step = 0,
      .max_neurons_per_part = 0,
      .max_inputs_per_neuron = 0,  // each function's own arity (sum and sigma: any)
      .mass_rule = MassRule::Density,
      .mass_scale = 0,
      .edge_roll_free = true,
      .reflect_axes = {0, 1, 2},  // III-B: "reflection of body parts as well as body symmetry"
      // III-B: "most limitations on joint movement ... through natural collisions
      // between adjacent segments": no default limits; a genome may still carry some
      .default_hinge_limits = std::nullopt,
      .hinge_limits_fixed = false,
      .max_abs_bias = 0,
      .max_abs_weight = 0,
      .sensors = {SensorType::Photoreceptor},  // III-D; each muscle adds its length (III-E)
      .max_sensors_per_part = 0,
      .max_effectors_per_part = 0,
      .global_neurons = true,  // as Sims: the brain is one network of nodes and wires (III-C)
      .group_fn = "sigma",     // IV-C: pandemonium between skills, each switched by its sigma (IV-B)
      .operators = OperatorScheme::Graph,
      .edge_lattice = false,
      .edge_scale_free = true,
      .edge_terminal_only = true,
      .limb_io = false,
      .slot_wiring = false,
      .muscle_effectors = true,       // III-E: muscles are the only actuators
      .joined_parts_collide = true,   // III-B
  };
}

using json = nlohmann::json;
// A failed check: the message without the file name.
using Problem = std::optional<std::string>;

constexpr double kTol = 1e-9;

std::string problem(const std::string& path, std::string_view what, const json& got) {
  return path + ": " + std::string(what) + ", got " + json_one_line(got, 120);
}

std::string in_dialect(const DialectRules& r) {
  return std::string(" in dialect ") + std::string(to_string(r.dialect));
}

json vec_json(Vec3 v) { return json::array({v.x, v.y, v.z}); }
json limit_json(Limit l) { return json::array({l.lo, l.hi}); }
bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

template <class T, class F>
std::string join(const std::vector<T>& items, F name) {
  std::string s;
  for (const auto& it : items) {
    if (!s.empty()) s += ", ";
    s += name(it);
  }
  return s;
}

// "expected one of a, b, c", or "expected a" for a single choice.
std::string expected(const std::string& choices, std::size_t n) {
  return n == 1 ? "expected " + choices : "expected one of " + choices;
}

template <class T>
bool contains(const std::vector<T>& items, T x) {
  for (const auto& it : items)
    if (it == x) return true;
  return false;
}

const char* axis_name(int a) { return a == 0 ? "x" : a == 1 ? "y" : a == 2 ? "z" : "?"; }

json reflect_json(const std::vector<int>& axes) {
  json j = json::array();
  for (int a : axes) {
    if (a >= 0 && a < 3)
      j.push_back(axis_name(a));
    else
      j.push_back(a);
  }
  return j;
}

// Whether degree of freedom `dof` of a joint type is a rotation (else a translation).
bool dof_is_angular(JointType t, int dof) {
  switch (t) {
    case JointType::Slider: return false;
    case JointType::Cylindrical: return dof == 1;
    default: return true;
  }
}

// "pi/8" when the step divides pi evenly, else the number.
std::string angle_text(double step) {
  double k = kPi / step;
  if (std::abs(k - std::round(k)) < kTol) return "pi/" + std::to_string(std::lround(k));
  return json(step).dump();
}

bool near(Vec3 a, Vec3 b) {
  return std::abs(a.x - b.x) <= kTol && std::abs(a.y - b.y) <= kTol && std::abs(a.z - b.z) <= kTol;
}

// Checks one genome against its dialect; the first problem found wins.
class Validator {
 public:
  explicit Validator(const Genome& g) : g_(g), r_(dialect_rules(g.dialect)) {}

  Problem run() {
    int n = static_cast<int>(g_.nodes.size());
    if (n == 0) return problem("nodes", "a genome needs at least one node", json::array());
    if (r_.max_genes > 0 && n > r_.max_genes)
      return problem("nodes", "at most " + std::to_string(r_.max_genes) + " genes" + in_dialect(r_),
                     n);
    if (!r_.global_neurons && !g_.global_neurons.empty())
      return problem("global_neurons", "no global neurons" + in_dialect(r_),
                     static_cast<int>(g_.global_neurons.size()));
    // edge targets first: child sources and reachability depend on them
    for (int i = 0; i < n; ++i) {
      const auto& edges = g_.nodes[i].edges;
      for (int k = 0; k < static_cast<int>(edges.size()); ++k) {
        int to = edges[k].to;
        if (to < 0 || to >= n)
          return problem(edge_path(i, k) + ".to",
                         "no such node (the genome has " + std::to_string(n) + ")", to);
      }
    }
    // a catapult's arm and projectile before the nodes: the projectile's
    // fixed joint is the one exception to the dialect's joint types
    if (g_.catapult)
      if (auto p = check_catapult()) return p;
    if (r_.tree_only)
      if (auto p = check_tree()) return p;
    for (int i = 0; i < n; ++i)
      if (auto p = check_node(i)) return p;
    for (int j = 0; j < static_cast<int>(g_.global_neurons.size()); ++j)
      if (auto p =
              check_neuron(g_.global_neurons[j], "global_neurons[" + std::to_string(j) + "]", -1))
        return p;
    if (g_.catapult)
      if (auto p = check_release()) return p;
    if (auto p = lock_problem(g_)) return p;
    return check_reachable();
  }

 private:
  static std::string node_path(int i) { return "nodes[" + std::to_string(i) + "]"; }
  static std::string edge_path(int i, int k) {
    return node_path(i) + ".edges[" + std::to_string(k) + "]";
  }

  // tree_only: the root has no parent, every other node exactly one, no self-loops
  Problem check_tree() const {
    std::vector<std::string> parent(g_.nodes.size());
    std::string tree = "a tree genome" + in_dialect(r_);
    for (int i = 0; i < static_cast<int>(g_.nodes.size()); ++i) {
      const auto& edges = g_.nodes[i].edges;
      for (int k = 0; k < static_cast<int>(edges.size()); ++k) {
        int to = edges[k].to;
        std::string path = edge_path(i, k) + ".to";
        if (to == i) return problem(path, "reflexive edge not allowed in " + tree, to);
        if (to == 0) return problem(path, "no edge may lead to the root in " + tree, to);
        if (!parent[to].empty())
          return problem(path,
                         "node " + std::to_string(to) + " already has a parent (" + parent[to] +
                             "); " + tree + " allows one",
                         to);
        parent[to] = edge_path(i, k);
      }
    }
    return std::nullopt;
  }

  // Catapults (chaumont2007 4.1): the dialect, the projectile node, the one
  // edge of the arm (node 0) that holds it, no edge back to the arm, the delay.
  Problem check_catapult() const {
    const CatapultGene& c = *g_.catapult;
    int n = static_cast<int>(g_.nodes.size());
    if (g_.dialect != Dialect::Chaumont2007)
      return problem("catapult", "catapults belong to dialect chaumont2007 (section 4)",
                     std::string(to_string(g_.dialect)));
    int p = c.projectile;
    if (p < 1 || p >= n)
      return problem("catapult.projectile",
                     "must name a node other than the root (the arm), in [1, " +
                         std::to_string(n) + ")",
                     p);
    // the projectile: a plain box, grown once, held by a fixed joint
    const NodeGene& pn = g_.nodes[p];
    std::string path = node_path(p);
    if (pn.shape != Shape::Box)
      return problem(path + ".shape", "a catapult's projectile must be a box",
                     std::string(to_string(pn.shape)));
    if (pn.joint.type != JointType::Fixed)
      return problem(path + ".joint.type", "a catapult's projectile is held by a fixed joint",
                     std::string(to_string(pn.joint.type)));
    auto none = [&](std::string_view field, std::size_t count) -> Problem {
      if (count == 0) return std::nullopt;
      return problem(path + "." + std::string(field),
                     "a catapult's projectile has no " + std::string(field),
                     static_cast<int>(count));
    };
    if (auto q = none("neurons", pn.neurons.size())) return q;
    if (auto q = none("sensors", pn.sensors.size())) return q;
    if (auto q = none("effectors", pn.effectors.size())) return q;
    if (auto q = none("edges", pn.edges.size())) return q;
    if (pn.recursive_limit != 1)
      return problem(path + ".recursive_limit", "a catapult's projectile grows once (it must be 1)",
                     pn.recursive_limit);
    // edges: one from the arm to the projectile, none to the arm
    std::string held;  // the path of the edge that holds the projectile
    for (int i = 0; i < n; ++i) {
      const auto& edges = g_.nodes[i].edges;
      for (int k = 0; k < static_cast<int>(edges.size()); ++k) {
        const EdgeGene& e = edges[k];
        std::string epath = edge_path(i, k);
        if (e.to == 0)
          return problem(epath + ".to",
                         "no edge may lead to a catapult's arm (node 0): the arm exists once", 0);
        if (e.to != p) continue;
        if (i != 0)
          return problem(epath + ".to", "only the arm (node 0) may hold a catapult's projectile",
                         p);
        if (!held.empty())
          return problem(epath + ".to",
                         "a catapult's projectile is held by one edge only (already " + held + ")",
                         p);
        held = epath;
        if (!e.reflect.empty())
          return problem(epath + ".reflect", "the projectile's edge must not reflect (one projectile)",
                         reflect_json(e.reflect));
        if (e.terminal_only)
          return problem(epath + ".terminal_only", "must be false on the projectile's edge", true);
        if (e.scale != 1.0)
          return problem(epath + ".scale",
                         "must be 1 on the projectile's edge (its node gives the projectile's size)",
                         e.scale);
      }
    }
    if (held.empty())
      return problem("catapult.projectile",
                     "no edge of the arm (node 0) holds the projectile node", p);
    // the mechanism is locked (genome/locks.h), so that no operator grows a
    // second arm or changes the projectile
    auto names = [](unsigned bits) { return json(lock_names(bits)); };
    if (!(g_.nodes[0].lock & kLockInEdges))
      return problem("nodes[0].lock", "a catapult's arm has its in_edges locked (one arm)", names(g_.nodes[0].lock));
    const unsigned need = catapult_projectile_lock(true);
    if ((pn.lock & need) != need)
      return problem(path + ".lock",
                     "a catapult's projectile has its joint, in_edges, out_edges and units locked "
                     "(and its body, unless its size may mutate)",
                     names(pn.lock));
    int delay = c.release.delay_steps;
    if (delay < kMinReleaseDelaySteps || delay > kMaxReleaseDelaySteps)
      return problem("catapult.release.delay_steps",
                     "must be in [" + std::to_string(kMinReleaseDelaySteps) + ", " +
                         std::to_string(kMaxReleaseDelaySteps) + "]",
                     delay);
    return std::nullopt;
  }

  // A catapult's release inputs: sources of the arm (node 0) as a root
  // neuron's, never through the projectile's edge.
  Problem check_release() const {
    const auto& inputs = g_.catapult->release.inputs;
    int p = g_.catapult->projectile;
    const auto& edges = g_.nodes[0].edges;
    for (int k = 0; k < static_cast<int>(inputs.size()); ++k) {
      const InputGene& in = inputs[k];
      std::string path = "catapult.release.inputs[" + std::to_string(k) + "]";
      if (in.place == SourcePlace::Parent)
        return problem(path + ".from", "the release reads as from the arm, the root: it has no parent",
                       std::string(to_string(in.place)));
      if (in.place == SourcePlace::Child && in.edge >= 0 &&
          in.edge < static_cast<int>(edges.size()) && edges[in.edge].to == p)
        return problem(path + ".edge",
                       "reads through the projectile's edge (the projectile has no neurons or "
                       "sensors)",
                       in.edge);
      if (auto q = check_source(in, path, 0)) return q;
    }
    return std::nullopt;
  }

  Problem check_reachable() const {
    std::vector<bool> seen(g_.nodes.size(), false);
    std::vector<int> todo{0};
    seen[0] = true;
    while (!todo.empty()) {
      int i = todo.back();
      todo.pop_back();
      for (const auto& e : g_.nodes[i].edges)
        if (!seen[e.to]) {
          seen[e.to] = true;
          todo.push_back(e.to);
        }
    }
    for (int i = 0; i < static_cast<int>(seen.size()); ++i)
      if (!seen[i]) return node_path(i) + ": not reachable from the root";
    return std::nullopt;
  }

  Problem check_node(int i) const {
    const NodeGene& node = g_.nodes[i];
    std::string path = node_path(i);
    // body
    if (!contains(r_.shapes, node.shape))
      return problem(
          path + ".shape",
          "shape not allowed" + in_dialect(r_) + " (" +
              expected(join(r_.shapes, [](Shape s) { return std::string(to_string(s)); }),
                       r_.shapes.size()) +
              ")",
          std::string(to_string(node.shape)));
    if (!finite(node.size) || !(node.size.x > 0 && node.size.y > 0 && node.size.z > 0))
      return problem(path + ".size", "each dimension must be > 0", vec_json(node.size));
    for (int a = 0; a < 3; ++a)
      if (node.size[a] < kMinPartSize || node.size[a] > kMaxPartSize)
        return problem(path + ".size",
                       "each dimension must lie in " + range_text(kMinPartSize, kMaxPartSize) + " m",
                       vec_json(node.size));
    if (!std::isfinite(node.density) || !(node.density > 0))
      return problem(path + ".density", "must be > 0", node.density);
    if (node.density < kMinDensity || node.density > kMaxDensity)
      return problem(path + ".density",
                     "must lie in " + range_text(kMinDensity, kMaxDensity) + " kg/m^3", node.density);
    // a catapult's projectile hangs by a fixed joint (checked by check_catapult)
    bool projectile = g_.catapult && g_.catapult->projectile == i;
    if (auto p = check_joint(node.joint, path + ".joint", projectile)) return p;
    if (node.recursive_limit < 1)
      return problem(path + ".recursive_limit", "must be >= 1", node.recursive_limit);
    // brain
    int n_neurons = static_cast<int>(node.neurons.size());
    if (r_.max_neurons_per_part > 0 && n_neurons > r_.max_neurons_per_part)
      return problem(path + ".neurons",
                     "at most " + std::to_string(r_.max_neurons_per_part) + " neurons per part" +
                         in_dialect(r_),
                     n_neurons);
    for (int j = 0; j < n_neurons; ++j)
      if (auto p = check_neuron(node.neurons[j], path + ".neurons[" + std::to_string(j) + "]", i))
        return p;
    if (auto p = check_sensors(node, path)) return p;
    if (auto p = check_effectors(node, path, i)) return p;
    for (int k = 0; k < static_cast<int>(node.edges.size()); ++k)
      if (auto p = check_edge(node.edges[k], edge_path(i, k))) return p;
    return std::nullopt;
  }

  Problem check_joint(const JointGene& j, const std::string& path, bool allow_fixed) const {
    std::string type_name(to_string(j.type));
    if (!contains(r_.joints, j.type) && !(allow_fixed && j.type == JointType::Fixed))
      return problem(
          path + ".type",
          "joint type not allowed" + in_dialect(r_) + " (" +
              expected(join(r_.joints, [](JointType t) { return std::string(to_string(t)); }),
                       r_.joints.size()) +
              ")",
          type_name);
    for (auto [name, axis] : {std::pair{"axis1", j.axis1}, std::pair{"axis2", j.axis2}})
      if (!finite(axis) || std::abs(norm(axis) - 1) > 1e-6)
        return problem(path + "." + name, "must be a unit vector", vec_json(axis));
    bool two_axes = j.type == JointType::Universal || j.type == JointType::Spherical;
    if (two_axes && norm(cross(j.axis1, j.axis2)) < 1e-6)
      return problem(path + ".axis2", "must not be parallel to axis1 for a " + type_name + " joint",
                     vec_json(j.axis2));
    if (r_.hinge_axis_y_or_z && j.type == JointType::Hinge) {
      Vec3 a = j.axis1;
      if (!near(a, {0, 1, 0}) && !near(a, {0, -1, 0}) && !near(a, {0, 0, 1}) &&
          !near(a, {0, 0, -1}))
        return problem(path + ".axis1",
                       "hinge axis must be the part's y or z axis" + in_dialect(r_), vec_json(a));
    }
    // limits: none (unlimited or the dialect's default), or one per degree of freedom
    if (j.limits.empty()) return std::nullopt;
    int dofs = joint_dofs(j.type);
    json all = json::array();
    for (const Limit& l : j.limits) all.push_back(limit_json(l));
    if (static_cast<int>(j.limits.size()) != dofs)
      return problem(path + ".limits",
                     "a " + type_name + " joint needs " + std::to_string(dofs) +
                         " limits (one per degree of freedom) or none",
                     all);
    for (int d = 0; d < dofs; ++d) {
      const Limit& l = j.limits[d];
      std::string lpath = path + ".limits[" + std::to_string(d) + "]";
      if (!std::isfinite(l.lo) || !std::isfinite(l.hi))
        return problem(lpath, "limits must be finite", limit_json(l));
      if (l.lo > l.hi) return problem(lpath, "lower limit above upper limit", limit_json(l));
      if (dof_is_angular(j.type, d) && (l.lo < -kPi || l.hi > kPi))
        return problem(lpath, "angular limits must lie within [-pi, pi]", limit_json(l));
    }
    if (r_.hinge_limits_fixed && j.type == JointType::Hinge && r_.default_hinge_limits) {
      Limit want = *r_.default_hinge_limits;
      const Limit& l = j.limits[0];
      if (std::abs(l.lo - want.lo) > kTol || std::abs(l.hi - want.hi) > kTol)
        return problem(path + ".limits",
                       "hinge limits are fixed at " +
                           json_one_line(json::array({limit_json(want)})) + in_dialect(r_) +
                           " (give exactly these or none)",
                       all);
    }
    return std::nullopt;
  }

  // `owner`: node index, or -1 for a global neuron
  Problem check_neuron(const NeuronGene& nr, const std::string& path, int owner) const {
    const NeuronFnSpec* spec = find_neuron_fn(r_.neuron_set, nr.fn);
    if (!spec)
      return problem(path + ".fn",
                     "unknown function for dialect " + std::string(to_string(g_.dialect)) +
                         " (expected one of " +
                         join(neuron_fn_names(r_.neuron_set),
                              [](std::string_view s) { return std::string(s); }) +
                         ")",
                     nr.fn);
    std::string fn(spec->name);
    // a skill's switch (lessin2015 IV-B, genome/encapsulate.h): a global
    // neuron of the dialect's switch function, one per skill
    if (!nr.skill.empty()) {
      if (r_.group_fn.empty()) return problem(path + ".skill", "no skill switches" + in_dialect(r_), nr.skill);
      if (owner >= 0) return problem(path + ".skill", "a skill's switch is a global neuron", nr.skill);
      if (fn != r_.group_fn)
        return problem(path + ".skill",
                       "a skill's switch is a " + std::string(r_.group_fn) + " neuron" + in_dialect(r_) +
                           " (this is a " + fn + ")",
                       nr.skill);
      for (const NeuronGene& other : g_.global_neurons)
        if (&other != &nr && other.skill == nr.skill)
          return problem(path + ".skill", "two switches of one skill", nr.skill);
    } else {
      for (std::size_t k = 0; k < nr.inputs.size(); ++k)
        if (nr.inputs[k].gate != InputGene::kNoGate)
          return problem(path + ".inputs[" + std::to_string(k) + "].gate",
                         "only a skill switch's and an effector's inputs are gated", nr.inputs[k].gate);
    }
    // a pandemonium group (lessin2015 IV-C): only on the dialect's skill switch
    if (nr.group != NeuronGene::kNoGroup) {
      if (nr.group < 0)
        return problem(path + ".group", "must be >= 0 (" + std::to_string(NeuronGene::kNoGroup) + ": none)",
                       nr.group);
      if (r_.group_fn.empty())
        return problem(path + ".group", "no pandemonium groups" + in_dialect(r_), nr.group);
      if (fn != r_.group_fn)
        return problem(path + ".group",
                       "only a " + std::string(r_.group_fn) + " neuron may belong to a pandemonium group" +
                           in_dialect(r_) + " (this is a " + fn + ")",
                       nr.group);
    }
    // parameters, by the function's order
    if (nr.params.size() != spec->params.size())
      return problem(path + ".params",
                     fn + " takes " + std::to_string(spec->params.size()) + " parameter(s)",
                     nr.params);
    for (std::size_t p = 0; p < spec->params.size(); ++p) {
      const ParamSpec& ps = spec->params[p];
      double v = nr.params[p];
      std::string ppath = path + ".params." + std::string(ps.name);
      if (!std::isfinite(v) || v < ps.min || v > ps.max)
        return problem(
            ppath,
            "out of range [" + json(ps.min).dump() + ", " + json(ps.max).dump() + "] for " + fn, v);
      if (ps.integer && v != std::floor(v)) return problem(ppath, "must be an integer", v);
    }
    // bias: the threshold of weighted-sum neurons only
    if (!std::isfinite(nr.bias)) return problem(path + ".bias", "must be finite", nr.bias);
    if (spec->mode == InputMode::Positional && nr.bias != 0)
      return problem(path + ".bias", "function " + fn + " takes no bias (it must be 0)", nr.bias);
    if (auto p = check_bias(nr.bias, path + ".bias")) return p;
    // inputs
    int most = spec->max_inputs;
    if (r_.max_inputs_per_neuron > 0 && r_.max_inputs_per_neuron < most)
      most = r_.max_inputs_per_neuron;
    int n_in = static_cast<int>(nr.inputs.size());
    if (n_in > most)
      return problem(path + ".inputs",
                     "too many inputs for " + fn + " (at most " + std::to_string(most) + ")", n_in);
    return check_inputs(nr.inputs, path, owner);
  }

  Problem check_bias(double bias, const std::string& path) const {
    if (r_.max_abs_bias > 0 && std::abs(bias) > r_.max_abs_bias)
      return problem(path, "out of range " + range_text(r_.max_abs_bias) + in_dialect(r_), bias);
    return std::nullopt;
  }

  static std::string range_text(double bound) { return range_text(-bound, bound); }
  static std::string range_text(double lo, double hi) {
    // appended piecewise: GCC 12 at -O3 warns falsely (-Wrestrict) on "[" + string&&
    std::string s = "[";
    s.append(json(lo).dump()).append(", ").append(json(hi).dump()).append("]");
    return s;
  }

  Problem check_inputs(const std::vector<InputGene>& inputs, const std::string& owner_path,
                       int owner) const {
    for (int k = 0; k < static_cast<int>(inputs.size()); ++k)
      if (auto p =
              check_source(inputs[k], owner_path + ".inputs[" + std::to_string(k) + "]", owner))
        return p;
    return std::nullopt;
  }

  Problem check_source(const InputGene& in, const std::string& path, int owner) const {
    bool neuron = in.kind == SourceKind::Neuron;
    std::string what = neuron ? "neuron" : in.kind == SourceKind::Sensor ? "sensor" : "muscle";
    if (in.kind == SourceKind::Muscle && !r_.muscle_effectors)
      return problem(path + ".muscle", "no muscles" + in_dialect(r_), in.index);
    std::string ipath = path + "." + what;
    std::string place(to_string(in.place));
    if (!std::isfinite(in.weight)) return problem(path + ".weight", "must be finite", in.weight);
    if (r_.max_abs_weight > 0 && std::abs(in.weight) > r_.max_abs_weight)
      return problem(path + ".weight",
                     "out of range " + range_text(r_.max_abs_weight) + in_dialect(r_), in.weight);
    if (owner < 0 && in.place != SourcePlace::Root && in.place != SourcePlace::Global)
      return problem(path + ".from", "global neurons read only root and global sources", place);
    // a gate is a skill's switch (genome/encapsulate.h)
    if (in.gate != InputGene::kNoGate) {
      const int n = static_cast<int>(g_.global_neurons.size());
      if (r_.group_fn.empty()) return problem(path + ".gate", "no skill switches" + in_dialect(r_), in.gate);
      if (in.gate < 0 || in.gate >= n || g_.global_neurons[in.gate].skill.empty())
        return problem(path + ".gate",
                       "a gate names a global neuron that is a skill's switch (one with a \"skill\")", in.gate);
    }
    // how many neurons or sensors the source node has
    auto count = [&](const NodeGene& n) {
      return static_cast<int>(neuron                              ? n.neurons.size()
                              : in.kind == SourceKind::Sensor ? n.sensors.size()
                                                                : n.effectors.size());
    };
    auto has = [&](int available, const std::string& where) -> Problem {
      if (in.index >= 0 && in.index < available) return std::nullopt;
      return problem(
          ipath, "no such " + what + " " + where + " (it has " + std::to_string(available) + ")",
          in.index);
    };
    switch (in.place) {
      case SourcePlace::Self: return has(count(g_.nodes[owner]), "in this node");
      case SourcePlace::Parent:
        // a node may have several parents: checked when the creature develops
        if (in.index < 0) return problem(ipath, "must be >= 0", in.index);
        return std::nullopt;
      case SourcePlace::Child: {
        const auto& edges = g_.nodes[owner].edges;
        int n_edges = static_cast<int>(edges.size());
        if (in.edge < 0 || in.edge >= n_edges)
          return problem(path + ".edge",
                         "no such edge in this node (it has " + std::to_string(n_edges) + ")",
                         in.edge);
        int to = edges[in.edge].to;
        return has(count(g_.nodes[to]), "in the child node " + std::to_string(to));
      }
      case SourcePlace::Root: return has(count(g_.nodes[0]), "in the root node");
      case SourcePlace::Global: {
        if (!neuron) return problem(ipath, "global sources read neurons only", in.index);
        int n = static_cast<int>(g_.global_neurons.size());
        if (in.index >= 0 && in.index < n) return std::nullopt;
        return problem(ipath, "no such global neuron (there are " + std::to_string(n) + ")",
                       in.index);
      }
    }
    return std::nullopt;
  }

  Problem check_sensors(const NodeGene& node, const std::string& path) const {
    int n = static_cast<int>(node.sensors.size());
    if (r_.max_sensors_per_part > 0 && n > r_.max_sensors_per_part)
      return problem(path + ".sensors",
                     "at most " + std::to_string(r_.max_sensors_per_part) + " sensor(s) per part" +
                         in_dialect(r_),
                     n);
    for (int s = 0; s < n; ++s) {
      const SensorGene& sg = node.sensors[s];
      std::string spath = path + ".sensors[" + std::to_string(s) + "]";
      if (!contains(r_.sensors, sg.type))
        return problem(
            spath + ".type",
            "sensor type not allowed" + in_dialect(r_) + " (" +
                expected(join(r_.sensors, [](SensorType t) { return std::string(to_string(t)); }),
                         r_.sensors.size()) +
                ")",
            std::string(to_string(sg.type)));
      if (sg.type == SensorType::JointAngle)
        if (auto p = check_dof(sg.dof, node.joint.type, spath + ".dof")) return p;
      if (sg.type == SensorType::Photoreceptor)
        if (auto p = check_direction(sg.direction, spath + ".direction")) return p;
    }
    return std::nullopt;
  }

  Problem check_effectors(const NodeGene& node, const std::string& path, int owner) const {
    int n = static_cast<int>(node.effectors.size());
    if (r_.max_effectors_per_part > 0 && n > r_.max_effectors_per_part)
      return problem(path + ".effectors",
                     "at most " + std::to_string(r_.max_effectors_per_part) +
                         " effector(s) per part" + in_dialect(r_),
                     n);
    for (int e = 0; e < n; ++e) {
      const EffectorGene& eg = node.effectors[e];
      std::string epath = path + ".effectors[" + std::to_string(e) + "]";
      if (r_.muscle_effectors) {
        if (auto p = check_muscle(eg, epath)) return p;
      } else {
        if (eg.muscle)
          return problem(epath + ".muscle", "no muscles" + in_dialect(r_) + " (effectors drive joints)",
                         true);
        if (auto p = check_dof(eg.dof, node.joint.type, epath + ".dof")) return p;
      }
      if (!std::isfinite(eg.bias)) return problem(epath + ".bias", "must be finite", eg.bias);
      if (auto p = check_bias(eg.bias, epath + ".bias")) return p;
      // the dialect's input bound applies to effectors too (miconi2006: actuator neurons)
      int n_in = static_cast<int>(eg.inputs.size());
      if (r_.max_inputs_per_neuron > 0 && n_in > r_.max_inputs_per_neuron)
        return problem(epath + ".inputs",
                       "too many inputs (at most " + std::to_string(r_.max_inputs_per_neuron) +
                           ")" + in_dialect(r_),
                       n_in);
      if (auto p = check_inputs(eg.inputs, epath, owner)) return p;
    }
    return std::nullopt;
  }

  // a muscle dialect's effector: its muscle, whatever the joint
  Problem check_muscle(const EffectorGene& eg, const std::string& path) const {
    if (!eg.muscle)
      return problem(path + ".muscle", "every effector is a muscle" + in_dialect(r_), nullptr);
    if (eg.dof != 0) return problem(path + ".dof", "a muscle has no degree of freedom (0)", eg.dof);
    const MuscleGene& m = *eg.muscle;
    if (auto p = check_direction(m.parent_dir, path + ".muscle.parent_dir")) return p;
    if (auto p = check_direction(m.child_dir, path + ".muscle.child_dir")) return p;
    if (!std::isfinite(m.strength) || !(m.strength > 0) || m.strength > kMaxMuscleStrength)
      return problem(path + ".muscle.strength", "must lie in (0, " + json(kMaxMuscleStrength).dump() + "] N/m",
                     m.strength);
    return std::nullopt;
  }

  // a direction from a part's centre (photoreceptor, muscle anchor): finite, not zero
  static Problem check_direction(Vec3 d, const std::string& path) {
    if (!finite(d) || !(norm(d) > 1e-9))
      return problem(path, "a direction must be finite and not zero", vec_json(d));
    return std::nullopt;
  }

  static Problem check_dof(int dof, JointType t, const std::string& path) {
    int dofs = joint_dofs(t);
    if (dof >= 0 && dof < dofs) return std::nullopt;
    return problem(path,
                   "no such degree of freedom of a " + std::string(to_string(t)) +
                       " joint (it has " + std::to_string(dofs) + ")",
                   dof);
  }

  Problem check_edge(const EdgeGene& e, const std::string& path) const {
    if (!std::isfinite(e.u) || !std::isfinite(e.v) || std::abs(e.u) > 1 || std::abs(e.v) > 1)
      return problem(path + ".at", "must lie in [-1, 1] x [-1, 1]", json::array({e.u, e.v}));
    if (!finite(e.rotation))
      return problem(path + ".rotation", "angles must be finite", vec_json(e.rotation));
    if (!r_.edge_roll_free && std::abs(e.rotation.x) > kTol)
      return problem(path + ".rotation", "roll (x) must be 0" + in_dialect(r_),
                     vec_json(e.rotation));
    if (r_.angle_step > 0)
      for (int a = 0; a < 3; ++a) {
        double k = e.rotation[a] / r_.angle_step;
        if (std::abs(e.rotation[a] - std::round(k) * r_.angle_step) > kTol)
          return problem(
              path + ".rotation",
              "each angle must be a multiple of " + angle_text(r_.angle_step) + in_dialect(r_),
              vec_json(e.rotation));
      }
    if (!std::isfinite(e.scale) || !(e.scale > 0))
      return problem(path + ".scale", "must be > 0", e.scale);
    if (e.scale < kMinEdgeScale || e.scale > kMaxEdgeScale)
      return problem(path + ".scale", "must lie in " + range_text(kMinEdgeScale, kMaxEdgeScale),
                     e.scale);
    for (std::size_t a = 0; a < e.reflect.size(); ++a) {
      int axis = e.reflect[a];
      if (!contains(r_.reflect_axes, axis))
        return problem(
            path + ".reflect",
            "reflection axis not allowed" + in_dialect(r_) + " (" +
                expected(join(r_.reflect_axes, [](int x) { return std::string(axis_name(x)); }),
                         r_.reflect_axes.size()) +
                ")",
            reflect_json(e.reflect));
      for (std::size_t b = 0; b < a; ++b)
        if (e.reflect[b] == axis)
          return problem(path + ".reflect", "repeated axis", reflect_json(e.reflect));
    }
    return std::nullopt;
  }

  const Genome& g_;
  const DialectRules& r_;
};

}  // namespace

const DialectRules& dialect_rules(Dialect d) {
  static const DialectRules sims1994 = sims1994_rules();
  static const DialectRules miconi2006 = miconi2006_rules();
  static const DialectRules chaumont2007 = chaumont2007_rules();
  static const DialectRules lessin2015 = lessin2015_rules();
  switch (d) {
    case Dialect::Sims1994: return sims1994;
    case Dialect::Miconi2006: return miconi2006;
    case Dialect::Chaumont2007: return chaumont2007;
    case Dialect::Lessin2015: return lessin2015;
  }
  return sims1994;
}

std::optional<Dialect> parse_dialect(std::string_view name) {
  for (Dialect d : {Dialect::Sims1994, Dialect::Miconi2006, Dialect::Chaumont2007, Dialect::Lessin2015})
    if (to_string(d) == name) return d;
  return std::nullopt;
}

Status validate(const Genome& g) {
  if (auto p = Validator(g).run()) return Error{*p};
  return Ok{};
}

}  // namespace bx
