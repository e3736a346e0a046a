// Sims' graph genome as a genotype (genome/genotype.h): kind "graph", its
// JSON form the genome file's (genome/genome_json.h). Its operators, whose
// viability test grows the body, are develop/graph_ops.h.
#pragma once

#include "genome/genome.h"
#include "genome/genotype.h"

namespace bx {

class GraphGenotype : public Genotype {
 public:
  explicit GraphGenotype(Genome g) : genome(std::move(g)) {}
  static constexpr std::string_view kKind = "graph";
  std::string_view kind() const override { return kKind; }
  nlohmann::json to_json() const override;
  bool equals(const Genotype& other) const override;
  /// Its part count (up to 1000): evaluation time grows with it.
  double cost_hint() const override;

  Genome genome;
};

/// The graph genome inside `g`, or nullptr when `g` is of another kind.
const Genome* graph_genome(const Genotype& g);

}  // namespace bx
