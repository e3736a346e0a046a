// Internal to the genome layer: the operators of operators.h without their
// catapult dispatch, and the catapult versions they dispatch to
// (catapult.cpp). docs/operators.md, "Catapults", describes the scheme.
//
// The catapult versions detach the projectile and operate on the rest (the
// arm, node 0, and the body) with the plain operators. While detached, the
// rest keeps the release gene in Genome::catapult with projectile -1: it is
// then no catapult (is_catapult() is false, so the plain operators run), but
// the edits of genome_edit.h still treat its release inputs as inputs of
// node 0, so they keep reading the same sources as the body changes.
#pragma once

#include "core/rng.h"
#include "genome/genome.h"
#include "genome/operators.h"

namespace bx::detail {

/// random_genome() for a plain (non-catapult) genome.
Genome random_genome_plain(Dialect d, const OperatorDef& def, Rng& rng);

/// mutate() of a plain genome (or a detached catapult body).
void mutate_plain(Genome& g, const OperatorDef& def, double rate, Rng& rng);

/// crossover_at() of plain genomes. The child's root, global neurons and
/// `catapult` field (a detached release) come from `a`.
Genome crossover_at_plain(const Genome& a, const Genome& b, int cut, const OperatorDef& def,
                          Rng& rng);

/// The cut crossover() draws for parents `a` and `b`.
int crossover_cut(const Genome& a, const Genome& b, Rng& rng);

/// graft() of plain genomes; graph dialects take the branch's subgraph from
/// a node in [first_branch_node, size) (0 if the branch has no such node).
Genome graft_plain(const Genome& trunk, const Genome& branch, int first_branch_node,
                   const OperatorDef& def, Rng& rng);

/// normalize() of a plain genome (or a detached catapult body).
void normalize_plain(Genome& g, const OperatorDef& def, Rng& rng);

/// The catapult versions (at least one genome is_catapult()).
void mutate_catapult(Genome& g, const OperatorDef& def, double rate, Rng& rng);
/// `cut` < 0: drawn as crossover() draws it, on the parents' bodies.
Genome crossover_catapult(const Genome& a, const Genome& b, int cut, const OperatorDef& def,
                          Rng& rng);
Genome graft_catapult(const Genome& trunk, const Genome& branch, const OperatorDef& def, Rng& rng);
void normalize_catapult(Genome& g, const OperatorDef& def, Rng& rng);

}  // namespace bx::detail
