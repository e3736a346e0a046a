// The MPI evaluator: a run as wide as an MPI allocation (docs/cluster.md).
// `mpirun -np N bestiary run ... --evaluator mpi`: rank 0 runs the command (the
// algorithm, the database, the output) and hands each evaluation to one of the
// other N - 1 ranks; each of those evaluates in a forked child process of its
// own (a ProcessPoolEvaluator of one worker), so a creature that crashes ODE
// costs one evaluation, not the job. Jobs and outcomes travel as the process
// pool's records (eval/records_json.h); the task table reaches each rank once,
// as TOML text. An evaluation is a pure function of its job, so the run is
// the same, bit for bit, for any number of ranks or pool workers.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/result.h"
#include "eval/evaluator.h"
#include "eval/sim_config.h"

namespace bx {

/// Whether a command line asks for the MPI evaluator: `--evaluator mpi` or
/// `--evaluator=mpi` anywhere in it.
bool mpi_requested(int argc, char** argv);

/// Starts MPI for a command that asked for it. Rank 0 gets nullopt and goes
/// on with the command; MPI ends (the other ranks told to stop, then
/// MPI_Finalize) when rank 0's process exits. Every other rank serves
/// evaluations to rank 0's MpiEvaluator until rank 0 ends, and then gets its
/// exit code to return from main.
std::optional<int> mpi_start(int* argc, char*** argv);

/// The ranks that evaluate: all but rank 0 (0 when MPI was not started, or
/// when this process is the only rank).
int mpi_evaluating_ranks();

/// `run --seeds` under MPI: the world is split into one group of ranks per
/// seed (consecutive ranks; at least 2 each, so at most half as many seeds as
/// ranks), each with its own rank 0 running that seed's run and its own
/// evaluators. This process's group (0-based: the seed's place in the list)
/// and the number of groups (1 without --seeds, or when the list has more
/// seeds than half the ranks: the command then says so).
int mpi_group();
int mpi_groups();
/// Processes in the whole MPI job (1 when MPI was not started).
int mpi_world_size();

/// Whether this process can be the MPI evaluator's rank 0: MPI started and
/// at least one other rank, or an error that says how to launch it.
Status mpi_ready();

/// Rank 0's evaluator over the other ranks. An error when MPI was not started
/// or has no other rank, or when a task's config does not survive its trip as
/// TOML text (every rank must evaluate the config rank 0 has).
Result<std::unique_ptr<Evaluator>> make_mpi_evaluator(const std::vector<SimConfig>& tasks, double timeout_seconds);

}  // namespace bx
