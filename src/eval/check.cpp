#include "eval/check.h"

#include <algorithm>
#include <cstdio>

#include "core/rng.h"

namespace bx {

namespace {

// the stream of check seeds (evolution.cpp's streams are 1-4, trials' 5)
constexpr std::uint64_t kCheckStream = 6;

std::string fixed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

std::uint64_t check_seed(std::uint64_t seed, int k) {
  return stream_seed({seed, kCheckStream, static_cast<std::uint64_t>(k)});
}

CheckReport check_creature(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed,
                           const CheckDef& def) {
  CheckReport rep;
  rep.scored = evaluate(m, cfg, seed);
  const double scored = rep.scored.fitness;
  auto run = [&](std::string name, const SimConfig& c, std::uint64_t s) {
    CheckVariant v{std::move(name), evaluate(m, c, s), 0};
    v.ratio = scored > 0 ? v.result.fitness / scored : 0;
    rep.variants.push_back(std::move(v));
    return rep.variants.back().ratio;
  };

  // other physics seeds: their median, so one lucky or unlucky seed does not decide
  std::vector<double> seeds;
  for (int k = 1; k <= def.other_seeds; ++k)
    seeds.push_back(run("seed " + std::to_string(k + 1), cfg, check_seed(seed, k)));
  if (!seeds.empty()) {
    std::sort(seeds.begin(), seeds.end());
    std::size_t n = seeds.size();
    rep.median_other_seeds = n % 2 ? seeds[n / 2] : 0.5 * (seeds[n / 2 - 1] + seeds[n / 2]);
  }
  // convergence: smaller steps, a better solved step
  std::vector<std::pair<std::string, double>> converged;
  for (int div : {2, 4}) {
    SimConfig c = cfg;
    c.physics.dt /= div;
    std::string name = "dt/" + std::to_string(div);
    converged.push_back({name, run(name, c, seed)});
  }
  {
    SimConfig c = cfg;
    c.physics.solver_iterations *= 2;
    converged.push_back({"2x iterations", run("2x iterations", c, seed)});
  }
  // the effectors held at their means: motion without a changing signal is
  // paid for by constraint error, not by the motors
  double clamped = -1;
  if (!rep.scored.diagnostics.effector_mean.empty()) {
    SimConfig c = cfg;
    c.effector_clamp = rep.scored.diagnostics.effector_mean;
    clamped = run("clamped", c, seed);
  }

  // the gates
  if (!(scored > 0)) {
    rep.failures.push_back("the scored fitness " + fixed(scored) + " is not positive");
    return rep;
  }
  if (!seeds.empty() && rep.median_other_seeds < def.min_other_seeds)
    rep.failures.push_back("other seeds keep " + fixed(rep.median_other_seeds) + " (median) < " +
                           fixed(def.min_other_seeds));
  for (const auto& [name, ratio] : converged)
    if (ratio < def.min_converged)
      rep.failures.push_back(name + " keeps " + fixed(ratio) + " < " + fixed(def.min_converged));
  if (clamped > def.max_clamped)
    rep.failures.push_back("clamped effectors keep " + fixed(clamped) + " > " + fixed(def.max_clamped));
  return rep;
}

}  // namespace bx
