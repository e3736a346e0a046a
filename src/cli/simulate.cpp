// `bestiary simulate`: grow one genome, simulate it, report, optionally replay.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "cli/commands.h"
#include "develop/develop.h"
#include "eval/evaluate.h"
#include "genome/dialect.h"
#include "genome/genome_json.h"
#include "io/config.h"
#include "io/replay_file.h"

namespace bx {

namespace {

/// Arguments of `bestiary simulate`.
struct SimulateArgs {
  std::string genome;
  std::string config;
  std::optional<double> seconds;
  std::uint64_t seed = 1;
  std::string replay;
  bool json = false;
};

// shortest text that reads back as the same double
std::string shortest(double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

int cmd_simulate(const SimulateArgs& a) {
  // inputs: genome, config, flags; all checked before any work
  auto genome = load_genome(a.genome);
  if (!genome) return fail(genome.error());
  SimConfig cfg = default_sim_config(*genome);
  if (!a.config.empty())
    if (Status s = apply_config_file(cfg, a.config); !s) return fail(s.error());
  if (a.seconds) {
    if (!(*a.seconds > 0) || !std::isfinite(*a.seconds) || *a.seconds > 1e6)
      return fail("--seconds: expected a number in (0, 1e6], got " + shortest(*a.seconds));
    task_seconds(cfg) = *a.seconds;
  }
  if (!a.replay.empty()) {
    // make the replay's folder now, so a bad path fails before the simulation
    auto dir = std::filesystem::path(a.replay).parent_path();
    std::error_code ec;
    if (!dir.empty()) std::filesystem::create_directories(dir, ec);
    if (ec || (!dir.empty() && !std::filesystem::is_directory(dir)))
      return fail("--replay: cannot create directory \"" + dir.string() + "\"" +
                  (ec ? " (" + ec.message() + ")" : ""));
  }

  // grow, then simulate
  Development dev = develop(*genome, cfg.develop);
  nlohmann::json out;
  out["genome"] = a.genome;
  out["seed"] = a.seed;
  out["viable"] = dev.viable();
  if (!dev.viable()) {
    out["reason"] = dev.reason;
    out["fitness"] = 0.0;
    out["distance"] = 0.0;
    out["warnings"] = nlohmann::json::array();
    if (a.json)
      std::printf("%s\n", out.dump().c_str());
    else
      std::printf("%s: not viable: %s\n", a.genome.c_str(), dev.reason.c_str());
    return 0;
  }
  const CreatureModel& m = *dev.model;
  Replay replay;
  EvalResult res = evaluate(m, cfg, a.seed, a.replay.empty() ? nullptr : &replay);
  if (!a.replay.empty()) {
    ReplayInfo info{a.genome, a.seed, cfg.physics.dt, cfg.physics.friction};
    if (Status s = save_replay(a.replay, m, replay, res, info); !s) return fail(s.error());
  }

  // report
  double bl = m.body_length();
  if (a.json) {
    out["fitness"] = res.fitness;
    out["distance"] = res.distance;
    out["body_length"] = bl;
    out["parts"] = m.n_parts();
    out["joints"] = m.joints.size();
    out["neurons"] = m.brain.n_neurons();
    out["seconds"] = res.seconds;
    out["steps"] = res.steps;
    out["failed"] = res.failed;
    out["failure"] = res.failure;
    out["note"] = res.note;
    if (!res.trial_fitness.empty()) out["trial_fitness"] = res.trial_fitness;
    if (m.projectile >= 0) {
      out["release_time"] = res.release_time >= 0 ? nlohmann::json(res.release_time) : nlohmann::json(nullptr);
      out["target_miss"] = res.target_miss >= 0 ? nlohmann::json(res.target_miss) : nlohmann::json(nullptr);
    }
    out["warnings"] = res.warnings;
    out["replay"] = a.replay.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.replay);
    std::printf("%s\n", out.dump().c_str());
    return 0;
  }
  std::printf("%s: %s, %d parts, %zu joints, %d neurons, body length %.3f m\n", a.genome.c_str(),
              std::string(to_string(m.dialect)).c_str(), m.n_parts(), m.joints.size(),
              m.brain.n_neurons(), bl);
  for (const auto& w : res.warnings) std::printf("warning: %s\n", w.c_str());
  std::printf("simulated %.2f s (%ld steps), seed %llu\n", res.seconds, res.steps,
              static_cast<unsigned long long>(a.seed));
  if (res.failed) std::printf("failed: %s\n", res.failure.c_str());
  if (!res.note.empty()) std::printf("note: %s\n", res.note.c_str());
  if (cfg.task_kind == TaskKind::Throwing) {
    // the throw: when, how far, how close to the target
    if (res.release_time >= 0) std::printf("released at %.3f s\n", res.release_time);
    std::printf("projectile thrown %.4f m", res.distance);
    if (res.target_miss >= 0) std::printf(", passing %.4f m from the target", res.target_miss);
    std::printf("\nfitness %.6g\n", res.fitness);
  } else {
    std::printf("distance %.4f m (%.2f body lengths)\nfitness %.6g\n", res.distance,
                bl > 0 ? res.distance / bl : 0.0, res.fitness);
  }
  if (!res.trial_fitness.empty()) {
    // task.trials > 1: the lines above are the first trial's, the fitness the mean
    std::printf("fitness is the mean of %zu trials (the lines above are the first's):",
                res.trial_fitness.size());
    for (double f : res.trial_fitness) std::printf(" %.6g", f);
    std::printf("\n");
  }
  if (!a.replay.empty()) std::printf("replay written to %s\n", a.replay.c_str());
  return 0;
}

int cmd_config(const std::string& dialect, const std::string& config_file, bool reference) {
  if (reference) {
    std::printf("%s", config_reference_markdown().c_str());
    return 0;
  }
  auto d = parse_dialect(dialect);
  if (!d) return fail("dialect: expected sims1994, miconi2006 or chaumont2007, got \"" + dialect + "\"");
  SimConfig cfg = default_sim_config(*d);
  if (!config_file.empty())
    if (Status s = apply_config_file(cfg, config_file); !s) return fail(s.error());
  std::printf("%s", config_to_toml(cfg).c_str());
  return 0;
}

}  // namespace

void add_simulate_commands(CLI::App& app) {
  // arguments live as long as the app: parsing fills them, the callback reads them
  static SimulateArgs sim;
  auto* s = app.add_subcommand("simulate", "Grow a genome and simulate it on flat ground");
  s->add_option("genome", sim.genome, "Genome file (JSON)")->required();
  s->add_option("--config", sim.config, "TOML config overlaid on the dialect's defaults");
  s->add_option("--seconds", sim.seconds, "Simulated seconds (default: the config's task.seconds, or throwing.seconds)");
  s->add_option("--seed", sim.seed, "Seed of the evaluation")->default_val(1);
  s->add_option("--replay", sim.replay, "Write a replay file here (folders are made)");
  s->add_flag("--json", sim.json, "Print one JSON object instead of text");
  s->callback([] { std::exit(cmd_simulate(sim)); });

  static std::string dialect = "sims1994", cfg_file;
  static bool reference = false;
  auto* c = app.add_subcommand("config", "Print the effective config (TOML) of a dialect");
  c->add_option("dialect", dialect, "sims1994, miconi2006 or chaumont2007");
  c->add_option("--config", cfg_file, "TOML config overlaid on the dialect's defaults");
  c->add_flag("--reference", reference, "Print every key of every dialect as a Markdown table");
  c->callback([] { std::exit(cmd_config(dialect, cfg_file, reference)); });
}

}  // namespace bx
