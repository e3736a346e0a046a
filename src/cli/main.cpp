// The `bestiary` command.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "cli/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"Bestiary: evolve virtual creatures, bodies and brains together, in 3D physics"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(BESTIARY_VERSION) + " (" + BESTIARY_GIT + ")");

  // simulate
  bx::SimulateArgs sim;
  auto* s = app.add_subcommand("simulate", "Grow a genome and simulate it on flat ground");
  s->add_option("genome", sim.genome, "Genome file (JSON)")->required();
  s->add_option("--config", sim.config, "TOML config overlaid on the dialect's defaults");
  s->add_option("--seconds", sim.seconds, "Simulated seconds (default: the config's task.seconds)");
  s->add_option("--seed", sim.seed, "Seed of the evaluation")->default_val(1);
  s->add_option("--replay", sim.replay, "Write a replay file here");
  s->add_flag("--json", sim.json, "Print one JSON object instead of text");
  s->callback([&] { std::exit(bx::cmd_simulate(sim)); });

  // config: the effective config of a dialect
  std::string dialect = "sims1994";
  std::string cfg_file;
  auto* c = app.add_subcommand("config", "Print the effective config (TOML) of a dialect");
  c->add_option("dialect", dialect, "sims1994, miconi2006 or chaumont2007");
  c->add_option("--config", cfg_file, "TOML config overlaid on the dialect's defaults");
  c->callback([&] { std::exit(bx::cmd_config(dialect, cfg_file)); });

  CLI11_PARSE(app, argc, argv);
  return 0;
}
