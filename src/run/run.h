// A run on disk: a directory with the resolved config, the run database,
// a log, and the checkpoint inside the database. Creating, resuming and
// driving a run to its end, with progress on the terminal.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/result.h"
#include "eval/evaluator.h"
#include "io/config.h"
#include "io/run_store.h"
#include "io/syllabus.h"

namespace bx {

/// How to drive a run.
struct RunOptions {
  int workers = 2;          ///< worker processes (0: evaluate in this process)
  bool quiet = false;       ///< no progress output
  /// Stop after this many generations of this session (tests); 0: run to the end.
  int stop_after = 0;
  /// Makes the run's evaluator from its task table and evaluation timeout
  /// instead of a process pool of `workers` (the MPI evaluator,
  /// cluster/mpi_evaluator.h, lives above this layer); empty: the pool.
  std::function<Result<std::unique_ptr<Evaluator>>(const std::vector<SimConfig>& tasks, double timeout)> evaluator = {};
};

/// Where a run stands, for what `resume` says before it goes on; an error
/// names what is missing or damaged in its database (checked whole).
struct RunProgress {
  int generations_done = 0;   ///< generations stored (steady state: report intervals)
  int generations_total = 0;  ///< as configured
  long evaluations = 0;
  /// every stage evolved and, when the last asks for it, its best's
  /// held-out measure stored (evolution.held_out_evaluations)
  bool complete = false;
};
Result<RunProgress> run_progress(const std::string& dir);

/// `bestiary verify`: the run's database checked whole (RunStore::
/// check_integrity), its config and seed read, and every stored genome read
/// as its kind; an error names the first damage.
Result<Integrity> verify_run(const std::string& dir);

/// Lengthens a run: `overrides` may set only evolution.generations
/// (generational) or evolution.evaluations (steady state), to at least what
/// is done. Resumed, the run then ends exactly as a run configured that long
/// from the start (a steady-state run only if its budget ended on a report
/// interval). Updates the stored config and config.toml.
Status extend_run(const std::string& dir, const std::vector<std::string>& overrides);

/// Creates the run directory `dir` (which must not exist) for `cfg` and
/// `seed`, with `name` (the preset or config file) recorded.
Status create_run(const std::string& dir, const Syllabus& stages, const std::string& config_text,
                  const std::string& name, std::uint64_t seed);
/// A run of one stage.
inline Status create_run(const std::string& dir, const RunConfig& cfg, const std::string& config_text,
                         const std::string& name, std::uint64_t seed) {
  StageDef one;
  one.cfg = cfg;
  return create_run(dir, Syllabus{{std::move(one)}}, config_text, name, seed);
}

/// Removes the run directory `dir` that create_run made, if the run has
/// stored no generation yet: a run refused once begun (drive_run's error
/// before its first generation) then leaves nothing, as a run refused before
/// create_run does. A run with a generation stored is kept, resumable.
void discard_unstarted_run(const std::string& dir);

/// Whether every stage's breeding suits its genotypes (check_breeding) and
/// a stage that locks the body evolves creatures with one; the error names
/// the stage and the key. `run` checks before it creates the run folder.
Status check_run(const Syllabus& stages);

/// The world (evaluation seed) stage k's retest t (its t-th leaf skill)
/// runs in, for every child and for the skill's reference (drive_run: the
/// creature that ended the skill's last stage, on that stage's task).
std::uint64_t retest_seed(std::uint64_t run_seed, int stage, int retest);

/// The seed of the k-th (from 0) held-out evaluation of a run's best
/// (evolution.held_out_evaluations): of a stream that no trial, repeat,
/// retest or check draws from, so no evaluation selection saw used it.
std::uint64_t held_out_seed(std::uint64_t run_seed, int k);

/// The seeds of `run --seeds`: "A-B" (A to B), "A,B,C" or one seed, each a
/// whole number; an error names the text. At most 10,000 seeds, none twice.
Result<std::vector<std::uint64_t>> parse_seed_list(const std::string& text);

/// Runs (or resumes) the run in `dir` until it is finished. Safe to call on a
/// run killed at any moment: it continues from the last checkpoint and ends
/// exactly as the uninterrupted run would.
Status drive_run(const std::string& dir, const RunOptions& opt);

/// Paths inside a run directory.
std::string run_db_path(const std::string& dir);
std::string run_config_path(const std::string& dir);
std::string run_log_path(const std::string& dir);

}  // namespace bx
