// Evaluation: a pure function of (creature, config, seed).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "develop/creature_model.h"
#include "eval/sim_config.h"

namespace bx {

/// One recorded moment of an evaluation.
struct ReplayFrame {
  double t = 0;
  std::vector<double> poses;    ///< 7 per part: x y z qw qx qy qz
  std::vector<double> neurons;  ///< every neuron's output
  std::vector<double> effectors;  ///< every effector's signal
  std::vector<double> sensors;    ///< every sensor's reading, as the brain read it
  /// every joint's degrees of freedom in turn (rad or m): joint 0's dofs, joint 1's, ...
  std::vector<double> joint_angles;
  Vec3 com;
};

/// Frames of an evaluation, sampled at SimConfig::replay_fps, and what the
/// task adds to the scene.
struct Replay {
  std::vector<ReplayFrame> frames;
  // throwing: the projectile part, the release moment (-1: none) and the
  // aim task's target
  int projectile = -1;
  double release_time = -1;
  std::optional<Vec3> target;
};

/// What an evaluation measured.
struct EvalResult {
  bool failed = false;      ///< a numerical explosion ended it (fitness is 0)
  std::string failure;      ///< why, when failed
  std::string note;         ///< why the task scored 0 by rule (e.g. never settled), or empty
  double fitness = 0;
  double distance = 0;      ///< m, by the task's metric (throwing: D_p)
  double release_time = -1; ///< throwing: when the projectile was released (s), or -1
  double target_miss = -1;  ///< throwing, aim: D_t (m), or -1
  double seconds = 0;       ///< simulated time
  long steps = 0;
  std::vector<std::string> warnings;
  /// SimConfig::trials > 1: each trial's fitness, the first being the one
  /// a replay shows (`fitness` is their mean); empty for a single trial.
  std::vector<double> trial_fitness;
};

/// Simulates the creature on flat ground with its own brain, in the task
/// cfg.task_kind names (a throwing task needs a catapult: for another
/// creature it scores 0 with a note). Reseeds ODE's
/// generator from `seed` first, so equal inputs give bit-identical results.
/// When `replay` is given, frames are appended to it.
///
/// With cfg.trials = K > 1 it evaluates K times, under trial_seed(seed, 0..K-1):
/// fitness is the trials' mean (each in trial_fitness), steps their sum, and
/// a numerical explosion in any trial fails the whole evaluation; the rest
/// (distance, release, target miss, seconds, the replay) is the first
/// trial's, whose seed is `seed` itself.
EvalResult evaluate(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed,
                    Replay* replay = nullptr);

/// The physics seed of trial `trial` (0-based) of an evaluation under `seed`.
std::uint64_t trial_seed(std::uint64_t seed, int trial);

}  // namespace bx
