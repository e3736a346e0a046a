// A creature as evaluation sees it: a body (CreatureModel) and the controller
// that drives it, developed together from a genotype by its kind's row of the
// creature table (SimConfig::creature, config genotype.kind). Sims' graph
// genome grows its body and compiles its own brain (GraphBrain); a fixed
// body's kind builds its body in code and its controller from a float
// vector. The evaluators, check and the run see only this, whatever the kind.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "brain/controller.h"
#include "core/result.h"
#include "develop/creature_model.h"
#include "eval/sim_config.h"
#include "eval/sim_field.h"
#include "genome/float_vector.h"
#include "genome/genotype.h"

namespace bx {

/// A developed creature. Its controller may refer to its body (a graph
/// brain to the body's brain), so the two live and move together.
struct Creature {
  std::unique_ptr<const CreatureModel> body;
  std::unique_ptr<const ControllerModel> controller;
};

/// One creature kind: the genotypes it develops (Genotype::kind) and how.
struct CreatureKindRow {
  CreatureKind kind;
  std::string_view name;           ///< its genotype.kind in configs
  std::string_view genotype_kind;  ///< the Genotype::kind it develops
  /// The creature, or why the genotype is not viable (a value, never an
  /// exception); the genotype is of genotype_kind.
  Result<Creature> (*develop)(const Genotype&, const SimConfig&);
  /// A float-vector kind's genes: their count, box and mutation (the run
  /// breeds them with FloatVectorOps); null for a kind of other genotypes.
  FloatVectorDef (*float_genes)(const SimConfig&);
  /// The config keys it brings (none: its keys are the reader's own).
  std::vector<SimField> (*fields)();
  /// The settings it brings, as a dialect does, before a config's own keys
  /// apply: its body's physics and motors, its task (null: none).
  void (*defaults)(SimConfig&);
};

/// The row of a kind.
const CreatureKindRow& creature_kind_row(CreatureKind kind);
/// Every kind's name, in CreatureKind's order (the config's choices).
std::vector<std::string_view> creature_kind_names();
/// Every row's own config keys, in the table's order.
std::vector<SimField> creature_fields();

/// Develops a genotype into cfg.creature's creature: its body and
/// controller, or why it is not viable (a genotype of another kind than
/// the creature's is not viable either, and says so).
Result<Creature> develop_creature(const Genotype& g, const SimConfig& cfg);

/// A graph creature from its body: the body's own brain drives it.
Creature graph_creature(CreatureModel body);

}  // namespace bx
