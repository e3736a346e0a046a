// Mutation (operators.h): miconi2006's sequence of nine steps (sec. 5.1), and
// the per-parameter and structural mutations of the graph dialects (Sims
// 1994, chaumont2007 5.7). docs/operators.md has the details.
#include <algorithm>
#include <cmath>

#include "brain/neuron_set.h"
#include "genome/dialect.h"
#include "genome/locks.h"
#include "genome/genome_edit.h"
#include "genome/operators.h"

namespace bx {

namespace {

int uniform_int(Rng& rng, int lo, int hi) {
  if (hi <= lo) return lo;
  return lo + static_cast<int>(rng.below(static_cast<std::uint64_t>(hi - lo + 1)));
}

// x wrapped onto the torus [lo, hi] (miconi2006 5.1)
double torus(double x, Range r) {
  double span = r.hi - r.lo;
  if (!(span > 0)) return r.lo;
  double y = std::fmod(x - r.lo, span);
  if (y < 0) y += span;
  return std::clamp(r.lo + y, r.lo, r.hi);
}

// x wrapped into [-pi, pi]
double wrap_angle(double x) { return torus(x, {-kPi, kPi}); }

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

// whether node n grows with a parent (non-root, or the root reached again)
bool has_parent(const Genome& g, int n) { return n != 0 || !parents_of(g, 0).empty(); }

int max_genes(const Genome& g, const OperatorDef& def) {
  int r = dialect_rules(g.dialect).max_genes;
  return r > 0 ? std::min(def.max_genes, r) : def.max_genes;
}

// the edge that leads to node c in a tree: (parent, index), or (-1, -1)
std::pair<int, int> incoming_edge(const Genome& g, int c) {
  for (int p = 0; p < static_cast<int>(g.nodes.size()); ++p)
    for (int k = 0; k < static_cast<int>(g.nodes[p].edges.size()); ++k)
      if (g.nodes[p].edges[k].to == c) return {p, k};
  return {-1, -1};
}

const NeuronFnSpec* spec_of(const Genome& g, const NeuronGene& n) {
  return find_neuron_fn(dialect_rules(g.dialect).neuron_set, n.fn);
}

// a new neuron's number of inputs: a positional function's arity, or
// miconi's connection slots filled at the connection fraction
int new_input_count(const Genome& g, const NeuronGene& n, const OperatorDef& def, Rng& rng) {
  const NeuronFnSpec* spec = spec_of(g, n);
  if (spec->mode == InputMode::Positional) return spec->max_inputs;
  int k = 0;
  for (int s = 0; s < std::min(def.connection_slots, spec->max_inputs); ++s)
    k += rng.chance(def.connection_fraction);
  return k;
}

// ---------------------------------------------------------------- miconi2006

// (1) a random limb and its sub-limbs, never leaving fewer than min_genes
void miconi_delete_limb(Genome& g, const OperatorDef& def, Rng& rng) {
  int n = static_cast<int>(g.nodes.size());
  std::vector<int> ok;
  for (int i = 1; i < n; ++i)
    if (n - static_cast<int>(subtree(g, i).size()) >= def.min_genes) ok.push_back(i);
  if (ok.empty()) return;
  int victim = ok[rng.below(ok.size())];
  auto [p, k] = incoming_edge(g, victim);
  if (p < 0) return;
  remove_edge(g, p, k, SourceFix::Remove);
  remove_unreachable(g, SourceFix::Remove);
}

// (2) a random limb with random neural information on a random limb
void miconi_add_limb(Genome& g, const OperatorDef& def, Rng& rng) {
  int n = static_cast<int>(g.nodes.size());
  if (n >= max_genes(g, def)) return;
  int c = add_random_node(g, static_cast<int>(rng.below(n)), def, rng);
  wire_node(g, c, def, rng);
}

// (3) each neuron slot flipped: an existing neuron deleted, an empty slot
// filled with a new neuron with random connections
void miconi_neuron_slots(Genome& g, const OperatorDef& def, double p, Rng& rng) {
  for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i) {
    int existing = static_cast<int>(g.nodes[i].neurons.size());
    std::vector<bool> flip(def.neuron_slots);
    for (int s = 0; s < def.neuron_slots; ++s) flip[s] = rng.chance(p);
    int adds = 0;
    for (int s = def.neuron_slots - 1; s >= 0; --s) {
      if (!flip[s]) continue;
      if (s < existing)
        remove_neuron(g, i, s, SourceFix::Remove);
      else
        ++adds;
    }
    for (int a = 0; a < adds; ++a) {
      g.nodes[i].neurons.push_back(random_neuron(g.dialect, def, rng));
      int count = new_input_count(g, g.nodes[i].neurons.back(), def, rng);
      std::vector<InputGene> ins = random_inputs(g, i, count, def, rng);
      g.nodes[i].neurons.back().inputs = std::move(ins);
    }
  }
}

// calls f(owner, bias, inputs, is_effector) for every neuron and actuator, in order
template <class F>
void each_unit(Genome& g, F f) {
  for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i) {
    for (std::size_t k = 0; k < g.nodes[i].neurons.size(); ++k) {
      NeuronGene& nr = g.nodes[i].neurons[k];
      f(i, nr.bias, nr.inputs, false);
    }
    for (std::size_t k = 0; k < g.nodes[i].effectors.size(); ++k) {
      EffectorGene& ef = g.nodes[i].effectors[k];
      f(i, ef.bias, ef.inputs, true);
    }
  }
}

// (6) each connection slot flipped: an assigned one removed, an unassigned
// one given a random source and weight
void miconi_connection_slots(Genome& g, const OperatorDef& def, double p, Rng& rng) {
  int slots = def.connection_slots;
  int cap = dialect_rules(g.dialect).max_inputs_per_neuron;
  if (cap > 0) slots = std::min(slots, cap);
  each_unit(g, [&](int owner, double&, std::vector<InputGene>& inputs, bool) {
    int existing = static_cast<int>(inputs.size());
    std::vector<bool> flip(slots);
    for (int s = 0; s < slots; ++s) flip[s] = rng.chance(p);
    int adds = 0;
    for (int s = slots - 1; s >= 0; --s) {
      if (!flip[s]) continue;
      if (s < existing)
        inputs.erase(inputs.begin() + s);
      else
        ++adds;
    }
    for (int a = 0; a < adds; ++a) {
      InputGene in;
      if (random_input(g, owner, def, rng, in)) inputs.push_back(in);
    }
  });
}

// (9) one of seven morphological mutations of limb i: move the branch to
// another limb, new length, width or height, change one orientation angle,
// switch the hinge axis, flip reflection. The root only changes size.
void miconi_morphology(Genome& g, int i, const OperatorDef& def, Rng& rng) {
  const double step = def.angle_step;
  int op = i == 0 ? 1 + static_cast<int>(rng.below(3)) : static_cast<int>(rng.below(7));
  auto [p, k] = incoming_edge(g, i);
  if (i != 0 && p < 0) return;
  switch (op) {
    case 0: {  // move the limb and its sub-limbs to a limb outside its subtree
      std::vector<int> sub = subtree(g, i);
      std::vector<int> cands;
      for (int j = 0; j < static_cast<int>(g.nodes.size()); ++j)
        if (j != p && std::find(sub.begin(), sub.end(), j) == sub.end()) cands.push_back(j);
      if (cands.empty()) return;
      int q = cands[rng.below(cands.size())];
      move_edge(g, p, k, q, SourceFix::Clamp, &rng);
      reseat_edge(g.nodes[q].edges.back(), g.nodes[q].size, step);
      return;
    }
    case 1:
    case 2:
    case 3: {  // a new length (x), width (y) or height (z)
      int a = op - 1;
      g.nodes[i].size[a] = rng.uniform(def.size_min[a], def.size_max[a]);
      for (EdgeGene& e : g.nodes[i].edges) reseat_edge(e, g.nodes[i].size, step);
      return;
    }
    case 4: {  // longitude or latitude: a new lattice value within the range
      EdgeGene& e = g.nodes[p].edges[k];
      int half = static_cast<int>(std::lround(kPi / step));
      int m = static_cast<int>(std::lround(def.angle_mutation_range / step));
      int ky = static_cast<int>(std::lround(e.rotation.y / step));
      int kz = static_cast<int>(std::lround(e.rotation.z / step));
      if (m < 1) return;
      if (rng.chance(0.5)) {
        // longitude: around the circle
        int j = uniform_int(rng, 1, 2 * m);
        ky += j <= m ? j - m - 1 : j - m;  // -m..-1, 1..m
        while (ky > half) ky -= 2 * half;
        while (ky <= -half) ky += 2 * half;
      } else {
        // latitude: within [-pi/2, pi/2]
        std::vector<int> vals;
        for (int v = std::max(-half / 2, kz - m); v <= std::min(half / 2, kz + m); ++v)
          if (v != kz) vals.push_back(v);
        if (vals.empty()) return;
        kz = vals[rng.below(vals.size())];
      }
      Vec3 w{std::cos(ky * step) * std::cos(kz * step), std::sin(kz * step),
             -std::sin(ky * step) * std::cos(kz * step)};
      place_edge(e, g.nodes[p].size, face_frame(e.face) * w, 0, step);
      return;
    }
    case 5: {  // hinge axis: the limb's y <-> z
      Vec3& a = g.nodes[i].joint.axis1;
      a = std::abs(a.y) > 0.5 ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
      return;
    }
    case 6: {  // reflection across the parent's xz plane
      EdgeGene& e = g.nodes[p].edges[k];
      if (e.reflect.empty())
        e.reflect = {1};
      else
        e.reflect.clear();
      return;
    }
  }
}

void mutate_miconi(Genome& g, const OperatorDef& def, double p, Rng& rng) {
  auto on = [&def](MiconiStep s) { return (def.miconi_steps & s) != 0; };
  // (1) delete a limb, (2) add a limb
  if (on(kMiconiDeleteLimb) && rng.chance(p)) miconi_delete_limb(g, def, rng);
  if (on(kMiconiAddLimb) && rng.chance(p)) miconi_add_limb(g, def, rng);
  // (3) neuron slots
  if (on(kMiconiNeuronSlots)) miconi_neuron_slots(g, def, p, rng);
  // (4) thresholds on their torus
  if (on(kMiconiThresholds)) {
    Range nb = bias_bounds(def, g.dialect), eb = effector_bias_bounds(def, g.dialect);
    each_unit(g, [&](int, double& bias, std::vector<InputGene>&, bool effector) {
      if (rng.chance(p))
        bias = torus(bias + rng.uniform(-def.bias_step, def.bias_step), effector ? eb : nb);
    });
  }
  // (5) activation function
  if (on(kMiconiActivation)) {
    std::vector<std::string_view> names = neuron_fn_names(dialect_rules(g.dialect).neuron_set);
    for (NodeGene& n : g.nodes)
      for (NeuronGene& nr : n.neurons)
        if (rng.chance(p) && names.size() > 1) {
          // another function of the set (sigmoid <-> tanh)
          std::vector<std::string_view> others;
          for (auto nm : names)
            if (nm != nr.fn) others.push_back(nm);
          nr.fn = std::string(others[rng.below(others.size())]);
        }
  }
  // (6) connection slots
  if (on(kMiconiConnSlots)) miconi_connection_slots(g, def, p, rng);
  // (7) weights on their torus
  if (on(kMiconiWeights)) {
    Range wb = weight_bounds(def, g.dialect);
    each_unit(g, [&](int, double&, std::vector<InputGene>& inputs, bool) {
      for (InputGene& in : inputs)
        if (rng.chance(p))
          in.weight = torus(in.weight + rng.uniform(-def.weight_step, def.weight_step), wb);
    });
  }
  // (8) sources
  if (on(kMiconiSources))
    each_unit(g, [&](int owner, double&, std::vector<InputGene>& inputs, bool) {
      for (InputGene& in : inputs)
        if (rng.chance(p)) {
          std::vector<InputGene> cands = source_candidates(g, owner);
          if (cands.empty()) continue;
          double w = in.weight;
          in = cands[rng.below(cands.size())];
          in.weight = w;
        }
    });
  // (9) morphology, per limb
  if (on(kMiconiMorphology))
    for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i)
      if (rng.chance(p)) miconi_morphology(g, i, def, rng);
}

// ---------------------------------------------------------------- graph dialects

struct GraphMutator {
  Genome& g;
  const OperatorDef& def;
  double rate;
  Rng& rng;
  const DialectRules& r;
  bool locks = false;  ///< the genome has locks (genome/locks.h)

  bool hit() { return rng.chance(rate); }

  double perturb(double x, double lo, double hi) {
    return std::clamp(x + normal(rng) * def.param_sigma * (hi - lo), lo, hi);
  }
  double scale(double x, double lo, double hi) {
    return std::clamp(x * std::exp(normal(rng) * def.size_sigma), lo, hi);
  }

  Limit random_limit(JointType t, int dof) {
    if (dof_is_angular(t, dof))
      return {-rng.uniform(def.angle_limit_min, def.angle_limit_max),
              rng.uniform(def.angle_limit_min, def.angle_limit_max)};
    return {-rng.uniform(0, def.slide_limit_max), rng.uniform(0, def.slide_limit_max)};
  }

  void inputs(int owner, std::vector<InputGene>& ins) {
    Range wb = weight_bounds(def, g.dialect);
    for (InputGene& in : ins) {
      if (in.gate != InputGene::kNoGate) continue;  // an encapsulated skill's wire: frozen
      if (hit()) in.weight = perturb(in.weight, wb.lo, wb.hi);
      if (hit()) {
        std::vector<InputGene> cands = source_candidates(g, owner);
        if (cands.empty()) continue;
        double w = in.weight;
        in = cands[rng.below(cands.size())];
        in.weight = w;
      }
    }
  }

  void neuron(int owner, NeuronGene& nr) {
    const NeuronFnSpec* spec = spec_of(g, nr);
    if (!spec) return;
    // a skill's switch: only its free inputs evolve (genome/locks.h)
    if (!nr.skill.empty()) return inputs(owner, nr.inputs);
    for (std::size_t k = 0; k < spec->params.size() && k < nr.params.size(); ++k)
      if (hit()) {
        const ParamSpec& ps = spec->params[k];
        double v = perturb(nr.params[k], ps.min, ps.max);
        nr.params[k] = ps.integer ? std::round(v) : v;
      }
    if (spec->mode == InputMode::WeightedSum && hit()) {
      Range b = bias_bounds(def, g.dialect);
      nr.bias = perturb(nr.bias, b.lo, b.hi);
    }
    inputs(owner, nr.inputs);
  }

  void change_joint(int i, JointType t) {
    JointGene& j = g.nodes[i].joint;
    j.type = t;
    int dofs = joint_dofs(t);
    j.limits.clear();
    if (!r.joined_parts_collide)  // lessin2015: collisions limit joints (III-B)
      for (int k = 0; k < dofs; ++k) j.limits.push_back(random_limit(t, k));
    if ((t == JointType::Universal || t == JointType::Spherical) &&
        norm(cross(j.axis1, j.axis2)) < 1e-3)
      j.axis2 =
          normalized(cross(j.axis1, std::abs(j.axis1.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    // sensors and effectors follow the degrees of freedom
    for (int s = static_cast<int>(g.nodes[i].sensors.size()) - 1; s >= 0; --s) {
      SensorGene& sg = g.nodes[i].sensors[s];
      if (sg.type != SensorType::JointAngle || sg.dof < dofs) continue;
      if (dofs > 0)
        sg.dof = static_cast<int>(rng.below(dofs));
      else
        bx::remove_sensor(g, i, s, SourceFix::Reassign, &rng);
    }
    auto& efs = g.nodes[i].effectors;
    if (r.muscle_effectors) return;  // muscles pull across any joint
    for (int k = static_cast<int>(efs.size()) - 1; k >= 0; --k) {
      if (efs[k].dof < dofs) continue;
      if (dofs > 0)
        efs[k].dof = static_cast<int>(rng.below(dofs));
      else
        efs.erase(efs.begin() + k);
    }
  }

  Vec3 nudge_axis(Vec3 a) {
    return normalized(a + def.angle_sigma * Vec3{normal(rng), normal(rng), normal(rng)});
  }

  void node(int i) {
    NodeGene& n = g.nodes[i];
    // locked genes are skipped (genome/locks.h); an unlocked node draws as ever
    const unsigned lk = n.lock;
    const bool units_locked = has_locked_unit(n);
    // body
    if (!(lk & kLockBody)) {
      if (r.shapes.size() > 1 && hit()) {
        std::vector<Shape> others;
        for (Shape s : r.shapes)
          if (s != n.shape) others.push_back(s);
        n.shape = others[rng.below(others.size())];
      }
      for (int a = 0; a < 3; ++a)
        if (hit()) n.size[a] = scale(n.size[a], def.size_min[a], def.size_max[a]);
      if (def.mutate_density && hit())
        n.density = scale(n.density, def.density_range.lo, def.density_range.hi);
    }
    // joint (a new type re-draws the sensors and effectors on it: not under locked units)
    if (!(lk & kLockJoint)) {
      if (r.joints.size() > 1 && !units_locked && hit()) {
        std::vector<JointType> others;
        for (JointType t : r.joints)
          if (t != n.joint.type) others.push_back(t);
        change_joint(i, others[rng.below(others.size())]);
      }
      JointGene& j = g.nodes[i].joint;
      bool two = j.type == JointType::Universal || j.type == JointType::Spherical;
      if (hit()) {
        Vec3 a = nudge_axis(j.axis1);
        if (!two || norm(cross(a, j.axis2)) > 1e-3) j.axis1 = a;
      }
      if (hit()) {
        Vec3 a = nudge_axis(j.axis2);
        if (!two || norm(cross(j.axis1, a)) > 1e-3) j.axis2 = a;
      }
      for (int k = 0; k < static_cast<int>(j.limits.size()); ++k) {
        double m = dof_is_angular(j.type, k) ? kPi : def.slide_limit_max;
        if (hit()) j.limits[k].lo = perturb(j.limits[k].lo, -m, 0);
        if (hit()) j.limits[k].hi = perturb(j.limits[k].hi, 0, m);
      }
    }
    if (!(lk & kLockBody) && hit())
      g.nodes[i].recursive_limit =
          std::clamp(g.nodes[i].recursive_limit + (rng.chance(0.5) ? 1 : -1), 1,
                     std::max(1, def.recursive_limit_max));
    // brain
    const bool all_units = lk & kLockUnits;
    for (NeuronGene& nr : g.nodes[i].neurons)
      if (!all_units && !nr.locked) neuron(i, nr);
    int dofs = joint_dofs(g.nodes[i].joint.type);
    for (SensorGene& s : g.nodes[i].sensors) {
      if (all_units || s.locked || !hit()) continue;
      if (s.type == SensorType::JointAngle) {
        if (dofs > 1) s.dof = static_cast<int>(rng.below(dofs));
      } else if (s.type == SensorType::Photoreceptor) {
        s.direction = nudge_axis(s.direction);
      } else {
        s.face = static_cast<Face>(rng.below(6));
      }
    }
    Range eb = effector_bias_bounds(def, g.dialect);
    for (EffectorGene& ef : g.nodes[i].effectors) {
      if (all_units || ef.locked) continue;
      // carrying an encapsulated skill's wires, its muscle or degree of
      // freedom stays as that skill learned it
      if (!is_fixed(ef)) {
        if (ef.muscle) {
          // lessin2015 III-E: anchors and strength evolve
          MuscleGene& m = *ef.muscle;
          if (hit()) m.parent_dir = nudge_axis(m.parent_dir);
          if (hit()) m.child_dir = nudge_axis(m.child_dir);
          if (hit()) m.strength = scale(m.strength, def.muscle_strength_range.lo, def.muscle_strength_range.hi);
        } else if (dofs > 1 && hit()) {
          ef.dof = static_cast<int>(rng.below(dofs));
        }
      }
      if (hit()) ef.bias = perturb(ef.bias, eb.lo, eb.hi);
      inputs(i, ef.inputs);
    }
    // edges (not a locked node's own, nor those into a node whose in-edges are locked)
    for (EdgeGene& e : g.nodes[i].edges) {
      if ((lk & kLockOutEdges) || (g.nodes[e.to].lock & kLockInEdges)) continue;
      if (hit()) e.face = static_cast<Face>(rng.below(6));
      if (hit()) e.u = perturb(e.u, -1, 1);
      if (hit()) e.v = perturb(e.v, -1, 1);
      for (int a = 0; a < 3; ++a)
        if (hit()) e.rotation[a] = wrap_angle(e.rotation[a] + normal(rng) * def.angle_sigma);
      if (hit()) e.scale = scale(e.scale, def.scale_range.lo, def.scale_range.hi);
      if (!r.reflect_axes.empty() && hit()) {
        int axis = r.reflect_axes[rng.below(r.reflect_axes.size())];
        auto it = std::find(e.reflect.begin(), e.reflect.end(), axis);
        if (it != e.reflect.end())
          e.reflect.erase(it);
        else
          e.reflect.insert(std::upper_bound(e.reflect.begin(), e.reflect.end(), axis), axis);
      }
      if (hit()) e.terminal_only = !e.terminal_only;
    }
  }

  // ---- structural mutations (each tried once per call)

  int n_nodes() const { return static_cast<int>(g.nodes.size()); }

  void add_node() {
    if (n_nodes() >= max_genes(g, def)) return;
    int c = add_random_node(g, static_cast<int>(rng.below(n_nodes())), def, rng);
    wire_node(g, c, def, rng);
  }

  void remove_node() {
    if (n_nodes() < 2) return;
    int victim = 1 + static_cast<int>(rng.below(n_nodes() - 1));
    if (reachable_count(g, victim) < def.min_genes) return;
    bx::remove_node(g, victim, SourceFix::Reassign, &rng);
    remove_unreachable(g, SourceFix::Reassign, &rng);
  }

  std::vector<std::pair<int, int>> all_edges() const {
    std::vector<std::pair<int, int>> es;
    for (int i = 0; i < n_nodes(); ++i)
      for (int k = 0; k < static_cast<int>(g.nodes[i].edges.size()); ++k) es.push_back({i, k});
    return es;
  }

  void add_edge() {
    int p = static_cast<int>(rng.below(n_nodes()));
    int t = static_cast<int>(rng.below(n_nodes()));
    g.nodes[p].edges.push_back(random_edge(g, p, t, def, rng));
    if (t == p && g.nodes[p].recursive_limit < 2)
      g.nodes[p].recursive_limit = std::min(2, std::max(1, def.recursive_limit_max));
  }

  void remove_edge() {
    auto es = all_edges();
    if (es.empty()) return;
    auto [i, k] = es[rng.below(es.size())];
    if (reachable_count(g, -1, i, k) < def.min_genes) return;
    bx::remove_edge(g, i, k, SourceFix::Reassign, &rng);
    remove_unreachable(g, SourceFix::Reassign, &rng);
  }

  void retarget_edge() {
    auto es = all_edges();
    if (es.empty()) return;
    auto [i, k] = es[rng.below(es.size())];
    int old = g.nodes[i].edges[k].to;
    g.nodes[i].edges[k].to = static_cast<int>(rng.below(n_nodes()));
    if (reachable_count(g) < def.min_genes) {
      g.nodes[i].edges[k].to = old;
      return;
    }
    remove_unreachable(g, SourceFix::Reassign, &rng);
    repair_sources(g, SourceFix::Reassign, &rng);
  }

  void add_neuron() {
    if (def.p_wired_neuron > 0 && rng.chance(def.p_wired_neuron) && add_wired_neuron()) return;
    NeuronGene nr = random_neuron(g.dialect, def, rng);
    int owner = r.global_neurons && rng.chance(def.p_global_neuron)
                    ? -1
                    : static_cast<int>(rng.below(n_nodes()));
    place_neuron(owner, std::move(nr));
  }

  // `nr` appended to node `owner`'s neurons (-1: the global ones) with
  // random inputs, as a new neuron gets them; its index there
  int place_neuron(int owner, NeuronGene nr) {
    auto list = [&]() -> std::vector<NeuronGene>& { return owner < 0 ? g.global_neurons : g.nodes[owner].neurons; };
    list().push_back(nr);
    const int k = static_cast<int>(list().size()) - 1;
    int count = new_input_count(g, nr, def, rng);
    std::vector<InputGene> ins = random_inputs(g, owner, count, def, rng);
    list()[k].inputs = std::move(ins);
    return k;
  }

  // a random neuron over all nodes and the global ones: (owner, index)
  bool pick_neuron(int& owner, int& k) {
    int total = static_cast<int>(g.global_neurons.size());
    for (const NodeGene& n : g.nodes) total += static_cast<int>(n.neurons.size());
    if (total == 0) return false;
    int x = static_cast<int>(rng.below(total));
    for (int i = 0; i < n_nodes(); ++i) {
      int c = static_cast<int>(g.nodes[i].neurons.size());
      if (x < c) {
        owner = i;
        k = x;
        return true;
      }
      x -= c;
    }
    owner = -1;
    k = x;
    return true;
  }

  void remove_neuron() {
    int owner, k;
    if (!pick_neuron(owner, k)) return;
    if (owner < 0)
      remove_global_neuron(g, k, SourceFix::Reassign, &rng);
    else
      bx::remove_neuron(g, owner, k, SourceFix::Reassign, &rng);
  }

  void change_fn() {
    int owner, k;
    if (!pick_neuron(owner, k)) return;
    NeuronGene& nr = owner < 0 ? g.global_neurons[k] : g.nodes[owner].neurons[k];
    // a pandemonium member stays what its group needs (DialectRules::group_fn):
    // groups are the syllabus's, and no operator changes one; nor a switch
    if (nr.group != NeuronGene::kNoGroup || !nr.skill.empty()) return;
    std::vector<std::string_view> names = neuron_fn_names(r.neuron_set);
    std::vector<std::string_view> others;
    for (auto nm : names)
      if (nm != nr.fn) others.push_back(nm);
    if (others.empty()) return;
    const NeuronFnSpec* spec = find_neuron_fn(r.neuron_set, others[rng.below(others.size())]);
    nr.fn = std::string(spec->name);
    nr.params.clear();
    for (const ParamSpec& p : spec->params) nr.params.push_back(p.default_value);
    if (spec->mode == InputMode::Positional) nr.bias = 0;
    int arity = spec->max_inputs;
    if (r.max_inputs_per_neuron > 0) arity = std::min(arity, r.max_inputs_per_neuron);
    if (static_cast<int>(nr.inputs.size()) > arity) nr.inputs.resize(arity);
    // a positional function gets every argument
    if (spec->mode == InputMode::Positional) {
      int missing = arity - static_cast<int>(nr.inputs.size());
      std::vector<InputGene> more = random_inputs(g, owner, missing, def, rng);
      NeuronGene& same = owner < 0 ? g.global_neurons[k] : g.nodes[owner].neurons[k];
      same.inputs.insert(same.inputs.end(), more.begin(), more.end());
    }
  }

  void add_sensor() {
    int i = static_cast<int>(rng.below(n_nodes()));
    int dofs = joint_dofs(g.nodes[i].joint.type);
    bool angle_ok =
        has_parent(g, i) && dofs > 0 &&
        std::find(r.sensors.begin(), r.sensors.end(), SensorType::JointAngle) != r.sensors.end();
    bool contact_ok =
        std::find(r.sensors.begin(), r.sensors.end(), SensorType::Contact) != r.sensors.end();
    bool photo_ok =
        std::find(r.sensors.begin(), r.sensors.end(), SensorType::Photoreceptor) != r.sensors.end();
    if (!angle_ok && !contact_ok && !photo_ok) return;
    SensorGene s;
    if (!angle_ok && !contact_ok) {
      s.type = SensorType::Photoreceptor;  // lessin2015 III-D
      s.direction = random_direction(rng);
    } else if (angle_ok && (!contact_ok || rng.chance(0.5))) {
      s.type = SensorType::JointAngle;
      s.dof = static_cast<int>(rng.below(dofs));
    } else {
      s.type = SensorType::Contact;
      s.face = static_cast<Face>(rng.below(6));
    }
    g.nodes[i].sensors.push_back(s);
  }

  void remove_sensor() {
    int total = 0;
    for (const NodeGene& n : g.nodes) total += static_cast<int>(n.sensors.size());
    if (total == 0) return;
    int x = static_cast<int>(rng.below(total));
    for (int i = 0; i < n_nodes(); ++i) {
      int c = static_cast<int>(g.nodes[i].sensors.size());
      if (x < c) {
        bx::remove_sensor(g, i, x, SourceFix::Reassign, &rng);
        return;
      }
      x -= c;
    }
  }

  void add_effector() {
    std::vector<int> cands;
    for (int i = 0; i < n_nodes(); ++i)
      if ((r.muscle_effectors || joint_dofs(g.nodes[i].joint.type) > 0) && has_parent(g, i))
        cands.push_back(i);
    if (cands.empty()) return;
    int i = cands[rng.below(cands.size())];
    Range eb = effector_bias_bounds(def, g.dialect);
    EffectorGene e;
    if (r.muscle_effectors)
      e.muscle = random_muscle(def, rng);  // lessin2015 III-E: a new muscle to the parent
    else
      e.dof = static_cast<int>(rng.below(joint_dofs(g.nodes[i].joint.type)));
    e.bias = rng.uniform(eb.lo, eb.hi);
    e.inputs = random_inputs(
        g, i,
        uniform_int(rng, def.effector_inputs_at_creation.lo, def.effector_inputs_at_creation.hi),
        def, rng);
    g.nodes[i].effectors.push_back(std::move(e));
  }

  void remove_effector() {
    int total = 0;
    for (const NodeGene& n : g.nodes) total += static_cast<int>(n.effectors.size());
    if (total == 0) return;
    int x = static_cast<int>(rng.below(total));
    for (int i = 0; i < n_nodes(); ++i) {
      int c = static_cast<int>(g.nodes[i].effectors.size());
      if (x < c) {
        auto& efs = g.nodes[i].effectors;
        if (r.muscle_effectors)  // a muscle's length may be read: its readers renumbered, reassigned
          bx::remove_effector(g, i, x, SourceFix::Reassign, &rng);
        else
          efs.erase(efs.begin() + x);
        return;
      }
      x -= c;
    }
  }

  // the units that may take or lose an input: weighted-sum neurons and
  // effectors that no lock holds whole (an open switch among them), as
  // (owner, index, is effector); owner -1: a global neuron
  struct UnitRef {
    int owner, index;
    bool effector;
  };
  std::vector<UnitRef> wired_units() {
    std::vector<UnitRef> out;
    auto sum_neuron = [&](const NeuronGene& nr) {
      const NeuronFnSpec* spec = spec_of(g, nr);
      return !nr.locked && spec && spec->mode == InputMode::WeightedSum;
    };
    for (int i = 0; i < n_nodes(); ++i) {
      if (g.nodes[i].lock & kLockUnits) continue;
      for (int k = 0; k < static_cast<int>(g.nodes[i].neurons.size()); ++k)
        if (sum_neuron(g.nodes[i].neurons[k])) out.push_back({i, k, false});
      for (int k = 0; k < static_cast<int>(g.nodes[i].effectors.size()); ++k)
        if (!g.nodes[i].effectors[k].locked) out.push_back({i, k, true});
    }
    for (int k = 0; k < static_cast<int>(g.global_neurons.size()); ++k)
      if (sum_neuron(g.global_neurons[k])) out.push_back({-1, k, false});
    return out;
  }
  std::vector<InputGene>& inputs_of(const UnitRef& u) {
    if (u.effector) return g.nodes[u.owner].effectors[u.index].inputs;
    return u.owner < 0 ? g.global_neurons[u.index].inputs : g.nodes[u.owner].neurons[u.index].inputs;
  }

  // whether a unit may take one more input: an effector always, a neuron
  // below its function's input limit
  bool has_room(const UnitRef& u) const {
    if (u.effector) return true;
    const NeuronGene& nr = u.owner < 0 ? g.global_neurons[u.index] : g.nodes[u.owner].neurons[u.index];
    int most = spec_of(g, nr)->max_inputs;
    if (r.max_inputs_per_neuron > 0) most = std::min(most, r.max_inputs_per_neuron);
    return static_cast<int>(nr.inputs.size()) < most;
  }

  // the units that may take one more input (wired_units with room)
  std::vector<UnitRef> open_units() {
    std::vector<UnitRef> out;
    for (const UnitRef& u : wired_units())
      if (has_room(u)) out.push_back(u);
    return out;
  }

  // add_neuron in front of a unit (OperatorDef::p_wired_neuron): a random
  // neuron in a random open unit's node (or global, for a global unit),
  // wired as add_neuron wires one, and read by that unit with a random
  // weight. False (nothing drawn past the unit) when no unit is open.
  bool add_wired_neuron() {
    std::vector<UnitRef> units = open_units();
    if (units.empty()) return false;
    const UnitRef u = units[rng.below(units.size())];
    const int k = place_neuron(u.owner, random_neuron(g.dialect, def, rng));
    Range wb = weight_bounds(def, g.dialect);
    InputGene in;
    in.place = u.owner < 0 ? SourcePlace::Global : SourcePlace::Self;
    in.kind = SourceKind::Neuron;
    in.index = k;
    in.weight = rng.uniform(wb.lo, wb.hi);
    inputs_of(u).push_back(in);
    return true;
  }

  void add_input() {
    std::vector<UnitRef> units = wired_units();
    if (units.empty()) return;
    const UnitRef u = units[rng.below(units.size())];
    if (!has_room(u)) return;
    InputGene in;
    if (random_input(g, u.owner, def, rng, in)) inputs_of(u).push_back(in);
  }

  void remove_input() {
    std::vector<UnitRef> units = wired_units();
    if (units.empty()) return;
    const UnitRef u = units[rng.below(units.size())];
    std::vector<InputGene>& ins = inputs_of(u);
    const int first = gated_prefix(ins);  // gated inputs are frozen
    const int free = static_cast<int>(ins.size()) - first;
    if (free <= 0) return;
    ins.erase(ins.begin() + first + static_cast<std::ptrdiff_t>(rng.below(static_cast<std::uint64_t>(free))));
  }

  // A catapult's release (chaumont2007 4.1: the mechanism is fixed "except
  // its connection to the neural network"): its inputs mutate as a neuron's,
  // read as from the arm; then with `rate` one random input is added and
  // with `rate` a random one removed (our choice: a neuron's inputs are fixed
  // by its arity, the release's are not). Its delay never changes.
  void release() {
    std::vector<InputGene>& ins = g.catapult->release.inputs;
    inputs(0, ins);
    if (hit()) {
      InputGene in;
      if (random_input(g, 0, def, rng, in)) ins.push_back(in);
    }
    if (!ins.empty() && hit()) ins.erase(ins.begin() + static_cast<std::ptrdiff_t>(rng.below(ins.size())));
  }

  // a structural mutation; on a genome with locks, undone if it broke one
  // (it drew what it drew: the stream goes on as if it had stood)
  template <class Op>
  void structural(double chance, Op op) {
    if (!rng.chance(chance)) return;
    if (!locks) return op();
    Genome saved = g;
    op();
    if (!locks_kept(saved, g)) g = std::move(saved);
  }

  void run() {
    // every numeric field with probability `rate`
    for (int i = 0; i < n_nodes(); ++i) node(i);
    for (NeuronGene& nr : g.global_neurons)
      if (!nr.locked) neuron(-1, nr);
    if (is_catapult(g)) release();
    // structure, in a fixed order
    const StructuralRates& s = def.structure;
    structural(s.add_node, [&] { add_node(); });
    structural(s.remove_node, [&] { remove_node(); });
    structural(s.add_edge, [&] { add_edge(); });
    structural(s.remove_edge, [&] { remove_edge(); });
    structural(s.retarget_edge, [&] { retarget_edge(); });
    structural(s.add_neuron, [&] { add_neuron(); });
    structural(s.remove_neuron, [&] { remove_neuron(); });
    structural(s.add_sensor, [&] { add_sensor(); });
    structural(s.remove_sensor, [&] { remove_sensor(); });
    structural(s.add_effector, [&] { add_effector(); });
    structural(s.remove_effector, [&] { remove_effector(); });
    structural(s.change_fn, [&] { change_fn(); });
    // drawn only when set, so genomes of every preset without them mutate as before
    if (s.add_input > 0) structural(s.add_input, [&] { add_input(); });
    if (s.remove_input > 0) structural(s.remove_input, [&] { remove_input(); });
  }
};

}  // namespace

void mutate(Genome& g, const OperatorDef& def, double rate, Rng& rng) {
  if (g.nodes.empty()) return;
  Genome before = g;
  const bool locked = has_locks(before);
  if (dialect_rules(g.dialect).operators == OperatorScheme::LimbTree)
    mutate_miconi(g, def, rate, rng);
  else
    GraphMutator{g, def, rate, rng, dialect_rules(g.dialect), locked}.run();
  // an unchanged genome is left exactly as it was
  if (!(g == before)) normalize(g, def, rng);
  // the repairs keep valid locked genes as they are; should one not, the
  // mutation is undone rather than a lock broken
  if (locked && !locks_kept(before, g)) g = std::move(before);
}

}  // namespace bx
