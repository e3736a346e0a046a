// `bestiary simulate`: develop one creature (of any kind), simulate it,
// report, optionally replay.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "cli/commands.h"
#include "cli/creature.h"
#include "core/files.h"
#include "eval/evaluate.h"
#include "eval/task_table.h"
#include "eval/evaluator.h"
#include "genome/dialect.h"
#include "genome/json_text.h"
#include "io/config.h"
#include "io/replay_file.h"
#include "io/syllabus.h"
#include "task/throwing.h"

namespace bx {

namespace {

/// Arguments of `bestiary simulate`.
struct SimulateArgs {
  std::string genome;  ///< a genome file or a run's creature (cli/creature.h)
  CreatureFlags flags;
  std::string replay;
  bool json = false;
};

// A creature of a kind without a body: its kind evaluates its genotype (no
// world, nothing to replay); its fitness and measures, as `simulate` says them.
int simulate_without_body(const Subject& c, const SimulateArgs& a) {
  const SimConfig& cfg = c.cfg.sim;
  const EvalOutcome o = evaluate_genotype(*c.genotype, cfg, c.seed);
  const EvalResult& res = o.result;
  // a run's elite scored as the mean (or least) of several evaluations
  std::vector<double> each;
  double folded = 0;
  if (o.viable && c.scored_settings && c.evaluations > 1)
    folded = repeated_genotype_fitness(*c.genotype, cfg, c.seed, c.repeats(), o, &each);
  if (a.json) {
    nlohmann::json out;
    out["genome"] = a.genome;
    out["seed"] = c.seed;
    out["settings"] = c.settings;
    out["as_scored"] = c.scored_settings;
    out["stored_fitness"] = c.stored_fitness ? nlohmann::json(*c.stored_fitness) : nlohmann::json(nullptr);
    out["creature"] = c.kind_name();
    out["body"] = false;
    out["viable"] = o.viable;
    if (!o.viable) out["reason"] = o.reason;
    out["fitness"] = res.fitness;
    out["seconds"] = res.seconds;
    out["steps"] = res.steps;
    out["brain_steps"] = res.brain_steps;
    out["failed"] = res.failed;
    out["failure"] = res.failure;
    out["note"] = res.note;
    nlohmann::json metrics = nlohmann::json::object();
    for (const Metric& mt : res.metrics) metrics[mt.name] = mt.value;
    out["metrics"] = metrics;
    if (!each.empty()) {
      out["evaluation_fitness"] = each;
      out["scored_fitness"] = folded;
    }
    out["warnings"] = res.warnings;
    out["replay"] = nullptr;
    std::printf("%s\n", json_text(out).c_str());
    return 0;
  }
  if (!o.viable) {
    std::printf("%s: not viable: %s\n", c.label.c_str(), o.reason.c_str());
    return 0;
  }
  std::printf("%s: %s creature, no body\n", c.label.c_str(), c.kind_name().c_str());
  if (!c.settings.empty()) std::printf("%s\n", c.settings.c_str());
  std::printf("evaluated without a physics world: %.2f s of its controller (%ld steps), seed %llu\n", res.seconds,
              res.brain_steps, static_cast<unsigned long long>(c.seed));
  if (res.failed) std::printf("failed: %s\n", res.failure.c_str());
  if (!res.note.empty()) std::printf("note: %s\n", res.note.c_str());
  if (!res.metrics.empty()) std::printf("%s\n", metrics_line(res.metrics).c_str());
  std::printf("%s\n", fitness_line(res.fitness, c.scored_fitness()).c_str());
  if (!each.empty()) {
    std::printf("the run's fitness is the %s of %zu evaluations (the lines above are the first's):",
                score_name(cfg.trial_score), each.size());
    for (double f : each) std::printf(" %.6g", f);
    std::printf("\n%s\n", fitness_line(folded, c.stored_fitness).c_str());
  }
  return 0;
}

int cmd_simulate(const SimulateArgs& a) {
  // inputs: the creature, its config, flags; all checked before any work
  auto creature = resolve_creature(a.genome, a.flags);
  if (!creature) return fail(creature.error());
  const SimConfig& cfg = creature->cfg.sim;
  const std::uint64_t seed = creature->seed;
  if (!has_body(cfg.creature)) {
    if (!a.replay.empty()) return fail("--replay: " + no_body(cfg.creature, "nothing to replay"));
    return simulate_without_body(*creature, a);
  }
  if (!a.replay.empty()) {
    // make the replay's folder now, so a bad path fails before the simulation
    if (Status s = make_parent_dir("--replay", a.replay); !s) return fail(s.error());
  }

  // develop (a graph genome grows), then simulate
  auto dev = creature->develop();
  nlohmann::json out;
  out["genome"] = a.genome;
  out["seed"] = seed;
  out["settings"] = creature->settings;
  out["as_scored"] = creature->scored_settings;
  out["stored_fitness"] = creature->stored_fitness ? nlohmann::json(*creature->stored_fitness) : nlohmann::json(nullptr);
  out["viable"] = static_cast<bool>(dev);
  if (!dev) {
    out["reason"] = dev.error();
    out["fitness"] = 0.0;
    out["distance"] = 0.0;
    out["warnings"] = nlohmann::json::array();
    if (a.json)
      std::printf("%s\n", json_text(out).c_str());
    else
      std::printf("%s: not viable: %s\n", creature->label.c_str(), dev.error().c_str());
    return 0;
  }
  const CreatureModel& m = *dev->body;
  Replay replay;
  // every trial runs; the replay and the measures are the watched one's (--trial, else the first)
  EvalResult res = evaluate_trial(*dev, cfg, seed, creature->trial.value_or(0), a.replay.empty() ? nullptr : &replay);
  if (!a.replay.empty()) {
    ReplayInfo info{creature->label, seed, cfg.physics.dt, cfg.physics.friction, replay_creature(cfg)};
    if (Status s = save_replay(a.replay, m, replay, res, info); !s) return fail(s.error());
  }

  // a run's elite scored as the mean (or least) of several evaluations: the
  // others too, folded as the run folded them, so it reproduces the stored fitness
  std::vector<double> each;
  double mean = 0;
  if (creature->scored_settings && creature->evaluations > 1)
    mean = repeated_fitness(*dev, cfg, seed, creature->repeats(), res, &each);

  // report
  double bl = m.body_length();
  if (a.json) {
    out["fitness"] = res.fitness;
    out["distance"] = res.distance;
    out["body_length"] = bl;
    out["parts"] = m.n_parts();
    out["joints"] = m.joints.size();
    if (creature->graph_genome())
      out["neurons"] = m.brain.n_neurons();
    else
      out["creature"] = creature->kind_name();  // its controller is not a graph brain
    out["seconds"] = res.seconds;
    out["steps"] = res.steps;
    out["failed"] = res.failed;
    out["failure"] = res.failure;
    out["note"] = res.note;
    if (!res.trial_fitness.empty()) {
      out["trial_fitness"] = res.trial_fitness;
      out["trial"] = res.trial + 1;  // the one the other fields and the replay are of, from 1
      if (!res.setup.empty()) out["setup"] = res.setup;
    }
    if (!res.metrics.empty()) {
      nlohmann::json metrics = nlohmann::json::object();
      for (const Metric& mt : res.metrics) metrics[mt.name] = mt.value;
      out["metrics"] = metrics;
    }
    if (!each.empty()) {
      out["evaluation_fitness"] = each;
      out["scored_fitness"] = mean;
    }
    if (!res.markers.empty()) {
      // the task's moments: a throw's begin, release, touch end (s)
      nlohmann::json markers = nlohmann::json::object();
      for (const SceneMarker& mk : res.markers) markers[mk.name] = mk.t;
      out["markers"] = markers;
    }
    out["warnings"] = res.warnings;
    out["replay"] = a.replay.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.replay);
    std::printf("%s\n", json_text(out).c_str());
    return 0;
  }
  if (creature->graph_genome())
    std::printf("%s: %s, %d parts, %zu joints, %d neurons, body length %.3f m\n", creature->label.c_str(),
                std::string(to_string(m.dialect)).c_str(), m.n_parts(), m.joints.size(), m.brain.n_neurons(), bl);
  else  // a body and a controller of its kind: no graph brain's neurons to count
    std::printf("%s: %s creature, %d parts, %zu joints, %zu effectors, body length %.3f m\n", creature->label.c_str(),
                creature->kind_name().c_str(), m.n_parts(), m.joints.size(), m.effectors.size(), bl);
  for (const auto& w : res.warnings) std::printf("warning: %s\n", w.c_str());
  if (!creature->settings.empty()) std::printf("%s\n", creature->settings.c_str());
  std::printf("simulated %.2f s (%ld steps), seed %llu\n", res.seconds, res.steps,
              static_cast<unsigned long long>(seed));
  // which trial the lines below are of, and what it set up (Task::describe)
  if (!res.trial_fitness.empty() && (creature->trial || !res.setup.empty()))
    std::printf("trial %d of %zu%s\n", res.trial + 1, res.trial_fitness.size(),
                res.setup.empty() ? "" : (": " + res.setup).c_str());
  if (res.failed) std::printf("failed: %s\n", res.failure.c_str());
  if (!res.note.empty()) std::printf("note: %s\n", res.note.c_str());
  if (cfg.task_kind == TaskKind::Throwing) {
    // the throw: when, how far, how close to the target (the task's markers and metric)
    const auto begin = res.marker("begin"), release = res.marker("release"), touch = res.marker("touch end");
    const auto miss = res.metric(ThrowingTask::kTargetMiss);
    if (begin && *begin > 0) std::printf("at rest at %.3f s: the throw began\n", *begin);
    if (release) std::printf("released at %.3f s\n", *release);
    if (touch && release)
      std::printf("the creature touched its projectile at %.3f s, %.3f s after the release: the throw ended there "
                  "(throwing.touch_seconds)\n",
                  *touch, *touch - *release);
    std::printf("projectile thrown %.4f m", res.distance);
    if (miss) std::printf(", passing %.4f m from the target", *miss);
    std::printf("\n");
  } else if (!res.metrics.empty()) {
    // a task that names its own measures (levels, food, ...) says them in place of a distance
    std::printf("%s\n", metrics_line(res.metrics).c_str());
  } else {
    std::printf("distance %.4f m (%.2f body lengths)\n", res.distance, bl > 0 ? res.distance / bl : 0.0);
  }
  std::printf("%s\n", fitness_line(res.fitness, creature->scored_fitness()).c_str());
  if (!each.empty()) {
    // the run scored it as the mean (or least) of several evaluations, each under its own seed
    const std::string halves = finer_step_text(creature->repeats());
    std::printf("the run's fitness is the %s of %zu evaluations (the lines above are the first's%s):",
                score_name(cfg.trial_score), each.size(), halves.empty() ? "" : ("; " + halves).c_str());
    for (double f : each) std::printf(" %.6g", f);
    std::printf("\n%s\n", fitness_line(mean, creature->stored_fitness).c_str());
  }
  if (!res.trial_fitness.empty()) {
    // task.trials > 1: the lines above are the watched trial's, the fitness their fold (mean, least, the task's own)
    const std::string which = res.trial == 0 ? "the first's" : "trial " + std::to_string(res.trial + 1) + "'s";
    std::printf("fitness is the %s of %zu trials (the other lines above are %s):", trial_fold_name(cfg).c_str(),
                res.trial_fitness.size(), which.c_str());
    for (double f : res.trial_fitness) std::printf(" %.6g", f);
    std::printf("\n");
  }
  if (!a.replay.empty()) std::printf("replay written to %s\n", a.replay.c_str());
  return 0;
}

int cmd_config(const std::string& dialect, bool dialect_given, const std::string& config_file, bool reference) {
  if (reference) {
    std::printf("%s", config_reference_markdown().c_str());
    return 0;
  }
  auto d = parse_dialect(dialect);
  if (!d) return fail("dialect: expected sims1994, miconi2006, chaumont2007 or lessin2015, got \"" + dialect + "\"");
  if (config_file.empty()) {
    std::printf("%s", config_to_toml(default_sim_config(*d)).c_str());
    return 0;
  }
  // a config file's own dialect and creature kind give the defaults, as a run
  // reads it, unless a dialect is named here
  auto text = config_source(config_file);
  if (!text) return fail(text.error());
  std::vector<std::string> sets;
  if (dialect_given) sets.push_back("genome.dialect=\"" + dialect + "\"");
  // a config of stages: each stage's keys as a run stores them (config.toml)
  auto syl = read_syllabus(text->second, config_file, sets);
  if (!syl) return fail(syl.error());
  if (syl->staged()) {
    std::printf("%s", syllabus_to_toml(*syl).c_str());
    return 0;
  }
  std::printf("%s", config_to_toml(syl->stages.front().cfg.sim).c_str());
  return 0;
}

}  // namespace

void add_simulate_commands(CLI::App& app) {
  // arguments live as long as the app: parsing fills them, the callback reads them
  static SimulateArgs sim;
  auto* s = app.add_subcommand("simulate", "Grow a genome and simulate it on flat ground");
  add_creature_options(s, sim.genome, sim.flags);
  add_trial_option(s, sim.flags);
  s->add_option("--replay", sim.replay, "Write a replay file here (folders are made)");
  s->add_flag("--json", sim.json, "Print one JSON object instead of text");
  s->callback([] { std::exit(cmd_simulate(sim)); });

  static std::string dialect = "sims1994", cfg_file;
  static bool reference = false;
  auto* c = app.add_subcommand("config", "Print the effective config (TOML) of a dialect");
  static CLI::Option* dialect_opt =
      c->add_option("dialect", dialect, "sims1994, miconi2006, chaumont2007 or lessin2015 (with --config: that file's own)");
  c->add_option("--config", cfg_file, "TOML config (a file or a preset name) overlaid on its dialect's (and creature kind's) defaults; a config of stages prints every stage as a run stores it");
  c->add_flag("--reference", reference, "Print every key of every dialect as a Markdown table");
  c->callback([] { std::exit(cmd_config(dialect, dialect_opt->count() > 0, cfg_file, reference)); });
}

}  // namespace bx
