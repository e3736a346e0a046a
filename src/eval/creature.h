// A creature as evaluation sees it: a body (CreatureModel) and the controller
// that drives it, developed together from a genotype by its kind's row of the
// creature table (SimConfig::creature, config genotype.kind). Sims' graph
// genome grows its body and compiles its own brain (GraphBrain); a fixed
// body's kind builds its body in code and its controller from a float
// vector. The evaluators, check and the run see only this, whatever the kind.
// A kind without a body (a motif: a controller's part, scored alone)
// evaluates its genotype itself, with no physics world.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
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

struct EvalResult;  // eval/evaluate.h

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
  /// exception); the genotype is of genotype_kind. Null for a kind without
  /// a body.
  Result<Creature> (*develop)(const Genotype&, const SimConfig&);
  /// A kind without a body evaluates the genotype itself, a pure function
  /// of (genotype, config, seed) that builds no physics world: its fitness,
  /// named metrics and what else it measures into the result, or why the
  /// genotype is not viable. Null for a kind with a body, which develops
  /// and is simulated (eval/evaluate.h).
  Status (*evaluate)(const Genotype&, const SimConfig&, std::uint64_t seed, EvalResult&);
  /// A float-vector kind's genes: their count, box and mutation (the run
  /// breeds them with FloatVectorOps); null for a kind of other genotypes.
  FloatVectorDef (*float_genes)(const SimConfig&);
  /// The config keys it brings (none: its keys are the reader's own).
  std::vector<SimField> (*fields)();
  /// The settings it brings, as a dialect does, before a config's own keys
  /// apply: its body's physics and motors, its task (null: none).
  void (*defaults)(SimConfig&);
  /// What a config layer (a file, one --set) does besides storing the keys
  /// it set, given all of them ("section.key", whichever row brings them):
  /// e.g. a key that names a file reads the file into other keys. An error
  /// names the key and the value; the reader adds the layer's name. Run for
  /// every row, whatever the config's kind, as every key is read (null: nothing).
  Status (*resolve)(SimConfig&, const std::vector<std::string>& keys);
  /// Whether its keys agree with each other, once every layer is read (an
  /// error names the key and the value; null: no such rule). Run for every row.
  Status (*check)(const SimConfig&);
  /// The paper its creatures come from, as `bestiary presets` names it
  /// (empty: the config's dialect names it, as for Sims' graph genome).
  std::string_view paper;
};

/// The row of a kind.
const CreatureKindRow& creature_kind_row(CreatureKind kind);
/// Every row, in CreatureKind's order.
std::span<const CreatureKindRow> creature_kind_rows();
/// Every kind's name, in CreatureKind's order (the config's choices).
std::vector<std::string_view> creature_kind_names();
/// Every row's own config keys, in the table's order.
std::vector<SimField> creature_fields();

/// Whether a kind's creatures have a body (else the kind evaluates its
/// genotypes itself: CreatureKindRow::evaluate). Without one there is
/// nothing to replay, render, show or check.
bool has_body(CreatureKind kind);
/// "genotype.kind \"NAME\" has no body: " followed by `what` (e.g. "nothing
/// to render"): the one way commands refuse a kind without a body.
std::string no_body(CreatureKind kind, std::string_view what);

/// Makes cfg's creatures of `kind` with the settings the kind brings (its
/// row's defaults: a river creature's physics, PD motors, task and brain
/// rate), as a config naming only genotype.kind gets them; a config's own
/// keys apply after.
void apply_creature_kind(SimConfig& cfg, CreatureKind kind);

/// Develops a genotype into cfg.creature's creature: its body and
/// controller, or why it is not viable (a genotype of another kind than
/// the creature's is not viable either, and says so, as does a kind
/// without a body).
Result<Creature> develop_creature(const Genotype& g, const SimConfig& cfg);

/// A graph creature from its body: the body's own brain drives it.
Creature graph_creature(CreatureModel body);

}  // namespace bx
