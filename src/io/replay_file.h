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
  /// A creature of another kind than Sims' graph genome: its kind's name
  /// (genotype.kind), written as "creature" in place of the body's dialect;
  /// empty for a graph creature.
  std::string creature = {};
};

/// ReplayInfo::creature for a creature of cfg.creature's kind: empty for a
/// graph creature, else its kind's name.
std::string replay_creature(const SimConfig& cfg);

/// The replay as canonical JSON text (same inputs give the same bytes).
/// Its neurons are the body's brain's for a graph creature (info.creature
/// empty) whose frames hold one output per neuron of it; else the
/// controller's internal signals, as many as the frames hold at most (a
/// frame with fewer, e.g. before the controller's first step, is padded with
/// zeros), each named as the controller's ("part": -1, "fn": "controller").
std::string replay_to_string(const CreatureModel& m, const Replay& r, const EvalResult& res,
                             const ReplayInfo& info);

/// Writes it atomically to `path`.
Status save_replay(const std::string& path, const CreatureModel& m, const Replay& r,
                   const EvalResult& res, const ReplayInfo& info);

}  // namespace bx
