// The task table: one row per task kind (config task.kind), saying how to
// make the kind's Task for one trial of one creature, its length and drop,
// and the config keys it brings. A new task is a new row here and its own
// files in src/task/; the loop (step.h), evaluation (evaluate.h) and the
// config reader stay as they are.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "develop/creature_model.h"
#include "eval/sim_config.h"
#include "eval/sim_field.h"
#include "task/task.h"

namespace bx {

/// How `check` judges a task's fitness (eval/check.h).
struct CheckBasis {
  /// Doing nothing scores (a light to face is half faced, a body stands as
  /// high as it stands): check's ratios are of the gain over the creature's
  /// score with every joint held (its idle score), and the held gate, which
  /// asks whether a fall earned the fitness, does not apply.
  bool idle_scores = false;
  /// The task asks for a posture, whose score constant signals may earn (a
  /// pose held, or the swing as the muscles come on: lessin2015's Fast ESP
  /// creatures "jump as high as possible, or reach one limb up"): the
  /// clamped gate, which asks whether constant signals move the creature,
  /// does not apply.
  bool posture = false;
};

/// One task kind.
struct TaskRow {
  TaskKind kind;
  std::string_view name;  ///< its task.kind in configs
  /// The task of trial `trial` (0-based, as evaluate() counts them: a task
  /// may lay out each trial its own way), whose physics seed is `seed` (a
  /// task may draw its layout from it), or why this creature cannot have it.
  Result<std::unique_ptr<Task>> (*make)(const CreatureModel&, const SimConfig&, std::uint64_t seed, int trial);
  /// Its evaluation's length (s) and drop height (m) in a config, and their keys.
  double& (*seconds)(SimConfig&);
  double (*drop_height)(const SimConfig&);
  std::string_view seconds_key, drop_height_key;
  /// The config keys it brings (none: its keys are the reader's own).
  std::vector<SimField> (*fields)();
  /// Its rules between keys, checked by the config reader when it is the
  /// config's task (none: no rules), or which keys disagree and how.
  Status (*check)(const SimConfig&) = nullptr;
  /// How it folds an evaluation's trial scores (task.trials of them, in
  /// trial order) into its fitness when it has its own way (lessin2015's
  /// attack and fight-or-flight); nullptr: task.trial_score's mean or least.
  double (*fold)(const SimConfig&, std::span<const double>) = nullptr;
  /// What that fold is, for messages ("...: the fitness is X of N trials").
  std::string (*fold_name)(const SimConfig&) = nullptr;
  /// How check judges it under this config (nullptr: doing nothing scores 0, no posture).
  CheckBasis (*check_basis)(const SimConfig&) = nullptr;
};

/// The row of a kind.
const TaskRow& task_row(TaskKind kind);
/// Every kind's name, in TaskKind's order (the config's choices).
std::vector<std::string_view> task_kind_names();
/// Every row's own config keys, in the table's order.
std::vector<SimField> task_fields();

/// The task of cfg.task_kind for this creature's trial `trial` (0-based) of
/// physics seed `seed`, or why it cannot have it (throwing needs a catapult).
Result<std::unique_ptr<Task>> make_task(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed,
                                        int trial);

/// An evaluation's fitness from its trials' scores: the task's own fold
/// (TaskRow::fold), else their mean or least (task.trial_score).
double fold_trials(const SimConfig& cfg, std::span<const double> trials);
/// What fold_trials takes of them, for messages: "mean", "least", or the task's own.
std::string trial_fold_name(const SimConfig& cfg);

/// The config's task's rules between its keys (TaskRow::check): Ok, or why not.
Status check_task_keys(const SimConfig& cfg);

}  // namespace bx
