// Operator constants per dialect, random creation, and the building blocks
// the other operators share (operators.h).
#include <algorithm>
#include <cassert>
#include <cmath>

#include "brain/neuron_set.h"
#include "genome/dialect.h"
#include "genome/genome_edit.h"
#include "genome/operators.h"
#include "genome/operators_detail.h"

namespace bx {

// ---------------------------------------------------------------- defaults

OperatorDef default_operators(Dialect d) {
  // The one place the operators' constants are set. Sources are given per
  // field in operators.h and tabulated in docs/operators.md.
  OperatorDef def;
  def.dialect = d;
  // ---- shared by the dialects (our choices unless a paper is named)
  def.min_genes = 2;
  def.genes_at_creation = {2, 5};
  def.max_parts_at_creation = 0;  // the dialect's max_parts
  def.density = 1000;             // water, the genome's default
  def.mutate_density = false;
  def.density_range = {500, 2000};
  def.angle_limit_min = 0.3;
  def.angle_limit_max = kPi / 2;
  def.slide_limit_max = 0.2;
  def.recursive_limit_max = 4;
  def.scale_range = {0.5, 1.5};
  def.scale_at_creation = {0.8, 1.0};
  def.p_reflexive_edge = 0.15;
  def.p_extra_edge = 0.1;
  def.p_terminal_only = 0.05;
  def.edge_roll_max = kPi;
  def.min_sibling_angle = kPi / 3;
  def.neurons_at_creation = {0, 3};
  def.global_neurons_at_creation = {0, 1};
  def.sensors_at_creation = {0, 2};
  def.p_effector_per_dof = 0.8;
  def.effector_inputs_at_creation = {1, 2};
  def.muscles_at_creation = {1, 2};
  // a 10 cm stretch of a full-strength muscle pulls with 10 N to 2 kN: a 2 kg
  // part (sizes below, water) weighs 20 N
  def.muscle_strength_range = {100, 20000};
  def.connection_fraction = 0.75;  // miconi2006 Table 1
  def.connection_slots = 3;        // miconi2006 Table 1
  def.neuron_slots = 6;            // miconi2006 Table 1
  def.bias_range = {-1.5, 1.5};    // miconi2006 sec. 3
  def.effector_bias_range = {-0.5, 0.5};
  def.p_global_neuron = 0.1;
  def.bias_step = 0.33;                // miconi2006 5.1
  def.weight_step = 0.33;              // miconi2006 5.1
  def.angle_step = kPi / 8;            // miconi2006 sec. 2 (5.1's pi/4: see the field's comment)
  def.angle_mutation_range = kPi / 2;  // miconi2006 5.1
  def.miconi_steps = kMiconiAllSteps;
  def.param_sigma = 0.15;
  def.size_sigma = 0.25;
  def.angle_sigma = 0.4;
  // graph dialects: structural mutation rates per mutate() call
  StructuralRates graph;
  graph.add_node = 0.1;
  graph.remove_node = 0.05;
  graph.add_edge = 0.05;
  graph.remove_edge = 0.05;
  graph.retarget_edge = 0.05;
  graph.add_neuron = 0.1;
  graph.remove_neuron = 0.05;
  graph.add_sensor = 0.05;
  graph.remove_sensor = 0.05;
  graph.add_effector = 0.05;
  graph.remove_effector = 0.05;
  graph.change_fn = 0.1;
  switch (d) {
    case Dialect::Sims1994:
      def.max_genes = 20;  // our choice (the dialect has no limit)
      // part sizes of the example creatures (creatures/): 5 cm to 60 cm
      def.size_min = {0.1, 0.05, 0.05};
      def.size_max = {0.6, 0.4, 0.4};
      def.shape_weights = {
          {Shape::Box, 0.7}, {Shape::Sphere, 0.1}, {Shape::Capsule, 0.1}, {Shape::Cylinder, 0.1}};
      def.joint_weights = {{JointType::Hinge, 0.4},     {JointType::Universal, 0.2},
                           {JointType::Spherical, 0.1}, {JointType::Fixed, 0.1},
                           {JointType::Slider, 0.1},    {JointType::Cylindrical, 0.1}};
      def.p_reflect = 0.2;
      def.weight_range = {-2, 2};
      def.structure = graph;
      break;
    case Dialect::Miconi2006:
      def.max_genes = 7;                                                          // Table 1
      // our choice: limbs 0.2-1.0 m long, 0.1-0.5 m thick weigh 1.6 g to 0.2 kg
      // (0.8 tanh(xyz), Table 1); a 4 N motor (Table 1) swings the heaviest
      def.size_min = {0.2, 0.1, 0.1};
      def.size_max = {1.0, 0.5, 0.5};
      def.shape_weights = {{Shape::Box, 1}};        // sec. 2: blocks
      def.joint_weights = {{JointType::Hinge, 1}};  // sec. 2: hinges
      def.p_reflect = 0.1;                          // 4.1: P_ref
      def.edge_roll_max = 0;                        // sec. 2: two polar angles
      def.scale_at_creation = {1, 1};
      def.p_terminal_only = 0;
      def.p_reflexive_edge = 0;  // sec. 2: no loops
      def.p_extra_edge = 0;
      def.neurons_at_creation = {1, 3};  // our choice, within Table 1's 6
      def.global_neurons_at_creation = {0, 0};
      def.weight_range = {-1, 1};             // sec. 3
      def.effector_bias_range = {-1.5, 1.5};  // 3.1: the actuator is a neuron with a threshold
      def.structure = {};                     // miconi2006 has its own sequence (5.1)
      break;
    case Dialect::Chaumont2007:
      def.max_genes = 20;                                             // 5.5: n_max
      def.size_min = {0.1, 0.05, 0.05};
      def.size_max = {0.6, 0.4, 0.4};
      def.shape_weights = {{Shape::Box, 1}};                                    // 3.1: cuboids
      def.joint_weights = {{JointType::Hinge, 0.9}, {JointType::Slider, 0.1}};  // 5.1: 1 dof
      def.p_reflect = 0.2;
      def.weight_range = {-1, 1};  // Table I: values in [-1, 1]
      def.structure = graph;
      break;
    case Dialect::Lessin2015:
      def.max_genes = 20;  // the dialect's bound (our choice)
      def.size_min = {0.1, 0.05, 0.05};
      def.size_max = {0.6, 0.4, 0.4};
      // III-B: boxes, spheres and capsules; a photoreceptor (its only sensor,
      // III-D) on some parts at creation
      def.shape_weights = {{Shape::Box, 0.5}, {Shape::Sphere, 0.25}, {Shape::Capsule, 0.25}};
      def.joint_weights = {{JointType::Hinge, 0.4},  {JointType::Spherical, 0.3},
                           {JointType::Fixed, 0.1},  {JointType::Slider, 0.1},
                           {JointType::Cylindrical, 0.1}};
      def.sensors_at_creation = {0, 1};
      def.p_reflect = 0.2;
      def.weight_range = {-1, 1};
      def.effector_bias_range = {0, 0.5};  // a muscle's resting activation, in the set's [0, 1]
      def.structure = graph;
      break;
  }
  return def;
}

// ---------------------------------------------------------------- small draws

double normal(Rng& rng) {
  double u1 = 1.0 - rng.uniform();  // (0, 1]
  double u2 = rng.uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2 * kPi * u2);
}

namespace {

int uniform_int(Rng& rng, int lo, int hi) {
  if (hi <= lo) return lo;
  return lo + static_cast<int>(rng.below(static_cast<std::uint64_t>(hi - lo + 1)));
}

Range intersect(Range r, double bound) {
  if (bound <= 0) return r;
  return {std::max(r.lo, -bound), std::min(r.hi, bound)};
}

// weighted draw among the allowed items; the first allowed item if no weight applies
template <class T>
T pick_weighted(const std::vector<std::pair<T, double>>& weights, const std::vector<T>& allowed,
                Rng& rng) {
  double total = 0;
  for (const auto& [x, w] : weights)
    if (w > 0 && std::find(allowed.begin(), allowed.end(), x) != allowed.end()) total += w;
  if (total <= 0) return allowed.front();
  double r = rng.uniform() * total;
  for (const auto& [x, w] : weights) {
    if (!(w > 0) || std::find(allowed.begin(), allowed.end(), x) == allowed.end()) continue;
    if (r < w) return x;
    r -= w;
  }
  for (auto it = weights.rbegin(); it != weights.rend(); ++it)
    if (it->second > 0 && std::find(allowed.begin(), allowed.end(), it->first) != allowed.end())
      return it->first;
  return allowed.front();
}

bool dof_is_angular(JointType t, int dof) {
  switch (t) {
    case JointType::Slider:
      return false;
    case JointType::Cylindrical:
      return dof == 1;
    default:
      return true;
  }
}

// the axis through whose face the ray from the centre along d leaves the box
int exit_axis(Vec3 size, Vec3 d) {
  int a = 0;
  double t = 1e300;
  for (int i = 0; i < 3; ++i)
    if (std::abs(d[i]) > 1e-12 && size[i] / 2 / std::abs(d[i]) < t) {
      t = size[i] / 2 / std::abs(d[i]);
      a = i;
    }
  return a;
}

double angle_between(Vec3 a, Vec3 b) {
  return std::acos(std::clamp(dot(normalized(a), normalized(b)), -1.0, 1.0));
}

// direction from polar angles (rotation ry about y after rz about z, applied to x)
Vec3 polar(double ry, double rz) {
  return {std::cos(ry) * std::cos(rz), std::sin(rz), -std::sin(ry) * std::cos(rz)};
}

// An oriented box in a parent's frame: centre, rotation, half extents.
struct Box {
  Vec3 c;
  Mat3 R;
  Vec3 h;
};

// Separating-axis test of two oriented boxes, each shrunk by `margin` on every
// side (as develop()'s self-intersection test), so that touching is no overlap.
bool overlap(const Box& a, const Box& b, double margin) {
  Vec3 ha{std::max(a.h.x - margin, 0.0), std::max(a.h.y - margin, 0.0),
          std::max(a.h.z - margin, 0.0)};
  Vec3 hb{std::max(b.h.x - margin, 0.0), std::max(b.h.y - margin, 0.0),
          std::max(b.h.z - margin, 0.0)};
  Vec3 A[3] = {a.R.column(0), a.R.column(1), a.R.column(2)};
  Vec3 B[3] = {b.R.column(0), b.R.column(1), b.R.column(2)};
  Vec3 t = b.c - a.c;
  auto separates = [&](Vec3 L) {
    double n = norm(L);
    if (n < 1e-9) return false;
    L = (1.0 / n) * L;
    double ra = 0, rb = 0;
    for (int i = 0; i < 3; ++i) {
      ra += std::abs(dot(A[i], L)) * ha[i];
      rb += std::abs(dot(B[i], L)) * hb[i];
    }
    return std::abs(dot(t, L)) > ra + rb;
  };
  for (int i = 0; i < 3; ++i)
    if (separates(A[i]) || separates(B[i])) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (separates(cross(A[i], B[j]))) return false;
  return true;
}

// The box a child grows through edge e, in the parent's frame (nominal
// sizes: the scale of the edge only; boxes for every shape).
Box child_box(const EdgeGene& e, Vec3 parent_size, Vec3 child_size) {
  int a = face_axis(e.face), b = (a + 1) % 3, c = (a + 2) % 3;
  if (b > c) std::swap(b, c);
  Vec3 q;
  q[a] = face_sign(e.face) * parent_size[a] / 2;
  q[b] = e.u * parent_size[b] / 2;
  q[c] = e.v * parent_size[c] / 2;
  Box x;
  x.R = face_frame(e.face) * euler_xyz(e.rotation);
  x.h = (e.scale / 2) * child_size;
  x.c = q + x.R * Vec3{x.h.x, 0, 0};
  return x;
}

Box mirrored(Box x, int axis) {
  x.c[axis] = -x.c[axis];
  Vec3 f{1, 1, 1};
  f[axis] = -1;
  x.R = Mat3::diag(f.x, f.y, f.z) * x.R;
  return x;
}

// every copy an edge grows (2^n reflections)
std::vector<Box> copies_of(const EdgeGene& e, Vec3 parent_size, Vec3 child_size) {
  std::vector<Box> out;
  Box x = child_box(e, parent_size, child_size);
  int n = 1 << e.reflect.size();
  for (int mask = 0; mask < n; ++mask) {
    Box m = x;
    for (std::size_t r = 0; r < e.reflect.size(); ++r)
      if (mask & (1 << r)) m = mirrored(m, e.reflect[r]);
    out.push_back(m);
  }
  return out;
}

// Chooses the direction of a new edge from `parent` (to a child of size
// `child`) and places it: the child must not overlap the parent's other
// children (and their reflected copies), the parent's own parents, or its own
// reflected copy, and should point away from its siblings by
// def.min_sibling_angle. With `avoid_back` (a parent that hangs from
// something at its -x side) the child points forward (d.x >= 0). `reflect`:
// the child is mirrored (miconi: across y, leaving the parent through a +-y
// face; graph dialects: across its face's axis).
// Returns whether the placement found is clear of overlaps.
bool place_new_edge(const Genome& g, int parent, EdgeGene& e, Vec3 child, bool avoid_back,
                    bool reflect, const OperatorDef& def, Rng& rng) {
  const DialectRules& r = dialect_rules(g.dialect);
  bool lattice = r.edge_lattice;
  const NodeGene& pn = g.nodes[parent];
  Vec3 P = pn.size;
  // what is already there, in the parent's frame
  std::vector<Vec3> taken;
  std::vector<Box> obstacles;
  for (const EdgeGene& s : pn.edges)
    for (const Box& x : copies_of(s, P, g.nodes[s.to].size)) {
      obstacles.push_back(x);
      taken.push_back(x.R.column(0));
    }
  // the parent's own parents (a reflexive edge: another copy of the parent)
  for (int gp : parents_of(g, parent)) {
    for (const EdgeGene& s : g.nodes[gp].edges) {
      if (s.to != parent) continue;
      // the grandparent seen from the parent: invert the parent's placement,
      // in units of the parent's own size (the edge scales the parent)
      Box me = child_box(s, g.nodes[gp].size, P);
      Mat3 Rt = me.R.transposed();
      double k = 1.0 / s.scale;
      obstacles.push_back({k * (Rt * (-1.0 * me.c)), Rt, (0.5 * k) * g.nodes[gp].size});
    }
  }
  const double margin = 0.005;  // develop()'s default overlap margin
  int half = lattice ? static_cast<int>(std::lround(kPi / def.angle_step)) : 0;  // 8 for pi/8
  double roll = e.rotation.x;
  EdgeGene best = e;
  double best_score = -1;
  bool best_clear = false;
  bool have = false;
  for (int t = 0; t < 32; ++t) {
    Vec3 d;
    if (lattice) {
      int lon =
          avoid_back ? uniform_int(rng, -half / 2, half / 2) : uniform_int(rng, -half + 1, half);
      int lat = uniform_int(rng, -half / 2, half / 2);
      d = polar(lon * def.angle_step, lat * def.angle_step);
    } else {
      d = normalized(Vec3{normal(rng), normal(rng), normal(rng)});
      if (avoid_back && d.x < 0) d.x = -d.x;
    }
    if (reflect && lattice && exit_axis(P, d) != 1) continue;
    // recursion: a chain of copies that turns too much curls into itself
    if (e.to == parent && !lattice && d.x < std::cos(kPi / 4)) continue;
    EdgeGene c = e;
    place_edge(c, P, d, roll, r.angle_step);
    c.reflect.clear();
    if (reflect) {
      int axis = lattice ? 1 : face_axis(c.face);
      if (std::find(r.reflect_axes.begin(), r.reflect_axes.end(), axis) != r.reflect_axes.end())
        c.reflect = {axis};
    }
    std::vector<Box> mine = copies_of(c, P, child);
    bool clear = true;
    if (e.to == parent) {
      // recursion: the copy grown through this edge must clear the copy it hangs from
      Box me = child_box(c, P, P);
      Mat3 Rt = me.R.transposed();
      double k = 1.0 / c.scale;
      Box prev{k * (Rt * (-1.0 * me.c)), Rt, (0.5 * k) * P};
      for (const Box& m : mine) clear = clear && !overlap(m, prev, margin);
    }
    for (std::size_t i = 0; i < mine.size() && clear; ++i) {
      for (std::size_t j = i + 1; j < mine.size() && clear; ++j)
        clear = !overlap(mine[i], mine[j], margin);
      for (const Box& o : obstacles)
        if (clear && overlap(mine[i], o, margin)) clear = false;
    }
    double score = kPi;
    for (const Box& m : mine)
      for (Vec3 x : taken) score = std::min(score, angle_between(m.R.column(0), x));
    if (clear && score >= def.min_sibling_angle) {
      e = c;
      return true;
    }
    if (!have || (clear && !best_clear) || (clear == best_clear && score > best_score)) {
      have = true;
      best = c;
      best_clear = clear;
      best_score = score;
    }
  }
  if (!have) {
    // every draw broke a rule: straight out of a +-y face (miconi reflection), else forward
    Vec3 d = reflect && lattice ? Vec3{0, rng.chance(0.5) ? 1.0 : -1.0, 0} : Vec3{1, 0, 0};
    best = e;
    place_edge(best, P, d, roll, r.angle_step);
    best.reflect.clear();
    int axis = lattice ? 1 : face_axis(best.face);
    if (reflect &&
        std::find(r.reflect_axes.begin(), r.reflect_axes.end(), axis) != r.reflect_axes.end())
      best.reflect = {axis};
  }
  e = best;
  return best_clear;
}

JointGene random_joint(Dialect d, const OperatorDef& def, Rng& rng) {
  const DialectRules& r = dialect_rules(d);
  JointGene j;
  j.type = pick_weighted(def.joint_weights, r.joints, rng);
  bool y = rng.chance(0.5);
  Vec3 ey{0, 1, 0}, ez{0, 0, 1}, ex{1, 0, 0};
  switch (j.type) {
    case JointType::Hinge:
    case JointType::Universal:
    case JointType::Spherical:
      // swing across the limb's length
      j.axis1 = y ? ey : ez;
      j.axis2 = y ? ez : ey;
      break;
    case JointType::Slider:
    case JointType::Cylindrical:
      // slide (and twist) along the limb
      j.axis1 = ex;
      j.axis2 = ey;
      break;
    case JointType::Fixed:
      break;
  }
  if (dialect_rules(d).hinge_limits_fixed) return j;  // limits fixed by the dialect (miconi2006 Table 1)
  if (dialect_rules(d).joined_parts_collide) return j;  // limited by collisions (lessin2015 III-B)
  for (int k = 0; k < joint_dofs(j.type); ++k) {
    if (dof_is_angular(j.type, k))
      j.limits.push_back({-rng.uniform(def.angle_limit_min, def.angle_limit_max),
                          rng.uniform(def.angle_limit_min, def.angle_limit_max)});
    else
      j.limits.push_back(
          {-rng.uniform(0, def.slide_limit_max), rng.uniform(0, def.slide_limit_max)});
  }
  return j;
}

SensorGene random_sensor(Dialect d, const NodeGene& node, bool has_joint, Rng& rng) {
  const DialectRules& r = dialect_rules(d);
  bool angle_ok =
      has_joint && joint_dofs(node.joint.type) > 0 &&
      std::find(r.sensors.begin(), r.sensors.end(), SensorType::JointAngle) != r.sensors.end();
  bool contact_ok =
      std::find(r.sensors.begin(), r.sensors.end(), SensorType::Contact) != r.sensors.end();
  SensorGene s;
  if (!angle_ok && !contact_ok) {
    // lessin2015: photoreceptors only
    s.type = SensorType::Photoreceptor;
    s.direction = random_direction(rng);
  } else if (angle_ok && (!contact_ok || rng.chance(0.5))) {
    s.type = SensorType::JointAngle;
    s.dof = uniform_int(rng, 0, joint_dofs(node.joint.type) - 1);
  } else {
    s.type = SensorType::Contact;
    s.face = static_cast<Face>(rng.below(6));
  }
  return s;
}

// whether node n grows with a parent (non-root, or the root reached again)
bool has_parent(const Genome& g, int n) { return n != 0 || !parents_of(g, 0).empty(); }

}  // namespace

Range weight_bounds(const OperatorDef& def, Dialect d) {
  return intersect(def.weight_range, dialect_rules(d).max_abs_weight);
}
Range bias_bounds(const OperatorDef& def, Dialect d) {
  return intersect(def.bias_range, dialect_rules(d).max_abs_bias);
}
Range effector_bias_bounds(const OperatorDef& def, Dialect d) {
  return intersect(def.effector_bias_range, dialect_rules(d).max_abs_bias);
}

// ---------------------------------------------------------------- building blocks

Vec3 random_direction(Rng& rng) {
  for (;;) {
    Vec3 d{normal(rng), normal(rng), normal(rng)};
    if (norm(d) > 1e-6) return normalized(d);
  }
}

MuscleGene random_muscle(const OperatorDef& def, Rng& rng) {
  MuscleGene m;
  m.parent_dir = random_direction(rng);
  m.child_dir = random_direction(rng);
  const Range& k = def.muscle_strength_range;
  m.strength = k.lo * std::exp(rng.uniform() * std::log(k.hi / k.lo));
  return m;
}

NeuronGene random_neuron(Dialect d, const OperatorDef& def, Rng& rng) {
  NeuronSetId set = dialect_rules(d).neuron_set;
  std::vector<std::string_view> names = neuron_fn_names(set);
  const NeuronFnSpec* spec = find_neuron_fn(set, names[rng.below(names.size())]);
  NeuronGene n;
  n.fn = std::string(spec->name);
  for (const ParamSpec& p : spec->params) {
    double v = p.integer ? uniform_int(rng, static_cast<int>(p.min), static_cast<int>(p.max))
                         : rng.uniform(p.min, p.max);
    n.params.push_back(v);
  }
  if (spec->mode == InputMode::WeightedSum) {
    Range b = bias_bounds(def, d);
    n.bias = rng.uniform(b.lo, b.hi);
  }
  return n;
}

NodeGene random_part(Dialect d, bool root, const OperatorDef& def, Rng& rng) {
  const DialectRules& r = dialect_rules(d);
  NodeGene n;
  n.shape = pick_weighted(def.shape_weights, r.shapes, rng);
  for (int a = 0; a < 3; ++a) n.size[a] = rng.uniform(def.size_min[a], def.size_max[a]);
  n.density = def.density;
  n.joint = random_joint(d, def, rng);
  n.recursive_limit = 1;
  if (r.limb_io) {
    // miconi2006 sec. 3.1 and Fig. 1: one joint-angle sensor and one actuator per limb, none on the root
    if (!root) {
      n.sensors.push_back({SensorType::JointAngle, 0, Face::NegZ});
      Range b = effector_bias_bounds(def, d);
      n.effectors.push_back({0, rng.uniform(b.lo, b.hi), {}});
    }
    int k = std::min(uniform_int(rng, def.neurons_at_creation.lo, def.neurons_at_creation.hi),
                     def.neuron_slots);
    for (int i = 0; i < k; ++i) n.neurons.push_back(random_neuron(d, def, rng));
    return n;
  }
  int sensors = uniform_int(rng, def.sensors_at_creation.lo, def.sensors_at_creation.hi);
  for (int i = 0; i < sensors; ++i) n.sensors.push_back(random_sensor(d, n, !root, rng));
  if (!root && r.muscle_effectors) {
    // lessin2015 III-E: muscles to the parent, whatever the joint
    Range b = effector_bias_bounds(def, d);
    int k = uniform_int(rng, def.muscles_at_creation.lo, def.muscles_at_creation.hi);
    for (int i = 0; i < k; ++i) {
      EffectorGene e{0, rng.uniform(b.lo, b.hi), {}};
      e.muscle = random_muscle(def, rng);
      n.effectors.push_back(std::move(e));
    }
  } else if (!root) {
    Range b = effector_bias_bounds(def, d);
    for (int k = 0; k < joint_dofs(n.joint.type); ++k)
      if (rng.chance(def.p_effector_per_dof))
        n.effectors.push_back({k, rng.uniform(b.lo, b.hi), {}});
  }
  int k = uniform_int(rng, def.neurons_at_creation.lo, def.neurons_at_creation.hi);
  for (int i = 0; i < k; ++i) n.neurons.push_back(random_neuron(d, def, rng));
  return n;
}

namespace {

// random_edge(), also telling whether the child is clear of overlaps
EdgeGene random_edge_checked(const Genome& g, int parent, int to, const OperatorDef& def, Rng& rng,
                             bool& clear) {
  const DialectRules& r = dialect_rules(g.dialect);
  EdgeGene e;
  e.to = to;
  e.rotation.x = r.edge_roll_free ? rng.uniform(-def.edge_roll_max, def.edge_roll_max) : 0.0;
  e.scale = r.edge_scale_free ? rng.uniform(def.scale_at_creation.lo, def.scale_at_creation.hi) : 1.0;
  e.terminal_only = r.edge_terminal_only && rng.chance(def.p_terminal_only);
  // a reflexive edge grows copies of the parent at its own side: no mirrored chains
  bool reflect = to != parent && !r.reflect_axes.empty() && rng.chance(def.p_reflect);
  bool avoid_back = has_parent(g, parent) || to == parent;
  clear = place_new_edge(g, parent, e, g.nodes[to].size, avoid_back, reflect, def, rng);
  return e;
}

}  // namespace

EdgeGene random_edge(const Genome& g, int parent, int to, const OperatorDef& def, Rng& rng) {
  bool clear = false;
  return random_edge_checked(g, parent, to, def, rng, clear);
}

int add_random_node(Genome& g, int parent, const OperatorDef& def, Rng& rng) {
  int n = static_cast<int>(g.nodes.size());
  EdgeGene e;
  // a part that finds no clear place (e.g. thicker than a short parent is
  // long) is drawn again, a few times
  for (int attempt = 0; attempt < 4; ++attempt) {
    if (attempt > 0) g.nodes.pop_back();
    g.nodes.push_back(random_part(g.dialect, false, def, rng));
    bool clear = false;
    e = random_edge_checked(g, parent, n, def, rng, clear);
    if (clear) break;
  }
  g.nodes[parent].edges.push_back(e);
  return n;
}

bool random_input(const Genome& g, int owner, const OperatorDef& def, Rng& rng, InputGene& out) {
  std::vector<InputGene> cands = source_candidates(g, owner);
  if (cands.empty()) return false;
  out = cands[rng.below(cands.size())];
  Range w = weight_bounds(def, g.dialect);
  out.weight = rng.uniform(w.lo, w.hi);
  return true;
}

std::vector<InputGene> random_inputs(const Genome& g, int owner, int count, const OperatorDef& def,
                                     Rng& rng) {
  std::vector<InputGene> out;
  for (int k = 0; k < count; ++k) {
    InputGene in;
    if (random_input(g, owner, def, rng, in)) out.push_back(in);
  }
  return out;
}

namespace {

// how many inputs a new neuron gets: miconi slots filled at the connection
// fraction, a positional function's arity
int new_neuron_inputs(const Genome& g, const NeuronGene& n, const OperatorDef& def, Rng& rng) {
  const NeuronFnSpec* spec = find_neuron_fn(dialect_rules(g.dialect).neuron_set, n.fn);
  if (spec->mode == InputMode::Positional) return spec->max_inputs;
  int most = std::min(def.connection_slots, spec->max_inputs);
  int k = 0;
  for (int s = 0; s < most; ++s) k += rng.chance(def.connection_fraction);
  return k;
}

int new_effector_inputs(const Genome& g, const OperatorDef& def, Rng& rng) {
  if (!dialect_rules(g.dialect).slot_wiring)
    return uniform_int(rng, def.effector_inputs_at_creation.lo, def.effector_inputs_at_creation.hi);
  int k = 0;
  for (int s = 0; s < def.connection_slots; ++s) k += rng.chance(def.connection_fraction);
  return k;
}

}  // namespace

void wire_node(Genome& g, int n, const OperatorDef& def, Rng& rng) {
  auto& neurons = n >= 0 ? g.nodes[n].neurons : g.global_neurons;
  for (std::size_t k = 0; k < neurons.size(); ++k) {
    int count = new_neuron_inputs(g, neurons[k], def, rng);
    neurons[k].inputs = random_inputs(g, n, count, def, rng);
  }
  if (n < 0) return;
  for (auto& ef : g.nodes[n].effectors) {
    int count = new_effector_inputs(g, def, rng);
    ef.inputs = random_inputs(g, n, count, def, rng);
  }
}

// ---------------------------------------------------------------- normalize

void normalize(Genome& g, const OperatorDef& def, Rng& rng) {
  const DialectRules& r = dialect_rules(g.dialect);
  remove_unreachable(g, SourceFix::Reassign, &rng);
  auto allowed_sensor = [&r](SensorType t) {
    return std::find(r.sensors.begin(), r.sensors.end(), t) != r.sensors.end();
  };
  // neurons: known function, parameters in range, inputs within the arity
  auto fit_neuron = [&](NeuronGene& nr) {
    const NeuronFnSpec* spec = find_neuron_fn(r.neuron_set, nr.fn);
    if (!spec) {
      NeuronGene fresh = random_neuron(g.dialect, def, rng);
      nr.fn = fresh.fn;
      nr.params = fresh.params;
      nr.bias = fresh.bias;
      spec = find_neuron_fn(r.neuron_set, nr.fn);
    }
    nr.params.resize(spec->params.size());
    for (std::size_t p = 0; p < spec->params.size(); ++p) {
      const ParamSpec& ps = spec->params[p];
      double v = std::isfinite(nr.params[p]) ? nr.params[p] : ps.default_value;
      v = std::clamp(v, ps.min, ps.max);
      if (ps.integer) v = std::round(v);
      nr.params[p] = v;
    }
    if (spec->mode == InputMode::Positional) {
      nr.bias = 0;
    } else {
      Range b = bias_bounds(def, g.dialect);
      nr.bias = std::clamp(nr.bias, b.lo, b.hi);
    }
    int most = spec->max_inputs;
    if (r.max_inputs_per_neuron > 0) most = std::min(most, r.max_inputs_per_neuron);
    if (static_cast<int>(nr.inputs.size()) > most) nr.inputs.resize(most);
  };
  // global neurons
  if (!r.global_neurons)
    while (!g.global_neurons.empty())
      remove_global_neuron(g, static_cast<int>(g.global_neurons.size()) - 1, SourceFix::Reassign,
                           &rng);
  // a catapult (validate()'s check_catapult): one arm, no edge leads to it;
  // its projectile a box grown once, held by a fixed joint, whatever the
  // dialect's joints
  const int projectile = is_catapult(g) ? g.catapult->projectile : -1;
  if (projectile > 0) remove_edges_to(g, 0, SourceFix::Reassign, &rng);
  for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i) {
    NodeGene& n = g.nodes[i];
    if (i == projectile) {
      n.shape = Shape::Box;
      n.recursive_limit = 1;
      continue;
    }
    // body
    if (std::find(r.shapes.begin(), r.shapes.end(), n.shape) == r.shapes.end())
      n.shape = r.shapes[0];
    if (std::find(r.joints.begin(), r.joints.end(), n.joint.type) == r.joints.end()) {
      n.joint.type = r.joints[0];
      n.joint.limits.clear();
    }
    int dofs = joint_dofs(n.joint.type);
    if (!n.joint.limits.empty() && static_cast<int>(n.joint.limits.size()) != dofs)
      n.joint.limits.clear();
    if (r.hinge_axis_y_or_z && n.joint.type == JointType::Hinge) {
      // miconi2006 sec. 2: the hinge axis is the limb's y or z axis (validate()'s tolerance)
      Vec3 a = n.joint.axis1;
      auto near = [](double x, double want) { return std::abs(x - want) <= 1e-9; };
      bool y = near(a.x, 0) && near(std::abs(a.y), 1) && near(a.z, 0);
      bool z = near(a.x, 0) && near(a.y, 0) && near(std::abs(a.z), 1);
      if (!y && !z) n.joint.axis1 = {0, 0, 1};
    }
    // miconi2006 Table 1: the joint range is fixed; development applies it to empty limits
    if (r.hinge_limits_fixed && n.joint.type == JointType::Hinge) n.joint.limits.clear();
    if (n.recursive_limit < 1) n.recursive_limit = 1;
    // sensors: allowed types, existing dofs, canonical unused fields
    for (int s = static_cast<int>(n.sensors.size()) - 1; s >= 0; --s) {
      SensorGene& sg = g.nodes[i].sensors[s];
      bool bad = !allowed_sensor(sg.type) || (sg.type == SensorType::JointAngle && dofs == 0);
      if (bad) {
        remove_sensor(g, i, s, SourceFix::Reassign, &rng);
        continue;
      }
      if (sg.type == SensorType::JointAngle) {
        sg.dof = std::clamp(sg.dof, 0, dofs - 1);
        sg.face = Face::NegZ;
      } else {
        sg.dof = 0;
      }
      if (sg.type == SensorType::Photoreceptor) {
        sg.face = Face::NegZ;
        if (!(norm(sg.direction) > 1e-9) || !std::isfinite(norm(sg.direction)))
          sg.direction = random_direction(rng);
      } else {
        sg.direction = SensorGene{}.direction;
      }
    }
    auto& efs = g.nodes[i].effectors;
    if (r.muscle_effectors) {
      // every effector a muscle, with a valid one (lessin2015 III-E)
      for (EffectorGene& e : efs) {
        e.dof = 0;
        if (!e.muscle) e.muscle = random_muscle(def, rng);
        MuscleGene& m = *e.muscle;
        auto direction_ok = [](Vec3 d) { return std::isfinite(norm(d)) && norm(d) > 1e-9; };
        if (!direction_ok(m.parent_dir)) m.parent_dir = random_direction(rng);
        if (!direction_ok(m.child_dir)) m.child_dir = random_direction(rng);
        if (!(m.strength > 0)) m.strength = def.muscle_strength_range.lo;
        m.strength = std::min(m.strength, kMaxMuscleStrength);
      }
    } else {
      // effectors on existing dofs
      for (EffectorGene& e : efs) e.muscle.reset();
      for (int k = static_cast<int>(efs.size()) - 1; k >= 0; --k)
        if (efs[k].dof < 0 || efs[k].dof >= dofs) efs.erase(efs.begin() + k);
    }
    if (r.limb_io) {
      NodeGene& m = g.nodes[i];
      Range eb = effector_bias_bounds(def, g.dialect);
      if (i == 0) {
        // Fig. 1: the root has no sensor or actuator
        while (!m.sensors.empty())
          remove_sensor(g, 0, static_cast<int>(g.nodes[0].sensors.size()) - 1, SourceFix::Reassign,
                        &rng);
        g.nodes[0].effectors.clear();
      } else {
        // sec. 3.1: one joint-angle sensor and one actuator per limb
        while (g.nodes[i].sensors.size() > 1)
          remove_sensor(g, i, static_cast<int>(g.nodes[i].sensors.size()) - 1, SourceFix::Reassign,
                        &rng);
        NodeGene& mm = g.nodes[i];
        if (mm.sensors.empty()) mm.sensors.push_back({SensorType::JointAngle, 0, Face::NegZ});
        if (mm.effectors.size() > 1) mm.effectors.resize(1);
        if (mm.effectors.empty()) {
          mm.effectors.push_back({0, rng.uniform(eb.lo, eb.hi), {}});
          mm.effectors[0].inputs = random_inputs(g, i, new_effector_inputs(g, def, rng), def, rng);
        }
      }
    }
    if (r.max_neurons_per_part > 0)
      while (static_cast<int>(g.nodes[i].neurons.size()) > r.max_neurons_per_part)
        remove_neuron(g, i, static_cast<int>(g.nodes[i].neurons.size()) - 1, SourceFix::Remove);
    // edges: allowed reflections, no roll where orientation is two angles, angles on their step
    for (EdgeGene& e : g.nodes[i].edges) {
      e.reflect.erase(std::remove_if(e.reflect.begin(), e.reflect.end(),
                                     [&r](int a) {
                                       return std::find(r.reflect_axes.begin(), r.reflect_axes.end(), a) ==
                                              r.reflect_axes.end();
                                     }),
                      e.reflect.end());
      if (!r.edge_roll_free) e.rotation.x = 0;
      if (r.angle_step > 0)
        for (int a = 0; a < 3; ++a)
          e.rotation[a] = std::round(e.rotation[a] / r.angle_step) * r.angle_step;
    }
    for (NeuronGene& nr : g.nodes[i].neurons) fit_neuron(nr);
    for (EffectorGene& ef : g.nodes[i].effectors) {
      if (r.max_inputs_per_neuron > 0 &&
          static_cast<int>(ef.inputs.size()) > r.max_inputs_per_neuron)
        ef.inputs.resize(r.max_inputs_per_neuron);
      if (r.max_abs_bias > 0) ef.bias = std::clamp(ef.bias, -r.max_abs_bias, r.max_abs_bias);
    }
  }
  for (NeuronGene& nr : g.global_neurons) fit_neuron(nr);
  // weights within the dialect's bound
  if (r.max_abs_weight > 0) {
    auto clamp_w = [&r](std::vector<InputGene>& ins) {
      for (InputGene& in : ins)
        in.weight = std::clamp(in.weight, -r.max_abs_weight, r.max_abs_weight);
    };
    for (NodeGene& n : g.nodes) {
      for (auto& nr : n.neurons) clamp_w(nr.inputs);
      for (auto& ef : n.effectors) clamp_w(ef.inputs);
    }
    for (auto& nr : g.global_neurons) clamp_w(nr.inputs);
  }
  repair_sources(g, SourceFix::Reassign, &rng);
}

// ---------------------------------------------------------------- random genome

Genome random_genome(Dialect d, const OperatorDef& def, Rng& rng) {
  // catapults are chaumont2007's (section 4); other dialects ignore the flag
  if (def.catapult.enabled && d == Dialect::Chaumont2007) return random_catapult(def, rng);
  return detail::random_genome_plain(d, def, rng);
}

Genome detail::random_genome_plain(Dialect d, const OperatorDef& def_in, Rng& rng) {
  OperatorDef def = def_in;
  def.dialect = d;
  const DialectRules& r = dialect_rules(d);
  int most = def.max_genes;
  if (r.max_genes > 0) most = std::min(most, r.max_genes);
  int hi = std::clamp(def.genes_at_creation.hi, 1, std::max(1, most));
  int lo = std::clamp(def.genes_at_creation.lo, 1, hi);
  int max_parts = def.max_parts_at_creation > 0 ? def.max_parts_at_creation : r.max_parts;
  Genome g;
  for (int attempt = 0; attempt < 100; ++attempt) {
    g = Genome{};
    g.dialect = d;
    int n = uniform_int(rng, lo, hi);
    g.nodes.push_back(random_part(d, true, def, rng));
    // a tree first: every node hangs from an earlier one; graph dialects give
    // a node its recursion before its children, which are then placed clear
    // of the copy they hang from
    auto recurse = [&](int i) {
      if (r.tree_only || def.recursive_limit_max < 2 || !rng.chance(def.p_reflexive_edge)) return;
      g.nodes[i].edges.push_back(random_edge(g, i, i, def, rng));
      g.nodes[i].recursive_limit = uniform_int(rng, 2, def.recursive_limit_max);
    };
    recurse(0);
    for (int i = 1; i < n; ++i)
      recurse(add_random_node(g, static_cast<int>(rng.below(i)), def, rng));
    // graph dialects: extra edges (a node grown in two places, or a cycle)
    if (!r.tree_only)
      for (int i = 0; i < n; ++i)
        if (rng.chance(def.p_extra_edge))
          g.nodes[i].edges.push_back(random_edge(g, i, static_cast<int>(rng.below(n)), def, rng));
    if (r.global_neurons) {
      int k =
          uniform_int(rng, def.global_neurons_at_creation.lo, def.global_neurons_at_creation.hi);
      for (int i = 0; i < k; ++i) g.global_neurons.push_back(random_neuron(d, def, rng));
    }
    // wire once every node exists, so that neurons may read any neighbour
    for (int i = 0; i < n; ++i) wire_node(g, i, def, rng);
    wire_node(g, -1, def, rng);
    if (max_parts <= 0 || count_parts(g, max_parts) <= max_parts) return g;
  }
  // rare: too many parts every time; drop recursion and reflection
  for (NodeGene& n : g.nodes) {
    n.recursive_limit = 1;
    for (EdgeGene& e : n.edges) e.reflect.clear();
  }
  return g;
}

}  // namespace bx
