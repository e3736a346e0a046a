// Crossover and grafting (operators.h). docs/operators.md describes the
// splice and the repair rules.
#include <algorithm>
#include <cassert>
#include <tuple>

#include "genome/dialect.h"
#include "genome/genome_edit.h"
#include "genome/locks.h"
#include "genome/operators.h"

namespace bx {

namespace {

int max_genes(Dialect d, const OperatorDef& def) {
  int r = dialect_rules(d).max_genes;
  return r > 0 ? std::min(def.max_genes, r) : def.max_genes;
}

// Aligned rows: the child's node at each position comes from `a` before the
// cut and from `b` from the cut on. Positions that neither side fills (past
// a's end but before the cut) are skipped, so the child's nodes are
// renumbered: position -> child index, or -1.
struct Splice {
  int na, nb, cut, left;  // left = nodes taken from a
  int index_of(int pos) const {
    if (pos < 0) return -1;
    if (pos < left) return pos;
    if (pos >= cut && pos < nb) return left + pos - cut;
    return -1;
  }
  int size() const { return left + std::max(0, nb - cut); }
};

Splice make_splice(const Genome& a, const Genome& b, int cut) {
  Splice s;
  s.na = static_cast<int>(a.nodes.size());
  s.nb = static_cast<int>(b.nodes.size());
  s.cut = std::clamp(cut, 1, std::max({1, s.na, s.nb}));
  s.left = std::min(s.cut, s.na);
  return s;
}

// ---------------------------------------------------------------- miconi2006: parent pointers
// Miconi's nodes each describe their own attachment to their parent (sec. 2),
// so the splice carries each node's incoming edge with it. Child sources are
// carried as the position of the child they read.

struct Limb {
  NodeGene node;  // edges cleared; child sources hold the child's position in `edge`
  int parent = -1;
  EdgeGene edge;  // the incoming edge (its `to` unused)
};

std::vector<Limb> limbs_of(const Genome& g) {
  int n = static_cast<int>(g.nodes.size());
  std::vector<Limb> limbs(n);
  for (int i = 0; i < n; ++i) {
    const NodeGene& node = g.nodes[i];
    limbs[i].node = node;
    auto to_position = [&node](std::vector<InputGene>& ins) {
      for (InputGene& in : ins)
        if (in.place == SourcePlace::Child)
          in.edge = in.edge >= 0 && in.edge < static_cast<int>(node.edges.size())
                        ? node.edges[in.edge].to
                        : -1;
    };
    for (auto& nr : limbs[i].node.neurons) to_position(nr.inputs);
    for (auto& ef : limbs[i].node.effectors) to_position(ef.inputs);
    limbs[i].node.edges.clear();
  }
  for (int i = 0; i < n; ++i)
    for (const EdgeGene& e : g.nodes[i].edges)
      if (e.to > 0 && e.to < n && limbs[e.to].parent < 0 && e.to != i) {
        limbs[e.to].parent = i;
        limbs[e.to].edge = e;
      }
  return limbs;
}

// Makes the parent pointers a tree rooted at 0: nodes cut off from the root
// (no parent, or a cycle) are hung from a random node that reaches the root.
void repair_tree(std::vector<Limb>& limbs, Rng& rng) {
  int n = static_cast<int>(limbs.size());
  limbs[0].parent = -1;
  for (int j = 1; j < n; ++j)
    if (limbs[j].parent < 0 || limbs[j].parent >= n || limbs[j].parent == j) limbs[j].parent = -1;
  for (;;) {
    // which nodes reach the root
    std::vector<int> state(n, 0);  // 0 unknown, 1 reaches, 2 does not
    state[0] = 1;
    for (int j = 1; j < n; ++j) {
      std::vector<int> path;
      int x = j;
      std::vector<bool> on_path(n, false);
      while (x >= 0 && state[x] == 0 && !on_path[x]) {
        on_path[x] = true;
        path.push_back(x);
        x = limbs[x].parent;
      }
      int result = x >= 0 && state[x] == 1 ? 1 : 2;
      for (int y : path) state[y] = result;
    }
    int u = -1;
    for (int j = 1; j < n && u < 0; ++j)
      if (state[j] == 2) u = j;
    if (u < 0) return;
    // climb to the top of u's chain: an orphan or a node on a cycle
    std::vector<bool> seen(n, false);
    int x = u;
    while (limbs[x].parent >= 0 && !seen[x]) {
      seen[x] = true;
      x = limbs[x].parent;
    }
    std::vector<int> reach;
    for (int j = 0; j < n; ++j)
      if (state[j] == 1) reach.push_back(j);
    limbs[x].parent = reach[rng.below(reach.size())];
  }
}

Genome build_tree(const std::vector<Limb>& limbs, Dialect d, double step) {
  Genome g;
  g.dialect = d;
  int n = static_cast<int>(limbs.size());
  for (const Limb& l : limbs) g.nodes.push_back(l.node);
  for (int j = 1; j < n; ++j) {
    int p = limbs[j].parent;
    EdgeGene e = limbs[j].edge;
    e.to = j;
    // the attachment follows the (possibly new) parent's size
    reseat_edge(e, g.nodes[p].size, step);
    g.nodes[p].edges.push_back(e);
  }
  // child sources: the child's position back to an edge index (-1: not a child any more)
  for (int i = 0; i < n; ++i) {
    NodeGene& node = g.nodes[i];
    auto to_edge = [&node](std::vector<InputGene>& ins) {
      for (InputGene& in : ins) {
        if (in.place != SourcePlace::Child) continue;
        int pos = in.edge;
        in.edge = -1;
        for (int k = 0; k < static_cast<int>(node.edges.size()); ++k)
          if (node.edges[k].to == pos) in.edge = k;
      }
    };
    for (auto& nr : node.neurons) to_edge(nr.inputs);
    for (auto& ef : node.effectors) to_edge(ef.inputs);
  }
  return g;
}

Genome crossover_miconi(const Genome& a, const Genome& b, const Splice& s, const OperatorDef& def,
                        Rng& rng) {
  std::vector<Limb> la = limbs_of(a), lb = limbs_of(b);
  std::vector<Limb> child;
  auto take = [&](const Limb& l) {
    Limb c = l;
    c.parent = s.index_of(l.parent);
    auto remap = [&s](std::vector<InputGene>& ins) {
      for (InputGene& in : ins)
        if (in.place == SourcePlace::Child) in.edge = s.index_of(in.edge);
    };
    for (auto& nr : c.node.neurons) remap(nr.inputs);
    for (auto& ef : c.node.effectors) remap(ef.inputs);
    child.push_back(std::move(c));
  };
  for (int p = 0; p < s.left; ++p) take(la[p]);
  for (int p = s.cut; p < s.nb; ++p) take(lb[p]);
  repair_tree(child, rng);
  Genome g = build_tree(child, a.dialect, def.angle_step);
  normalize(g, def, rng);
  return g;
}

// ---------------------------------------------------------------- graph dialects

Genome crossover_graph(const Genome& a, const Genome& b, const Splice& s, const OperatorDef& def,
                       Rng& rng) {
  Genome g;
  g.dialect = a.dialect;
  for (int p = 0; p < s.left; ++p) g.nodes.push_back(a.nodes[p]);
  for (int p = s.cut; p < s.nb; ++p) g.nodes.push_back(b.nodes[p]);
  // global neurons come with the root's parent (our choice), and so does a
  // catapult's mechanism, read from the root
  g.global_neurons = a.global_neurons;
  g.catapult = a.catapult;
  // edges keep their positions; one pointing at a position the child lacks is
  // pointed at a random node (Sims 1994)
  int n = static_cast<int>(g.nodes.size());
  for (NodeGene& node : g.nodes)
    for (EdgeGene& e : node.edges) {
      int to = s.index_of(e.to);
      e.to = to >= 0 ? to : static_cast<int>(rng.below(n));
    }
  const bool locked = has_locks(a) || has_locks(b);
  if (locked) {
    // locks are a's (genome/locks.h): the cut lies after a's kept nodes
    // (crossover_cut); b's nodes come unlocked, and an edge of theirs (or a
    // random one) into a node whose in-edges are locked goes to another node
    for (int i = s.left; i < n; ++i) unlock(g.nodes[i]);
    std::vector<int> open;
    for (int i = 0; i < n; ++i)
      if (!(g.nodes[i].lock & kLockInEdges)) open.push_back(i);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < static_cast<int>(g.nodes[i].edges.size()); ++k) {
        EdgeGene& e = g.nodes[i].edges[k];
        bool own = i < s.left && s.index_of(a.nodes[i].edges[k].to) == e.to;
        if (own || !(g.nodes[e.to].lock & kLockInEdges)) continue;
        if (!open.empty()) e.to = open[rng.below(open.size())];
      }
  }
  remove_unreachable(g, SourceFix::Reassign, &rng);
  normalize(g, def, rng);
  // what the repairs could not keep: the child is a copy of a
  if (locked && !locks_kept(a, g)) return a;
  return g;
}

// ---------------------------------------------------------------- crossover

// a cut strictly inside the longer row, so that each parent gives
// something, and after a's kept nodes (genome/locks.h), which it keeps
int crossover_cut(const Genome& a, const Genome& b, Rng& rng) {
  int m = static_cast<int>(std::max(a.nodes.size(), b.nodes.size()));
  int lo = std::max(1, last_kept_node(a) + 1);
  return m <= lo ? lo : lo + static_cast<int>(rng.below(m - lo));
}

}  // namespace

Genome crossover_at(const Genome& a, const Genome& b, int cut, const OperatorDef& def, Rng& rng) {
  assert(a.dialect == b.dialect && !a.nodes.empty() && !b.nodes.empty());
  // a cut never falls among a's kept nodes (genome/locks.h)
  if (has_locks(a)) cut = std::max(cut, last_kept_node(a) + 1);
  Splice s = make_splice(a, b, cut);
  if (dialect_rules(a.dialect).operators == OperatorScheme::LimbTree) return crossover_miconi(a, b, s, def, rng);
  return crossover_graph(a, b, s, def, rng);
}

Genome crossover(const Genome& a, const Genome& b, const OperatorDef& def, Rng& rng) {
  return crossover_at(a, b, crossover_cut(a, b, rng), def, rng);
}

Genome crossover(const Genome& a, const Genome& b, Rng& rng) {
  return crossover(a, b, default_operators(a.dialect), rng);
}

// ---------------------------------------------------------------- grafting

Genome graft(const Genome& trunk, const Genome& branch, const OperatorDef& def, Rng& rng) {
  assert(trunk.dialect == branch.dialect && !trunk.nodes.empty() && !branch.nodes.empty());
  Genome g = trunk;
  int most = max_genes(g.dialect, def);
  int nb = static_cast<int>(branch.nodes.size());
  // the trunk's edge that will lead to the new branch, and the room left
  int parent = -1, edge = -1, budget = 0;
  const bool limb_tree = dialect_rules(g.dialect).operators == OperatorScheme::LimbTree;
  if (limb_tree) {
    // miconi2006 5.1: remove a random branch (a limb and its sub-limbs)
    int n = static_cast<int>(g.nodes.size());
    if (n > 1) {
      int r = 1 + static_cast<int>(rng.below(n - 1));
      for (int p = 0; p < n && parent < 0; ++p)
        for (int k = 0; k < static_cast<int>(g.nodes[p].edges.size()); ++k)
          if (g.nodes[p].edges[k].to == r) {
            parent = p;
            edge = k;
            break;
          }
    }
  } else {
    // Sims 1994: one of the trunk's edges, chosen at random, among those
    // that leave room for at least one new node; never a locked edge
    // (genome/locks.h: out of a node with locked out-edges, into one with
    // locked in-edges)
    std::vector<std::pair<int, int>> es;
    for (int i = 0; i < static_cast<int>(g.nodes.size()); ++i)
      for (int k = 0; k < static_cast<int>(g.nodes[i].edges.size()); ++k)
        if (most - reachable_count(g, -1, i, k) >= 1 && !(g.nodes[i].lock & kLockOutEdges) &&
            !(g.nodes[g.nodes[i].edges[k].to].lock & kLockInEdges))
          es.push_back({i, k});
    if (!es.empty()) std::tie(parent, edge) = es[rng.below(es.size())];
  }
  if (parent < 0) {
    // no branch to replace: grow a new edge from the root, if there is room
    // (a root with locked edges takes no new one)
    if (static_cast<int>(g.nodes.size()) >= most || (g.nodes[0].lock & (kLockOutEdges | kLockInEdges))) {
      normalize(g, def, rng);
      return g;
    }
    g.nodes[0].edges.push_back(random_edge(g, 0, 0, def, rng));
    parent = 0;
    edge = static_cast<int>(g.nodes[0].edges.size()) - 1;
    budget = most - reachable_count(g, -1, parent, edge);
  } else {
    budget = most - reachable_count(g, -1, parent, edge);
  }
  // the new branch: miconi2006, a non-root limb whose subtree fits; graph
  // dialects, any node (its reachable subgraph is copied, cut to the budget)
  int src = 0;
  if (limb_tree && nb > 1) {
    std::vector<int> fits, any;
    for (int j = 1; j < nb; ++j) {
      any.push_back(j);
      if (static_cast<int>(subtree(branch, j).size()) <= budget) fits.push_back(j);
    }
    const auto& pool = fits.empty() ? any : fits;
    src = pool[rng.below(pool.size())];
  } else if (!limb_tree) {
    if (!has_locks(branch)) {
      src = static_cast<int>(rng.below(nb));
    } else {
      // never a kept node (genome/locks.h): a skill or a mechanism (a
      // catapult's arm or projectile, Fig. 5) is not a limb
      std::vector<int> free;
      for (int j = 0; j < nb; ++j)
        if (!is_kept(branch.nodes[j])) free.push_back(j);
      if (free.empty()) return trunk;
      src = free[rng.below(free.size())];
    }
  }
  // locks are the trunk's (genome/locks.h): the branch comes unlocked; a
  // child that lost one (a kept node cut off with the replaced branch) is
  // a copy of the trunk
  const bool locked = has_locks(trunk) || has_locks(branch);
  Genome loose;
  if (locked) {
    loose = branch;
    for (NodeGene& node : loose.nodes) unlock(node);
  }
  // connectivity kept where indices exist (miconi2006 5.1), clamped otherwise
  splice_subgraph(g, parent, edge, locked ? loose : branch, src, std::max(1, budget), SourceFix::Clamp, &rng);
  normalize(g, def, rng);
  if (locked && !locks_kept(trunk, g)) return trunk;
  return g;
}

Genome graft(const Genome& trunk, const Genome& branch, Rng& rng) {
  return graft(trunk, branch, default_operators(trunk.dialect), rng);
}

}  // namespace bx
