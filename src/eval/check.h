// `bestiary check`: is a creature's fitness physics or artefact? Its scored
// evaluation is repeated under other physics seeds, at smaller steps, with
// more solver iterations, with a slower motor, with the brain at half its
// rate, with its effectors held at their means and, for locomotion, twice as
// long; a fitness that collapses (or, at a smaller step, soars) under any of
// these was not earned by behaviour (docs/physics.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "eval/creature.h"
#include "eval/evaluate.h"
#include "eval/task_table.h"

namespace bx {

/// How a check combines its other seeds' ratios (CheckDef::other_seeds_statistic).
enum class SeedStatistic { Median, Mean };
/// Its name, as the config spells it: "median" or "mean".
inline const char* statistic_name(SeedStatistic s) { return s == SeedStatistic::Mean ? "mean" : "median"; }

/// The gates of a check, as fractions of the scored fitness (config section
/// [check]). Defaults: issue 11's.
struct CheckDef {
  int other_seeds = 5;            ///< physics seeds besides the scored one
  /// How the other seeds' ratios combine: their median, so one lucky or
  /// unlucky seed does not decide (a throw), or their mean, for a task whose
  /// outcomes over seeds are a rare large score among small ones (a river
  /// level: 100 in a third of layouts, about 9 in the rest), where the
  /// median misses the rare score that a mean fitness (task.trial_score)
  /// counts; with enough seeds (other_seeds) to estimate it. Under the mean,
  /// each gate on a mean over seeds (other seeds, and the variants under
  /// converge_seeds > 1) widens by two standard errors of the difference
  /// (CheckVariant::slack), so that it fails a creature for what the seeds
  /// show, not for their number.
  SeedStatistic other_seeds_statistic = SeedStatistic::Median;
  double min_other_seeds = 0.75;  ///< their median (mean) must keep this much
  double min_converged = 0.75;    ///< dt/2, dt/4 and twice the iterations each keep this much
  /// ... and keep at most this much: a fitness that rises by more than the
  /// gate as the step shrinks was not converged either (docs/physics.md cause 27)
  double max_converged = 1.25;
  /// The motor-lag variant: every motor's first-order response time
  /// (motor.response_time) lengthened by this (s), as a real actuator's
  /// windings and rotor lag its command. 0: no such variant.
  double motor_lag = 0.01;
  /// Under that lag, and with the brain at half its rate (brain.rate_hz / 2),
  /// the fitness keeps at least this much; a creature that falls below under
  /// either is a buzzer (it earns its fitness by flipping its signals at the
  /// brain's rate, which no real actuator follows): named and failed.
  double min_motor_lag = 0.5;
  /// 0: no half-rate variant (for a brain whose timing is the task's: a
  /// catapult's release fires after a count of brain steps, 4.1).
  double min_half_rate = 0.25;
  /// Locomotion: in a run twice as long, the centre of mass travels (in the
  /// plane) over its last third at least this share of its travel over the
  /// first: a gait that fades is not a gait. 0: no such gate (a throw's task
  /// never has it).
  double min_sustained = 0.5;
  double max_clamped = 0.25;      ///< effectors held at their means keep at most this much
  /// Every joint held still by its motor (the controller still releasing a
  /// catapult's projectile) keeps at most this much: a throw that survives
  /// it is a fall, not a swing (docs/physics.md cause 20). A walker held
  /// still goes nowhere, so for locomotion this gate asks what `clamped` asks.
  double max_held = 0.5;
  /// dt/2, dt/4, twice the iterations, the motor lag and the half rate are each evaluated under this many
  /// seeds (the scored one and the first other seeds) and compared by their
  /// median (mean, as other_seeds_statistic says) with the same at dt under
  /// the same seeds. 1: one evaluation
  /// against the scored fitness. More for a chaotic task (a throw), where
  /// any change of the step draws another throw as a change of seed does.
  int converge_seeds = 1;
  /// A clamped run that keeps more than max_clamped is forgiven when it is at
  /// rest over its last rest_seconds (its centre of mass moves less than
  /// kRestTravel of the body length: the rest law's bound): its distance was
  /// a transient (one slow stroke of its servos, a topple), honest physics
  /// but no gait, which CheckReport::notes names. 0: the strict gate.
  double rest_seconds = 15;
  friend bool operator==(const CheckDef&, const CheckDef&) = default;
};

/// One re-evaluation of a check.
struct CheckVariant {
  /// "seed 2", "dt/2", "dt/4", "2x iterations" (QuickStep only), "motor lag 10 ms",
  /// "brain at 30 Hz", "clamped", "held"
  std::string name;
  /// its evaluation (under converge_seeds > 1: the scored seed's, with the
  /// median fitness over the seeds)
  EvalResult result;
  double ratio = 0;   ///< its fitness over the scored fitness (or medians over medians)
  /// The gate its ratio is judged by, in words ("median >= 0.75", "in [0.75, 1.25]", "none: ...").
  std::string gate;
  /// Under converge_seeds > 1: the fitness under each seed, the scored seed
  /// first (a step that switches some seeds to another outcome shows here).
  std::vector<double> seed_fitness;
  /// Under other_seeds_statistic = mean: by how much its gates widen (as a
  /// share of what it is compared with): two standard errors of the
  /// difference of the two means, the noise of so many evaluations, not
  /// physics (a level reached in a fifth of the layouts moves a mean of 20
  /// by a fifth of itself). 0 under the median, and for the other gates.
  double slack = 0;
};

/// What a check found.
struct CheckReport {
  EvalResult scored;  ///< the evaluation under the creature's own seed
  /// The fitness the ratios of other seeds are taken against: the scored
  /// evaluation's, or for a creature scored over several evaluations (a
  /// run's elite, evolution.elite_evaluations) their mean or least.
  double scored_fitness = 0;
  /// Under several evaluations: each one's fitness, the own seed's first.
  std::vector<double> scored_by_seed;
  /// Its run's held-out measure (evolution.held_out_evaluations: its fitness
  /// under seeds selection never saw), when it has one: the other seeds'
  /// ratios are taken against it instead, like with like.
  std::optional<HeldOut> held_out;
  std::vector<CheckVariant> variants;
  /// The other seeds' ratios combined (CheckDef::other_seeds_statistic:
  /// their median or mean).
  double other_seeds = 0;
  /// The clamped run's centre of mass: how far it moved in the plane over the
  /// last CheckDef::rest_seconds of the run, as a share of the body length
  /// (-1: not measured: rest_seconds is 0 or longer than the run).
  double clamped_end_travel = -1;
  /// The sustained gate's run, twice as long: the centre of mass's travel in
  /// the plane over its first and its last third (m), and their ratio (last
  /// over first; -1: not measured: not locomotion, the gate off, or a run
  /// that failed).
  double sustained_first = 0, sustained_last = 0, sustained = -1;
  /// How its task is judged (TaskRow::check_basis): when doing nothing
  /// scores, `idle` is the score with every joint held, and every ratio is
  /// of the gain over it.
  CheckBasis basis;
  double idle = 0;
  /// The creature earns its fitness by buzzing: the lag or the half rate took it.
  bool buzzer = false;
  /// Every other seed's evaluation drove its effectors with the same signals
  /// as the scored one, bit for bit (each effector's mean and spread over the
  /// run): nothing the seeds change reaches its controller. Where a seed draws
  /// the world the creature meets (a river layout, a light's heading), it
  /// does not sense it: an open loop, whose path is its gait's alone. Not a
  /// gate (a walker on flat ground has nothing to sense), a note.
  bool open_loop = false;
  std::vector<std::string> failures;  ///< each gate that failed, with its figures; empty: passed
  /// What the figures say of the motion beside the gates, e.g. that it is
  /// mostly passive (a fall: held joints keep more than half of it).
  std::vector<std::string> notes;
  bool passed() const { return failures.empty(); }
};

/// Checks the creature's evaluation under `cfg` and `seed` (the one that
/// scored it) against the gates. A creature its run evaluated several times
/// (`repeats`: under repeat_seed(seed, 0..evaluations-1), the mean or least
/// as cfg.trial_score folds) has its other seeds compared with that score,
/// what selection saw; the steps, iterations, clamped and held effectors
/// compare with the own seed's evaluation, like with like.
///
/// The scored evaluation measures each effector's dominant frequency
/// (scored.diagnostics.effector_hz). Variants that cannot differ from the
/// scored run are not made: twice the solver iterations under the exact
/// solver, which has none; the motor lag when check.motor_lag is 0, the half
/// rate when check.min_half_rate is 0, and both for a creature without
/// effectors.
///
/// The creature is its body driven by its controller, whatever its kind
/// (develop_creature); the variants that hold its joints or clamp its
/// effectors do so through the config (SimConfig::hold_joints,
/// SimConfig::effector_clamp), below any controller.
///
/// A creature with a held-out measure (`held_out`: its run's best,
/// evolution.held_out_evaluations) has its other seeds compared with that
/// instead: selection kept the creature for its score, so the score
/// overstates what it does in a fresh world where one evaluation is noisy,
/// and other seeds are fresh worlds.
CheckReport check_creature(const Creature& c, const SimConfig& cfg, std::uint64_t seed, const CheckDef& def,
                           const Repeats& repeats = {}, const std::optional<HeldOut>& held_out = {});

/// The rest law (docs/physics.md, tests/eval/rest_law_test.cpp): with its
/// effectors held constant, a settled creature's centre of mass moves less
/// than this share of its body length in CheckDef::rest_seconds.
inline constexpr double kRestTravel = 0.02;

/// The sustained gate judges only a creature whose centre of mass travelled
/// at least this share of its body length over the first third of its run.
inline constexpr double kSustainedFrom = 0.1;

/// Held joints keeping more than this share of the fitness: the motion is
/// mostly passive (a fall), which CheckReport::notes says whatever the gates.
inline constexpr double kPassiveHeld = 0.5;

/// The physics seed of a check's k-th other seed (k from 1), unlike any trial's.
std::uint64_t check_seed(std::uint64_t seed, int k);

}  // namespace bx
