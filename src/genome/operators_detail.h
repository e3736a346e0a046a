// Internal to the genome layer: random creation of a genome that is not a
// catapult, which random_catapult() (catapult.cpp) builds its arm and body
// with.
#pragma once

#include "core/rng.h"
#include "genome/genome.h"
#include "genome/operators.h"

namespace bx::detail {

/// random_genome() for a plain (non-catapult) genome.
Genome random_genome_plain(Dialect d, const OperatorDef& def, Rng& rng);

}  // namespace bx::detail
