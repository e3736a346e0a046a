// `bestiary simulate` end to end: output, replays identical across processes,
// and bad input of every kind as one error line, a non-zero exit and no file.
#include <gtest/gtest.h>

#include "support/run_command.h"
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using bxtest::Outcome;
using bxtest::bestiary;
using bxtest::creature;
using bxtest::slurp;

class Simulate : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("bx_cli_" + std::to_string(::getpid()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
  fs::path dir;
};

TEST_F(Simulate, JsonReportsTheResult) {
  Outcome r = bestiary("simulate " + creature("walker.json") + " --seconds 10 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["viable"].get<bool>());
  EXPECT_GE(j["distance"].get<double>(), j["body_length"].get<double>());
  EXPECT_NEAR(j["fitness"].get<double>(), j["distance"].get<double>() / 10, 1e-9);  // speed
  EXPECT_EQ(j["parts"], 5);
  EXPECT_TRUE(j["warnings"].is_array());
  EXPECT_EQ(j["steps"], 1000);
}

TEST_F(Simulate, SameGenomeAndSeedGiveByteIdenticalReplaysInSeparateProcesses) {
  fs::path a = dir / "a.json", b = dir / "b.json", c = dir / "c.json";
  std::string base = "simulate " + creature("snake.json") + " --seconds 4 --seed 11 --replay ";
  ASSERT_EQ(bestiary(base + a.string()).code, 0);
  ASSERT_EQ(bestiary(base + b.string()).code, 0);
  std::string ra = slurp(a), rb = slurp(b);
  EXPECT_GT(ra.size(), 1000u);
  EXPECT_EQ(ra, rb);
  // the replay is versioned and complete
  auto j = nlohmann::json::parse(ra);
  EXPECT_EQ(j["format"], "bestiary-replay");
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["parts"].size(), 6u);
  EXPECT_EQ(j["frames"].size(), 121u);
  EXPECT_EQ(j["frames"][120]["poses"].size(), 6u);
  // and a different physics configuration gives a different one
  fs::path cfg = write("c.toml", "[physics]\nerp = 0.5\n");
  ASSERT_EQ(bestiary(base + c.string() + " --config " + cfg.string()).code, 0);
  EXPECT_NE(slurp(c), ra);
}

TEST_F(Simulate, NonViableCreatureIsReportedAsAValue) {
  fs::path g = write("overlap.json", R"({"format":"bestiary-genome","version":1,"dialect":"sims1994",
    "nodes":[{"size":[0.5,0.5,0.5],"edges":[{"to":1},{"to":1}]},{"size":[0.3,0.1,0.1]}]})");
  Outcome r = bestiary("simulate " + g.string() + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["viable"].get<bool>());
  EXPECT_EQ(j["reason"], "self-intersection: parts 1 (gene 1) and 2 (gene 1) overlap");
}

// every kind of bad input: exit 2, exactly one line on stderr, no output file
TEST_F(Simulate, BadInputGivesOneErrorLineAndNoFile) {
  fs::path replay = dir / "out.replay.json";
  fs::path bad_genome = write("bad.json", R"({"format":"bestiary-genome","version":1,"dialect":"sims1994",
    "nodes":[{"size":[0.5,-1,0.5]}]})");
  fs::path bad_cfg = write("bad.toml", "[physics]\nerp = 3\n");
  fs::path old_cfg = write("old.toml", "[brain]\nsteps_per_physics_step = 2\n");
  struct Case {
    std::string args, error;
  };
  std::vector<Case> cases = {
      {(dir / "missing.json").string(),
       (dir / "missing.json").string() + ": cannot open file (No such file or directory)"},
      {bad_genome.string(), bad_genome.string() + ": nodes[0].size: each dimension must be > 0, got [0.5, -1.0, 0.5]"},
      {creature("box.json") + " --config " + bad_cfg.string(),
       bad_cfg.string() + ": physics.erp: out of range [0, 1], got 3"},
      {creature("box.json") + " --config " + old_cfg.string(),
       old_cfg.string() + ": brain.steps_per_physics_step: replaced by brain.rate_hz (brain steps per simulated second), got 2"},
      {creature("box.json") + " --seconds -2", "--seconds: expected a number in (0, 1e6], got -2"},
      {creature("box.json") + " --config " + (dir / "nope.toml").string(),
       (dir / "nope.toml").string() + ": cannot open"},
  };
  for (const auto& c : cases) {
    Outcome r = bestiary("simulate " + c.args + " --replay " + replay.string());
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(r.out, "") << c.args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("bestiary: " + c.error, 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(replay)) << c.args;
  }
  // a replay's missing folders are made; one that cannot be made is refused
  Outcome ok = bestiary("simulate " + creature("box.json") + " --seconds 1 --replay " +
                        (dir / "new/folder/r.json").string());
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(dir / "new/folder/r.json"));
  Outcome r = bestiary("simulate " + creature("box.json") + " --replay " +
                       (bad_cfg / "r.json").string());  // under a regular file
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("bestiary: --replay: cannot create directory", 0), 0u) << r.err;
}

}  // namespace
