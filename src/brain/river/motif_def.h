// What a config says of the river crossing's CTRNN motif, beside its values
// (SimConfig::motif, the [motif] keys): the file they were read from, and
// how the motif kind (genotype.kind = "motif": a motif's 15 genes, scored
// without a body) scores and breeds motifs. docs/rivercrossing.md, "The
// motif run" and "The motif file".
#pragma once

#include <string>

#include "brain/river/motif_fitness.h"

namespace bx {

/// Where a config's motif came from: a motif file (motif.file), and the hash
/// of the text it was read from (motif.hash), so a run records the motif it
/// used and which file gave it. Both empty: the motif's values were given
/// as keys, or left at the default found_motif().
struct MotifSource {
  std::string file;  ///< a shipped motif's name ("stanton2015-found") or a path, as the config gave it
  std::string hash;  ///< FNV-1a 64 of the file's text when it was read, 16 hex digits
  friend bool operator==(const MotifSource&, const MotifSource&) = default;
};

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
