// A float vector genotype: a fixed number of reals in a box, with per-gene
// Gaussian mutation and single-point crossover (the river crossing evolves
// its controller's weights so, rivercrossing in ../shared/SYSTEMS.md).
#pragma once

#include <vector>

#include "genome/genotype.h"

namespace bx {

/// The genes.
class FloatVector : public Genotype {
 public:
  explicit FloatVector(std::vector<double> genes) : genes(std::move(genes)) {}
  std::string_view kind() const override { return "floats"; }
  nlohmann::json to_json() const override;
  bool equals(const Genotype& other) const override;
  /// Reads {"genes": [...]}: finite numbers, any count (the operators check
  /// the count and the box).
  static Result<FloatVector> from_json(const nlohmann::json& j, std::string_view source);

  std::vector<double> genes;
};

/// The operators and their constants.
struct FloatVectorDef {
  int length = 1;
  double lo = -1, hi = 1;  ///< every gene stays in [lo, hi]
  double sigma = 0.1;      ///< mutation: a mutated gene moves by N(0, sigma), clamped into [lo, hi]
};

class FloatVectorOps : public GenotypeOps {
 public:
  explicit FloatVectorOps(FloatVectorDef def) : def_(def) {}
  std::string_view kind() const override { return "floats"; }
  /// Each gene uniform in [lo, hi).
  std::unique_ptr<Genotype> random(Rng& rng) const override;
  /// Each gene, with probability `rate`, moves by N(0, sigma), clamped.
  std::unique_ptr<Genotype> mutate(const Genotype& g, double rate, Rng& rng) const override;
  /// Single point: a's genes before a cut drawn in [1, length - 1], b's from it.
  std::unique_ptr<Genotype> crossover(const Genotype& a, const Genotype& b, Rng& rng) const override;
  /// {"genes": [...]}: `length` finite numbers within [lo, hi].
  Result<std::unique_ptr<Genotype>> from_json(const nlohmann::json& j) const override;

 private:
  FloatVectorDef def_;
};

}  // namespace bx
