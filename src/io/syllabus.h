// Multi-stage runs: a config whose [[stage]] tables make a run a sequence of
// stages, each evolving its own population on its own task and constants,
// the next starting from what the last one left (lessin2015's syllabus, where
// a stage is a skill; or shaping, where it is a schedule of constants). A
// config without [[stage]] tables is a run of one stage.
//
//   [genome]              # the base config: every stage's defaults
//   dialect = "lessin2015"
//
//   [[stage]]
//   name = "forward"
//   [stage.task]          # the stage's own keys, on the base
//   kind = "locomotion"
//
//   [[stage]]
//   name = "left turn"
//   start = "best"        # random | best | population (default: best); file (first stage only,
//                         #   with file = "NAME|PATH": a canonical creature or a genome file)
//   uses = ["forward"]    # stages whose skills it builds on: learned before it
//   group = "turn"        # its pandemonium group
//   body = "locked"       # free | locked: its founders' bodies locked (Fast ESP)
//   encapsulate = true    # when it ends, its skill is encapsulated (ESP, IV-B)
//   retest_tolerance = 0.2  # General ESP (VI, Algorithm 1): every child is retested on each
//                         #   earlier leaf skill and scores 0 if one falls below (1 - 0.2) x
//                         #   what that skill had learned
//   reconcile = "forward" # General ESP (VI, Algorithm 2): the stage evolves that skill's
//                         #   control again on its own task, the rest fixed
//   [stage.evolution]
//   generations = 20
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "io/config.h"

namespace bx {

/// What a stage's first generation is made of.
enum class StageStart {
  Random,      ///< random genotypes (the first stage's only choice)
  Best,        ///< the last stage's best: once as it is, the rest of the population its mutants
  Population,  ///< the last stage's final population, best first, each once as it is
  File,        ///< a genome file's creature (the first stage only): once as it is, the rest its mutants
};

/// One stage of a run.
struct StageDef {
  std::string name;               ///< unique in the run; "" for a plain config's single stage
  std::vector<std::string> uses;  ///< earlier stages whose skills it builds on
  std::string group;              ///< its pandemonium group ("": none)
  StageStart start = StageStart::Random;
  /// start = File: a canonical creature's name (creatures/) or a genome
  /// file's path, and the FNV-1a hash of its text as the config was first
  /// read (the reader writes it; the run refuses the file if it changed).
  std::string file;
  std::string file_hash;
  /// The body is locked from this stage on (lessin2015's Fast ESP, IV-D):
  /// the stage's founders get their body locked, so no operator changes it;
  /// muscles, photoreceptors and neurons may still be added.
  bool lock_body = false;
  /// When the stage ends, its skill is encapsulated (lessin2015 IV-B,
  /// genome/encapsulate.h) in the next stage's founders: frozen, switched by
  /// a switch of the stage's name in its pandemonium group.
  bool encapsulate = false;
  /// General ESP (lessin2015 VI, Algorithm 1): the body may change, so every
  /// child is evaluated again on each leaf skill learned before (leaf_skills:
  /// run alone, its own stage's task) and scores 0 if one falls below (1 -
  /// tolerance) x the fitness that skill had when its stage ended. None:
  /// no retests (Fast ESP, or a stage that changes no body).
  std::optional<double> retest_tolerance;
  /// General ESP's reconciliation (lessin2015 VI, Algorithm 2): the name of an
  /// earlier skill whose control this stage evolves again, on that skill's
  /// own task run alone, the rest of the creature fixed (genome/reconcile.h:
  /// its wires' weights); its config's simulation is that stage's, with
  /// brain.skill, and its operators are restricted so. "": none.
  std::string reconcile;
  RunConfig cfg;                  ///< the base config with the stage's tables (and --set) overlaid
  friend bool operator==(const StageDef&, const StageDef&) = default;
};

/// A run's stages, in order: at least one.
struct Syllabus {
  std::vector<StageDef> stages;
  /// Made from [[stage]] tables (a plain config's run has one stage, unnamed).
  bool staged() const { return stages.size() != 1 || !stages.front().name.empty(); }
  /// The index of the stage named `name`, or -1.
  int find(std::string_view name) const;
  /// A pandemonium group's id in the genome (NeuronGene::group): the groups
  /// numbered from 0 in the order the stages first name them; -1 for "".
  int group_id(std::string_view group) const;
  /// The leaf skills learned before stage k (lessin2015 VI-A, Fig. 19: the
  /// skills that drive the body directly): earlier stages that encapsulate
  /// their skill and use none, in order.
  std::vector<int> leaf_skills(int k) const;
  /// The last stage before k that evolved stage j's skill: j, or a later
  /// stage that reconciled it.
  int learned_in(int j, int k) const;
  friend bool operator==(const Syllabus&, const Syllabus&) = default;
};

/// One retest of a stage (StageDef::retest_tolerance): the leaf skill's
/// stage and its row in task_table().
struct RetestRow {
  int stage = 0;
  int task = 0;
};

/// The evaluator's task table of a run: row k is stage k's simulation, then
/// one row per retest: for each stage with retests, each leaf skill before it
/// run alone (its stage's simulation with brain.skill = its name), in stage order.
std::vector<SimConfig> task_table(const Syllabus& s);
/// Stage k's retests, in the order of leaf_skills(k); none without retest_tolerance.
/// A retest's skill must keep what the last stage that evolved it (its own,
/// or a later one that reconciled it: learned_in) ended with.
std::vector<RetestRow> retest_rows(const Syllabus& s, int k);

/// The stages of a config text: its [[stage]] tables, each on the base (the
/// rest of the text), then the overrides (which every stage gets); without
/// them, one stage of read_run_config(text, source, overrides). Errors name
/// the stage and the key: an unknown stage in `uses`, one used before it is
/// learned, a name given twice, a stage of another dialect or creature kind
/// than the first's (its population could not start from the last's).
Result<Syllabus> read_syllabus(std::string_view text, std::string_view source,
                               const std::vector<std::string>& overrides = {});

/// A syllabus as TOML that read_syllabus reads back to it exactly: the first
/// stage's config with every key, then each stage's table with the keys in
/// which its config differs from the first's. A plain config's single stage
/// is config_to_toml of it.
std::string syllabus_to_toml(const Syllabus& s);

/// The names of StageStart's values, in order.
std::string_view stage_start_name(StageStart s);

}  // namespace bx
