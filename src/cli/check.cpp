// `bestiary check`: re-evaluates a creature as it was scored, then under
// other physics seeds, smaller steps, more solver iterations, a lagging motor,
// a slower brain, with its effectors held at their means and twice as long,
// and says whether its fitness is physics or
// artefact (src/eval/check.h, docs/physics.md).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "cli/commands.h"
#include "cli/creature.h"
#include "core/files.h"
#include "eval/check.h"
#include "eval/records_json.h"
#include "genome/json_text.h"
#include "run/run.h"
#include "io/config.h"
#include "io/run_store.h"

namespace bx {

namespace {

namespace fs = std::filesystem;

/// Arguments of `bestiary check`.
struct CheckArgs {
  std::string target;  ///< a genome file or a run's creature (cli/creature.h)
  CreatureFlags flags;
  bool json = false;
};

std::string ratio_text(double r) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", r);
  return buf;
}

int cmd_check(const CheckArgs& a) {
  auto subject = resolve_creature(a.target, a.flags);
  if (!subject) return fail(subject.error());
  const SimConfig& sim = subject->cfg.sim;
  if (!has_body(sim.creature)) return fail(no_body(sim.creature, "nothing to check"));
  auto creature = subject->develop();
  if (!creature) return fail(subject->label + ": not viable: " + creature.error());
  const CreatureModel& m = *creature->body;
  if (!a.json)
    std::fprintf(stderr, "checking %s: %d parts, %zu effectors, seed %llu ...\n", subject->label.c_str(),
                 m.n_parts(), m.effectors.size(), static_cast<unsigned long long>(subject->seed));
  if (!a.json && !subject->settings.empty()) std::fprintf(stderr, "%s\n", subject->settings.c_str());
  // a run's elite: its other seeds against the score selection saw (mean or least)
  // (or, where its run measured it, against what it scored where selection never looked)
  CheckReport rep = check_creature(*creature, sim, subject->seed, subject->cfg.check, subject->repeats(),
                                   subject->scored_settings ? subject->held_out : std::nullopt);
  const EvalResult& s = rep.scored;
  const EvalDiagnostics& d = s.diagnostics;

  if (a.json) {
    nlohmann::json out;
    out["subject"] = subject->label;
    out["seed"] = subject->seed;
    out["fitness"] = s.fitness;
    out["scored_fitness"] = rep.scored_fitness;
    if (!rep.scored_by_seed.empty()) out["scored_by_seed"] = rep.scored_by_seed;
    if (rep.held_out) out["held_out"] = held_out_to_json(*rep.held_out);
    out["stored_fitness"] = subject->stored_fitness ? nlohmann::json(*subject->stored_fitness) : nlohmann::json(nullptr);
    out["failed"] = s.failed;
    out["failure"] = s.failure;
    for (const auto& v : rep.variants)
      out["variants"].push_back({{"name", v.name}, {"fitness", v.result.fitness}, {"ratio", v.ratio},
                                 {"gate", v.gate}, {"failed", v.result.failed}, {"failure", v.result.failure},
                                 {"seed_fitness", v.seed_fitness}, {"slack", v.slack}});
    out["other_seeds"] = rep.other_seeds;  // the ratio, their median or mean:
    out["other_seeds_statistic"] = statistic_name(subject->cfg.check.other_seeds_statistic);
    // ratios of the gain over doing nothing, where doing nothing scores
    out["idle"] = rep.basis.idle_scores ? nlohmann::json(rep.idle) : nlohmann::json(nullptr);
    out["posture"] = rep.basis.posture;
    out["effector_mean"] = d.effector_mean;
    out["effector_sd"] = d.effector_sd;
    out["effector_hz"] = d.effector_hz;
    out["brain_hz"] = sim.brain_hz;
    out["buzzer"] = rep.buzzer;
    out["open_loop"] = rep.open_loop;
    if (rep.sustained >= 0)
      out["sustained"] = {{"ratio", rep.sustained}, {"first_third", rep.sustained_first}, {"last_third", rep.sustained_last}};
    out["max_joint_gap"] = d.max_joint_gap;
    out["worst_joint"] = d.worst_joint;
    out["max_stop_overshoot"] = d.max_stop_overshoot;
    out["max_penetration"] = d.max_penetration;
    out["passed"] = rep.passed();
    out["failures"] = rep.failures;
    out["notes"] = rep.notes;
    if (rep.clamped_end_travel >= 0) out["clamped_end_travel"] = rep.clamped_end_travel;
    std::printf("%s\n", json_text(out).c_str());
    return rep.passed() ? 0 : 1;
  }

  std::printf("%s: fitness %.6g", subject->label.c_str(), s.fitness);
  if (subject->stored_fitness) std::printf(" (stored %.6g)", *subject->stored_fitness);
  std::printf(", seed %llu\n", static_cast<unsigned long long>(subject->seed));
  if (s.failed) std::printf("  failed: %s\n", s.failure.c_str());
  if (!rep.scored_by_seed.empty()) {
    // other seeds are compared with what selection saw
    const std::string halves = finer_step_text(subject->repeats());
    std::printf("  scored as the %s of %zu evaluations%s:", score_name(sim.trial_score), rep.scored_by_seed.size(),
                halves.empty() ? "" : (" (" + halves + ")").c_str());
    for (double f : rep.scored_by_seed) std::printf(" %.4g", f);
    std::printf(" = %.6g%s\n", rep.scored_fitness, rep.held_out ? "" : " (other seeds' ratios are to this)");
  }
  if (rep.held_out)
    std::printf("  held out: the %s of %zu evaluations under seeds its run never used = %.6g (other seeds' ratios "
                "are to this: what selection saw overstates a creature kept for it)\n",
                score_name(sim.trial_score), rep.held_out->by_seed.size(), rep.held_out->fitness);
  if (rep.basis.idle_scores)
    std::printf("  doing nothing (every joint held) scores %.6g: each ratio below is of the gain over it\n", rep.idle);
  int width = 0;  // the names in one column
  for (const auto& v : rep.variants) width = std::max(width, static_cast<int>(v.name.size()));
  for (const auto& v : rep.variants) {
    std::printf("  %-*s fitness %-12.6g ratio %-7s gate %s", width, v.name.c_str(), v.result.fitness,
                ratio_text(v.ratio).c_str(), v.gate.c_str());
    if (v.result.failed) std::printf("  (failed: %s)", v.result.failure.c_str());
    if (!v.seed_fitness.empty()) {
      std::printf("  by seed:");
      for (double f : v.seed_fitness) std::printf(" %.4g", f);
    }
    std::printf("\n");
  }
  if (subject->cfg.check.other_seeds > 0)
    std::printf("  other seeds: %s ratio %s\n",
                statistic_name(subject->cfg.check.other_seeds_statistic),
                ratio_text(rep.other_seeds).c_str());
  else
    std::printf("  other seeds: none (check.other_seeds = 0)\n");
  if (rep.sustained >= 0)
    std::printf("  twice as long: last third travels %.3f of the first (%.3g m against %.3g m)\n", rep.sustained,
                rep.sustained_last, rep.sustained_first);
  std::printf("  effector activity (s.d. of each signal while driven):");
  for (double sd : d.effector_sd) std::printf(" %.3f", sd);
  if (d.effector_sd.empty()) std::printf(" none");
  std::printf("\n  dominant frequency of each signal (Hz; the brain runs at %.4g Hz):", sim.brain_hz);
  for (double hz : d.effector_hz) std::printf(" %.3g", hz);
  if (d.effector_hz.empty()) std::printf(" none");
  std::printf("\n  largest joint separation %.2f mm", 1000 * d.max_joint_gap);
  if (d.worst_joint >= 0) std::printf(" (joint %d)", d.worst_joint);
  std::printf(", stop overshoot %.3f (rad, or m for a slider), deepest interpenetration %.2f mm\n",
              d.max_stop_overshoot, 1000 * d.max_penetration);
  std::printf("  (ratio: each variant's fitness over the scored one; clamped: every effector held at its mean "
              "signal, so constant signals must not travel; held: every joint held still by its motor; stop "
              "overshoot: how far any joint went past its limit)\n");
  for (const auto& n : rep.notes) std::printf("note: %s\n", n.c_str());
  if (rep.passed()) {
    std::printf("verdict: pass\n");
    return 0;
  }
  std::printf("verdict: FAIL:");
  for (std::size_t k = 0; k < rep.failures.size(); ++k)
    std::printf("%s %s", k ? ";" : "", rep.failures[k].c_str());
  std::printf("\n");
  return 1;
}

}  // namespace

void add_check_command(CLI::App& app) {
  static CheckArgs a;
  auto* c = app.add_subcommand(
      "check", "Re-evaluate a creature under other seeds, smaller steps, lagging motors, a slower brain and clamped effectors");
  add_creature_options(c, a.target, a.flags);
  c->add_flag("--json", a.json, "Print one JSON object");
  c->footer("Exit code 0: passed the gates ([check] config keys); 1: failed them; 2: bad input.");
  c->callback([] { std::exit(cmd_check(a)); });
}

}  // namespace bx
