// The canonical creatures of creatures/, read and developed for a test.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "develop/develop.h"
#include "genome/genome_json.h"
#include "io/config.h"

namespace bxtest {

/// The genome of creatures/NAME (a test failure, and an empty genome, if it does not read).
inline bx::Genome load_creature(const std::string& name) {
  auto g = bx::load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name);
  EXPECT_TRUE(g.ok()) << g.error();
  return g.ok() ? *g : bx::Genome{};
}

/// creatures/NAME.json developed under its dialect's defaults, with that
/// config (test failures if it does not read or is not viable).
struct DevelopedCreature {
  bx::RunConfig cfg;
  bx::Development dev;
};
inline DevelopedCreature develop_creature(const std::string& name) {
  const bx::Genome g = load_creature(name + ".json");
  auto cfg = bx::read_run_config("[genome]\ndialect = \"" + std::string(bx::to_string(g.dialect)) + "\"\n", "test");
  EXPECT_TRUE(cfg.ok()) << cfg.error();
  DevelopedCreature out{cfg.ok() ? *cfg : bx::RunConfig{}, {}};
  out.dev = bx::develop(g, out.cfg.sim.develop);
  EXPECT_TRUE(out.dev.viable()) << name << ": " << out.dev.reason;
  return out;
}

}  // namespace bxtest
