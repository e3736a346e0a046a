// The JSON form of an evaluation's outcome (EvalOutcome and its EvalResult):
// one serialiser, every field, used by the process pool's wire. Doubles
// travel at full precision (a read gives the same bits); a non-finite one is
// written as null and read back as NaN.
#pragma once

#include <nlohmann/json.hpp>

#include "core/result.h"
#include "eval/evaluator.h"

namespace bx {

nlohmann::json outcome_to_json(const EvalOutcome& o);

/// Reads what outcome_to_json wrote; an error names the field that is missing
/// or of the wrong type.
Result<EvalOutcome> outcome_from_json(const nlohmann::json& j);

}  // namespace bx
