// bench_river: what a river crossing evaluation costs (issue 32; Stanton &
// Channon 2015's 10 simulated minutes), against raw ODE stepping the same
// quadruped in the same process (docs/benchmarks.md).
//
//   ours     bx::evaluate() itself, the production code: the quadruped (9
//            parts, 12 PD motors) under its hybrid controller (decision
//            network, shunting model, physical network, 5 CTRNN motifs, 12
//            motor neurons) on the river task (the grid world and its inputs)
//   raw ODE  the same bodies, geoms, joints, ground, contact rules and solver
//            settings built with direct ODE calls (bench/raw_ode.h), the PD
//            motors driven to the targets our run gave them (recorded once,
//            untimed), each step reading the joint's angle and setting its
//            motor's speed as World does, so both do the same physics work;
//            no controller, task or checks
//
// Output: one line per creature, then the totals, `cpu_s_per_600s_evaluation:
// X` (ours, the median of the creatures' medians, scaled to 600 s) and
// `ratio_vs_raw_ode: Y` (the smallest ratio of steps/s). Checks (does raw
// reproduce our trajectory bit for bit?) go to stderr, with a fingerprint of
// each creature's evaluation (FNV-1a of every step's poses, signals, neurons
// and joint angles and of the result), equal before and after a change that
// changes no result. Controllers whose evaluation ends early (a death, a
// blow-up) are drawn again, at most 200 times. Exit code 0; 1 if a check
// fails; 2 on a bad argument or when no controller lasts.
#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "core/rng.h"
#include "eval/creature.h"
#include "eval/evaluate.h"
#include "eval/sim_config.h"
#include "eval/task_table.h"
#include "genome/float_vector.h"
#include "geometry/ode.h"
#include "physics/world.h"
#include "contact_counter.h"
#include "raw_ode.h"

namespace {

using namespace bx;
using namespace bx::bench;

// the paper's evaluation: 10 simulated minutes
constexpr double kPaperSeconds = 600;
// draws of controllers that end early, at most (a solver that tears every
// body would draw for ever)
constexpr int kMaxRedraws = 200;

struct Options {
  double seconds = kPaperSeconds;
  int reps = 5;
  int n = 2;
  std::uint64_t seed = 1;
  std::optional<Solver> solver;
  std::optional<int> iterations;
  std::optional<double> dt;
  std::string only;  ///< "ours" or "raw": time one side alone (for profiling)
};

// the river crossing's config (docs/rivercrossing.md, "Physics"): its
// quadruped and task, the paper's physics and PD motors, with the solver and
// step asked for
SimConfig river_config(const Options& o) {
  SimConfig cfg;
  apply_creature_kind(cfg, CreatureKind::River);  // the kind's physics, PD motors, task and brain rate
  cfg.river.task.seconds = o.seconds;
  if (o.solver) cfg.physics.solver = *o.solver;
  if (o.iterations) cfg.physics.solver_iterations = *o.iterations;
  if (o.dt) cfg.physics.dt = *o.dt;
  return cfg;
}

// one creature: random genes, its evaluation seed, its motor tape
struct Sample {
  FloatVector genes{std::vector<double>{}};
  Creature creature;
  std::uint64_t seed = 0;
  Pose placement;
  MotorTape tape;
  long steps = 0;
  double fitness = 0;
  std::vector<double> ours_t, raw_t;
  double ours_contacts = 0, raw_contacts = 0;
};

// where EvalState puts the creature for this seed: the task's drop, and the
// seed's turn about the vertical and lift (seed_draw)
Pose placement_of(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed) {
  const SeedDraw d = seed_draw(cfg, seed);
  auto task = make_task(m, cfg, seed, 0);
  if (!task) {
    std::fprintf(stderr, "bench_river: %s\n", task.error().c_str());
    std::exit(2);
  }
  const double drop = (*task)->scenario().drop_height + d.lift;
  return {{0, 0, drop - m.min_z()}, Mat3::rotation({0, 0, 1}, d.yaw)};
}

// FNV-1a over exact bits: a fingerprint of an evaluation, so that an
// optimisation can show it changed no result
struct Fingerprint {
  std::uint64_t h = 1469598103934665603ull;
  void add(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) {
      h ^= b[i];
      h *= 1099511628211ull;
    }
  }
  void add(double v) { add(&v, sizeof v); }
  void add(const std::vector<double>& v) { add(v.data(), v.size() * sizeof(double)); }
};

// every frame's poses, signals, neurons and joint angles, and the result
std::uint64_t fingerprint(const Replay& replay, const EvalResult& r) {
  Fingerprint f;
  for (const ReplayFrame& fr : replay.frames) {
    f.add(fr.t);
    f.add(fr.poses);
    f.add(fr.effectors);
    f.add(fr.neurons);
    f.add(fr.joint_angles);
  }
  f.add(r.fitness);
  for (const Metric& m : r.metrics) f.add(m.value);
  f.add(r.diagnostics.max_joint_gap);
  f.add(r.diagnostics.max_stop_overshoot);
  f.add(r.diagnostics.max_penetration);
  f.add(r.diagnostics.effector_mean);
  f.add(r.diagnostics.effector_sd);
  f.add(r.diagnostics.effector_hz);
  return f.h;
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::lround(q * static_cast<double>(v.size() - 1)))];
}

int usage(const char* msg) {
  if (msg) std::fprintf(stderr, "bench_river: %s\n", msg);
  std::fprintf(stderr,
               "usage: bench_river [--quick] [--seconds S] [--reps R] [--n N] [--seed S]\n"
               "                   [--solver exact|quickstep] [--iterations N] [--dt H] [--only ours|raw]\n"
               "  CPU time of a river crossing evaluation (the quadruped under its controller)\n"
               "  against raw ODE stepping the same quadruped with the same PD targets\n"
               "  --quick       10 s evaluations x 2 repetitions, 1 creature (smoke test)\n"
               "  --seconds S   evaluation length (default 600, the paper's)\n"
               "  --n N         random controllers (default 2), each a full-length evaluation\n"
               "  --solver, --iterations, --dt: the physics (default: the river's, exact at 0.01 s)\n"
               "  --only ours|raw   time one side alone, for profiling (the ratios then mean nothing)\n"
               "  defaults: 600 s x 5 repetitions, seed 1\n");
  return msg ? 2 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto text = [&](const char* name) -> std::string {
      if (i + 1 >= argc) std::exit(usage((std::string(name) + ": missing value").c_str()));
      return argv[++i];
    };
    auto positive = [&](const char* name) -> double {
      std::string t = text(name);
      char* end = nullptr;
      double v = std::strtod(t.c_str(), &end);
      if (*end || !(v > 0) || !std::isfinite(v))
        std::exit(usage((std::string(name) + ": expected a positive number, got \"" + t + "\"").c_str()));
      return v;
    };
    auto whole = [&](const char* name) -> long {
      double v = positive(name);
      if (v != std::floor(v)) std::exit(usage((std::string(name) + ": expected a positive integer").c_str()));
      return static_cast<long>(v);
    };
    if (a == "--quick") {
      o.seconds = 10;
      o.reps = 2;
      o.n = 1;
    } else if (a == "--seconds") {
      o.seconds = positive("--seconds");
    } else if (a == "--reps") {
      o.reps = static_cast<int>(whole("--reps"));
    } else if (a == "--n") {
      o.n = static_cast<int>(whole("--n"));
    } else if (a == "--seed") {
      o.seed = static_cast<std::uint64_t>(whole("--seed"));
    } else if (a == "--solver") {
      std::string v = text("--solver");
      if (v != "quickstep" && v != "exact")
        return usage(("--solver: expected quickstep or exact, got \"" + v + "\"").c_str());
      o.solver = v == "exact" ? Solver::Exact : Solver::QuickStep;
    } else if (a == "--iterations") {
      o.iterations = static_cast<int>(whole("--iterations"));
    } else if (a == "--dt") {
      o.dt = positive("--dt");
    } else if (a == "--only") {
      o.only = text("--only");
      if (o.only != "ours" && o.only != "raw")
        return usage(("--only: expected ours or raw, got \"" + o.only + "\"").c_str());
    } else if (a == "-h" || a == "--help") {
      return usage(nullptr);
    } else {
      return usage(("unknown argument \"" + a + "\"").c_str());
    }
  }
  if (!bind_contact_counter()) {
    std::fprintf(stderr, "bench_river: cannot find ODE's dJointCreateContact\n");
    return 2;
  }
  ensure_ode_initialized();

  const SimConfig cfg = river_config(o);
  if (std::string why = raw_replay_unsupported(cfg); !why.empty()) {
    std::fprintf(stderr, "bench_river: %s\n", why.c_str());
    return 2;
  }
  const FloatVectorDef box = creature_kind_row(cfg.creature).float_genes(cfg);
  const long full = std::lround(o.seconds / cfg.physics.dt);

  // ---- creatures: random controllers, each recorded once (untimed) with a
  // frame every step for its motor tape; redrawn if its evaluation ends
  // before the time is up (a death, a blow-up): the figures are per
  // full-length evaluation
  SimConfig rec_cfg = cfg;
  rec_cfg.replay_fps = 1.0 / cfg.physics.dt;
  std::vector<Sample> cs(static_cast<std::size_t>(o.n));
  int redrawn = 0, different = 0;
  std::uint64_t draw = 0;
  for (int i = 0; i < o.n; ++i) {
    Sample& c = cs[static_cast<std::size_t>(i)];
    for (;; ++draw, ++redrawn) {
      Rng rng(stream_seed({o.seed, 1, draw}));
      std::vector<double> g(static_cast<std::size_t>(box.length));
      for (double& x : g) x = rng.uniform(box.lo, box.hi);
      c.genes = FloatVector(std::move(g));
      auto dev = develop_creature(c.genes, cfg);
      if (!dev) {
        std::fprintf(stderr, "bench_river: %s\n", dev.error().c_str());
        return 2;
      }
      c.creature = std::move(*dev);
      c.seed = stream_seed({o.seed, 2, draw});
      Replay replay;
      EvalResult rec = evaluate(c.creature, rec_cfg, c.seed, &replay);
      if (rec.failed || rec.steps != full) {
        if (redrawn + 1 >= kMaxRedraws) {
          std::fprintf(stderr, "bench_river: %d controllers drawn, none evaluated to the end (the last: %s)\n",
                       kMaxRedraws, rec.failed ? rec.failure.c_str() : "it died");
          return 2;
        }
        continue;
      }
      const CreatureModel& m = *c.creature.body;
      c.steps = rec.steps;
      c.fitness = rec.fitness;
      c.placement = placement_of(m, cfg, c.seed);
      c.tape = record_motor_tape(m, cfg, replay, c.steps);
      // check: raw ODE reproduces our trajectory (same physics work)
      const double dev_m = max_part_deviation(m, replay, run_raw(m, cfg, c.placement, c.tape, c.seed));
      std::fprintf(stderr,
                   "check creature %d: %ld steps, raw ODE replay ends %s (max part deviation %.3g m); "
                   "our run's fingerprint %016llx\n",
                   i + 1, c.steps, dev_m == 0 ? "bit-identical to ours" : "DIFFERENT from ours", dev_m,
                   static_cast<unsigned long long>(fingerprint(replay, rec)));
      if (dev_m != 0) ++different;
      ++draw;
      break;
    }
  }

  // ---- warm up, then alternate timed repetitions, creature by creature
  const bool ours_on = o.only != "raw", raw_on = o.only != "ours";
  for (Sample& c : cs) {
    if (ours_on) evaluate(c.creature, cfg, c.seed);
    if (raw_on) run_raw(*c.creature.body, cfg, c.placement, c.tape, c.seed);
  }
  for (int r = 0; r < o.reps; ++r) {
    for (Sample& c : cs) {
      const long c0 = g_contacts;
      const double t0 = cpu_seconds();
      EvalResult res;
      if (ours_on) res = evaluate(c.creature, cfg, c.seed);
      else res.steps = c.steps, res.fitness = c.fitness;
      const double t1 = cpu_seconds();
      const long c1 = g_contacts;
      if (raw_on) run_raw(*c.creature.body, cfg, c.placement, c.tape, c.seed);
      const double t2 = cpu_seconds();
      const long c2 = g_contacts;
      if (res.steps != c.steps || res.fitness != c.fitness) {
        std::fprintf(stderr, "bench_river: a repetition took %ld steps (fitness %g), expected %ld (%g)\n",
                     res.steps, res.fitness, c.steps, c.fitness);
        return 1;
      }
      c.ours_t.push_back(t1 - t0);
      c.raw_t.push_back(t2 - t1);
      c.ours_contacts = static_cast<double>(c1 - c0) / static_cast<double>(c.steps);
      c.raw_contacts = static_cast<double>(c2 - c1) / static_cast<double>(c.steps);
    }
  }

  // ---- figures
  const char* solver = cfg.physics.solver == Solver::Exact ? "exact (dWorldStep)" : "QuickStep";
  std::printf("river crossing, the quadruped (9 parts, 12 PD motors) under random controllers: %d creature%s "
              "(seed %llu; %d redrawn for ending early), %g s evaluations (%ld steps of %g s), solver %s",
              o.n, o.n == 1 ? "" : "s", static_cast<unsigned long long>(o.seed), redrawn, o.seconds, full,
              cfg.physics.dt, solver);
  if (cfg.physics.solver == Solver::QuickStep) std::printf(" %d iterations", cfg.physics.solver_iterations);
  std::printf(", %d repetitions, CPU time\n", o.reps);
  const double scale = kPaperSeconds / o.seconds;  // to a 600 s evaluation
  std::vector<double> cpu_600, ratios;
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const Sample& c = cs[i];
    const double ours = median(c.ours_t), raw = median(c.raw_t);
    const double steps = static_cast<double>(c.steps);
    std::vector<double> per_run;
    for (std::size_t r = 0; r < c.ours_t.size(); ++r) per_run.push_back(c.raw_t[r] / c.ours_t[r]);
    std::printf("creature %zu (fitness %g): ours %.0f steps/s, raw ODE %.0f steps/s, ratio %.3f (per run min %.3f, "
                "max %.3f), contacts/step ours %.2f raw %.2f\n",
                i + 1, c.fitness, steps / ours, steps / raw, raw / ours,
                *std::min_element(per_run.begin(), per_run.end()), *std::max_element(per_run.begin(), per_run.end()),
                c.ours_contacts, c.raw_contacts);
    std::printf("  CPU-s per 600 s evaluation: ours min %.3f, median %.3f, max %.3f (%.3f evaluations/s); "
                "raw ODE min %.3f, median %.3f, max %.3f\n",
                scale * quantile(c.ours_t, 0), scale * ours, scale * quantile(c.ours_t, 1), 1 / (scale * ours),
                scale * quantile(c.raw_t, 0), scale * raw, scale * quantile(c.raw_t, 1));
    std::fflush(stdout);
    cpu_600.push_back(scale * ours);
    ratios.push_back(raw / ours);
  }
  const double cpu = median(cpu_600);
  std::printf("goal (a 600 s evaluation in at most 1 CPU-s): %s, %.3f CPU-s (%.2f evaluations/s)\n",
              cpu <= 1 ? "met" : "not met", cpu, 1 / cpu);
  std::printf("cpu_s_per_600s_evaluation: %.3f\n", cpu);
  std::printf("ratio_vs_raw_ode: %.3f\n", *std::min_element(ratios.begin(), ratios.end()));
  // a raw run that differs does other physics work: its figures mean nothing
  return different ? 1 : 0;
}
