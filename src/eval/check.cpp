#include "eval/check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/rng.h"

namespace bx {

namespace {

// the stream of check seeds (evolution.cpp's streams are 1-4, trials' 5)
constexpr std::uint64_t kCheckStream = 6;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n == 0 ? 0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string fixed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

std::string share(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

}  // namespace

std::uint64_t check_seed(std::uint64_t seed, int k) {
  return stream_seed({seed, kCheckStream, static_cast<std::uint64_t>(k)});
}

CheckReport check_creature(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed,
                           const CheckDef& def, const Repeats& repeats) {
  CheckReport rep;
  rep.scored = evaluate(m, cfg, seed);
  const double scored = rep.scored.fitness;
  // what selection saw: the mean (or least) over the creature's evaluations, folded as the run folded them
  rep.scored_fitness =
      repeats.evaluations > 1 ? repeated_fitness(m, cfg, seed, repeats, rep.scored, &rep.scored_by_seed) : scored;
  auto ratio = [](double f, double of) { return of > 0 ? f / of : 0; };
  auto run = [&](std::string name, const SimConfig& c, std::uint64_t s, double of, Replay* frames = nullptr) {
    CheckVariant v{std::move(name), evaluate(m, c, s, frames), 0, {}};
    v.ratio = ratio(v.result.fitness, of);
    rep.variants.push_back(std::move(v));
    return rep.variants.back().ratio;
  };

  // other physics seeds: their median, so one lucky or unlucky seed does not decide
  std::vector<double> seeds;
  for (int k = 1; k <= def.other_seeds; ++k)
    seeds.push_back(run("seed " + std::to_string(k + 1), cfg, check_seed(seed, k), rep.scored_fitness));
  if (!seeds.empty()) rep.median_other_seeds = median(seeds);

  // convergence: smaller steps, a better solved step; with converge_seeds > 1
  // each by its median over those seeds against the median at dt over them
  const int ks = std::max(1, def.converge_seeds);
  std::vector<double> at_dt{scored};
  for (int k = 1; k < ks; ++k)
    at_dt.push_back(k <= def.other_seeds ? rep.variants[k - 1].result.fitness
                                         : evaluate(m, cfg, check_seed(seed, k)).fitness);
  const double base = median(at_dt);
  std::vector<std::pair<std::string, double>> converged;
  auto converge = [&](const std::string& name, const SimConfig& c) {
    if (ks == 1) return converged.push_back({name, run(name, c, seed, scored)});
    CheckVariant v{name + " (median of " + std::to_string(ks) + " seeds)", evaluate(m, c, seed), 0, {}};
    std::vector<double> f{v.result.fitness};
    for (int k = 1; k < ks; ++k) f.push_back(evaluate(m, c, check_seed(seed, k)).fitness);
    v.seed_fitness = f;
    v.result.fitness = median(f);
    v.ratio = ratio(v.result.fitness, base);
    rep.variants.push_back(v);
    converged.push_back({v.name, v.ratio});
  };
  for (int div : {2, 4}) {
    SimConfig c = cfg;
    c.physics.dt /= div;
    converge("dt/" + std::to_string(div), c);
  }
  {
    SimConfig c = cfg;
    c.physics.solver_iterations *= 2;
    converge("2x iterations", c);
  }
  // the effectors held at their means: sustained motion without a changing
  // signal is paid for by constraint error, not by the motors; a motion that
  // ends (one stroke, a topple) is named in a note, not failed
  // (a creature without effectors, or never driven, has nothing to clamp or
  // hold: whatever it does is passive, and both keep all of it)
  double clamped = -1;
  {
    SimConfig c = cfg;
    c.effector_clamp = rep.scored.diagnostics.effector_mean;
    const bool none = c.effector_clamp.empty();
    // its frames say where its centre of mass went over the last rest_seconds
    Replay frames;
    clamped = run(none ? "clamped (no effector driven)" : "clamped", c, seed, scored,
                  def.rest_seconds > 0 ? &frames : nullptr);
    if (!frames.frames.empty()) {
      const ReplayFrame& last = frames.frames.back();
      auto from = std::find_if(frames.frames.begin(), frames.frames.end(),
                               [&](const ReplayFrame& f) { return f.t >= last.t - def.rest_seconds - 1e-9; });
      if (from != frames.frames.begin() && last.t - from->t >= def.rest_seconds - 1e-6)
        rep.clamped_end_travel = std::hypot(last.com.x - from->com.x, last.com.y - from->com.y) / m.body_length();
    }
  }
  // every joint held still, the controller still acting on the task (a
  // catapult's release): a throw that keeps its distance is a fall
  double held = -1;
  {
    SimConfig c = cfg;
    c.hold_joints = true;
    held = run(m.effectors.empty() ? "held (no effectors)" : "held", c, seed, scored);
  }

  if (held > kPassiveHeld)
    rep.notes.push_back("mostly passive: with its joints held it keeps " + fixed(held) +
                        " of its fitness (a fall, not a swing)");

  // the gates
  if (!(scored > 0) || !(rep.scored_fitness > 0)) {
    rep.failures.push_back("the scored fitness " + fixed(std::min(scored, rep.scored_fitness)) + " is not positive");
    return rep;
  }
  if (!seeds.empty() && rep.median_other_seeds < def.min_other_seeds)
    rep.failures.push_back("other seeds keep " + fixed(rep.median_other_seeds) + " (median) < " +
                           fixed(def.min_other_seeds));
  for (const auto& [name, ratio] : converged)
    if (ratio < def.min_converged)
      rep.failures.push_back(name + " keeps " + fixed(ratio) + " < " + fixed(def.min_converged));
  if (clamped > def.max_clamped) {
    const std::string keep = "clamped effectors keep " + fixed(clamped);
    const std::string window = "in its last " + fixed(def.rest_seconds) + " s";
    if (rep.clamped_end_travel >= 0 && rep.clamped_end_travel < kRestTravel)
      rep.notes.push_back("a transient, not a gait: " + keep + " of its fitness, then rest (" +
                          share(rep.clamped_end_travel) + " of its length " + window +
                          "): a slow stroke of its servos or a topple");
    else
      rep.failures.push_back(keep + " > " + fixed(def.max_clamped) +
                             (rep.clamped_end_travel >= 0
                                  ? ", still moving (" + share(rep.clamped_end_travel) + " of its length " + window + ")"
                                  : ""));
  }
  if (held > def.max_held)
    rep.failures.push_back("held joints keep " + fixed(held) + " > " + fixed(def.max_held));
  return rep;
}

}  // namespace bx
