// The canonical creatures of creatures/, read and developed for a test.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "develop/develop.h"
#include "genome/genome_json.h"

namespace bxtest {

/// The genome of creatures/NAME (a test failure, and an empty genome, if it does not read).
inline bx::Genome load_creature(const std::string& name) {
  auto g = bx::load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name);
  EXPECT_TRUE(g.ok()) << g.error();
  return g.ok() ? *g : bx::Genome{};
}

}  // namespace bxtest
