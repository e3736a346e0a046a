// The motif kind (genotype.kind = "motif"): a float vector of a CTRNN
// motif's 15 genes (motif_from_genes), scored by the motif's fitness
// (brain/river/motif_fitness.h) with no body and no physics world: the river
// crossing's motif run (Stanton & Channon 2015, "Neural Architecture";
// preset rivercrossing-motif). Its row of the creature table
// (eval/creature.cpp) is made of these.
#pragma once

#include <cstdint>
#include <vector>

#include "core/result.h"
#include "eval/sim_config.h"
#include "eval/sim_field.h"
#include "genome/float_vector.h"
#include "genome/genotype.h"

namespace bx {

struct EvalResult;

/// Its genes: motif_gene_count() of them in [-1, 1], a mutated one moving by
/// N(0, motif_kind.gene_sigma).
FloatVectorDef motif_kind_genes(const SimConfig& cfg);

/// Its config keys: the fitness's constants ([motif_fitness] seconds, dt,
/// high_input, target_hz, amplitude).
std::vector<SimField> motif_kind_fields();

/// Whether those keys can score (check_motif_fitness_def).
Status check_motif_kind(const SimConfig& cfg);

/// Scores a genotype of the kind: its genes decoded by motif_from_genes (a
/// count other than 15 or a gene outside [-1, 1]: not viable, with the
/// reason), both runs of score_motif under cfg.motif_kind.fitness. The
/// fitness is motif_fitness's; the metrics "oscillation", "quiescence",
/// "dominant hz" (under input) and "quiet power" (without input); seconds
/// the two runs' simulated time, brain_steps their Euler steps, steps 0 (no
/// physics). A pure function of (genes, config): `seed` draws nothing.
Status evaluate_motif_genes(const Genotype& g, const SimConfig& cfg, std::uint64_t seed, EvalResult& out);

}  // namespace bx
