// bench_mpi: what the MPI evaluator adds to an evaluation, against the
// process pool (docs/cluster.md, docs/benchmarks.md). Run under mpirun with
// two ranks:
//
//   mpirun -np 2 ./build/bench_mpi [--quick] [--jobs N] [--seconds S] [--rounds R]
//
// Rank 0 evaluates the same jobs (N random viable creatures of the `quick`
// preset, each simulated for S seconds: short, so that the fixed costs show)
// in rounds, each round through three evaluators in turn:
//   serial   SerialEvaluator, in this process: the evaluations alone
//   pool     a ProcessPoolEvaluator of 1 worker: + the pipe, JSON, a child
//   mpi      the MPI evaluator over rank 1 (which evaluates in a child of its
//            own): + MPI messages and the rank's own pipe to its child
// Wall-clock time of each round's batch (the work spans processes, so one
// process's CPU time would miss it), per evaluation, min/median/max over
// the rounds, then `pool_overhead_ms` (pool - serial), `mpi_overhead_ms`
// (mpi - pool) per evaluation, medians, and `ratio_mpi_vs_pool` (mpi's
// median time per evaluation over the pool's). Every evaluator's results are
// checked equal to the serial ones (stderr, exit 1 if not).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "args.h"
#include "cluster/mpi_evaluator.h"
#include "core/rng.h"
#include "develop/develop.h"
#include "eval/evaluator.h"
#include "genome/graph_genotype.h"
#include "genome/operators.h"
#include "io/config.h"
#include "io/presets.h"

namespace {

using namespace bx;

double wall_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

int usage(const char* why) {
  std::fprintf(stderr, "bench_mpi: %s\nusage: mpirun -np 2 bench_mpi [--quick] [--jobs N] [--seconds S] [--rounds R]\n",
               why);
  return 2;
}

struct Spread {
  double min, median, max;
};

Spread spread(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return {v.front(), v[v.size() / 2], v.back()};
}

}  // namespace

int main(int argc, char** argv) {
  if (auto code = mpi_start(&argc, &argv)) return *code;  // rank 1: serve rank 0's jobs
  int jobs_n = 64, rounds = 9;
  double seconds = 0.05;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) {
      jobs_n = 16;
      rounds = 3;
    } else if (!std::strcmp(argv[i], "--jobs")) {
      jobs_n = static_cast<int>(bxbench::number_after(i, argc, argv, "--jobs", usage,
                                                      [](double v) { return v >= 1 && v <= 100000 && v == (int)v; },
                                                      "a whole number from 1 to 100000"));
    } else if (!std::strcmp(argv[i], "--rounds")) {
      rounds = static_cast<int>(bxbench::number_after(i, argc, argv, "--rounds", usage,
                                                      [](double v) { return v >= 1 && v <= 1000 && v == (int)v; },
                                                      "a whole number from 1 to 1000"));
    } else if (!std::strcmp(argv[i], "--seconds")) {
      seconds = bxbench::number_after(i, argc, argv, "--seconds", usage,
                                      [](double v) { return v > 0 && v <= 600; }, "seconds in (0, 600]");
    } else {
      return usage((std::string(argv[i]) + ": unknown argument").c_str());
    }
  }
  if (Status s = mpi_ready(); !s) return usage(s.error().c_str());

  auto cfg = read_run_config(find_preset("quick")->text, "quick");
  if (!cfg) return usage(cfg.error().c_str());
  task_seconds(cfg->sim) = seconds;

  // random viable creatures of the preset, each with its own seed
  Rng rng(stream_seed({7, 1}));
  std::vector<GraphGenotype> genotypes;
  genotypes.reserve(static_cast<std::size_t>(jobs_n));  // no reallocation: the jobs point into it
  std::vector<EvalJob> jobs;
  while (static_cast<int>(genotypes.size()) < jobs_n) {
    Genome g = random_genome(cfg->dialect, cfg->operators, rng);
    if (!develop(g, cfg->sim.develop).viable()) continue;
    genotypes.emplace_back(std::move(g));
    jobs.push_back({&genotypes.back(), stream_seed({7, 2, genotypes.size()})});
  }

  const std::vector<SimConfig> tasks{cfg->sim};
  SerialEvaluator serial(tasks);
  ProcessPoolEvaluator pool(tasks, 1, 600);
  auto mpi = make_mpi_evaluator(tasks, 600);
  if (!mpi) return usage(mpi.error().c_str());

  const std::vector<EvalOutcome> expected = serial.evaluate(jobs);
  bool same = true;
  auto check = [&](const std::vector<EvalOutcome>& got, const char* who) {
    for (std::size_t k = 0; k < got.size(); ++k)
      if (got[k].result.fitness != expected[k].result.fitness || got[k].result.failed != expected[k].result.failed) {
        std::fprintf(stderr, "%s: job %zu differs from the serial evaluation\n", who, k);
        same = false;
        return;
      }
  };
  std::vector<double> t_serial, t_pool, t_mpi;
  for (int r = 0; r < rounds; ++r) {
    double t0 = wall_seconds();
    serial.evaluate(jobs);
    double t1 = wall_seconds();
    check(pool.evaluate(jobs), "pool");
    double t2 = wall_seconds();
    check((*mpi)->evaluate(jobs), "mpi");
    double t3 = wall_seconds();
    t_serial.push_back((t1 - t0) / jobs_n * 1e3);
    t_pool.push_back((t2 - t1) / jobs_n * 1e3);
    t_mpi.push_back((t3 - t2) / jobs_n * 1e3);
  }
  std::printf("bench_mpi: %d creatures of `quick`, %g s each, %d rounds; wall ms per evaluation min/median/max\n",
              jobs_n, seconds, rounds);
  const Spread s = spread(t_serial), p = spread(t_pool), m = spread(t_mpi);
  std::printf("  serial (in process)   %8.3f %8.3f %8.3f\n", s.min, s.median, s.max);
  std::printf("  pool (1 worker)       %8.3f %8.3f %8.3f\n", p.min, p.median, p.max);
  std::printf("  mpi (1 rank)          %8.3f %8.3f %8.3f\n", m.min, m.median, m.max);
  std::printf("pool_overhead_ms: %.3f\n", p.median - s.median);
  std::printf("mpi_overhead_ms: %.3f\n", m.median - p.median);
  std::printf("ratio_mpi_vs_pool: %.3f\n", m.median / p.median);
  if (!same) std::fprintf(stderr, "bench_mpi: results differ between evaluators\n");
  return same ? 0 : 1;
}
