// The graph genome's operators as GenotypeOps (genome/genotype.h): Sims'
// mutation, crossover and grafting of one dialect with its constants
// (genome/operators.h), random creation, and viability: a genome is viable
// when it is valid and grows a body (develop/develop.h), which is why these
// live in the develop layer and not beside the genome.
#pragma once

#include "develop/develop.h"
#include "genome/dialect.h"
#include "genome/genotype.h"
#include "genome/operators.h"

namespace bx {

class GraphOps : public GenotypeOps {
 public:
  GraphOps(Dialect dialect, OperatorDef ops, DevelopDef develop)
      : dialect_(dialect), ops_(std::move(ops)), develop_(develop) {}
  std::string_view kind() const override;
  std::unique_ptr<Genotype> random(Rng& rng) const override;
  std::unique_ptr<Genotype> mutate(const Genotype& g, double rate, Rng& rng) const override;
  std::unique_ptr<Genotype> crossover(const Genotype& a, const Genotype& b, Rng& rng) const override;
  Status viable(const Genotype& g) const override;
  bool can_graft() const override { return true; }
  std::unique_ptr<Genotype> graft(const Genotype& trunk, const Genotype& branch, Rng& rng) const override;
  /// The genome file's form; the genome must be of this dialect.
  Result<std::unique_ptr<Genotype>> from_json(const nlohmann::json& j) const override;
  bool can_lock_body() const override { return true; }
  /// Every node's body, joint and edges locked (genome/locks.h): no part
  /// grows, goes or changes; neurons, sensors and effectors stay free.
  std::unique_ptr<Genotype> with_body_locked(const Genotype& g) const override;
  /// In dialects with skill switches (lessin2015): genome/encapsulate.h.
  bool can_encapsulate() const override;
  Result<std::unique_ptr<Genotype>> with_skill_encapsulated(const Genotype& g, const SkillDef& skill,
                                                            const std::vector<std::string>& uses) const override;

 private:
  Dialect dialect_;
  OperatorDef ops_;
  DevelopDef develop_;
};

}  // namespace bx
