// Development: traverse the genome graph from the root, grow one part per
// visit, then compile sensors, effectors and the brain into flat arrays.
#include "develop/develop.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_set>

#include "genome/dialect.h"
#include "genome/genome_edit.h"  // face_frame: the edge frame on a face
#include "geometry/overlap.h"

namespace bx {

namespace {

// One grown part while developing. Its transform (A, p) may be improper
// (det A = -1) inside a mirrored branch; the part's proper rotation is
// derived from it at the end.
struct Instance {
  int node = 0;
  int parent = -1;       // instance index
  int via_edge = -1;     // edge index in the parent's node
  Mat3 A;                // local -> creature frame, possibly improper
  Mat3 parent_A;         // the parent's A as this instance's reflections mirror it
  Mat3 edge_Q;           // the edge's frame in the parent's (x out of its face, then its rotation)
  Vec3 p;
  double scale = 1;
  Vec3 size;             // scaled extents
  std::vector<std::vector<int>> children;  // per edge of the node: instances grown
};

// distance from the centre to the surface along unit direction d (local frame)
double surface_distance(Shape shape, Vec3 size, Vec3 d) {
  switch (shape) {
    case Shape::Box: {
      double t = 1e300;
      for (int i = 0; i < 3; ++i)
        if (std::abs(d[i]) > 1e-12) t = std::min(t, size[i] / 2 / std::abs(d[i]));
      return t;
    }
    case Shape::Sphere: return size.x / 2;
    case Shape::Cylinder: {
      double r = size.y / 2, radial = std::hypot(d.y, d.z);
      double t = radial > 1e-12 ? r / radial : 1e300;
      if (std::abs(d.x) > 1e-12) t = std::min(t, size.x / 2 / std::abs(d.x));
      return t;
    }
    case Shape::Capsule: {
      double r = size.y / 2, h = std::max(size.x / 2 - r, 0.0), radial = std::hypot(d.y, d.z);
      double t = radial > 1e-12 ? r / radial : 1e300;
      if (std::abs(t * d.x) <= h) return t;
      // the end cap: |t d - c| = r with c = (+-h, 0, 0)
      double cx = d.x >= 0 ? h : -h, dc = d.x * cx;
      return dc + std::sqrt(std::max(dc * dc - cx * cx + r * r, 0.0));
    }
  }
  return 0;
}

// half extent of a part along its own x axis
double half_x(Shape shape, Vec3 size) { return size.x / 2; }

// half of a part's thinner extent across its x axis (a sphere's and a
// capsule's radius)
double half_thickness(Shape shape, Vec3 size) {
  switch (shape) {
    case Shape::Sphere: return size.x / 2;
    case Shape::Capsule:
    case Shape::Cylinder: return size.y / 2;
    case Shape::Box: return std::min(size.y, size.z) / 2;
  }
  return 0;
}

// the attachment point of an edge on the parent's surface, parent-local
Vec3 attach_point(Shape shape, Vec3 size, const EdgeGene& e) {
  int a = face_axis(e.face), b = (a + 1) % 3, c = (a + 2) % 3;
  if (b > c) std::swap(b, c);  // u, v run along the other two axes in x,y,z order
  Vec3 q;
  q[a] = face_sign(e.face) * size[a] / 2;
  q[b] = e.u * size[b] / 2;
  q[c] = e.v * size[c] / 2;
  if (shape == Shape::Box) return q;
  // other shapes: move the box-face point onto the surface along its ray
  Vec3 d = normalized(q);
  return surface_distance(shape, size, d) * d;
}

double volume(Shape shape, Vec3 s) {
  switch (shape) {
    case Shape::Box: return s.x * s.y * s.z;
    case Shape::Sphere: return 4.0 / 3.0 * kPi * std::pow(s.x / 2, 3);
    case Shape::Cylinder: return kPi * std::pow(s.y / 2, 2) * s.x;
    case Shape::Capsule: {
      double r = s.y / 2;
      return kPi * r * r * std::max(s.x - 2 * r, 0.0) + 4.0 / 3.0 * kPi * r * r * r;
    }
  }
  return 0;
}

// area of the cross-section perpendicular to the part's x axis
double cross_section(Shape shape, Vec3 s) {
  return shape == Shape::Box ? s.y * s.z : kPi * std::pow((shape == Shape::Sphere ? s.x : s.y) / 2, 2);
}

// a number as %g prints it, for reasons
std::string num_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string vec_text(Vec3 v) {
  // appended piecewise: GCC 12 at -O3 warns falsely (-Wrestrict) on "[" + string&&
  std::string s = "[";
  s.append(num_text(v.x)).append(", ").append(num_text(v.y)).append(", ").append(num_text(v.z)).append("]");
  return s;
}

// unit vector perpendicular to a, as close to b as possible
Vec3 orthogonalize(Vec3 a, Vec3 b) {
  Vec3 r = b - dot(a, b) * a;
  if (norm(r) < 1e-9) r = cross(a, std::abs(a.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0});
  return normalized(r);
}

class Grower {
 public:
  // gap_share: a child whose joint collides with its parent starts this
  // share of its half-thickness off the parent (DevelopDef::collide_gap)
  Grower(const Genome& g, int max_parts, double gap_share)
      : g_(g), max_parts_(max_parts), gap_share_(gap_share) {}

  /// The instances in depth-first order; empty if more than max_parts.
  /// Iterative, with the count of each node on the current root-to-part path
  /// kept up to date, so growing n parts takes O(n) time and no stack (a node
  /// with an edge to itself grows a chain as long as max_parts allows).
  std::vector<Instance> grow() {
    Instance root;
    root.node = 0;
    root.size = g_.nodes[0].size;
    root.children.resize(g_.nodes[0].edges.size());
    out_.push_back(root);
    on_path_.assign(g_.nodes.size(), 0);
    enter(0);
    while (!stack_.empty()) {
      Frame& f = stack_.back();
      const NodeGene& node = g_.nodes[out_[f.instance].node];
      if (f.edge >= node.edges.size()) {
        // every edge done: leave this part
        --on_path_[out_[f.instance].node];
        stack_.pop_back();
        continue;
      }
      const EdgeGene& e = node.edges[f.edge];
      // one instance per combination of reflections: 2^n
      int copies = 1 << e.reflect.size();
      if (f.mask == 0 && ((e.terminal_only && !f.at_limit) ||
                          on_path_[e.to] >= g_.nodes[e.to].recursive_limit)) {
        ++f.edge;
        continue;
      }
      if (f.mask >= copies) {
        ++f.edge;
        f.mask = 0;
        continue;
      }
      Vec3 flip{1, 1, 1};
      for (std::size_t r = 0; r < e.reflect.size(); ++r)
        if (f.mask & (1 << r)) flip[e.reflect[r]] = -1;
      if (static_cast<int>(out_.size()) >= max_parts_) return {};
      int i = f.instance, k = static_cast<int>(f.edge);
      ++f.mask;  // `f` is not used after enter(), which may move the stack
      int c = add_child(i, k, Mat3::diag(flip.x, flip.y, flip.z));
      out_[i].children[k].push_back(c);
      enter(c);
    }
    return std::move(out_);
  }

 private:
  // a part being grown: the next edge and reflection to follow
  struct Frame {
    int instance;
    std::size_t edge = 0;
    int mask = 0;
    bool at_limit = false;  // its node is at its recursive limit on this path
  };

  void enter(int i) {
    int n = out_[i].node;
    ++on_path_[n];
    stack_.push_back({i, 0, 0, on_path_[n] >= g_.nodes[n].recursive_limit});
  }

  int add_child(int i, int edge, const Mat3& mirror) {
    const Instance& par = out_[i];
    const NodeGene& pnode = g_.nodes[par.node];
    const EdgeGene& e = pnode.edges[edge];
    const NodeGene& cnode = g_.nodes[e.to];
    Instance ch;
    ch.node = e.to;
    ch.parent = i;
    ch.via_edge = edge;
    ch.scale = par.scale * e.scale;
    ch.size = ch.scale * cnode.size;
    ch.children.resize(cnode.edges.size());
    // child frame relative to the parent: face frame, then the edge's rotation
    Mat3 Q = face_frame(e.face) * euler_xyz(e.rotation);
    Vec3 q = attach_point(pnode.shape, par.size, e);
    const double gap = gap_share_ * half_thickness(cnode.shape, ch.size);
    Vec3 centre = q + Q * Vec3{half_x(cnode.shape, ch.size) + gap, 0, 0};
    Mat3 AM = par.A * mirror;
    ch.A = AM * Q;
    ch.parent_A = AM;
    ch.edge_Q = Q;
    ch.p = par.p + AM * centre;
    anchors_.resize(out_.size() + 1);
    anchors_[out_.size()] = par.p + AM * q;
    out_.push_back(std::move(ch));
    return static_cast<int>(out_.size()) - 1;
  }

 public:
  std::vector<Vec3> anchors_;  // anchor of each instance's joint (creature frame)

 private:
  const Genome& g_;
  int max_parts_;
  double gap_share_;
  std::vector<Instance> out_;
  std::vector<int> on_path_;  // per node: its parts on the path from the root to the current one
  std::vector<Frame> stack_;  // that path
};

// Resolves one input gene of instance `inst` to a value slot (-1: reads 0).
class Wiring {
 public:
  Wiring(const Genome& g, const std::vector<Instance>& inst, CreatureModel& m)
      : g_(g), inst_(inst), m_(m) {}

  std::vector<int> sensor_base, neuron_base;
  std::vector<int> muscle_sensor_base, muscle_count;  // per instance: its muscles' length sensors
  int global_base = 0;

  int slot(int owner, const InputGene& in, const std::string& where) {
    int target = -1;
    switch (in.place) {
      case SourcePlace::Self: target = owner; break;
      case SourcePlace::Parent: target = owner >= 0 ? inst_[owner].parent : -1; break;
      case SourcePlace::Root: target = 0; break;
      case SourcePlace::Child: {
        // the first instance grown through that edge (the unreflected copy)
        const auto& kids = inst_[owner].children;
        if (in.edge < static_cast<int>(kids.size()) && !kids[in.edge].empty())
          target = kids[in.edge][0];
        break;
      }
      case SourcePlace::Global:
        if (in.index < static_cast<int>(g_.global_neurons.size()))
          return m_.brain.n_sensors + global_base + in.index;
        return missing(where);
    }
    if (target < 0) return missing(where);
    const NodeGene& tn = g_.nodes[inst_[target].node];
    if (in.kind == SourceKind::Sensor) {
      if (in.index >= static_cast<int>(tn.sensors.size())) return missing(where);
      return sensor_base[target] + in.index;
    }
    if (in.kind == SourceKind::Muscle) {
      if (in.index >= muscle_count[target]) return missing(where);  // e.g. the root's
      return muscle_sensor_base[target] + in.index;
    }
    if (in.index >= static_cast<int>(tn.neurons.size())) return missing(where);
    return m_.brain.n_sensors + neuron_base[target] + in.index;
  }

  /// The value slot of a gated input's switch (a global neuron), or -1.
  int gate_slot(const InputGene& in) const {
    if (in.gate < 0 || in.gate >= static_cast<int>(g_.global_neurons.size())) return -1;
    return m_.brain.n_sensors + global_base + in.gate;
  }

 private:
  int missing(const std::string& where) {
    if (reported_.insert(where).second)
      m_.warnings.push_back(where + ": its source does not exist in this body; it reads 0");
    return -1;
  }
  const Genome& g_;
  const std::vector<Instance>& inst_;
  CreatureModel& m_;
  std::unordered_set<std::string> reported_;
};

// compiles one neuron (or global neuron) into the brain arrays
void add_neuron(BrainModel& b, const NeuronGene& ng, int part, int owner, Wiring& wiring,
                const std::string& where) {
  const NeuronFnSpec* spec = find_neuron_fn(b.set, ng.fn);
  b.fn.push_back(spec->id);
  b.bias.push_back(ng.bias);
  // parameters: the gene's, then defaults for the rest
  for (std::size_t k = 0; k < spec->params.size(); ++k)
    b.params.push_back(k < ng.params.size() ? ng.params[k] : spec->params[k].default_value);
  std::span<const double> ps(b.params.data() + b.param_begin.back(), spec->params.size());
  b.param_begin.push_back(static_cast<std::uint32_t>(b.params.size()));
  b.state_begin.push_back(b.state_begin.back() + spec->state_size(ps));
  for (std::size_t k = 0; k < ng.inputs.size(); ++k) {
    b.input_src.push_back(
        wiring.slot(owner, ng.inputs[k], where + ".inputs[" + std::to_string(k) + "]"));
    b.input_weight.push_back(ng.inputs[k].weight);
    b.input_gate.push_back(wiring.gate_slot(ng.inputs[k]));
  }
  b.input_begin.push_back(static_cast<std::uint32_t>(b.input_src.size()));
  b.neuron_part.push_back(part);
}

// the brain's pandemonium groups (lessin2015 IV-C) from (genome group id,
// neuron index) pairs in development order: one group per distinct id, by
// increasing id, its members in development order (the first wins a tie,
// brain/pandemonium.h). No pairs, no groups: the arrays stay empty.
void add_groups(BrainModel& b, std::vector<std::pair<int, std::int32_t>> grouped) {
  if (grouped.empty()) return;
  // neuron indices rise in development order, so sorting the pairs sorts by
  // id and keeps that order within a group
  std::sort(grouped.begin(), grouped.end());
  b.group_begin = {0};
  for (std::size_t k = 0; k < grouped.size(); ++k) {
    if (k > 0 && grouped[k].first != grouped[k - 1].first)
      b.group_begin.push_back(static_cast<std::uint32_t>(k));
    b.group_member.push_back(grouped[k].second);
  }
  b.group_begin.push_back(static_cast<std::uint32_t>(grouped.size()));
}

// a neuron of the catapult's fixed mechanism, owned by the arm (part 0), with
// inputs given as value slots; returns its value slot
int add_mechanism_neuron(BrainModel& b, std::string_view fn, std::vector<double> params,
                         std::vector<std::int32_t> inputs) {
  const NeuronFnSpec* spec = find_neuron_fn(b.set, fn);
  b.fn.push_back(spec->id);
  b.bias.push_back(0);
  b.params.insert(b.params.end(), params.begin(), params.end());
  std::span<const double> ps(b.params.data() + b.param_begin.back(), params.size());
  b.param_begin.push_back(static_cast<std::uint32_t>(b.params.size()));
  b.state_begin.push_back(b.state_begin.back() + spec->state_size(ps));
  for (std::int32_t src : inputs) {
    b.input_src.push_back(src);
    b.input_weight.push_back(1.0);
    b.input_gate.push_back(-1);
  }
  b.input_begin.push_back(static_cast<std::uint32_t>(b.input_src.size()));
  b.neuron_part.push_back(0);
  return b.n_sensors + b.n_neurons() - 1;
}

}  // namespace

Development develop(const Genome& g, const DevelopDef& def) {
  const DialectRules& rules = dialect_rules(g.dialect);
  int max_parts = def.max_parts > 0 ? def.max_parts : (rules.max_parts > 0 ? rules.max_parts : 1000);

  // grow the tree of part instances
  Grower grower(g, max_parts, rules.joined_parts_collide ? def.collide_gap : 0.0);
  std::vector<Instance> inst = grower.grow();
  if (inst.empty()) return {std::nullopt, "too many parts: more than " + std::to_string(max_parts)};
  const auto& anchors = grower.anchors_;

  CreatureModel m;
  m.dialect = g.dialect;
  int n = static_cast<int>(inst.size());
  std::vector<bool> flipped(n);  // improper frame: proper rotation flips local z

  // parts and joints
  for (int i = 0; i < n; ++i) {
    const Instance& in = inst[i];
    const NodeGene& node = g.nodes[in.node];
    PartModel part;
    part.shape = node.shape;
    part.size = in.size;
    part.mass = rules.mass_rule == MassRule::TanhVolume
                    ? rules.mass_scale * std::tanh(in.size.x * in.size.y * in.size.z)
                    : node.density * volume(node.shape, in.size);
    flipped[i] = in.A.det() < 0;
    part.pose = {in.p, flipped[i] ? in.A * Mat3::diag(1, 1, -1) : in.A};
    part.parent = in.parent;
    part.gene = in.node;
    part.mirrored = flipped[i];
    part.depth = in.parent < 0 ? 0 : m.parts[in.parent].depth + 1;
    m.parts.push_back(part);
  }
  // physical ranges (genome/dialect.h): a part's size compounds the scales of
  // the edges that grew it, so genes within range can still grow parts that
  // are not; checked before ODE sees them
  for (int i = 0; i < n; ++i) {
    const PartModel& p = m.parts[i];
    auto part_name = [&] {
      return "part " + std::to_string(i) + " (gene " + std::to_string(p.gene) + ")";
    };
    for (int a = 0; a < 3; ++a)
      if (!(p.size[a] >= kMinPartSize && p.size[a] <= kMaxPartSize))
        return {std::nullopt, part_name() + ": size " + vec_text(p.size) + " m, each extent must lie in [" +
                                  num_text(kMinPartSize) + ", " + num_text(kMaxPartSize) +
                                  "] m (edge scales compound along the body)"};
    if (!(p.mass >= kMinPartMass && p.mass <= kMaxPartMass))
      return {std::nullopt, part_name() + ": mass " + num_text(p.mass) + " kg, must lie in [" +
                                num_text(kMinPartMass) + ", " + num_text(kMaxPartMass) + "] kg"};
  }
  if (def.max_body_length > 0) {
    double length = m.body_length();
    if (length > def.max_body_length) {
      char buf[128];
      std::snprintf(buf, sizeof buf, "too large: body length %.4g m, above develop.max_body_length %g",
                    length, def.max_body_length);
      return {std::nullopt, buf};
    }
  }
  std::vector<int> joint_of(n, -1);
  for (int i = 1; i < n; ++i) {
    const Instance& in = inst[i];
    const JointGene& jg = g.nodes[in.node].joint;
    JointModel j;
    j.type = jg.type;
    j.parent = in.parent;
    j.child = i;
    j.anchor = anchors[i];
    // axes are pseudovectors: in a mirrored frame they flip with the determinant
    double s = flipped[i] ? -1.0 : 1.0;
    Vec3 a1 = normalized(s * (in.A * jg.axis1));
    Vec3 a2 = s * (in.A * jg.axis2);
    j.axis1 = a1;
    j.axis2 = orthogonalize(a1, normalized(a2));
    j.limits = jg.limits;
    if (j.limits.empty() && j.type == JointType::Hinge && rules.default_hinge_limits)
      j.limits = {*rules.default_hinge_limits};
    j.parts_collide = rules.joined_parts_collide;  // lessin2015 III-B: shapes limit the joint
    if (j.parts_collide && j.limits.empty() &&
        (j.type == JointType::Slider || j.type == JointType::Cylindrical)) {
      // collisions stop only a slide towards the parent (DevelopDef::slide_range)
      const double r = def.slide_range * half_thickness(g.nodes[in.node].shape, in.size);
      j.limits = {{-r, r}};
    }
    joint_of[i] = static_cast<int>(m.joints.size());
    m.joints.push_back(j);
  }

  // self-intersection of parts not joined to each other (a catapult's
  // projectile, released later, counts as not joined to its arm)
  int released = -1;
  if (g.catapult)
    for (int i = 0; i < n; ++i)
      if (inst[i].node == g.catapult->projectile) released = i;
  auto [a, b] = find_self_intersection(m, def.overlap_margin, released);
  if (a >= 0)
    return {std::nullopt, "self-intersection: parts " + std::to_string(a) + " (gene " +
                              std::to_string(m.parts[a].gene) + ") and " + std::to_string(b) +
                              " (gene " + std::to_string(m.parts[b].gene) + ") overlap"};

  // muscles (lessin2015 III-E): each effector of a muscle dialect's part, to
  // its parent, between the points where its two directions leave the parts
  std::vector<int> muscle_base(n, 0);
  if (rules.muscle_effectors)
    for (int i = 0; i < n; ++i) {
      muscle_base[i] = static_cast<int>(m.muscles.size());
      if (i == 0) continue;  // the root has no parent to pull
      const NodeGene& node = g.nodes[inst[i].node];
      const Instance& par = inst[inst[i].parent];
      for (std::size_t k = 0; k < node.effectors.size(); ++k) {
        const MuscleGene& mg = *node.effectors[k].muscle;
        // points in the (possibly mirrored) local frames: a reflected part's
        // muscle is mirrored too, on the parent as the reflection mirrors it.
        // The parent's end is given in the frame of the edge that grew this
        // part, so each copy grown by multiple or recursive edges pulls from
        // its own side of the parent
        Vec3 dp = inst[i].edge_Q * normalized(mg.parent_dir), dc = normalized(mg.child_dir);
        Vec3 a = par.p + inst[i].parent_A * (surface_distance(g.nodes[par.node].shape, par.size, dp) * dp);
        Vec3 b = inst[i].p + inst[i].A * (surface_distance(node.shape, inst[i].size, dc) * dc);
        MuscleModel mm;
        mm.part_a = inst[i].parent;
        mm.part_b = i;
        mm.anchor_a = a;
        mm.anchor_b = b;
        mm.strength = mg.strength;
        mm.length = norm(b - a);
        mm.rest_length = def.muscle_rest_fraction * mm.length;
        if (!(mm.length >= def.min_muscle_length)) {
          char buf[160];
          std::snprintf(buf, sizeof buf, "nodes[%d].effectors[%zu].muscle: %.3g m long as built, below %g m",
                        inst[i].node, k, mm.length, def.min_muscle_length);
          return {std::nullopt, buf};
        }
        m.muscles.push_back(mm);
      }
    }

  // sensors, then neuron numbering
  BrainModel& brain = m.brain;
  brain.set = rules.neuron_set;
  Wiring wiring(g, inst, m);
  wiring.sensor_base.resize(n);
  wiring.muscle_sensor_base.resize(n);
  wiring.neuron_base.resize(n);
  int n_neurons = 0;
  for (int i = 0; i < n; ++i) {
    const NodeGene& node = g.nodes[inst[i].node];
    wiring.sensor_base[i] = static_cast<int>(m.sensors.size());
    wiring.neuron_base[i] = n_neurons;
    n_neurons += static_cast<int>(node.neurons.size());
    for (const SensorGene& sg : node.sensors) {
      SensorModel s;
      s.type = sg.type;
      s.part = i;
      s.joint = joint_of[i];
      s.dof = sg.dof;
      // a contact face in a mirrored frame: the proper frame flips local z
      s.face = flipped[i] && face_axis(sg.face) == 2 ? make_face(2, -face_sign(sg.face)) : sg.face;
      // a direction likewise (the proper frame of a mirrored part flips local z)
      s.direction = flipped[i] ? Vec3{sg.direction.x, sg.direction.y, -sg.direction.z} : sg.direction;
      m.sensors.push_back(s);
    }
    // each muscle's length node (lessin2015 III-E), read as SourceKind::Muscle
    wiring.muscle_sensor_base[i] = static_cast<int>(m.sensors.size());
    const int muscles_here =
        (i + 1 < n ? muscle_base[i + 1] : static_cast<int>(m.muscles.size())) - muscle_base[i];
    wiring.muscle_count.push_back(rules.muscle_effectors ? muscles_here : 0);
    for (int k = 0; rules.muscle_effectors && k < muscles_here; ++k) {
      SensorModel s;
      s.type = SensorType::MuscleLength;
      s.part = i;
      s.joint = joint_of[i];
      s.muscle = muscle_base[i] + k;
      m.sensors.push_back(s);
    }
  }
  brain.n_sensors = static_cast<int>(m.sensors.size());
  wiring.global_base = n_neurons;

  // neurons of every part, then the global neurons; each copy of a neuron in
  // a pandemonium group joins it: (group id, neuron index)
  brain.param_begin = {0};
  brain.state_begin = {0};
  brain.input_begin = {0};
  std::vector<std::pair<int, std::int32_t>> grouped;
  auto join_group = [&](const NeuronGene& ng) {
    if (ng.group != NeuronGene::kNoGroup) grouped.push_back({ng.group, brain.n_neurons() - 1});
  };
  for (int i = 0; i < n; ++i) {
    const NodeGene& node = g.nodes[inst[i].node];
    for (std::size_t k = 0; k < node.neurons.size(); ++k) {
      add_neuron(brain, node.neurons[k], i, i, wiring,
                 "nodes[" + std::to_string(inst[i].node) + "].neurons[" + std::to_string(k) + "]");
      join_group(node.neurons[k]);
    }
  }
  // with a skill selected (DevelopDef::skill), its switch is a constant 1 and
  // every other switch follows only its gated inputs (the wires of
  // encapsulated skills: those the selected one drives pass, the rest are 0)
  const bool selected = !def.skill.empty();
  if (selected && std::none_of(g.global_neurons.begin(), g.global_neurons.end(),
                               [&](const NeuronGene& nr) { return nr.skill == def.skill; })) {
    std::string names;
    for (const NeuronGene& nr : g.global_neurons)
      if (!nr.skill.empty()) names += (names.empty() ? "\"" : ", \"") + nr.skill + "\"";
    return {std::nullopt, "brain.skill: no skill \"" + def.skill + "\" in this genome (its skills: " +
                              (names.empty() ? "none" : names) + ")"};
  }
  for (std::size_t k = 0; k < g.global_neurons.size(); ++k) {
    const NeuronGene& ng = g.global_neurons[k];
    NeuronGene forced;
    if (selected && !ng.skill.empty()) {
      forced = ng;
      const bool it = ng.skill == def.skill;
      forced.inputs.erase(std::remove_if(forced.inputs.begin(), forced.inputs.end(),
                                         [&](const InputGene& in) { return it || in.gate == InputGene::kNoGate; }),
                          forced.inputs.end());
      forced.bias = it ? 1.0 : 0.0;
    }
    add_neuron(brain, selected && !ng.skill.empty() ? forced : ng, -1, 0, wiring,
               "global_neurons[" + std::to_string(k) + "]");
    join_group(ng);
  }
  add_groups(brain, std::move(grouped));

  // a catapult's release mechanism (chaumont2007 Fig. 4): a constant through a
  // delay line, so the release fires at brain step delay_steps at the latest
  // (the constant publishes at step 0, the line adds delay_steps - 1), or
  // earlier when the body's network drives it
  if (g.catapult) {
    const CatapultGene& cat = *g.catapult;
    for (int i = 0; i < n; ++i)
      if (inst[i].node == cat.projectile) {
        m.projectile = i;
        m.release_joint = joint_of[i];
      }
    // the release effector: the brain's one task output, the delay line its floor
    int cst = add_mechanism_neuron(brain, "cst", {1.0}, {});
    brain.task_output_floor.push_back(
        add_mechanism_neuron(brain, "mem", {static_cast<double>(cat.release.delay_steps - 1)}, {cst}));
    brain.task_output_threshold.push_back(ReleaseGene::kFiringThreshold);
    // a row of the table: its inputs follow any rows before it
    if (brain.task_output_input_begin.empty()) brain.task_output_input_begin = {0};
    for (std::size_t k = 0; k < cat.release.inputs.size(); ++k) {
      const InputGene& in = cat.release.inputs[k];
      brain.task_output_input_src.push_back(
          wiring.slot(0, in, "catapult.release.inputs[" + std::to_string(k) + "]"));
      brain.task_output_input_weight.push_back(in.weight);
    }
    brain.task_output_input_begin.push_back(static_cast<std::uint32_t>(brain.task_output_input_src.size()));
  }

  // effectors of every part that has a joint
  brain.effector_input_begin = {0};
  for (int i = 1; i < n; ++i) {
    const NodeGene& node = g.nodes[inst[i].node];
    for (std::size_t k = 0; k < node.effectors.size(); ++k) {
      const EffectorGene& eg = node.effectors[k];
      EffectorModel e;
      e.joint = joint_of[i];
      e.dof = eg.dof;
      if (rules.muscle_effectors) e.muscle = muscle_base[i] + static_cast<int>(k);
      const PartModel& pc = m.parts[i];
      const PartModel& pp = m.parts[inst[i].parent];
      e.cross_section = std::max(cross_section(pc.shape, pc.size), cross_section(pp.shape, pp.size));
      m.effectors.push_back(e);
      // with a skill selected, only the encapsulated skills' (gated) wires
      // drive it: its bias and ungated inputs are the skill being learned's
      brain.effector_bias.push_back(selected ? 0.0 : eg.bias);
      std::string where =
          "nodes[" + std::to_string(inst[i].node) + "].effectors[" + std::to_string(k) + "]";
      for (std::size_t q = 0; q < eg.inputs.size(); ++q) {
        if (selected && eg.inputs[q].gate == InputGene::kNoGate) continue;
        brain.effector_input_src.push_back(
            wiring.slot(i, eg.inputs[q], where + ".inputs[" + std::to_string(q) + "]"));
        brain.effector_input_weight.push_back(eg.inputs[q].weight);
        brain.effector_input_gate.push_back(wiring.gate_slot(eg.inputs[q]));
      }
      brain.effector_input_begin.push_back(static_cast<std::uint32_t>(brain.effector_input_src.size()));
    }
  }
  // no gate anywhere: the brain keeps the plain loops (BrainModel::input_gate)
  auto ungated = [](const std::vector<std::int32_t>& v) {
    return std::all_of(v.begin(), v.end(), [](std::int32_t x) { return x < 0; });
  };
  if (ungated(brain.input_gate)) brain.input_gate.clear();
  if (ungated(brain.effector_input_gate)) brain.effector_input_gate.clear();
  return {std::move(m), {}};
}

std::pair<int, int> find_self_intersection(const CreatureModel& m, double margin, int released) {
  std::vector<Solid> solids(m.parts.size());
  for (std::size_t i = 0; i < solids.size(); ++i) {
    const PartModel& p = m.parts[i];
    bool free = static_cast<int>(i) == released;
    // a part whose joint lets it collide with its parent (JointModel::
    // parts_collide) may not start inside it either: the contact would push
    // the pair apart against the joint
    bool collides = false;
    for (const JointModel& j : m.joints)
      if (j.child == static_cast<int>(i) && j.parts_collide) collides = true;
    solids[i] = {p.shape, p.size, p.pose, free || collides ? -1 : p.parent};
  }
  return first_overlap(solids, margin);
}

}  // namespace bx
