// `bestiary simulate`: grow one genome, simulate it, report, optionally replay.
#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/commands.h"
#include "develop/develop.h"
#include "eval/evaluate.h"
#include "genome/dialect.h"
#include "genome/genome_json.h"
#include "io/config.h"
#include "io/replay_file.h"

namespace bx {

namespace {

int fail(const std::string& msg) {
  std::fprintf(stderr, "bestiary: %s\n", msg.c_str());
  return 2;
}

// shortest text that reads back as the same double
std::string shortest(double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace

int cmd_simulate(const SimulateArgs& a) {
  // inputs: genome, config, flags; all checked before any work
  auto genome = load_genome(a.genome);
  if (!genome) return fail(genome.error());
  SimConfig cfg = default_sim_config(genome->dialect);
  if (!a.config.empty())
    if (Status s = apply_config_file(cfg, a.config); !s) return fail(s.error());
  if (a.seconds) {
    if (!(*a.seconds > 0) || !std::isfinite(*a.seconds) || *a.seconds > 1e6)
      return fail("--seconds: expected a number in (0, 1e6], got " + shortest(*a.seconds));
    cfg.task.seconds = *a.seconds;
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
  std::printf("distance %.4f m (%.2f body lengths)\nfitness %.6g\n", res.distance,
              bl > 0 ? res.distance / bl : 0.0, res.fitness);
  if (!a.replay.empty()) std::printf("replay written to %s\n", a.replay.c_str());
  return 0;
}

int cmd_config(const std::string& dialect, const std::string& config_file) {
  auto d = parse_dialect(dialect);
  if (!d) return fail("dialect: expected sims1994, miconi2006 or chaumont2007, got \"" + dialect + "\"");
  SimConfig cfg = default_sim_config(*d);
  if (!config_file.empty())
    if (Status s = apply_config_file(cfg, config_file); !s) return fail(s.error());
  std::printf("%s", config_to_toml(cfg).c_str());
  return 0;
}

}  // namespace bx
