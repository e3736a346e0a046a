// How the motif kind (genotype.kind = "motif": a CTRNN motif's 15 genes,
// scored without a body) scores and breeds motifs. docs/rivercrossing.md,
// "The motif run".
#pragma once

#include "brain/river/motif_fitness.h"

namespace bx {

/// The motif kind's constants: its fitness (the [motif_fitness] keys), how
/// its genes decode (motif_from_genes: every gene in [-1, 1]) and mutate.
struct MotifKindDef {
  MotifFitnessDef fitness;
  MotifGeneDef genes;
  /// A mutated gene moves by N(0, gene_sigma), clamped into [-1, 1]: the
  /// search that found found_motif() (MotifSearch.DISABLED_EvolveAMotif).
  /// The paper gives none.
  double gene_sigma = 0.1;
  friend bool operator==(const MotifKindDef&, const MotifKindDef&) = default;
};

}  // namespace bx
