// Replay files: what a viewer needs to draw a creature and every part's pose
// per frame. Versioned JSON ("bestiary-replay", version 1; docs/replay-format.md).
#pragma once

#include <cstdint>
#include <string>

#include "core/result.h"
#include "develop/creature_model.h"
#include "eval/evaluate.h"

namespace bx {

/// What a replay says about where it came from.
struct ReplayInfo {
  std::string genome_source;  ///< file name of the genome
  std::uint64_t seed = 0;
  double dt = 0;              ///< physics step (s)
  double friction = 0;
};

/// The replay as canonical JSON text (same inputs give the same bytes).
std::string replay_to_string(const CreatureModel& m, const Replay& r, const EvalResult& res,
                             const ReplayInfo& info);

/// Writes it atomically to `path`.
Status save_replay(const std::string& path, const CreatureModel& m, const Replay& r,
                   const EvalResult& res, const ReplayInfo& info);

}  // namespace bx
