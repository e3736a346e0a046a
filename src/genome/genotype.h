// What evolution breeds, whatever it encodes: a genotype, and the operators
// of its kind with their constants. Sims' graph genome is one kind
// (genome/graph_genotype.h, its operators develop/graph_ops.h); a float
// vector (a fixed body's controller weights, the river crossing's) is another
// (genome/float_vector.h). The algorithms in src/evolve/ see only these
// interfaces, as pagmo's algorithms see decision vectors and leave it to the
// problem to turn them into fitness: here the evaluator does
// (eval/evaluator.h, evaluate_genotype).
#pragma once

#include <cassert>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "core/rng.h"
#include "genome/skill.h"

namespace bx {

/// One genotype. Immutable once made; operators make new ones.
class Genotype {
 public:
  virtual ~Genotype() = default;
  /// Its kind ("graph", "floats"), stored beside its JSON form.
  virtual std::string_view kind() const = 0;
  /// Its JSON form (what the run database and the pool's jobs hold).
  virtual nlohmann::json to_json() const = 0;
  virtual bool equals(const Genotype& other) const = 0;
  /// How long it takes to evaluate, relative to others of its kind (the
  /// process pool hands out the costliest first); 1 when all cost the same.
  virtual double cost_hint() const { return 1; }
};

/// Reads a stored genotype (the run database's, a job's) of the named kind:
/// the structure of its JSON form; the constants a kind's operators keep (a
/// float vector's length and box) are checked by GenotypeOps::from_json. An
/// error names `source`, the field and the value, or the unknown kind.
Result<std::unique_ptr<Genotype>> read_genotype(std::string_view kind, const nlohmann::json& j,
                                                std::string_view source);
/// The same from JSON text (a graph genome through the genome file's strict
/// reader: its limits, its error positions).
Result<std::unique_ptr<Genotype>> parse_genotype(std::string_view kind, std::string_view text,
                                                 std::string_view source);

/// How genotypes of one kind are made, varied and read: the kind's operators
/// with their constants. Every random draw comes from the Rng passed in.
class GenotypeOps {
 public:
  virtual ~GenotypeOps() = default;
  virtual std::string_view kind() const = 0;
  virtual std::unique_ptr<Genotype> random(Rng& rng) const = 0;
  /// A mutated copy; `rate` is the kind's per-site mutation probability.
  virtual std::unique_ptr<Genotype> mutate(const Genotype& g, double rate, Rng& rng) const = 0;
  virtual std::unique_ptr<Genotype> crossover(const Genotype& a, const Genotype& b, Rng& rng) const = 0;
  /// Whether a genotype may be evaluated at all (a graph genome must grow a
  /// body), or why not; the algorithms redraw a child that is not.
  virtual Status viable(const Genotype&) const { return Ok{}; }
  /// Whether graft() exists for this kind (Sims' grafting is a graph
  /// operator); a config giving p_graft > 0 to a kind without it is an error.
  virtual bool can_graft() const { return false; }
  /// Only when can_graft(): a programmer error otherwise.
  virtual std::unique_ptr<Genotype> graft(const Genotype&, const Genotype&, Rng&) const {
    assert(!"graft() on a genotype kind without grafting");
    return nullptr;
  }
  /// Reads what Genotype::to_json wrote; an error names the field and the value.
  virtual Result<std::unique_ptr<Genotype>> from_json(const nlohmann::json& j) const = 0;
  /// Whether with_body_locked() exists for this kind (one with a body).
  virtual bool can_lock_body() const { return false; }
  /// Only when can_lock_body(): a copy whose body no operator may change
  /// (lessin2015's Fast ESP, IV-D: the skeleton is locked after the first
  /// skill), while its units (neurons, sensors, muscles) stay free.
  virtual std::unique_ptr<Genotype> with_body_locked(const Genotype&) const {
    assert(!"with_body_locked() on a genotype kind without a body");
    return nullptr;
  }
  /// Whether with_skill_encapsulated() exists for this kind.
  virtual bool can_encapsulate() const { return false; }
  /// Only when can_encapsulate(): a copy with the skill it has learned
  /// encapsulated as `skill` (when `skill.name` is not empty; lessin2015
  /// IV-B, genome/encapsulate.h) and the switches of the skills named in
  /// `uses` open to the next one.
  virtual Result<std::unique_ptr<Genotype>> with_skill_encapsulated(const Genotype&, const SkillDef& skill,
                                                                    const std::vector<std::string>& uses) const {
    (void)skill, (void)uses;
    return Error{"encapsulation on a genotype kind without skills"};
  }
};

}  // namespace bx
