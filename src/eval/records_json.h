// The JSON forms of the evaluator's records: a job (the genotype's kind and
// JSON form, and the evaluation seed) and its outcome (EvalOutcome and its
// EvalResult), used by the process pool's wire; and a run's held-out measure
// of its best (HeldOut), stored in the run, a genome file's provenance and
// check's JSON. One serialiser each, every field. Doubles
// travel at full precision (a read gives the same bits); a non-finite one is
// written as null and read back as NaN. A graph genome travels in its one
// file form (genome/genome_json.h).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>

#include "core/result.h"
#include "eval/evaluate.h"
#include "eval/evaluator.h"

namespace bx {

/// A job as read back: it owns its genotype.
struct ReadJob {
  std::unique_ptr<Genotype> genotype;
  std::uint64_t seed = 0;
  int step_divisor = 1;  ///< EvalJob::step_divisor
  int task = 0;          ///< EvalJob::task
};

nlohmann::json job_to_json(const EvalJob& job);

/// Reads what job_to_json wrote; an error names the field, or says what is
/// wrong with the genotype (or that its kind is unknown).
Result<ReadJob> job_from_json(const nlohmann::json& j);

nlohmann::json outcome_to_json(const EvalOutcome& o);

/// Reads what outcome_to_json wrote; an error names the field that is missing
/// or of the wrong type.
Result<EvalOutcome> outcome_from_json(const nlohmann::json& j);

/// {"id": the individual, "by_seed": [each evaluation's fitness], "fitness": their fold}
nlohmann::json held_out_to_json(const HeldOut& h);

/// Reads what held_out_to_json wrote; "id" may be absent unless `with_id` (a
/// genome file's provenance before the id was written names its individual
/// itself: 0 then). An error starts with `who` and says what was expected.
Result<HeldOut> held_out_from_json(const nlohmann::json& j, const std::string& who, bool with_id);

}  // namespace bx
