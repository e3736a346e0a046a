// Evaluation: a pure function of (creature, config, seed).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/scene_record.h"
#include "develop/creature_model.h"
#include "eval/creature.h"
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
/// task and the controller show beside the creature.
struct Replay {
  std::vector<ReplayFrame> frames;
  /// Their scene record (Task::record, ControllerState::record), its
  /// events at every physics step's end where something changed.
  SceneRecord scene;
};

/// How physically sound an evaluation was, and how its controller drove
/// the motors (docs/physics.md): what `bestiary check` reports.
struct EvalDiagnostics {
  double max_joint_gap = 0;       ///< m: farthest any joint came apart (World::joint_gap)
  int worst_joint = -1;           ///< the joint that did
  double max_stop_overshoot = 0;  ///< rad or m: farthest past a joint stop
  double max_penetration = 0;     ///< m: deepest contact, with the ground or between parts
  /// Each effector's signal while the controller drove the motors: mean and
  /// standard deviation over those steps (empty if it never did).
  std::vector<double> effector_mean, effector_sd;
  /// Each effector's dominant frequency (Hz) while driven (dominant_frequency
  /// of its signal at every physics step; 0: constant), when measured
  /// (SimConfig::effector_spectrum, or a replay): else empty.
  std::vector<double> effector_hz;
};

/// What an evaluation measured.
struct EvalResult {
  bool failed = false;      ///< a numerical explosion ended it (fitness is 0)
  std::string failure;      ///< why, when failed
  std::string note;         ///< why the task scored 0 by rule (e.g. never settled), or empty
  double fitness = 0;
  double distance = 0;      ///< m, by the task's metric (throwing: D_p)
  /// The task's own measures by name (TaskScore::metrics: an aim task's
  /// "target miss", the river crossing's levels and food); the shown trial's
  /// (`trial`: the first, unless evaluate_trial showed another).
  std::vector<Metric> metrics;
  /// The task's named moments (its scene record's markers, SceneRecord: a
  /// throw's "begin", "release" and "touch end"), whether or not a replay was
  /// recorded; the shown trial's.
  std::vector<SceneMarker> markers;
  double seconds = 0;       ///< simulated time, the shown trial's
  long steps = 0;            ///< physics steps
  long brain_steps = 0;      ///< brain steps run (at SimConfig::brain_hz; not those the task had the brain wait)
  std::vector<std::string> warnings;
  /// SimConfig::trials > 1: each trial's fitness, in trial order (`fitness`
  /// is their fold: fold_trials); empty for a single trial.
  std::vector<double> trial_fitness;
  /// Which trial (0-based) the per-trial fields (distance, metrics, markers,
  /// seconds, note, diagnostics, setup) and a replay are of: 0 unless
  /// evaluate_trial showed another.
  int trial = 0;
  /// What the shown trial set up, for a viewer's label (Task::describe:
  /// "light at 135 degrees"), or empty when its task does not say.
  std::string setup;
  /// The shown trial's.
  EvalDiagnostics diagnostics;

  /// The metric of this name, if the task reported it.
  std::optional<double> metric(std::string_view name) const;
  /// When the moment of this name happened (s), if it did.
  std::optional<double> marker(std::string_view name) const;
};

/// Simulates the creature (its body driven by its controller) on flat
/// ground, in the task cfg.task_kind names (a throwing task needs a catapult:
/// for another creature it scores 0 with a note). Reseeds ODE's
/// generator from `seed` first, so equal inputs give bit-identical results.
/// When `replay` is given, frames are appended to it.
///
/// With cfg.trials = K > 1 it evaluates K times, under trial_seed(seed, 0..K-1),
/// trial k's task made for trial k (make_task: a task may lay out each
/// trial its own way):
/// fitness is the trials' mean (each in trial_fitness), steps and
/// brain_steps their sums, and a numerical explosion in any trial fails the
/// whole evaluation; the rest (distance, metrics, markers, seconds, the
/// replay) is the first trial's, whose seed is `seed` itself (evaluate_trial
/// shows another).
EvalResult evaluate(const CreatureModel& body, const ControllerModel& controller, const SimConfig& cfg,
                    std::uint64_t seed, Replay* replay = nullptr);
inline EvalResult evaluate(const Creature& c, const SimConfig& cfg, std::uint64_t seed, Replay* replay = nullptr) {
  return evaluate(*c.body, *c.controller, cfg, seed, replay);
}
/// A graph creature's body, driven by its own brain (GraphBrain).
EvalResult evaluate(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed, Replay* replay = nullptr);

/// evaluate(), showing trial `trial` (0-based, below cfg.trials) in place of
/// the first: every trial runs as evaluate() runs it (trial k under
/// trial_seed(seed, k), its task made for trial k), so fitness,
/// trial_fitness, steps, brain_steps and a failure are the whole
/// evaluation's, bit for bit evaluate()'s; the replay and the per-trial
/// fields (EvalResult::trial) are trial `trial`'s. A user watching a
/// creature sees each trial's scenario so (`bestiary simulate --trial`).
EvalResult evaluate_trial(const CreatureModel& body, const ControllerModel& controller, const SimConfig& cfg,
                          std::uint64_t seed, int trial, Replay* replay = nullptr);
inline EvalResult evaluate_trial(const Creature& c, const SimConfig& cfg, std::uint64_t seed, int trial,
                                 Replay* replay = nullptr) {
  return evaluate_trial(*c.body, *c.controller, cfg, seed, trial, replay);
}

/// evaluate_trial for each of the first replays.size() trials at once, from
/// one evaluation (each trial runs once): the k-th result and replays[k] are
/// what evaluate_trial(..., k, &replays[k]) gives. replays.size() must be
/// at least 1 and at most cfg.trials (1 for a single trial).
std::vector<EvalResult> evaluate_trials(const CreatureModel& body, const ControllerModel& controller,
                                        const SimConfig& cfg, std::uint64_t seed, std::span<Replay> replays);

/// The brain's schedule: how many brain steps have run by the end of the
/// first `physics_steps` physics steps of `dt`. Brain step k (from 0) runs
/// just before the physics step whose span [n dt, (n+1) dt) holds its time
/// k / brain_hz, so this counts the k with k / brain_hz < physics_steps * dt,
/// to a millionth of a brain step (rounding never adds or drops one: at
/// brain_hz = 1 / dt it is physics_steps, at 2 / dt twice that).
long brain_steps_due(long physics_steps, double dt, double brain_hz);

/// What a physics seed draws for its evaluation besides ODE's generator: the
/// start's turn about the vertical (rad) and lift (m), and the motors' response
/// time (s) (task.start_yaw_jitter, task.start_drop_jitter,
/// motor.response_time_jitter).
struct SeedDraw {
  double yaw = 0, lift = 0, response_time = 0;
};
SeedDraw seed_draw(const SimConfig& cfg, std::uint64_t seed);

/// The physics seed of trial `trial` (0-based) of an evaluation under `seed`.
std::uint64_t trial_seed(std::uint64_t seed, int trial);

/// The seed of evaluation `k` (0-based) of a creature first evaluated under
/// `seed`: `seed` itself for k = 0, then fresh ones (a run's elites are
/// evaluated again so, evolution.elite_evaluations). Unlike any trial's or
/// check's seed.
std::uint64_t repeat_seed(std::uint64_t seed, int k);

/// The score of n + 1 evaluations from that of the first n (n >= 1) and the
/// next, as task.trial_score folds trials: their mean, or the least of them.
/// The one way a run and the commands that reproduce its scores fold
/// repeated evaluations, so both get the same double.
double fold_score(TrialScore how, double so_far, int n, double next);
/// The same of all of them at once: their mean or least (0 for none).
double fold_scores(TrialScore how, std::span<const double> scores);
/// What fold_score takes of the evaluations, for messages: "mean" or "least".
const char* score_name(TrialScore how);

/// `cfg` stepped at its physics.dt / divisor, all else as it was (times, the
/// brain's rate and, given as at a step, ERP and CFM follow: cause 18).
SimConfig divided_step_config(const SimConfig& cfg, int divisor);

/// `cfg` at its step, half of it and a quarter of it, built once: the
/// configs repeat_step_divisor picks from.
class DividedSteps {
 public:
  explicit DividedSteps(const SimConfig& cfg)
      : at_{cfg, divided_step_config(cfg, 2), divided_step_config(cfg, 4)} {}
  /// physics.dt / divisor, for a divisor of 1, 2 or 4
  const SimConfig& at(int divisor) const { return at_[divisor == 1 ? 0 : divisor == 2 ? 1 : 2]; }

 private:
  SimConfig at_[3];
};

/// How a run evaluated a creature again (an elite; its evolution config).
struct Repeats {
  int evaluations = 1;        ///< how many in all (evolution.elite_evaluations reached)
  double failed_fitness = 0;  ///< what a failed one counts (evolution.failed_fitness)
  /// The evaluations cycle through the step, half of it (evolution.elite_half_step)
  /// and a quarter of it (evolution.elite_quarter_step).
  bool half_step = false;
  bool quarter_step = false;
};

/// The run's best evaluated, once its last stage ended, under seeds no
/// evaluation of the run used (evolution.held_out_evaluations): what it
/// scores where selection never looked. Stored in the run (RunStore::held_out,
/// its metadata "held_out"); `check` compares other seeds with it.
struct HeldOut {
  std::int64_t id = 0;          ///< the individual: the run's best when it was measured
  std::vector<double> by_seed;  ///< each evaluation's fitness, in seed order (held_out_seed)
  double fitness = 0;           ///< their fold (task.trial_score), a failed one counted as evolution.failed_fitness
  friend bool operator==(const HeldOut&, const HeldOut&) = default;
};

/// What a run divides the step by for evaluation k (0-based) of a creature:
/// 1, 2 or 4, cycling through 1, 2 (half_step) and 4 (quarter_step); with
/// half_step alone the 2nd, 4th, ... are at half the step.
int repeat_step_divisor(const Repeats& r, int k);

/// For messages: which of them stepped finer, counted from 1 ("evaluation 2
/// at half the step", "evaluations 2 and 4 at half the step", "evaluations 2
/// and 5 at half the step, 3 at a quarter of it"), or "" when none did.
std::string finer_step_text(const Repeats& r);

/// The fitness a run gave a creature it evaluated `r.evaluations` times (an
/// elite, evolution.elite_evaluations): the fold_score (cfg.trial_score) of
/// its evaluations under repeat_seed(seed, 0..evaluations-1), each at the
/// step repeat_step_divisor says, a failed one counting as
/// `r.failed_fitness`. `first` is evaluation 0, already simulated; each
/// evaluation's fitness goes to `each` when given.
double repeated_fitness(const CreatureModel& body, const ControllerModel& controller, const SimConfig& cfg,
                        std::uint64_t seed, const Repeats& r, const EvalResult& first,
                        std::vector<double>* each = nullptr);
inline double repeated_fitness(const Creature& c, const SimConfig& cfg, std::uint64_t seed, const Repeats& r,
                               const EvalResult& first, std::vector<double>* each = nullptr) {
  return repeated_fitness(*c.body, *c.controller, cfg, seed, r, first, each);
}
/// A graph creature's body, driven by its own brain.
double repeated_fitness(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed, const Repeats& r,
                        const EvalResult& first, std::vector<double>* each = nullptr);

}  // namespace bx
