// One way to name a creature on the command line, for every command that
// simulates one (simulate, show, render, check, best), of any creature kind:
//   GENOME.json          a genotype file (genome/genotype_file.h): a graph
//                        genome with its dialect's defaults and seed 1, or
//                        another kind's genotype with --config; or, if `best
//                        --out` wrote it, the run's config and the seed that
//                        scored it (its "provenance")
//   RUN_DIR              the run's best so far
//   RUN_DIR:ID           the run's individual ID
//   RUN_DIR:gen=G        the best of generation G
// A run's individual is always re-evaluated with the run's config and its own
// stored evaluation seed, so what a command shows is what was scored.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "eval/creature.h"
#include "evolve/evolution.h"
#include "io/config.h"
#include "io/run_store.h"

namespace CLI {
class App;
}

namespace bx {

/// The flags that change which creature, or how it is evaluated.
struct CreatureFlags {
  std::string config;                 ///< --config: genome files only
  std::optional<std::uint64_t> seed;  ///< --seed: genome files only
  std::vector<std::string> set;       ///< --set section.key=value
  std::optional<std::int64_t> id;     ///< --id: a run's individual
  std::optional<int> gen;             ///< --gen: the best of a run's generation
  std::optional<double> seconds;      ///< --seconds: the evaluation's length
  /// --trial: which of the evaluation's trials to watch, from 1 (simulate,
  /// show, render: add_trial_option); unset: the first (show: every one).
  std::optional<int> trial;
};

/// A creature to evaluate, with the config and seed to evaluate it with.
struct Subject {
  /// What develops into the creature, of the kind cfg.sim.creature develops.
  std::shared_ptr<const Genotype> genotype;
  RunConfig cfg;
  std::uint64_t seed = 1;
  std::string label;                    ///< "RUN individual 12 (generation 3)", or the file
  std::optional<double> stored_fitness; ///< the fitness its run recorded, when known
  /// How many evaluations the stored fitness is the mean (or least: the
  /// run's task.trial_score) of (a run's elite, evolution.elite_evaluations):
  /// under repeat_seed(seed, 0..n-1).
  int evaluations = 1;
  std::optional<Individual> individual; ///< a run's individual, as stored
  /// Its run's held-out measure of it (evolution.held_out_evaluations: the
  /// run's best, evaluated under seeds the run never used), when it has one;
  /// from a genome file, as its provenance carries it (id 0).
  std::optional<HeldOut> held_out;
  std::string run_dir;                  ///< its run, if any
  /// The trial (0-based, below task.trials) --trial chose to watch, whose
  /// replay and measures a command shows (evaluate_trial; the fitness stays
  /// the whole evaluation's); unset when not chosen.
  std::optional<int> trial;
  /// Its run's config as a genome file's provenance carries it: the stored
  /// text, or for a multi-stage run its stage's config (every key).
  std::string run_config_text;
  /// Where the settings come from, and whether they are the scored ones; one
  /// line for the user (empty when there is nothing to say).
  std::string settings;
  bool scored_settings = false;  ///< the config and seed that scored it, unchanged

  /// The graph genome, when the genotype is one (else nullptr: a creature
  /// of another kind has no genome to print or dialect to read).
  const Genome* graph_genome() const;
  /// Develops it, as its run did: its body and controller, or why it is not
  /// viable (develop_creature).
  Result<Creature> develop() const;
  /// What it is, in a word: its genome's dialect, or its creature kind's name.
  std::string kind_name() const { return evolved_name(cfg); }

  /// The stored fitness when one evaluation should reproduce it.
  std::optional<double> scored_fitness() const {
    return scored_settings && evaluations == 1 ? stored_fitness : std::nullopt;
  }
  /// How its run evaluated it again, as repeated_fitness reproduces it (one
  /// evaluation unless the settings are the scored ones).
  Repeats repeats() const;
  /// Evaluated as scored under several evaluations, what one evaluation
  /// shows: "(evaluation 1 of N; the stored fitness S is their mean)" (or least,
  /// as the run's task.trial_score folds them, and which stepped at half the
  /// step: finer_step_text); else "".
  std::string evaluations_note() const;
};

/// True when `target` names a run (RUN_DIR, RUN_DIR:ID, RUN_DIR:gen=G).
bool names_run(const std::string& target);

/// The creature `target` names, with the flags applied; errors name the
/// target or the flag.
Result<Subject> resolve_creature(const std::string& target, const CreatureFlags& flags);

/// A run's individual's provenance, for the genotype file `best --out` writes:
/// run, individual, generation, fitness (and how many evaluations it is the
/// mean of), seed, and the run's config (its
/// text and a hash), so the file alone reproduces the scored evaluation.
nlohmann::json provenance_json(const Subject& c, const std::string& config_text);

/// Sets the task's length from --seconds (unset: unchanged); checks its range.
Status set_seconds(SimConfig& sim, const std::optional<double>& seconds);

/// "fitness F", and whether it equals the stored fitness bit for bit.
std::string fitness_line(double fitness, const std::optional<double>& stored);

/// A task's named measures on one line: "level 2, levels completed 1, food
/// eaten 3, ..." (EvalResult::metrics, in the task's order).
std::string metrics_line(const std::vector<Metric>& metrics);

/// The target positional and the flags above, as every command that takes a
/// creature declares them.
void add_creature_options(CLI::App* cmd, std::string& target, CreatureFlags& flags);
/// --trial, for the commands that watch one evaluation (simulate, show,
/// render): check's gates and best's file are of the whole evaluation.
void add_trial_option(CLI::App* cmd, CreatureFlags& flags);

/// The shortest text that reads back as the same double (fitness reports
/// that can be compared bit for bit).
std::string exact_number(double v);

}  // namespace bx
