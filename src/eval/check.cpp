#include "eval/check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/rng.h"
#include "eval/task_table.h"

namespace bx {

namespace {

// the stream of check seeds (evolution.cpp's streams are 1-4, trials' 5)
constexpr std::uint64_t kCheckStream = 6;

double mean(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return v.empty() ? 0 : sum / static_cast<double>(v.size());
}

// the standard error of the mean of v (0 for fewer than two)
double standard_error(const std::vector<double>& v) {
  const std::size_t n = v.size();
  if (n < 2) return 0;
  const double m = mean(v);
  double ss = 0;
  for (double x : v) ss += (x - m) * (x - m);
  return std::sqrt(ss / static_cast<double>(n - 1) / static_cast<double>(n));
}

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

// The first frame at or after time t (the last frame when none is).
const ReplayFrame& frame_at(const Replay& r, double t) {
  auto f = std::find_if(r.frames.begin(), r.frames.end(), [&](const ReplayFrame& x) { return x.t >= t - 1e-9; });
  return f == r.frames.end() ? r.frames.back() : *f;
}

// How far the centre of mass moved in the plane between two frames (m).
double plane_travel(const ReplayFrame& a, const ReplayFrame& b) {
  return std::hypot(b.com.x - a.com.x, b.com.y - a.com.y);
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

CheckReport check_creature(const Creature& creature, const SimConfig& cfg, std::uint64_t seed, const CheckDef& def,
                           const Repeats& repeats, const std::optional<HeldOut>& held_out) {
  const CreatureModel& m = *creature.body;
  CheckReport rep;
  {
    SimConfig c = cfg;
    c.effector_spectrum = true;  // each effector's dominant frequency
    rep.scored = evaluate(creature, c, seed);
  }
  const double scored = rep.scored.fitness;
  // what selection saw: the mean (or least) over the creature's evaluations, folded as the run folded them
  rep.scored_fitness =
      repeats.evaluations > 1 ? repeated_fitness(creature, cfg, seed, repeats, rep.scored, &rep.scored_by_seed) : scored;
  // a task at which doing nothing scores: every ratio is of the gain over
  // the creature's score with every joint held (its idle score)
  const TaskRow& row = task_row(cfg.task_kind);
  rep.basis = row.check_basis ? row.check_basis(cfg) : CheckBasis{};
  double idle = 0;
  auto ratio = [&](double f, double of) { return of - idle > 0 ? (f - idle) / (of - idle) : 0; };
  auto run = [&](std::string name, const SimConfig& c, std::uint64_t s, double of, Replay* frames = nullptr) {
    CheckVariant v{std::move(name), evaluate(creature, c, s, frames), 0, {}, {}};
    v.ratio = ratio(v.result.fitness, of);
    rep.variants.push_back(std::move(v));
    return rep.variants.back().ratio;
  };
  auto held_config = [&] {
    SimConfig c = cfg;
    c.hold_joints = true;
    return c;
  };
  double held = -1;
  if (rep.basis.idle_scores) {
    // measured first: the ratios below need it
    held = run("held: doing nothing", held_config(), seed, scored);
    rep.idle = idle = rep.variants.back().result.fitness;
    rep.variants.back().ratio = 0;
  }

  // other physics seeds: their median, so one lucky or unlucky seed does
  // not decide, or their mean (a rare large score counts as a mean fitness counts it)
  // (against the held-out measure where there is one: both are fresh worlds)
  rep.held_out = held_out;
  const double reference = held_out ? held_out->fitness : rep.scored_fitness;
  const std::size_t first_seed = rep.variants.size();
  for (int k = 1; k <= def.other_seeds; ++k) run("seed " + std::to_string(k + 1), cfg, check_seed(seed, k), reference);
  // the other seeds' variants' ratios or fitnesses
  auto of_seeds = [&](auto field) {
    std::vector<double> v;
    for (std::size_t k = first_seed; k < first_seed + static_cast<std::size_t>(def.other_seeds); ++k)
      v.push_back(field(rep.variants[k]));
    return v;
  };
  const bool by_mean = def.other_seeds_statistic == SeedStatistic::Mean;
  const char* statistic = statistic_name(def.other_seeds_statistic);
  auto combine = [&](const std::vector<double>& v) { return by_mean ? mean(v) : median(v); };
  // under the mean: two standard errors of the difference of the means of
  // `a` and of `b` (each fitness), as a share of `of`'s gain over idle
  auto slack = [&](const std::vector<double>& a, const std::vector<double>& b, double of) {
    if (!by_mean || !(of - idle > 0)) return 0.0;
    return 2 * std::hypot(standard_error(a), standard_error(b)) / (of - idle);
  };
  double seeds_slack = 0;
  if (def.other_seeds > 0) {
    rep.other_seeds = combine(of_seeds([](const CheckVariant& v) { return v.ratio; }));
    // against the held-out evaluations, or those that scored it (one alone: no spread to know)
    seeds_slack = slack(of_seeds([](const CheckVariant& v) { return v.result.fitness; }),
                        held_out ? held_out->by_seed : rep.scored_by_seed, reference);
    for (std::size_t k = first_seed; k < rep.variants.size(); ++k) rep.variants[k].slack = seeds_slack;
    // the same signals under every seed: an open loop
    const EvalDiagnostics& own = rep.scored.diagnostics;
    rep.open_loop = !own.effector_mean.empty();
    for (std::size_t k = first_seed; k < rep.variants.size(); ++k) {
      const EvalDiagnostics& d = rep.variants[k].result.diagnostics;
      rep.open_loop = rep.open_loop && d.effector_mean == own.effector_mean && d.effector_sd == own.effector_sd;
    }
    if (rep.open_loop)
      rep.notes.push_back("open loop: under all " + std::to_string(def.other_seeds) +
                          " other seeds its effector signals are the scored run's, bit for bit: nothing the seeds "
                          "change (where they draw its world, what it meets there) reaches its controller");
  }

  // the same creature under another config (a smaller step, a better solved
  // step, a slower motor, a slower brain); with converge_seeds > 1 each by its
  // median (mean) over those seeds against the same at dt over them
  const int ks = std::max(1, def.converge_seeds);
  std::vector<double> at_dt{scored};
  for (int k = 1; k < ks; ++k)
    at_dt.push_back(k <= def.other_seeds ? rep.variants[first_seed + k - 1].result.fitness
                                         : evaluate(creature, cfg, check_seed(seed, k)).fitness);
  const double base = combine(at_dt);
  auto compare = [&](const std::string& name, const SimConfig& c) {
    if (ks == 1) return run(name, c, seed, scored);
    CheckVariant v{name + " (" + statistic + " of " + std::to_string(ks) + " seeds)", evaluate(creature, c, seed), 0,
                   {}, {}};
    std::vector<double> f{v.result.fitness};
    for (int k = 1; k < ks; ++k) f.push_back(evaluate(creature, c, check_seed(seed, k)).fitness);
    v.seed_fitness = f;
    v.result.fitness = combine(f);
    v.ratio = ratio(v.result.fitness, base);
    v.slack = slack(f, at_dt, base);
    rep.variants.push_back(v);
    return v.ratio;
  };
  // a variant as the gates read it: its name without "(mean of N seeds)", its ratio and slack
  struct Judged {
    std::string name;
    double ratio, slack;
  };
  auto judged = [&](const std::string& name, const SimConfig& c) {
    compare(name, c);
    return Judged{name, rep.variants.back().ratio, rep.variants.back().slack};
  };
  std::vector<Judged> converged;
  for (int div : {2, 4}) converged.push_back(judged("dt/" + std::to_string(div), divided_step_config(cfg, div)));
  if (cfg.physics.solver == Solver::QuickStep) {  // the exact solver has no iterations to double
    SimConfig c = cfg;
    c.physics.solver_iterations *= 2;
    converged.push_back(judged("2x iterations", c));
  }
  // what a real actuator imposes: a motor that lags its command, a brain at
  // half its rate; a fitness earned by flipping signals at the brain's rate
  // does not survive them (a buzzer)
  // (a creature without effectors has no actuator to slow: neither is made)
  std::vector<std::string> buzz;
  const bool actuated = !m.effectors.empty();
  if (actuated && def.motor_lag > 0) {
    SimConfig c = cfg;
    c.motor.response_time += def.motor_lag;
    const std::string name = "motor lag +" + fixed(1000 * def.motor_lag) + " ms";
    const auto [_, r, sl] = judged(name, c);
    if (r < def.min_motor_lag - sl)
      buzz.push_back("with its motors lagging " + fixed(1000 * def.motor_lag) + " ms more it keeps " + fixed(r) +
                     " < " + fixed(def.min_motor_lag));
  }
  if (actuated && def.min_half_rate > 0) {
    SimConfig c = cfg;
    c.brain_hz /= 2;
    const std::string name = "brain at " + fixed(c.brain_hz) + " Hz";
    const auto [_, r, sl] = judged(name, c);
    if (r < def.min_half_rate - sl)
      buzz.push_back("with its brain at half its rate (" + fixed(c.brain_hz) + " Hz) it keeps " + fixed(r) + " < " +
                     fixed(def.min_half_rate));
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
      const ReplayFrame& from = frame_at(frames, last.t - def.rest_seconds);
      if (&from != &frames.frames.front() && last.t - from.t >= def.rest_seconds - 1e-6)
        rep.clamped_end_travel = plane_travel(from, last) / m.body_length();
    }
  }
  // every joint held still, the controller still acting on the task (a
  // catapult's release): a throw that keeps its distance is a fall
  if (!rep.basis.idle_scores)
    held = run(m.effectors.empty() ? "held (no effectors)" : "held", held_config(), seed, scored);
  // locomotion twice as long: does the gait go on?
  std::string sustained_failure;
  if (cfg.task_kind == TaskKind::Locomotion && def.min_sustained > 0) {
    SimConfig c = cfg;
    c.task.seconds *= 2;
    Replay frames;
    const EvalResult r = evaluate(creature, c, seed, &frames);
    if (r.failed) {
      sustained_failure = "twice as long (" + fixed(c.task.seconds) + " s) it fails: " + r.failure;
    } else if (frames.frames.size() >= 3) {
      const ReplayFrame &first = frames.frames.front(), &last = frames.frames.back();
      const double third = (last.t - first.t) / 3;
      rep.sustained_first = plane_travel(first, frame_at(frames, first.t + third));
      rep.sustained_last = plane_travel(frame_at(frames, last.t - third), last);
      rep.sustained = rep.sustained_first > 0 ? rep.sustained_last / rep.sustained_first : 0;
      // a creature that hardly moved in the first third has no gait to fade
      if (rep.sustained_first >= kSustainedFrom * m.body_length() && rep.sustained < def.min_sustained)
        sustained_failure = "not sustained: twice as long (" + fixed(c.task.seconds) + " s), its last third travels " +
                            share(rep.sustained) + " of its first (" + fixed(rep.sustained_last) + " m against " +
                            fixed(rep.sustained_first) + " m) < " + fixed(def.min_sustained);
    }
  }

  // each variant's gate, in words, for the report
  for (CheckVariant& v : rep.variants) {
    const auto starts = [&](const char* p) { return v.name.rfind(p, 0) == 0; };
    // a gate widened by the noise of the mean: "0.75 - 0.31"
    const auto low = [&](double g) { return fixed(g) + (v.slack > 0 ? " - " + fixed(v.slack) : ""); };
    const auto high = [&](double g) { return fixed(g) + (v.slack > 0 ? " + " + fixed(v.slack) : ""); };
    if (starts("seed "))
      v.gate = std::string("their ") + statistic + " >= " + low(def.min_other_seeds);
    else if (starts("dt/") || starts("2x iterations"))
      v.gate = "in [" + low(def.min_converged) + ", " + high(def.max_converged) + "]";
    else if (starts("motor lag"))
      v.gate = ">= " + low(def.min_motor_lag);
    else if (starts("brain at"))
      v.gate = ">= " + low(def.min_half_rate);
    else if (starts("held: doing nothing"))
      v.gate = "none: the idle score the ratios subtract";
    else if (starts("clamped"))
      v.gate = rep.basis.posture ? "none: a posture task"
                                 : "<= " + fixed(def.max_clamped) + ", or at rest over its last " +
                                       fixed(def.rest_seconds) + " s";
    else if (starts("held"))
      v.gate = "<= " + fixed(def.max_held);
  }
  if (rep.basis.idle_scores)
    rep.notes.push_back("doing nothing (every joint held) scores " + fixed(idle) +
                        ": every ratio is of the gain over it, (fitness - " + fixed(idle) + ") / (scored - " +
                        fixed(idle) + ")");
  else if (held > kPassiveHeld)
    rep.notes.push_back("mostly passive: with its joints held it keeps " + fixed(held) +
                        " of its fitness (a fall, not a swing)");
  if (rep.basis.posture)
    rep.notes.push_back("a posture task, whose highest point constant signals may reach (a pose held, or the swing "
                        "as the muscles come on): the clamped gate does not apply");

  // the gates
  if (rep.basis.idle_scores && !(std::min(scored, rep.scored_fitness) > idle)) {
    rep.failures.push_back("the scored fitness " + fixed(std::min(scored, rep.scored_fitness)) +
                           " is no more than doing nothing's " + fixed(idle) + " (every joint held)");
    return rep;
  }
  if (!(scored > 0) || !(rep.scored_fitness > 0)) {
    rep.failures.push_back("the scored fitness " + fixed(std::min(scored, rep.scored_fitness)) + " is not positive");
    return rep;
  }
  // (under the mean, each gate less the noise of so few evaluations: "(mean, less 2 s.e. 0.31)")
  const auto less = [](double sl) { return sl > 0 ? " less 2 s.e. " + fixed(sl) : std::string(); };
  if (def.other_seeds > 0 && rep.other_seeds < def.min_other_seeds - seeds_slack)
    rep.failures.push_back("other seeds keep " + fixed(rep.other_seeds) + " (" + statistic + ") < " +
                           fixed(def.min_other_seeds) + less(seeds_slack));
  for (const Judged& c : converged) {
    if (c.ratio < def.min_converged - c.slack)
      rep.failures.push_back(c.name + " keeps " + fixed(c.ratio) + " < " + fixed(def.min_converged) + less(c.slack));
    else if (c.ratio > def.max_converged + c.slack)
      rep.failures.push_back(c.name + " rises to " + fixed(c.ratio) + " > " + fixed(def.max_converged) +
                             (c.slack > 0 ? " plus 2 s.e. " + fixed(c.slack) : "") +
                             " (not converged: the fitness grows as the step shrinks)");
  }
  if (!buzz.empty()) {
    rep.buzzer = true;
    std::string what = "a buzzer (its signals' dominant frequencies";
    for (std::size_t e = 0; e < rep.scored.diagnostics.effector_hz.size(); ++e)
      what += (e ? ", " : " ") + fixed(rep.scored.diagnostics.effector_hz[e]);
    what += " Hz, its brain at " + fixed(cfg.brain_hz) + " Hz): ";
    for (std::size_t k = 0; k < buzz.size(); ++k) what += (k ? "; " : "") + buzz[k];
    rep.failures.push_back(what);
  }
  if (clamped > def.max_clamped && !rep.basis.posture) {
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
  if (!rep.basis.idle_scores && held > def.max_held)
    rep.failures.push_back("held joints keep " + fixed(held) + " > " + fixed(def.max_held));
  if (!sustained_failure.empty()) rep.failures.push_back(sustained_failure);
  return rep;
}

}  // namespace bx
