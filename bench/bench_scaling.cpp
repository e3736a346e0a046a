// bench_scaling: how many workers each preset's run can keep busy
// (docs/cluster.md, "How wide a run goes"). For each preset named (default:
// the full presets of the four papers and `quick`):
//
//   batches   a short real run of the preset (its algorithm, population and
//             batch; evaluations shortened to 1 simulated second so that it
//             takes seconds; generational: 2 generations, steady state: its
//             initial population and one report interval) driven through an evaluator
//             that records the size of every batch the algorithm hands it and
//             the wall time spent inside and outside evaluate(): outside is
//             the parent's serial work (breeding, the database), per batch.
//   job cost  the first K jobs of the run's first batch (random creatures of
//             the preset) evaluated again at the preset's own length and
//             step: the CPU time of each (thread CPU time), the distribution
//             a cluster's workers see in early generations.
//   model     for W = 1, 8, 64, 128, 256, 512 and 4096 workers, each recorded batch's
//             (a steady state's after its initial population: its long run)
//             jobs (each a cost drawn in turn from the K measured) handed
//             longest first to W workers: the batch takes its makespan plus
//             the parent's serial time per batch. busy(W) = the jobs' total
//             cost / (W x the run's time); speedup(W) = time(1) / time(W).
//             The parent is the bottleneck where its serial time per batch
//             exceeds the batch's makespan. The run is made once per W,
//             its evaluator telling it W workers: the elite's rounds fill
//             idle workers with evaluations ahead, so the batches (and the
//             busy share: the evaluations made ahead count as work) depend on
//             W; the run itself does not.
//
// Output: a table per preset and, on the last line, `busy_at_64_workers:` of
// the first preset. Deterministic inputs (seed 1); times vary with the machine.
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <map>
#include <queue>
#include <string>
#include <vector>

#include "args.h"
#include "eval/evaluate.h"
#include "eval/evaluator.h"
#include "eval/task_table.h"
#include "io/config.h"
#include "io/presets.h"
#include "io/syllabus.h"
#include "run/run.h"

namespace {

using namespace bx;
namespace fs = std::filesystem;

double wall_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

int usage(const char* why) {
  std::fprintf(stderr,
               "bench_scaling: %s\nusage: bench_scaling [--quick] [--samples K] [--set section.key=value]... [PRESET...]\n"
               "  --quick     the -small presets' families: quick and rivercrossing-small, K = 4\n"
               "  --samples   jobs of the first batch evaluated at the preset's own length (default 12)\n"
               "  --set       a config value for every preset named (evolution.islands=10: a run on islands)\n",
               why);
  return 2;
}

// What the timing evaluator saw.
struct Seen {
  std::vector<int> batches;     // jobs per evaluate() call
  double inside = 0;            // wall seconds inside the run's evaluations
  double sampling = 0;          // wall seconds spent on the full-length samples
  std::vector<double> job_cpu;  // CPU seconds of each full-length sample
};

// The run's evaluator (serial, on the shortened tasks), timing itself; the
// first `samples` jobs it sees are evaluated again on the preset's own tasks.
class TimingEvaluator : public Evaluator {
 public:
  TimingEvaluator(const std::vector<SimConfig>& run_tasks, const std::vector<SimConfig>& full_tasks, int samples,
                  Seen* seen)
      : run_(run_tasks), samples_(samples), seen_(seen) {
    for (const SimConfig& c : full_tasks) full_.emplace_back(c);
  }
  std::vector<EvalOutcome> evaluate(const std::vector<EvalJob>& jobs) override {
    seen_->batches.push_back(static_cast<int>(jobs.size()));
    const double t0 = wall_seconds();
    std::vector<EvalOutcome> out = run_.evaluate(jobs);
    const double t1 = wall_seconds();
    seen_->inside += t1 - t0;
    for (const EvalJob& j : jobs) {
      if (samples_ <= 0) break;
      --samples_;
      const double c0 = thread_cpu_seconds();
      evaluate_genotype(*j.genotype, full_[static_cast<std::size_t>(j.task)].at(j.step_divisor), j.seed);
      seen_->job_cpu.push_back(thread_cpu_seconds() - c0);
    }
    seen_->sampling += wall_seconds() - t1;
    return out;
  }
  /// The width the run is told it has: the elite's rounds fill idle
  /// workers with evaluations ahead (evolution.h), so what the algorithm
  /// hands out depends on it.
  int workers() const override { return workers_; }
  int workers_ = 1;

 private:
  SerialEvaluator run_;
  std::vector<DividedSteps> full_;
  int samples_;
  Seen* seen_;
};

// longest-first makespan of `costs` on w workers
double makespan(std::vector<double> costs, int w) {
  std::sort(costs.begin(), costs.end(), std::greater<>());
  std::priority_queue<double, std::vector<double>, std::greater<>> free_at;
  for (int k = 0; k < w && k < static_cast<int>(costs.size()); ++k) free_at.push(0);
  double end = 0;
  for (double c : costs) {
    const double t = free_at.top() + c;
    free_at.pop();
    free_at.push(t);
    end = std::max(end, t);
  }
  return end;
}

struct Width {
  int workers;
  double busy, speedup, parent_share;
};

constexpr int kWidths[] = {1, 8, 64, 128, 256, 512, 4096};

// the model: every batch the run handed out at each width (a steady state's
// after its initial population: the run's long run), its jobs' costs drawn
// in turn from the samples
std::vector<Width> model(const Seen& seen, const std::map<int, std::vector<int>>& batches_at, bool steady,
                         double parent_per_batch) {
  std::vector<Width> out;
  double time_1 = 0;
  for (int w : kWidths) {
    std::vector<int> batches = batches_at.at(w);
    if (steady && batches.size() > 1) batches.erase(batches.begin());
    std::size_t draw = 0;
    double total = 0, work = 0, parent = 0;
    for (int b : batches) {
      std::vector<double> costs;
      for (int k = 0; k < b; ++k) costs.push_back(seen.job_cpu[draw++ % seen.job_cpu.size()]);
      for (double c : costs) work += c;
      total += makespan(costs, w) + parent_per_batch;
      parent += parent_per_batch;
    }
    if (w == 1) time_1 = total;
    out.push_back({w, work / (w * total), time_1 / total, parent / total});
  }
  return out;
}

int bench(const std::string& preset, int samples, const std::vector<std::string>& sets, double& busy_64) {
  const Preset* p = find_preset(preset);
  if (!p) return usage((preset + ": no such preset").c_str());
  auto full = read_syllabus(p->text, preset, sets);
  if (!full) return usage(full.error().c_str());
  const RunConfig& first = full->stages.front().cfg;
  const TaskRow& row = task_row(first.sim.task_kind);
  const bool generational = first.evolution.algorithm == Algorithm::Generational;
  std::vector<std::string> shorter = sets;
  shorter.push_back(std::string(row.seconds_key) + "=1");
  if (generational) {
    shorter.push_back("evolution.generations=2");
  } else {
    // one report interval as the preset has it (its elite re-evaluated once, as every interval)
    const long every = first.evolution.report_every > 0 ? first.evolution.report_every : first.evolution.population;
    shorter.push_back("evolution.evaluations=" + std::to_string(every));
  }
  auto run_syl = read_syllabus(p->text, preset, shorter);
  if (!run_syl) return usage(run_syl.error().c_str());
  const std::vector<SimConfig> full_tasks = task_table(*full);
  // the run at each width (the samples and the parent's time from the first, one worker)
  Seen seen;
  std::map<int, std::vector<int>> batches_at;
  double wall = 0;
  for (int w : kWidths) {
    const fs::path dir = fs::temp_directory_path() / ("bx_bench_scaling_" + std::to_string(::getpid()) + "_" + preset);
    fs::remove_all(dir);
    if (Status s = create_run(dir.string(), *run_syl, p->text, preset, 1); !s) return usage(s.error().c_str());
    Seen at;
    RunOptions opt;
    opt.quiet = true;
    opt.evaluator = [&](const std::vector<SimConfig>& tasks, double) -> Result<std::unique_ptr<Evaluator>> {
      auto e = std::make_unique<TimingEvaluator>(tasks, full_tasks, w == 1 ? samples : 0, &at);
      e->workers_ = w;
      return std::unique_ptr<Evaluator>(std::move(e));
    };
    const double t0 = wall_seconds();
    const Status s = drive_run(dir.string(), opt);
    if (w == 1) wall = wall_seconds() - t0;
    fs::remove_all(dir);
    if (!s) return usage(s.error().c_str());
    if (w == 1) seen = at;
    batches_at[w] = at.batches;
  }
  if (seen.job_cpu.empty() || seen.batches.empty()) return usage((preset + ": no evaluation seen").c_str());
  const double parent = std::max(0.0, wall - seen.inside - seen.sampling);
  // the first batch is the initial population; the parent's work per batch is over the rest too
  const double parent_per_batch = parent / static_cast<double>(seen.batches.size());
  std::vector<double> c = seen.job_cpu;
  std::sort(c.begin(), c.end());
  std::vector<int> b = seen.batches;
  std::sort(b.begin(), b.end());
  std::printf("%s (%s): %zu batches of %d-%d jobs (median %d); parent %.4f s per batch; job CPU s at the "
              "preset's length (%zu random creatures): min %.3f median %.3f max %.3f\n",
              preset.c_str(), generational ? "generational" : "steady state", seen.batches.size(), b.front(),
              b.back(), b[b.size() / 2], parent_per_batch, c.size(), c.front(), c[c.size() / 2], c.back());
  std::printf("  batches in order:");
  for (std::size_t k = 0; k < seen.batches.size() && k < 24; ++k) std::printf(" %d", seen.batches[k]);
  std::printf("%s\n", seen.batches.size() > 24 ? " ..." : "");
  std::printf("  batches in order at 64 workers (the elite's rounds fill idle workers):");
  for (std::size_t k = 0; k < batches_at[64].size() && k < 24; ++k) std::printf(" %d", batches_at[64][k]);
  std::printf("%s\n", batches_at[64].size() > 24 ? " ..." : "");
  if (!generational)
    std::printf("  the long run (the batches after the initial population of %d):\n", seen.batches.front());
  std::printf("  %8s %8s %8s %14s\n", "workers", "busy", "speedup", "parent share");
  for (const Width& w : model(seen, batches_at, !generational, parent_per_batch)) {
    std::printf("  %8d %8.3f %8.1f %14.4f\n", w.workers, w.busy, w.speedup, w.parent_share);
    if (w.workers == 64 && busy_64 < 0) busy_64 = w.busy;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> presets, sets;
  int samples = 12;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) {
      quick = true;
    } else if (!std::strcmp(argv[i], "--samples")) {
      samples = static_cast<int>(bxbench::number_after(i, argc, argv, "--samples", usage,
                                                       [](double v) { return v >= 1 && v <= 1000 && v == (int)v; },
                                                       "a whole number from 1 to 1000"));
    } else if (!std::strcmp(argv[i], "--set")) {
      if (i + 1 >= argc) return usage("--set: expected section.key=value");
      sets.push_back(argv[++i]);
    } else if (argv[i][0] == '-') {
      return usage((std::string(argv[i]) + ": unknown argument").c_str());
    } else {
      presets.push_back(argv[i]);
    }
  }
  if (quick) {
    samples = std::min(samples, 4);
    if (presets.empty()) presets = {"quick", "rivercrossing-small"};
  }
  if (presets.empty())
    presets = {"quick", "miconi2006", "chaumont2007-walker", "chaumont2007-catapult", "lessin2015-locomotion",
               "lessin2015-general-strike", "rivercrossing"};
  double busy_64 = -1;
  for (const std::string& p : presets)
    if (int code = bench(p, samples, sets, busy_64); code != 0) return code;
  std::printf("busy_at_64_workers: %.3f\n", busy_64);
  return 0;
}
