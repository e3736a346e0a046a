#include "eval/creature.h"

#include <string>

#include "develop/develop.h"
#include "genome/graph_genotype.h"

namespace bx {

namespace {

Result<Creature> develop_graph(const Genotype& g, const SimConfig& cfg) {
  Development dev = develop(*graph_genome(g), cfg.develop);
  if (!dev.viable()) return Error{dev.reason};
  return graph_creature(std::move(*dev.model));
}

// one row per CreatureKind, in its order
const CreatureKindRow kKinds[] = {
    {CreatureKind::Graph, "graph", GraphGenotype::kKind, develop_graph},
};

}  // namespace

const CreatureKindRow& creature_kind_row(CreatureKind kind) { return kKinds[static_cast<int>(kind)]; }

std::vector<std::string_view> creature_kind_names() {
  std::vector<std::string_view> out;
  for (const CreatureKindRow& r : kKinds) out.push_back(r.name);
  return out;
}

Result<Creature> develop_creature(const Genotype& g, const SimConfig& cfg) {
  const CreatureKindRow& row = creature_kind_row(cfg.creature);
  if (g.kind() != row.genotype_kind)
    return Error{"a genotype of kind " + std::string(g.kind()) + ", but genotype.kind \"" + std::string(row.name) +
                 "\" develops " + std::string(row.genotype_kind) + " genotypes"};
  return row.develop(g, cfg);
}

Creature graph_creature(CreatureModel body) {
  Creature c;
  auto owned = std::make_unique<const CreatureModel>(std::move(body));
  c.controller = std::make_unique<GraphBrain>(owned->brain);
  c.body = std::move(owned);
  return c;
}

}  // namespace bx
