#include "eval/motif_kind.h"

#include <cmath>

#include "brain/river/motif_fitness.h"
#include "eval/evaluate.h"

namespace bx {

FloatVectorDef motif_kind_genes(const SimConfig& cfg) {
  return {motif_gene_count(), -1, 1, cfg.motif_kind.gene_sigma};
}

std::vector<SimField> motif_kind_fields() {
  auto at = [](double MotifFitnessDef::*field) -> std::function<void*(SimConfig&)> {
    return [field](SimConfig& c) -> void* { return &(c.motif_kind.fitness.*field); };
  };
  return {
      {"motif_fitness", "seconds", SimField::Real, 1e-6, 1e4, {}, at(&MotifFitnessDef::seconds), "genotype.kind = \"motif\": each of a motif's two runs lasts this long (s), a whole number of steps of dt"},
      {"motif_fitness", "dt", SimField::Real, 1e-6, 1, {}, at(&MotifFitnessDef::dt), "... its Euler step (s; the river controller's)"},
      {"motif_fitness", "high_input", SimField::Real, -1e6, 1e6, {}, at(&MotifFitnessDef::high_input), "... the input of the first run (the second has none)"},
      {"motif_fitness", "target_hz", SimField::Real, 1e-6, 1e6, {}, at(&MotifFitnessDef::target_hz), "... the frequency to oscillate at under that input (Hz), a whole number of cycles in seconds"},
      {"motif_fitness", "amplitude", SimField::Real, 1e-6, 1e6, {}, at(&MotifFitnessDef::amplitude), "... the reference oscillation's amplitude: a sine this large at target_hz scores 1 under input, a wobble this large without input scores 0"},
  };
}

Status check_motif_kind(const SimConfig& cfg) { return check_motif_fitness_def(cfg.motif_kind.fitness); }

Status evaluate_motif_genes(const Genotype& g, const SimConfig& cfg, std::uint64_t, EvalResult& out) {
  const MotifKindDef& k = cfg.motif_kind;
  if (Status s = check_motif_fitness_def(k.fitness); !s) return s;
  auto m = motif_from_genes(static_cast<const FloatVector&>(g).genes, k.genes);
  if (!m) return Error{m.error()};
  const MotifScore s = score_motif(*m, k.fitness);
  out.fitness = s.fitness;
  out.metrics = {{"oscillation", s.oscillation},
                 {"quiescence", s.quiescence},
                 {"dominant hz", s.dominant_hz},
                 {"quiet power", s.quiet_power}};
  if (!s.finite) out.note = "an output was not finite (inf or NaN): fitness 0";
  // two runs, each seconds / dt Euler steps of the motif, no physics step
  out.seconds = 2 * k.fitness.seconds;
  out.brain_steps = 2 * std::lround(k.fitness.seconds / k.fitness.dt);
  out.steps = 0;
  return Ok{};
}

}  // namespace bx
