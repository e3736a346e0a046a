// Evaluators: how a batch of genotypes gets evaluated. The evolutionary
// algorithms hand a batch to an Evaluator and never touch processes
// themselves (docs/design.md). Every evaluator gives identical results for the
// same jobs, because an evaluation is a pure function of (genotype, config,
// seed).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "eval/evaluate.h"
#include "eval/sim_config.h"
#include "genome/genome.h"
#include "genome/genotype.h"

namespace bx {

/// One evaluation to do.
struct EvalJob {
  const Genotype* genotype = nullptr;
  std::uint64_t seed = 0;
  /// Step at physics.dt / step_divisor (divided_step_config: 1, 2 or 4): an
  /// elite evaluated again so (evolution.elite_half_step, elite_quarter_step).
  int step_divisor = 1;
  /// Which of the evaluator's tasks (its configs, one per stage of a
  /// multi-stage run: io/syllabus.h) it is evaluated on.
  int task = 0;
};

/// What came of one job.
struct EvalOutcome {
  bool viable = true;
  std::string reason;  ///< why not viable
  EvalResult result;   ///< failed == true when the evaluation crashed, timed out or blew up
};

/// Grows and evaluates one genome.
EvalOutcome evaluate_genome(const Genome& g, const SimConfig& cfg, std::uint64_t seed);

/// Evaluates one genotype: the work of every evaluator. It develops into
/// cfg.creature's creature (develop_creature: not viable when it does not,
/// a genotype of another kind included) and that creature is evaluated; a
/// kind without a body evaluates it itself, with no physics world
/// (CreatureKindRow::evaluate).
EvalOutcome evaluate_genotype(const Genotype& g, const SimConfig& cfg, std::uint64_t seed);

/// repeated_fitness for any genotype, each evaluation by evaluate_genotype
/// (a kind without a body has no Creature to pass): the fold of `first` and
/// r.evaluations - 1 more under repeat_seed(seed, k), each at the step
/// repeat_step_divisor says; each one's fitness to `each` when given.
double repeated_genotype_fitness(const Genotype& g, const SimConfig& cfg, std::uint64_t seed, const Repeats& r,
                                 const EvalOutcome& first, std::vector<double>* each = nullptr);

/// The order in which to hand a batch's jobs out: longest first (a graph
/// genome: most parts; Genotype::cost_hint), so that no worker idles on one
/// long job at the end of a batch; ties keep the batch's order.
std::vector<int> longest_first(const std::vector<EvalJob>& jobs);

/// Evaluates batches of jobs; results come back in job order. An evaluator
/// holds a task table: the configs its jobs name by EvalJob::task (as
/// pagmo's batch evaluator receives the problem with each batch), so one
/// batch may mix tasks.
class Evaluator {
 public:
  virtual ~Evaluator() = default;
  virtual std::vector<EvalOutcome> evaluate(const std::vector<EvalJob>& jobs) = 0;
  /// Worker processes in use (1 for the serial evaluator).
  virtual int workers() const = 0;
};

/// Evaluates in this process, one job after another.
class SerialEvaluator : public Evaluator {
 public:
  explicit SerialEvaluator(const std::vector<SimConfig>& tasks);
  explicit SerialEvaluator(const SimConfig& cfg) : SerialEvaluator(std::vector<SimConfig>{cfg}) {}
  std::vector<EvalOutcome> evaluate(const std::vector<EvalJob>& jobs) override;
  int workers() const override { return 1; }

 private:
  /// each task's config at its step, half and a quarter of it (EvalJob::step_divisor)
  std::vector<DividedSteps> steps_;
};

/// Evaluates in K worker processes, one creature at a time each (ODE's random
/// generator is process-wide). A worker lost on a job (it crashed, was killed
/// from outside, or ran past the timeout) is replaced and the job given again,
/// once: a lost worker costs nothing, while a job that crashes or times out
/// twice is recorded as failed with its reason, "(twice)"; the batch goes on.
/// Workers ignore SIGINT and SIGTERM and die with the process that made them.
/// `work` is what a worker does with a job: evaluate_genotype unless a test
/// passes one that crashes or hangs on purpose.
using WorkerJob = std::function<EvalOutcome(const Genotype&, const SimConfig&, std::uint64_t seed)>;
class ProcessPoolEvaluator : public Evaluator {
 public:
  ProcessPoolEvaluator(std::vector<SimConfig> tasks, int workers, double timeout_seconds, WorkerJob work = {});
  ProcessPoolEvaluator(SimConfig cfg, int workers, double timeout_seconds, WorkerJob work = {})
      : ProcessPoolEvaluator(std::vector<SimConfig>{std::move(cfg)}, workers, timeout_seconds, std::move(work)) {}
  ~ProcessPoolEvaluator() override;
  std::vector<EvalOutcome> evaluate(const std::vector<EvalJob>& jobs) override;
  int workers() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A process pool of `workers` processes; 0 evaluates in this process (no
/// protection from crashes: for debugging).
std::unique_ptr<Evaluator> make_evaluator(const std::vector<SimConfig>& tasks, int workers, double timeout_seconds);
inline std::unique_ptr<Evaluator> make_evaluator(const SimConfig& cfg, int workers, double timeout_seconds) {
  return make_evaluator(std::vector<SimConfig>{cfg}, workers, timeout_seconds);
}

}  // namespace bx
