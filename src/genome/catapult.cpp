// Catapults (chaumont2007 section 4; operators.h, docs/operators.md):
// random creation. The operators keep a catapult a catapult through locks
// (genome/locks.h): its arm's in-edges and its projectile are locked at
// creation, so the ordinary operators never grow a second arm nor touch the
// projectile; mutation rewires the release (mutation.cpp) and normalize
// keeps the projectile a box grown once (random_genome.cpp).
#include <algorithm>

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

// The constants for the arm and body of a random catapult: one gene less
// (the projectile counts towards max_genes), one part less.
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

}  // namespace

// ---------------------------------------------------------------- creation

bool is_catapult(const Genome& g) {
  return g.catapult && g.catapult->projectile > 0 &&
         g.catapult->projectile < static_cast<int>(g.nodes.size());
}

unsigned catapult_projectile_lock(bool mutable_size) {
  return kLockJoint | kLockUnits | kLockInEdges | kLockOutEdges | (mutable_size ? 0u : kLockBody);
}

Genome random_catapult(const OperatorDef& def, Rng& rng) {
  const Dialect d = Dialect::Chaumont2007;
  OperatorDef bdef = body_def(def, d);
  // the arm and the body: a walker's genome, one gene short
  Genome g = detail::random_genome_plain(d, bdef, rng);
  // edges to the root would grow a second arm (the root is reached anyway:
  // no node is stranded; child sources on them are reassigned)
  remove_edges_to(g, 0, SourceFix::Reassign, &rng);
  // the release's wiring from the body's network (read as from the arm)
  g.catapult = CatapultGene{-1, ReleaseGene{def.catapult.release_delay_steps, {}}};
  const IntRange& k = def.catapult.release_inputs_at_creation;
  g.catapult->release.inputs = random_inputs(g, 0, uniform_int(rng, k.lo, k.hi), bdef, rng);
  // the projectile: node 1 (the body's nodes move up one), held by the arm's
  // last edge, placed as a limb of the arm would be
  for (NodeGene& n : g.nodes)
    for (EdgeGene& e : n.edges)
      if (e.to >= 1) ++e.to;
  NodeGene p;
  p.shape = Shape::Box;
  p.size = def.catapult.projectile_size;
  p.density = def.catapult.projectile_density;
  p.joint.type = JointType::Fixed;
  g.nodes.insert(g.nodes.begin() + 1, p);
  OperatorDef pdef = bdef;
  pdef.scale_at_creation = {1, 1};
  pdef.p_reflect = 0;
  pdef.p_terminal_only = 0;
  EdgeGene e = random_edge(g, 0, 1, pdef, rng);
  e.to = 1;
  e.scale = 1.0;
  e.reflect.clear();
  e.terminal_only = false;
  g.nodes[0].edges.push_back(e);
  g.catapult->projectile = 1;
  // the mechanism, locked (genome/locks.h): no edge ever leads to the arm,
  // and the projectile, its joint and its edge never change (its size
  // does with mutate_projectile)
  g.nodes[0].lock = kLockInEdges;
  g.nodes[1].lock = catapult_projectile_lock(def.catapult.mutate_projectile);
  return g;
}

}  // namespace bx
