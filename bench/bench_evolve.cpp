// bench_evolve: evaluations per second of the `miconi2006-small` preset's
// evaluations in the process pool with 1 and 2 (up to K) workers, against raw
// ODE stepping the same creatures with the same motor commands
// (docs/benchmarks.md).
//
//   pool     ProcessPoolEvaluator::evaluate() itself (the production code: the
//            genome sent as JSON, developed and evaluated in a worker, the
//            outcome sent back), wall-clock time of whole batches
//   raw ODE  each creature built with direct ODE calls and stepped replaying
//            the servo commands our run gave (bench/raw_ode.h), serially in
//            this process, thread CPU time
//
// Output: evals/s per worker count, the raw ODE rate and diagnostics, then
// `worker_scaling: X` (K workers over 1) and `steps_per_s_vs_raw_ode: Y`
// (physics steps per second of K workers over K x the raw ODE rate). Checks
// (raw replays bit-identical? pool results equal to in-process ones?) go to
// stderr.
#include <ode/ode.h>

#include <dirent.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "genome/graph_genotype.h"
#include "core/rng.h"
#include "develop/develop.h"
#include "eval/evaluate.h"
#include "eval/evaluator.h"
#include "geometry/ode.h"
#include "genome/genome_json.h"
#include "genome/operators.h"
#include "io/config.h"
#include "io/presets.h"
#include "physics/world.h"
#include "raw_ode.h"

namespace {

using namespace bx;
using namespace bx::bench;

constexpr const char* kPreset = "miconi2006-small";

double wall_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

std::string fmt_g(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// the 1-minute load average, or -1
double load_average() {
  std::ifstream f("/proc/loadavg");
  double l = -1;
  f >> l;
  return l;
}

// ---------------------------------------------------------------------------
// Worker processes: the pool does not name them, so find this process's
// children in /proc and read their scheduler statistics.

std::vector<int> child_pids() {
  std::vector<int> pids;
  const int self = static_cast<int>(::getpid());
  DIR* d = ::opendir("/proc");
  if (!d) return pids;
  while (dirent* e = ::readdir(d)) {
    char* end = nullptr;
    long pid = std::strtol(e->d_name, &end, 10);
    if (*end || pid <= 0) continue;
    std::ifstream f(std::string("/proc/") + e->d_name + "/stat");
    std::string s((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    auto rp = s.rfind(')');
    if (rp == std::string::npos) continue;
    std::istringstream in(s.substr(rp + 1));
    std::string state;
    int ppid = 0;
    in >> state >> ppid;
    if (ppid == self) pids.push_back(static_cast<int>(pid));
  }
  ::closedir(d);
  std::sort(pids.begin(), pids.end());
  return pids;
}

// Scheduler times of processes so far (s): running on a CPU, and runnable but
// waiting for one (other load); from /proc/PID/schedstat, in nanoseconds.
struct SchedTimes {
  double run = 0, wait = 0;
};

SchedTimes sched_times(const std::vector<int>& pids) {
  SchedTimes t;
  for (int pid : pids) {
    std::ifstream f("/proc/" + std::to_string(pid) + "/schedstat");
    unsigned long long run = 0, wait = 0;
    if (f >> run >> wait) {
      t.run += 1e-9 * static_cast<double>(run);
      t.wait += 1e-9 * static_cast<double>(wait);
    }
  }
  return t;
}

// ---------------------------------------------------------------------------

struct Sample {
  Genome genome;
  CreatureModel model;
  std::uint64_t seed = 0;  // evaluation seed
  long steps = 0;          // physics steps of its evaluation
  double fitness = 0;      // of its in-process evaluation
  MotorTape tape;
};

// Makespan of jobs of these lengths handed, in order and batch by batch, to
// the first idle of k workers (as the pool does), with no other cost: what
// uneven job lengths alone allow.
double list_schedule_makespan(const std::vector<double>& t, int k, std::size_t batch) {
  double total = 0;
  for (std::size_t b0 = 0; b0 < t.size(); b0 += batch) {
    std::vector<double> free_at(static_cast<std::size_t>(k), 0.0);
    for (std::size_t j = b0; j < std::min(t.size(), b0 + batch); ++j) {
      auto it = std::min_element(free_at.begin(), free_at.end());
      *it += t[j];
    }
    total += *std::max_element(free_at.begin(), free_at.end());
  }
  return total;
}

// One timed batch of one pool (s).
struct PoolRep {
  double wall = 0;         // the batch, start to end
  double parent_cpu = 0;   // this process's CPU time
  double parent_wait = 0;  // this process runnable, waiting for a CPU
  double run = 0;          // workers running, summed over workers
  double wait = 0;         // workers runnable, waiting for a CPU
  double idle = 0;         // workers without a job: k x wall - run - wait
};

int usage(const char* msg) {
  if (msg) std::fprintf(stderr, "bench_evolve: %s\n", msg);
  std::fprintf(stderr,
               "usage: bench_evolve [--quick] [--n N] [--seconds S] [--reps R] [--seed S]\n"
               "                    [--workers-max K] [--batch B]\n"
               "  evaluations per second of %s evaluations with 1..K pool workers,\n"
               "  and physics steps per second against raw ODE\n"
               "  --quick        6 creatures, 2 s (200-step) evaluations, 3 repetitions (smoke test)\n"
               "  --n            random viable creatures in the batch (default 40)\n"
               "  --seconds      evaluation length (default 20; the preset's is 100)\n"
               "  --reps         timed repetitions (default 5; the median is reported)\n"
               "  --seed         creature and evaluation seed (default 1)\n"
               "  --workers-max  largest pool (default 2): worker_scaling is K workers over 1\n"
               "  --batch        jobs per evaluate() call (default: all N in one; the preset's\n"
               "                 steady-state loop uses 8)\n",
               kPreset);
  return msg ? 2 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  int n = 40;
  double seconds = 20;
  int reps = 5;
  std::uint64_t seed = 1;
  int workers_max = 2;
  int batch = 0;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](const char* name) -> double {
      if (i + 1 >= argc) std::exit(usage((std::string(name) + ": missing value").c_str()));
      char* end = nullptr;
      double v = std::strtod(argv[++i], &end);
      if (*end || !(v > 0)) std::exit(usage((std::string(name) + ": expected a positive number, got \"" +
                                             argv[i] + "\"").c_str()));
      return v;
    };
    auto integer = [&](const char* name) -> int {
      double v = value(name);
      if (v != std::floor(v) || v > 1e6)
        std::exit(usage((std::string(name) + ": expected a positive integer, got \"" + argv[i] + "\"").c_str()));
      return static_cast<int>(v);
    };
    if (a == "--quick") {
      n = 6;
      seconds = 2;
      reps = 3;
    } else if (a == "--n") {
      n = integer("--n");
    } else if (a == "--seconds") {
      seconds = value("--seconds");
    } else if (a == "--reps") {
      reps = integer("--reps");
    } else if (a == "--seed") {
      seed = static_cast<std::uint64_t>(integer("--seed"));
    } else if (a == "--workers-max") {
      workers_max = integer("--workers-max");
    } else if (a == "--batch") {
      batch = integer("--batch");
    } else if (a == "-h" || a == "--help") {
      return usage(nullptr);
    } else {
      return usage(("unknown argument \"" + a + "\"").c_str());
    }
  }
  if (batch <= 0 || batch > n) batch = n;
  const double load_start = load_average();

  // the preset's config, evaluations shortened to `seconds`
  const Preset* preset = nullptr;
  for (const Preset& p : presets())
    if (p.name == kPreset) preset = &p;
  if (!preset) {
    std::fprintf(stderr, "bench_evolve: no preset named %s\n", kPreset);
    return 2;
  }
  auto rc = read_run_config(preset->text, kPreset);
  if (!rc) {
    std::fprintf(stderr, "bench_evolve: %s\n", rc.error().c_str());
    return 2;
  }
  RunConfig cfg = *rc;
  const double preset_seconds = cfg.sim.task.seconds;
  cfg.sim.task.seconds = seconds;
  if (std::string why = raw_replay_unsupported(cfg.sim); !why.empty()) {
    std::fprintf(stderr, "bench_evolve: %s: %s\n", kPreset, why.c_str());
    return 2;
  }
  ensure_ode_initialized();

  // where evaluate() puts a creature: drop_height above the ground, raised
  // and turned about the vertical by what its physics seed draws
  // (task.start_drop_jitter, task.start_yaw_jitter: evaluate.h's seed_draw)
  auto placement_of = [&](const Sample& c) {
    const SeedDraw d = seed_draw(cfg.sim, c.seed);
    return Pose{{0, 0, cfg.sim.task.drop_height + d.lift - c.model.min_z()}, Mat3::rotation({0, 0, 1}, d.yaw)};
  };
  // ---- creatures: random viable genomes, each recorded once (untimed) with a
  // frame every step for its motor tape; redrawn if not viable or if its
  // evaluation blows up (the raw replay needs a complete run)
  SimConfig rec_cfg = cfg.sim;
  rec_cfg.replay_fps = 1.0 / cfg.sim.physics.dt;
  std::vector<Sample> cs;
  cs.reserve(static_cast<std::size_t>(n));
  Rng rng(stream_seed({seed, 1}));
  long not_viable = 0, blew_up = 0;
  int identical = 0;
  double worst_dev = 0;
  for (int i = 0; i < n; ++i) {
    for (;;) {
      Genome g = random_genome(cfg.dialect, cfg.operators, rng);
      Development dev = develop(g, cfg.sim.develop);
      if (!dev.viable()) {
        ++not_viable;
        continue;
      }
      Sample c;
      c.genome = std::move(g);
      c.model = std::move(*dev.model);
      c.seed = stream_seed({seed, 2, static_cast<std::uint64_t>(i)});
      Replay replay;
      EvalResult rec = evaluate(c.model, rec_cfg, c.seed, &replay);
      if (rec.failed) {
        ++blew_up;
        continue;
      }
      c.steps = rec.steps;
      c.fitness = rec.fitness;
      if (static_cast<long>(replay.frames.size()) != c.steps + 1) {
        std::fprintf(stderr, "bench_evolve: creature %d: expected %ld replay frames, got %zu\n", i,
                     c.steps + 1, replay.frames.size());
        return 2;
      }
      c.tape = record_motor_tape(c.model, cfg.sim, replay, c.steps);
      // check: raw ODE reproduces our trajectory (same physics work)
      double dev_m = max_part_deviation(c.model, replay, run_raw(c.model, cfg.sim, placement_of(c), c.tape, c.seed));
      if (dev_m == 0) ++identical;
      if (std::isnan(dev_m) || dev_m > worst_dev) worst_dev = dev_m;
      cs.push_back(std::move(c));
      break;
    }
  }
  long total_steps = 0, min_steps = cs[0].steps, max_steps = cs[0].steps;
  int min_parts = 1 << 30, max_parts = 0;
  double parts_sum = 0;
  for (const Sample& c : cs) {
    total_steps += c.steps;
    min_steps = std::min(min_steps, c.steps);
    max_steps = std::max(max_steps, c.steps);
    min_parts = std::min(min_parts, c.model.n_parts());
    max_parts = std::max(max_parts, c.model.n_parts());
    parts_sum += c.model.n_parts();
  }
  std::fprintf(stderr,
               "check: raw ODE replay ends %s for %d of %d creatures (max part deviation %.3g m)\n",
               identical == n ? "bit-identical to ours" : "DIFFERENT from ours", identical, n,
               worst_dev);

  // ---- the other work a worker does per job: the genome's JSON text both
  // ways (the parent writes it, the worker parses it) and development
  int inproc_mismatch = 0;
  double json_sum = 0, develop_sum = 0;
  for (const Sample& c : cs) {
    std::vector<double> json_t, develop_t;
    for (int r = 0; r < reps; ++r) {
      double t0 = cpu_seconds();
      auto g = genome_from_json(nlohmann::json::parse(genome_to_json(c.genome).dump()), "job");
      double t1 = cpu_seconds();
      Development dev = develop(*g, cfg.sim.develop);
      double t2 = cpu_seconds();
      if (!dev.viable()) ++inproc_mismatch;
      json_t.push_back(t1 - t0);
      develop_t.push_back(t2 - t1);
    }
    json_sum += median(json_t);
    develop_sum += median(develop_t);
  }

  // ---- the pools: one per worker count, alive together (idle workers wait
  // on their pipe)
  std::vector<GraphGenotype> genotypes;
  genotypes.reserve(cs.size());  // no reallocation: the jobs point into it
  std::vector<EvalJob> jobs;
  for (const Sample& c : cs) {
    genotypes.emplace_back(c.genome);
    jobs.push_back({&genotypes.back(), c.seed});
  }
  const double timeout = 600;
  std::vector<std::unique_ptr<ProcessPoolEvaluator>> pools;
  std::vector<std::vector<int>> pool_pids;
  for (int k = 1; k <= workers_max; ++k) {
    std::vector<int> before = child_pids();
    pools.push_back(std::make_unique<ProcessPoolEvaluator>(cfg.sim, k, timeout));
    std::vector<int> after = child_pids(), mine;
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(),
                        std::back_inserter(mine));
    pool_pids.push_back(mine);
  }
  int pool_mismatch = 0;
  auto run_batch = [&](int k) {
    std::vector<EvalOutcome> out;
    for (std::size_t b0 = 0; b0 < jobs.size(); b0 += static_cast<std::size_t>(batch)) {
      std::vector<EvalJob> part(jobs.begin() + static_cast<long>(b0),
                                jobs.begin() + static_cast<long>(std::min(jobs.size(), b0 + batch)));
      std::vector<EvalOutcome> o = pools[static_cast<std::size_t>(k - 1)]->evaluate(part);
      out.insert(out.end(), o.begin(), o.end());
    }
    for (std::size_t j = 0; j < cs.size(); ++j) {
      const EvalResult& r = out[j].result;
      if (!out[j].viable || r.failed || r.steps != cs[j].steps || r.fitness != cs[j].fitness)
        ++pool_mismatch;
    }
  };


  // ---- raw ODE in K processes at once, each replaying every creature: what
  // this machine gives K copies of the bare physics (shared caches, memory,
  // the hypervisor), the hardware's own scaling. Returns {wall, mean CPU}.
  auto raw_concurrent = [&]() -> std::pair<double, double> {
    std::vector<pid_t> kids;
    std::vector<int> fds;
    double t0 = wall_seconds();
    for (int k = 0; k < workers_max; ++k) {
      int fd[2];
      if (::pipe(fd) != 0) std::exit(2);
      pid_t pid = ::fork();
      if (pid < 0) std::exit(2);
      if (pid == 0) {
        ::close(fd[0]);
        double c0 = cpu_seconds();
        for (const Sample& c : cs) run_raw(c.model, cfg.sim, placement_of(c), c.tape, c.seed);
        double cpu = cpu_seconds() - c0;
        ssize_t wr = ::write(fd[1], &cpu, sizeof cpu);
        ::_exit(wr == static_cast<ssize_t>(sizeof cpu) ? 0 : 1);
      }
      ::close(fd[1]);
      kids.push_back(pid);
      fds.push_back(fd[0]);
    }
    double cpu_sum = 0;
    for (std::size_t k = 0; k < kids.size(); ++k) {
      double cpu = 0;
      if (::read(fds[k], &cpu, sizeof cpu) != static_cast<ssize_t>(sizeof cpu)) std::exit(2);
      ::close(fds[k]);
      ::waitpid(kids[k], nullptr, 0);
      cpu_sum += cpu;
    }
    return {wall_seconds() - t0, cpu_sum / workers_max};
  };

  // ---- warm up, then repetitions: each one times, in turn, our evaluate()
  // and raw ODE serially in this process (thread CPU time, alternating per
  // creature), raw ODE in K processes at once, and a batch on each pool
  // (wall time), so that drifts in machine load hit all of them
  evaluate(cs[0].model, cfg.sim, cs[0].seed);
  run_raw(cs[0].model, cfg.sim, placement_of(cs[0]), cs[0].tape, cs[0].seed);
  for (int k = 1; k <= workers_max; ++k) run_batch(k);
  std::vector<std::vector<double>> ours_t(cs.size()), raw_t(cs.size());
  std::vector<double> conc_wall, conc_cpu;
  // per pool and repetition: wall time of the batch, the parent's CPU time,
  // and the workers' time split into running, waiting for a CPU and idle
  std::vector<std::vector<PoolRep>> reps_of(static_cast<std::size_t>(workers_max));
  const std::vector<int> self{static_cast<int>(::getpid())};
  for (int r = 0; r < reps; ++r) {
    for (std::size_t i = 0; i < cs.size(); ++i) {
      const Sample& c = cs[i];
      double t0 = cpu_seconds();
      EvalResult res = evaluate(c.model, cfg.sim, c.seed);
      double t1 = cpu_seconds();
      run_raw(c.model, cfg.sim, placement_of(c), c.tape, c.seed);
      double t2 = cpu_seconds();
      if (res.steps != c.steps || res.fitness != c.fitness) ++inproc_mismatch;
      ours_t[i].push_back(t1 - t0);
      raw_t[i].push_back(t2 - t1);
    }
    if (workers_max > 1) {
      auto [w, c] = raw_concurrent();
      conc_wall.push_back(w);
      conc_cpu.push_back(c);
    }
    for (int k = 1; k <= workers_max; ++k) {
      const auto ki = static_cast<std::size_t>(k - 1);
      SchedTimes w0 = sched_times(pool_pids[ki]), p0 = sched_times(self);
      double c0 = cpu_seconds();
      double t0 = wall_seconds();
      run_batch(k);
      double t1 = wall_seconds();
      double c1 = cpu_seconds();
      SchedTimes w1 = sched_times(pool_pids[ki]), p1 = sched_times(self);
      PoolRep pr;
      pr.wall = t1 - t0;
      pr.parent_cpu = c1 - c0;
      pr.parent_wait = p1.wait - p0.wait;
      pr.run = w1.run - w0.run;
      pr.wait = w1.wait - w0.wait;
      pr.idle = std::max(0.0, k * pr.wall - pr.run - pr.wait);
      reps_of[ki].push_back(pr);
    }
  }
  double ours_sum = 0, raw_sum = 0;
  std::vector<double> job_t;  // each job's length: its median in-process evaluate() time
  for (std::size_t i = 0; i < cs.size(); ++i) {
    job_t.push_back(median(ours_t[i]));
    ours_sum += job_t.back();
    raw_sum += median(raw_t[i]);
  }
  const double raw_sps = static_cast<double>(total_steps) / raw_sum;
  const double ours_sps = static_cast<double>(total_steps) / ours_sum;
  // newest pool first: a pool's workers inherit the pipe ends of the pools
  // made before it, so an older pool's workers see end-of-file (and exit) only
  // once the newer pools' workers are gone
  while (!pools.empty()) pools.pop_back();
  const double load_end = load_average();
  std::fprintf(stderr,
               "check: pool results (%d repetitions x 1..%d workers) %s in-process evaluate() "
               "(%d mismatches); in-process repetitions: %d mismatches\n",
               reps + 1, workers_max, pool_mismatch == 0 ? "equal" : "DIFFER FROM", pool_mismatch,
               inproc_mismatch);

  // ---- report
  std::string steps_text = min_steps == max_steps
                               ? std::to_string(min_steps)
                               : std::to_string(min_steps) + "-" + std::to_string(max_steps);
  std::printf("%s: %d random viable creatures (%d-%d parts, mean %.1f; seed %llu; %ld not viable "
              "and %ld blown-up redrawn), task.seconds %g (%s), batch %d, median of %d "
              "repetitions\n",
              kPreset, n, min_parts, max_parts, parts_sum / n, static_cast<unsigned long long>(seed),
              not_viable, blew_up, seconds,
              seconds == preset_seconds
                  ? "the preset's"
                  : ("the preset's " + fmt_g(preset_seconds) + " s " +
                     (seconds < preset_seconds ? "shortened" : "lengthened")).c_str(),
              batch, reps);
  std::printf("in-process evaluate() (serial): %.0f steps/s, %.3f x raw ODE\n", ours_sps,
              ours_sps / raw_sps);
  std::printf("per job outside evaluate(), in-process: genome to JSON text and back %.2f ms, "
              "develop() %.2f ms (an evaluation: %.2f ms)\n",
              1e3 * json_sum / n, 1e3 * develop_sum / n, 1e3 * ours_sum / n);
  const double ms1 = list_schedule_makespan(job_t, 1, static_cast<std::size_t>(batch));
  // the same jobs handed out most parts first within each batch (parts
  // predict an evaluation's cost): what ordering the batch could recover
  std::vector<double> job_lpt;
  for (std::size_t b0 = 0; b0 < cs.size(); b0 += static_cast<std::size_t>(batch)) {
    std::vector<std::size_t> idx;
    for (std::size_t j = b0; j < std::min(cs.size(), b0 + static_cast<std::size_t>(batch)); ++j)
      idx.push_back(j);
    std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
      return cs[a].model.n_parts() > cs[b].model.n_parts();
    });
    for (std::size_t j : idx) job_lpt.push_back(job_t[j]);
  }
  std::vector<double> wall_med, est_med;
  for (int k = 1; k <= workers_max; ++k) {
    const auto& rk = reps_of[static_cast<std::size_t>(k - 1)];
    auto med = [&](auto field) {
      std::vector<double> v;
      for (const PoolRep& pr : rk) v.push_back(field(pr));
      return median(v);
    };
    const double w = med([](const PoolRep& pr) { return pr.wall; });
    // without other load: the batch minus the time its workers waited for a CPU
    const double est = med([&](const PoolRep& pr) { return pr.wall - pr.wait / k; });
    const double run = med([](const PoolRep& pr) { return pr.run; });
    const double busy = k * w;
    wall_med.push_back(w);
    est_med.push_back(est);
    if (k == 1)
      std::printf("1 worker: %.2f evals/s (%d evaluations of %s steps)\n", n / w, n,
                  steps_text.c_str());
    else
      std::printf("%d workers: %.2f evals/s\n", k, n / w);
    std::printf("  ");
    if (k > 1)
      std::printf("x%.3f of 1 worker (job lengths alone allow x%.3f, most parts first x%.3f); ",
                  wall_med[0] / w,
                  ms1 / list_schedule_makespan(job_t, k, static_cast<std::size_t>(batch)),
                  ms1 / list_schedule_makespan(job_lpt, k, static_cast<std::size_t>(batch)));
    std::printf("%.0f steps/s; worker time %.0f%% running, %.0f%% waiting for a CPU, %.0f%% idle; "
                "worker CPU %.3f x in-process evaluate(); parent %.2f ms CPU and %.2f ms waiting "
                "for a CPU per evaluation\n",
                static_cast<double>(total_steps) / w, 100 * run / busy,
                100 * med([](const PoolRep& pr) { return pr.wait; }) / busy,
                100 * med([](const PoolRep& pr) { return pr.idle; }) / busy, run / ours_sum,
                1e3 * med([](const PoolRep& pr) { return pr.parent_cpu; }) / n,
                1e3 * med([](const PoolRep& pr) { return pr.parent_wait; }) / n);
  }
  std::printf("raw ODE (serial, same creatures and motor commands): %.0f steps/s\n", raw_sps);
  if (workers_max > 1) {
    const double cw = median(conc_wall), cc = median(conc_cpu);
    std::printf("  raw ODE in %d processes at once: %.0f steps/s each by CPU time (%.3f x serial), "
                "%.0f steps/s together by wall time (x%.3f of serial)\n",
                workers_max, static_cast<double>(total_steps) / cc,
                static_cast<double>(total_steps) / cc / raw_sps,
                workers_max * static_cast<double>(total_steps) / cw,
                workers_max * static_cast<double>(total_steps) / cw / raw_sps);
  }
  std::printf("load average (1 min): %.2f at start, %.2f at end, on %ld cores\n", load_start,
              load_end, ::sysconf(_SC_NPROCESSORS_ONLN));
  const double k_top = workers_max;
  std::printf("without the other load (batch time minus the workers' wait for a CPU): "
              "worker_scaling ~%.3f, steps_per_s_vs_raw_ode ~%.3f\n",
              est_med[0] / est_med.back(),
              static_cast<double>(total_steps) / est_med.back() / (k_top * raw_sps));
  std::printf("worker_scaling: %.3f\n", wall_med[0] / wall_med.back());
  std::printf("steps_per_s_vs_raw_ode: %.3f\n",
              static_cast<double>(total_steps) / wall_med.back() / (k_top * raw_sps));
  return (identical == n && pool_mismatch == 0 && inproc_mismatch == 0) ? 0 : 1;
}
