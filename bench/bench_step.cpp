// bench_step: steps per second of a full evaluation (brain, sensors, motors,
// contacts, explosion checks, task) against raw ODE stepping the same bodies
// and joints in the same process (docs/benchmarks.md).
//
//   ours     bx::evaluate() itself, the production code, over N steps
//   raw ODE  the same bodies, geoms, joints, ground, contact rules and solver
//            settings built with direct ODE calls, stepped with dSpaceCollide
//            + dWorldQuickStep + dJointGroupEmpty, its motors replaying the
//            joint torques our run applied (recorded once, untimed) so that
//            both do identical physics work; no brain, sensors or checks
//            (bench/raw_ode.h, shared with bench_evolve)
//
// Output: one line per creature, then `ratio_vs_raw_ode: X` (the smaller
// ratio). Checks (does raw reproduce our trajectory bit for bit?) go to stderr.
#include <ode/ode.h>

#include <time.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "develop/develop.h"
#include "eval/evaluate.h"
#include "eval/sim_config.h"
#include "geometry/ode.h"
#include "genome/genome_json.h"
#include "physics/world.h"
#include "contact_counter.h"
#include "raw_ode.h"

#ifndef BESTIARY_SOURCE_DIR
#define BESTIARY_SOURCE_DIR "."
#endif

namespace {

using namespace bx;
using namespace bx::bench;

struct Figures {
  double ours_sps = 0, raw_sps = 0;
  double ours_contacts = 0, raw_contacts = 0;
  // ours / raw of each paired repetition (the machine is shared: the spread)
  double ratio_min = 0, ratio_max = 0;
};

/// The solver to time (--solver, --iterations); default: the dialect's.
struct SolverChoice {
  std::optional<Solver> solver;
  std::optional<int> iterations;
};

Figures bench_creature(const char* label, const std::string& path, long steps, int reps,
                       std::uint64_t seed, const SolverChoice& choice) {
  auto genome = load_genome(path);
  if (!genome) {
    std::fprintf(stderr, "bench_step: %s\n", genome.error().c_str());
    std::exit(2);
  }
  SimConfig cfg = default_sim_config(genome->dialect);
  if (choice.solver) cfg.physics.solver = *choice.solver;
  if (choice.iterations) cfg.physics.solver_iterations = *choice.iterations;
  // the raw replay places the creature unturned
  cfg.start_yaw_jitter = 0;
  if (cfg.motor.model != MotorModel::Torque) {
    std::fprintf(stderr, "bench_step: %s: raw replay supports the Torque motor model only\n",
                 path.c_str());
    std::exit(2);
  }
  Development dev = develop(*genome, cfg.develop);
  if (!dev.viable()) {
    std::fprintf(stderr, "bench_step: %s: not viable: %s\n", path.c_str(), dev.reason.c_str());
    std::exit(2);
  }
  const CreatureModel& m = *dev.model;
  cfg.task.seconds = static_cast<double>(steps) * cfg.physics.dt;
  const Pose placement{{0, 0, cfg.task.drop_height - m.min_z()}, Mat3::identity()};

  // untimed: our run with a frame every step, to record the effector signals
  // (recording only reads the world, so the physics is that of the timed runs)
  SimConfig rec_cfg = cfg;
  rec_cfg.replay_fps = 1.0 / cfg.physics.dt;
  Replay replay;
  EvalResult rec = evaluate(m, rec_cfg, seed, &replay);
  if (rec.failed) {
    std::fprintf(stderr, "bench_step: %s: %s (the benchmark needs a full-length run)\n", label,
                 rec.failure.c_str());
    std::exit(2);
  }
  const long n = rec.steps;
  if (static_cast<long>(replay.frames.size()) != n + 1) {
    std::fprintf(stderr, "bench_step: %s: expected %ld replay frames, got %zu\n", label, n + 1,
                 replay.frames.size());
    std::exit(2);
  }
  MotorTape tape = record_motor_tape(m, cfg, replay, n);

  // check: raw ODE reproduces our trajectory (same physics work)
  std::vector<Vec3> raw_end = run_raw(m, cfg, placement, tape, seed);
  double max_dev = max_part_deviation(m, replay, raw_end);
  std::fprintf(stderr, "check %s: %ld steps, raw ODE replay ends %s (max part deviation %.3g m)\n",
               label, n, max_dev == 0 ? "bit-identical to ours" : "DIFFERENT from ours", max_dev);

  // warm up, then alternate timed repetitions
  evaluate(m, cfg, seed);
  run_raw(m, cfg, placement, tape, seed);
  std::vector<double> ours_t, raw_t;
  Figures f;
  for (int r = 0; r < reps; ++r) {
    long c0 = g_contacts;
    double t0 = cpu_seconds();
    EvalResult res = evaluate(m, cfg, seed);
    double t1 = cpu_seconds();
    long c1 = g_contacts;
    run_raw(m, cfg, placement, tape, seed);
    double t2 = cpu_seconds();
    long c2 = g_contacts;
    if (res.steps != n) {
      std::fprintf(stderr, "bench_step: %s: run %d took %ld steps, expected %ld\n", label, r,
                   res.steps, n);
      std::exit(2);
    }
    ours_t.push_back(t1 - t0);
    raw_t.push_back(t2 - t1);
    f.ours_contacts = static_cast<double>(c1 - c0) / static_cast<double>(n);
    f.raw_contacts = static_cast<double>(c2 - c1) / static_cast<double>(n);
  }
  f.ours_sps = static_cast<double>(n) / median(ours_t);
  f.raw_sps = static_cast<double>(n) / median(raw_t);
  std::vector<double> ratios;
  for (std::size_t r = 0; r < ours_t.size(); ++r) ratios.push_back(raw_t[r] / ours_t[r]);
  f.ratio_min = *std::min_element(ratios.begin(), ratios.end());
  f.ratio_max = *std::max_element(ratios.begin(), ratios.end());
  return f;
}

int usage(const char* msg) {
  if (msg) std::fprintf(stderr, "bench_step: %s\n", msg);
  std::fprintf(stderr,
               "usage: bench_step [--quick] [--steps N] [--reps R] [--seed S] [--only NAME]\n"
               "                  [--solver quickstep|exact] [--iterations N]\n"
               "  steps per second of our evaluation vs raw ODE, 6- and 12-part creatures\n"
               "  --quick   500 steps x 3 repetitions (smoke test)\n"
               "  --only    one creature: snake or centipede (for profiling)\n"
               "  --solver, --iterations: the physics solver (default: the dialect's, exact)\n"
               "  defaults: 5000 steps x 9 repetitions, seed 1\n");
  return msg ? 2 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  long steps = 5000;
  int reps = 9;
  std::uint64_t seed = 1;
  std::string only;
  SolverChoice choice;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](const char* name) -> long {
      if (i + 1 >= argc) std::exit(usage((std::string(name) + ": missing value").c_str()));
      char* end = nullptr;
      long v = std::strtol(argv[++i], &end, 10);
      if (*end || v < 1) std::exit(usage((std::string(name) + ": expected a positive integer, got \"" +
                                          argv[i] + "\"").c_str()));
      return v;
    };
    if (a == "--quick") {
      steps = 500;
      reps = 3;
    } else if (a == "--steps") {
      steps = value("--steps");
    } else if (a == "--reps") {
      reps = static_cast<int>(value("--reps"));
    } else if (a == "--seed") {
      seed = static_cast<std::uint64_t>(value("--seed"));
    } else if (a == "--only" && i + 1 < argc) {
      only = argv[++i];
      if (only != "snake" && only != "centipede")
        return usage(("--only: expected snake or centipede, got \"" + only + "\"").c_str());
    } else if (a == "--solver" && i + 1 < argc) {
      std::string v = argv[++i];
      if (v != "quickstep" && v != "exact")
        return usage(("--solver: expected quickstep or exact, got \"" + v + "\"").c_str());
      choice.solver = v == "exact" ? Solver::Exact : Solver::QuickStep;
    } else if (a == "--iterations") {
      choice.iterations = static_cast<int>(value("--iterations"));
    } else if (a == "-h" || a == "--help") {
      return usage(nullptr);
    } else {
      return usage(("unknown argument \"" + a + "\"").c_str());
    }
  }

  if (!bind_contact_counter()) {
    std::fprintf(stderr, "bench_step: cannot find ODE's dJointCreateContact\n");
    return 2;
  }
  bx::ensure_ode_initialized();

  // creature files: $BESTIARY_SOURCE_DIR, else the source tree this was built from
  const char* env = std::getenv("BESTIARY_SOURCE_DIR");
  std::string dir = std::string(env && *env ? env : BESTIARY_SOURCE_DIR) + "/creatures/";
  struct Case {
    const char* label;
    const char* file;
    const char* name;
  };
  double worst = 1e300;
  for (Case c : {Case{"snake (6 parts)", "snake.json", "snake"},
                 Case{"centipede (12 parts)", "centipede.json", "centipede"}}) {
    if (!only.empty() && only != c.name) continue;
    Figures f = bench_creature(c.label, dir + c.file, steps, reps, seed, choice);
    double ratio = f.ours_sps / f.raw_sps;
    worst = std::min(worst, ratio);
    std::printf("%s: ours %.0f steps/s, raw ODE %.0f steps/s, ratio %.3f (per run min %.3f, max %.3f), "
                "contacts/step ours %.1f raw %.1f\n",
                c.label, f.ours_sps, f.raw_sps, ratio, f.ratio_min, f.ratio_max, f.ours_contacts,
                f.raw_contacts);
    std::fflush(stdout);
  }
  std::printf("ratio_vs_raw_ode: %.3f\n", worst);
  return 0;
}
