// Catapults (chaumont2007 section 4; operators.h, docs/operators.md):
// random creation, and the catapult versions of mutation, crossover,
// grafting and normalize. Each detaches the projectile, runs the plain
// operator on the arm and body (operators_detail.h), and attaches the
// projectile again: one arm, one projectile, the mechanism untouched but for
// its inputs.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "genome/dialect.h"
#include "genome/genome_edit.h"
#include "genome/operators.h"
#include "genome/operators_detail.h"

namespace bx {

namespace {

int uniform_int(Rng& rng, int lo, int hi) {
  if (hi <= lo) return lo;
  return lo + static_cast<int>(rng.below(static_cast<std::uint64_t>(hi - lo + 1)));
}

// x moved by a Gaussian step of param_sigma times the range, clamped
double perturb(double x, double lo, double hi, const OperatorDef& def, Rng& rng) {
  return std::clamp(x + normal(rng) * def.param_sigma * (hi - lo), lo, hi);
}

// x wrapped into [-pi, pi]
double wrap_angle(double x) {
  double y = std::fmod(x + kPi, 2 * kPi);
  if (y < 0) y += 2 * kPi;
  return std::clamp(y - kPi, -kPi, kPi);
}

// A catapult taken apart: the arm and body as a genome of their own, the
// projectile node and the arm's edge to it.
struct Parts {
  /// The arm (node 0) and the body. `catapult` holds the release, with
  /// projectile -1 (operators_detail.h): edits keep its inputs valid.
  Genome body;
  NodeGene projectile;
  EdgeGene edge;  ///< its `to` is set when attached
};

// The constants for the arm and body: one gene less (the projectile counts
// towards max_genes), one part less at creation.
OperatorDef body_def(const OperatorDef& def, Dialect d) {
  const DialectRules& r = dialect_rules(d);
  OperatorDef b = def;
  b.dialect = d;
  int most = r.max_genes > 0 ? std::min(def.max_genes, r.max_genes) : def.max_genes;
  b.max_genes = std::max(1, most - 1);
  int parts = def.max_parts_at_creation > 0 ? def.max_parts_at_creation : r.max_parts;
  if (parts > 1) b.max_parts_at_creation = parts - 1;
  b.catapult.enabled = false;
  return b;
}

Parts detach(const Genome& g) {
  assert(is_catapult(g));
  Parts d;
  int p = g.catapult->projectile;
  d.projectile = g.nodes[p];
  // the arm's edge to the projectile (a valid catapult has exactly one)
  for (const EdgeGene& e : g.nodes[0].edges)
    if (e.to == p) {
      d.edge = e;
      break;
    }
  // the projectile has nothing to read: removing it only renumbers the
  // nodes after it and the arm's child sources (the release's too) on
  // later edges
  d.body = g;
  d.body.catapult->projectile = -1;
  remove_node(d.body, p, SourceFix::Remove);
  return d;
}

// A parent that is not a catapult as a body: without a release, cut to the
// first `most` nodes breadth-first from its root if it has more.
Genome as_body(const Genome& g, int most, Rng& rng) {
  Genome b = g;
  b.catapult.reset();
  if (static_cast<int>(b.nodes.size()) <= most) return b;
  b.nodes.clear();
  append_subgraph(b, g, 0, most);
  repair_sources(b, SourceFix::Reassign, &rng);
  return b;
}

// Edges to node 0 grow a second arm: removed (the root is reached anyway,
// so no node becomes unreachable; child sources on them are reassigned).
void drop_edges_to_arm(Genome& g, Rng& rng) {
  for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i)
    for (int k = static_cast<int>(g.nodes[i].edges.size()) - 1; k >= 0; --k)
      if (g.nodes[i].edges[k].to == 0) remove_edge(g, i, k, SourceFix::Reassign, &rng);
}

// The body with the projectile attached again in canonical form: the last
// node, held by the arm's last edge. The projectile and its edge are made
// to follow the rules (validate()) whatever they were.
Genome attach(Genome body, NodeGene projectile, EdgeGene edge) {
  assert(body.catapult);
  projectile.shape = Shape::Box;
  projectile.joint.type = JointType::Fixed;
  projectile.joint.limits.clear();
  projectile.recursive_limit = 1;
  projectile.neurons.clear();
  projectile.sensors.clear();
  projectile.effectors.clear();
  projectile.edges.clear();
  int p = static_cast<int>(body.nodes.size());
  body.nodes.push_back(std::move(projectile));
  edge.to = p;
  edge.scale = 1.0;
  edge.reflect.clear();
  edge.terminal_only = false;
  body.nodes[0].edges.push_back(edge);
  CatapultGene& c = *body.catapult;
  c.projectile = p;
  c.release.delay_steps = std::clamp(c.release.delay_steps, kMinReleaseDelaySteps, kMaxReleaseDelaySteps);
  return body;
}

// The release's inputs mutate as a neuron's (each weight and each source at
// `rate`); with `rate` each, one random input is added and one removed.
void mutate_release(Genome& body, const OperatorDef& def, double rate, Rng& rng) {
  std::vector<InputGene>& ins = body.catapult->release.inputs;
  Range wb = weight_bounds(def, body.dialect);
  for (InputGene& in : ins) {
    if (rng.chance(rate)) in.weight = perturb(in.weight, wb.lo, wb.hi, def, rng);
    if (rng.chance(rate)) {
      std::vector<InputGene> cands = source_candidates(body, 0);
      if (cands.empty()) continue;
      double w = in.weight;
      in = cands[rng.below(cands.size())];
      in.weight = w;
    }
  }
  if (rng.chance(rate)) {
    InputGene in;
    if (random_input(body, 0, def, rng, in)) ins.push_back(in);
  }
  if (!ins.empty() && rng.chance(rate))
    ins.erase(ins.begin() + static_cast<std::ptrdiff_t>(rng.below(ins.size())));
}

// Where the arm holds the projectile: face, (u, v) and rotation mutate as an
// edge's; scale, reflection and terminal-only are fixed.
void mutate_attachment(EdgeGene& e, const OperatorDef& def, double rate, Rng& rng) {
  if (rng.chance(rate)) e.face = static_cast<Face>(rng.below(6));
  if (rng.chance(rate)) e.u = perturb(e.u, -1, 1, def, rng);
  if (rng.chance(rate)) e.v = perturb(e.v, -1, 1, def, rng);
  for (int a = 0; a < 3; ++a)
    if (rng.chance(rate)) e.rotation[a] = wrap_angle(e.rotation[a] + normal(rng) * def.angle_sigma);
}

// The projectile's size (chaumont2007 4.2: "in some experiments"), as a
// part's: times exp(N(0, size_sigma)) within size_min..size_max.
void mutate_projectile(NodeGene& p, const OperatorDef& def, double rate, Rng& rng) {
  for (int a = 0; a < 3; ++a)
    if (rng.chance(rate))
      p.size[a] = std::clamp(p.size[a] * std::exp(normal(rng) * def.size_sigma), def.size_min[a],
                             def.size_max[a]);
}

}  // namespace

// ---------------------------------------------------------------- creation

bool is_catapult(const Genome& g) {
  return g.catapult && g.catapult->projectile > 0 &&
         g.catapult->projectile < static_cast<int>(g.nodes.size());
}

Genome random_catapult(const OperatorDef& def, Rng& rng) {
  const Dialect d = Dialect::Chaumont2007;
  OperatorDef bdef = body_def(def, d);
  // the arm and the body: a walker's genome, one gene short
  Genome g = detail::random_genome_plain(d, bdef, rng);
  g.catapult = CatapultGene{-1, ReleaseGene{def.catapult.release_delay_steps, {}}};
  drop_edges_to_arm(g, rng);
  // the release's wiring from the body's network
  const IntRange& k = def.catapult.release_inputs_at_creation;
  g.catapult->release.inputs = random_inputs(g, 0, uniform_int(rng, k.lo, k.hi), bdef, rng);
  // the projectile, placed as a limb of the arm would be
  NodeGene p;
  p.shape = Shape::Box;
  p.size = def.catapult.projectile_size;
  p.density = def.catapult.projectile_density;
  p.joint.type = JointType::Fixed;
  g.nodes.push_back(p);
  OperatorDef pdef = bdef;
  pdef.scale_at_creation = {1, 1};
  pdef.p_reflect = 0;
  pdef.p_terminal_only = 0;
  EdgeGene e = random_edge(g, 0, static_cast<int>(g.nodes.size()) - 1, pdef, rng);
  g.nodes.pop_back();
  return attach(std::move(g), std::move(p), e);
}

// ---------------------------------------------------------------- operators

void detail::mutate_catapult(Genome& g, const OperatorDef& def, double rate, Rng& rng) {
  Parts d = detach(g);
  const Parts before = d;
  // the arm and the body, as a walker's genome
  mutate_plain(d.body, body_def(def, g.dialect), rate, rng);
  drop_edges_to_arm(d.body, rng);
  // the mechanism: its wiring only (never its delay)
  mutate_release(d.body, def, rate, rng);
  mutate_attachment(d.edge, def, rate, rng);
  if (def.catapult.mutate_projectile) mutate_projectile(d.projectile, def, rate, rng);
  // an unchanged catapult is left exactly as it was
  if (d.body == before.body && d.edge == before.edge && d.projectile == before.projectile) return;
  g = attach(std::move(d.body), std::move(d.projectile), d.edge);
}

Genome detail::crossover_catapult(const Genome& a, const Genome& b, int cut, const OperatorDef& def,
                                  Rng& rng) {
  assert(a.dialect == b.dialect && (is_catapult(a) || is_catapult(b)));
  OperatorDef bdef = body_def(def, a.dialect);
  // the mechanism's parent: a, or b if only b is a catapult
  bool from_a = is_catapult(a);
  Parts m = detach(from_a ? a : b);
  Genome body_a = from_a ? m.body : as_body(a, bdef.max_genes, rng);
  Genome body_b = is_catapult(b) ? (from_a ? detach(b).body : m.body) : as_body(b, bdef.max_genes, rng);
  // the bodies cross as walkers; the child's arm is a's root, with a's
  // release (tracked as a root input)
  if (cut < 0) cut = crossover_cut(body_a, body_b, rng);
  Genome child = crossover_at_plain(body_a, body_b, cut, bdef, rng);
  if (!from_a) {
    // b's release on a's arm: sources that do not exist there reassigned
    child.catapult = m.body.catapult;
    repair_sources(child, SourceFix::Reassign, &rng);
  }
  drop_edges_to_arm(child, rng);
  return attach(std::move(child), std::move(m.projectile), m.edge);
}

Genome detail::graft_catapult(const Genome& trunk, const Genome& branch, const OperatorDef& def,
                              Rng& rng) {
  assert(trunk.dialect == branch.dialect && (is_catapult(trunk) || is_catapult(branch)));
  OperatorDef bdef = body_def(def, trunk.dialect);
  bool from_trunk = is_catapult(trunk);
  Parts m = detach(from_trunk ? trunk : branch);
  Genome body_t = from_trunk ? m.body : as_body(trunk, bdef.max_genes, rng);
  Genome body_b = is_catapult(branch) ? (from_trunk ? detach(branch).body : m.body)
                                      : as_body(branch, bdef.max_genes, rng);
  // a catapult branch gives a subgraph of its body, never its arm (Fig. 5)
  int first = is_catapult(branch) ? 1 : 0;
  Genome child = graft_plain(body_t, body_b, first, bdef, rng);
  if (!from_trunk) {
    child.catapult = m.body.catapult;
    repair_sources(child, SourceFix::Reassign, &rng);
  }
  drop_edges_to_arm(child, rng);
  return attach(std::move(child), std::move(m.projectile), m.edge);
}

void detail::normalize_catapult(Genome& g, const OperatorDef& def, Rng& rng) {
  Parts d = detach(g);
  normalize_plain(d.body, def, rng);
  drop_edges_to_arm(d.body, rng);
  g = attach(std::move(d.body), std::move(d.projectile), d.edge);
}

}  // namespace bx
