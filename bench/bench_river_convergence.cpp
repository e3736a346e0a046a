// bench_river_convergence: what the river crossing's physics step and solver
// buy and cost (docs/benchmarks.md). Random controllers walk the quadruped
// for 10 s under several steps and solvers; each walk's torso trajectory is
// compared with a reference walk at a much finer step, and each setting's
// cost is measured as CPU-s per 600 s evaluation.
//
//   reference   the exact solver (dWorldStep) at 0.01 s / 8, ERP and CFM
//               given at 0.01 s (physics.erp_cfm_dt: the same joint and
//               contact springs at every step, so only the integration
//               differs)
//   rows        the exact solver at 1/16, 1/4 and 1/2 of 0.01 s and at
//               0.02 s (ERP and CFM given at 0.01 s); at 0.005 s with ERP and
//               CFM per step; the river's own setting (exact, 0.01 s);
//               QuickStep at several iteration counts at 0.01 s (ERP and CFM
//               per step, the river's) and 0.02 s (given at 0.01 s); and the
//               river's setting with its start turned by a millionth more,
//               against the river's setting: how much a change far below
//               any step's error grows in a walk
//
// Per row: CPU-s per 600 s evaluation (the best of 3 timed 10 s evaluations,
// times 60, setup included), how far the torso's centre ends from the
// reference's at 10 s and at most over the walk (cell widths; the median and
// the largest over the creatures), the largest joint gap and the deepest
// contact of any walk (cell widths), and the creatures that failed (the
// first failure's message below the row). The
// controller runs closed-loop, as in an evaluation. Exit code 0; 2 on a bad
// argument.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "args.h"
#include "core/rng.h"
#include "eval/creature.h"
#include "eval/evaluate.h"
#include "eval/sim_config.h"
#include "genome/float_vector.h"
#include "geometry/ode.h"
#include "raw_ode.h"  // cpu_seconds, median

namespace {

using namespace bx;
using namespace bx::bench;

struct Variant {
  std::string name;
  Solver solver = Solver::Exact;
  int iterations = 20;
  double dt = 0.01;
  double erp_cfm_dt = 0.01;  ///< 0: ERP and CFM per step
  double yaw_scale = 1;      ///< start_yaw_jitter times this
  int versus = 0;            ///< the row whose walks it is compared with (0: the reference)
};

struct Walk {
  bool failed = false;
  std::string failure;
  std::vector<Vec3> torso;  ///< at 0, 0.1, ..., 10 s (cell widths)
  double gap = 0, depth = 0;  ///< largest joint gap and contact depth (cell widths)
};

struct Row {
  double cpu_600 = 0;
  std::vector<double> end_off, max_off;
  double gap = 0, depth = 0;
  int failed = 0;
  std::string failure;  ///< the first
};

SimConfig config_of(const SimConfig& base, const Variant& v) {
  SimConfig c = base;
  c.physics.solver = v.solver;
  c.physics.solver_iterations = v.iterations;
  c.physics.dt = v.dt;
  c.physics.erp_cfm_dt = v.erp_cfm_dt;
  c.start_yaw_jitter *= v.yaw_scale;
  return c;
}

Walk walk(const Creature& c, const SimConfig& cfg, std::uint64_t seed, double unit) {
  SimConfig rec = cfg;
  rec.replay_fps = 10;
  Replay replay;
  const EvalResult r = evaluate(c, rec, seed, &replay);
  Walk w;
  w.failed = r.failed;
  w.failure = r.failure;
  for (const ReplayFrame& f : replay.frames) w.torso.push_back((1 / unit) * Vec3{f.poses[0], f.poses[1], f.poses[2]});
  w.gap = r.diagnostics.max_joint_gap / unit;
  w.depth = r.diagnostics.max_penetration / unit;
  return w;
}

int usage(const char* msg) {
  if (msg) std::fprintf(stderr, "bench_river_convergence: %s\n", msg);
  std::fprintf(stderr,
               "usage: bench_river_convergence [--n N] [--seconds S] [--seed S]\n"
               "  the river quadruped's torso trajectory under several physics steps and solvers\n"
               "  against a reference at 0.01 s / 8, and each setting's CPU-s per 600 s evaluation\n"
               "  --n N        random controllers (default 8)\n"
               "  --seconds S  walk length (default 10)\n");
  return msg ? 2 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  int n = 8;
  double seconds = 10;
  std::uint64_t seed = 1;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](const char* name) {
      return bxbench::number_after(i, argc, argv, name, usage, [](double v) { return v > 0; }, "a positive number");
    };
    if (a == "--n") n = static_cast<int>(value("--n"));
    else if (a == "--seconds") seconds = value("--seconds");
    else if (a == "--seed") seed = static_cast<std::uint64_t>(value("--seed"));
    else if (a == "-h" || a == "--help") return usage(nullptr);
    else return usage(("unknown argument \"" + a + "\"").c_str());
  }
  ensure_ode_initialized();

  // the river crossing's config (docs/rivercrossing.md, "Physics")
  SimConfig base;
  apply_creature_kind(base, CreatureKind::River);  // the kind's physics, PD motors, task and brain rate
  base.river.task.seconds = seconds;
  const double unit = base.river.body.unit, h = base.physics.dt;

  std::vector<Variant> variants = {
      {"exact, dt/8 = 0.00125 s (the reference)", Solver::Exact, 20, h / 8},
      {"exact, dt/16 = 0.000625 s", Solver::Exact, 20, h / 16},
      {"exact, dt/4 = 0.0025 s", Solver::Exact, 20, h / 4},
      {"exact, dt/2 = 0.005 s", Solver::Exact, 20, h / 2},
      {"exact, 0.005 s, ERP and CFM per step", Solver::Exact, 20, h / 2, 0},
      {"exact, 0.01 s (the river's)", Solver::Exact, 20, h, 0},
      {"exact, 0.02 s", Solver::Exact, 20, 2 * h},
  };
  for (int it : {10, 20, 40, 80, 160})
    variants.push_back({"QuickStep " + std::to_string(it) + ", 0.01 s", Solver::QuickStep, it, h, 0});
  for (int it : {20, 40})
    variants.push_back({"QuickStep " + std::to_string(it) + ", 0.02 s", Solver::QuickStep, it, 2 * h});
  const int river_row = 5;  // exact, 0.01 s
  variants.push_back({"the river's, start turned 1e-6 more, vs the river's", Solver::Exact, 20, h, 0, 1 + 1e-6, river_row});

  // the creatures: random controllers, as bench_river draws them
  const FloatVectorDef box = creature_kind_row(base.creature).float_genes(base);
  std::vector<Creature> creatures;
  std::vector<std::uint64_t> seeds;
  for (int i = 0; i < n; ++i) {
    Rng rng(stream_seed({seed, 1, static_cast<std::uint64_t>(i)}));
    std::vector<double> g(static_cast<std::size_t>(box.length));
    for (double& x : g) x = rng.uniform(box.lo, box.hi);
    auto c = develop_creature(FloatVector(std::move(g)), base);
    if (!c) {
      std::fprintf(stderr, "bench_river_convergence: %s\n", c.error().c_str());
      return 2;
    }
    creatures.push_back(std::move(*c));
    seeds.push_back(stream_seed({seed, 2, static_cast<std::uint64_t>(i)}));
  }

  // every row's walks, the reference's first
  std::vector<std::vector<Walk>> walks(variants.size());
  for (int i = 0; i < n; ++i) walks[0].push_back(walk(creatures[i], config_of(base, variants[0]), seeds[i], unit));
  double travel = 0;  // the reference's median planar displacement
  {
    std::vector<double> d;
    for (const Walk& w : walks[0]) {
      const Vec3 m = w.torso.back() - w.torso.front();
      d.push_back(std::hypot(m.x, m.y));
    }
    travel = median(d);
  }
  std::printf("river quadruped, %d random controllers (seed %llu), %g s walks; torso offsets from the reference "
              "in cell widths (u = %g m); the reference's torso moves a median %.3f u in the plane\n",
              n, static_cast<unsigned long long>(seed), seconds, unit, travel);
  std::printf("%-52s %10s %22s %22s %9s %9s %6s\n", "setting", "CPU-s/600s", "off at end: med, max",
              "off at most: med, max", "gap (u)", "depth (u)", "failed");
  for (std::size_t vi = 0; vi < variants.size(); ++vi) {
    const Variant& v = variants[vi];
    const SimConfig cfg = config_of(base, v);
    const std::vector<Walk>& reference = walks[static_cast<std::size_t>(v.versus)];
    Row row;
    std::vector<double> times;
    for (int i = 0; i < n; ++i) {
      if (vi > 0) walks[vi].push_back(walk(creatures[i], cfg, seeds[i], unit));
      const Walk& w = walks[vi][static_cast<std::size_t>(i)];
      row.gap = std::max(row.gap, w.gap);
      row.depth = std::max(row.depth, w.depth);
      if (w.failed || reference[i].failed || w.torso.size() != reference[i].torso.size()) {
        ++row.failed;
        if (row.failure.empty()) row.failure = w.failed ? w.failure : "its reference failed";
        continue;
      }
      double most = 0;
      for (std::size_t k = 0; k < w.torso.size(); ++k) most = std::max(most, norm(w.torso[k] - reference[i].torso[k]));
      row.end_off.push_back(norm(w.torso.back() - reference[i].torso.back()));
      row.max_off.push_back(most);
      // cost: the best of 3 timed evaluations, no replay
      double best = 1e300;
      for (int r = 0; r < 3; ++r) {
        const double t0 = cpu_seconds();
        evaluate(creatures[i], cfg, seeds[i]);
        best = std::min(best, cpu_seconds() - t0);
      }
      times.push_back(best);
    }
    row.cpu_600 = times.empty() ? 0 : median(times) * 600 / seconds;
    auto med_max = [](const std::vector<double>& v) {
      char b[64];
      if (v.empty()) return std::string("-");
      std::snprintf(b, sizeof b, "%.2g, %.2g", median(v), *std::max_element(v.begin(), v.end()));
      return std::string(b);
    };
    char cost[32] = "-";
    if (!times.empty()) std::snprintf(cost, sizeof cost, "%.3f", row.cpu_600);
    std::printf("%-52s %10s %22s %22s %9.2g %9.2g %6d\n", v.name.c_str(), cost, med_max(row.end_off).c_str(),
                med_max(row.max_off).c_str(), row.gap, row.depth, row.failed);
    if (!row.failure.empty()) std::printf("    first failure: %s\n", row.failure.c_str());
    std::fflush(stdout);
  }
  return 0;
}
