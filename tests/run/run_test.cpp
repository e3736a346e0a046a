// Runs on disk: the database does not depend on the number of workers, and a
// run stopped after any generation and resumed ends exactly as one never
// stopped.
#include "run/run.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/version.h"
#include "io/run_store.h"
#include "support/run_command.h"
#include "support/tiny_runs.h"

namespace bx {
namespace {

namespace fs = std::filesystem;

const char* kConfig = R"(
[genome]
dialect = "sims1994"
[evolution]
algorithm = "generational"
population = 10
generations = 4
[task]
seconds = 1
)";

// a small catapult run (chaumont2007 section 4): the throwing task
const char* kCatapultConfig = R"(
[genome]
dialect = "chaumont2007"
[catapult]
enabled = true
[task]
kind = "throwing"
[evolution]
population = 12
generations = 3
[throwing]
seconds = 3
)";

// a tiny river crossing run (tests/support/tiny_runs.h)
const char* kRiverConfig = bxtest::kTinyRiverRun;

// every row of the generation and individual tables, as text
std::string dump(const std::string& dir) {
  std::string out;
  for (const char* q : {"SELECT * FROM generation ORDER BY gen", "SELECT * FROM individual ORDER BY id",
                        "SELECT * FROM generation_metric ORDER BY gen, name", "SELECT gen, state FROM checkpoint"})
    out += bxtest::query(run_db_path(dir), q);
  return out;
}

class Runs : public ::testing::Test {
 protected:
  void SetUp() override {
    root = fs::temp_directory_path() /
           ("bx_runs_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root);
    fs::create_directories(root);
  }
  void TearDown() override { fs::remove_all(root); }
  std::string make(const std::string& name, std::uint64_t seed = 9, const char* config = kConfig) {
    auto cfg = read_run_config(config, "test.toml");
    EXPECT_TRUE(cfg.ok()) << cfg.error();
    std::string dir = (root / name).string();
    Status s = create_run(dir, *cfg, config, "test.toml", seed);
    EXPECT_TRUE(s.ok()) << s.error();
    return dir;
  }
  fs::path root;
};

TEST(SeedList, ReadsARangeAListOrOneSeedAndNamesBadText) {
  EXPECT_EQ(*parse_seed_list("3-6"), (std::vector<std::uint64_t>{3, 4, 5, 6}));
  EXPECT_EQ(*parse_seed_list("7,2,9"), (std::vector<std::uint64_t>{7, 2, 9}));
  EXPECT_EQ(*parse_seed_list("5"), (std::vector<std::uint64_t>{5}));
  EXPECT_EQ(*parse_seed_list("4-4"), (std::vector<std::uint64_t>{4}));
  for (const char* bad : {"", "6-3", "a-b", "1,,2", "1-", "-2", "1.5", "1,2,"}) {
    auto r = parse_seed_list(bad);
    ASSERT_FALSE(r.ok()) << bad;
    EXPECT_NE(r.error().find(std::string("--seeds \"") + bad + "\""), std::string::npos) << r.error();
  }
  EXPECT_NE(parse_seed_list("1,2,1").error().find("seed 1 twice"), std::string::npos);
  EXPECT_NE(parse_seed_list("1-20000").error().find("more than 10,000"), std::string::npos);
}

TEST_F(Runs, DatabaseIsTheSameForOneOrTwoWorkers) {
  std::string one = make("one"), two = make("two");
  ASSERT_TRUE(drive_run(one, {1, true, 0}).ok());
  ASSERT_TRUE(drive_run(two, {2, true, 0}).ok());
  std::string a = dump(one);
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, dump(two));
  auto store = RunStore::open(run_db_path(one));
  ASSERT_TRUE(store.ok());
  EXPECT_EQ((*store)->generations().size(), 4u);
  EXPECT_EQ((*store)->meta("seed"), "9");
  EXPECT_EQ((*store)->meta("bestiary_version"), bx::bestiary_version());
}

TEST_F(Runs, StoppedAfterAnyGenerationAndResumedEndsTheSame) {
  std::string whole = make("whole");
  ASSERT_TRUE(drive_run(whole, {2, true, 0}).ok());
  std::string expected = dump(whole);
  for (int stop : {1, 2, 3}) {
    std::string dir = make("stop" + std::to_string(stop));
    ASSERT_TRUE(drive_run(dir, {2, true, stop}).ok());
    EXPECT_NE(dump(dir), expected);
    ASSERT_TRUE(drive_run(dir, {1, true, 0}).ok());  // another worker count, too
    EXPECT_EQ(dump(dir), expected) << "stopped after " << stop;
  }
  // resuming a finished run does nothing
  ASSERT_TRUE(drive_run(whole, {2, true, 0}).ok());
  EXPECT_EQ(dump(whole), expected);
}

TEST_F(Runs, CatapultRunsAreTheSameForAnyWorkersAndResumeExactly) {
  std::string one = make("one", 3, kCatapultConfig), two = make("two", 3, kCatapultConfig);
  ASSERT_TRUE(drive_run(one, {1, true, 0}).ok());
  ASSERT_TRUE(drive_run(two, {2, true, 0}).ok());
  std::string expected = dump(one);
  EXPECT_EQ(expected, dump(two));
  EXPECT_NE(expected.find("\"catapult\""), std::string::npos) << "the genomes are catapults";
  std::string stopped = make("stopped", 3, kCatapultConfig);
  ASSERT_TRUE(drive_run(stopped, {2, true, 1}).ok());
  ASSERT_TRUE(drive_run(stopped, {1, true, 0}).ok());
  EXPECT_EQ(dump(stopped), expected);
}

// evolution.elite_evaluations: elites evaluated again change rows of earlier
// generations; the database still resumes exactly after any generation
TEST_F(Runs, ElitesEvaluatedAgainResumeExactly) {
  std::string text = kConfig;
  text.insert(text.find("[task]"), "elite_evaluations = 3\n");
  std::string whole = make("whole", 9, text.c_str());
  ASSERT_TRUE(drive_run(whole, {2, true, 0}).ok());
  std::string expected = dump(whole);
  // the elite (2 of 10) has 3 evaluations each; the database has them
  EXPECT_GE(std::stoi(bxtest::query(run_db_path(whole), "SELECT count(*) FROM individual WHERE evaluations = 3")), 2);
  // (one whose mean fell out of the elite on the way keeps fewer)
  EXPECT_EQ(bxtest::query(run_db_path(whole), "SELECT count(*) FROM individual WHERE evaluations NOT IN (1, 2, 3)"),
            "0|\n");
  for (int stop : {1, 2}) {
    std::string dir = make("stop" + std::to_string(stop), 9, text.c_str());
    ASSERT_TRUE(drive_run(dir, {2, true, stop}).ok());
    ASSERT_TRUE(drive_run(dir, {1, true, 0}).ok());
    EXPECT_EQ(dump(dir), expected) << "stopped after " << stop;
  }
  // each evaluation is counted: 10 + 3 x 8 children, and 2 more for each elite entrant
  auto store = RunStore::open(run_db_path(whole));
  ASSERT_TRUE(store.ok());
  auto gens = (*store)->generations();
  ASSERT_EQ(gens.size(), 4u);
  EXPECT_GT(gens.back().evaluations, 34);
  auto best = (*store)->best_individual();
  ASSERT_TRUE(best.ok());
  EXPECT_EQ(best->evaluations, 3);
}

// tournaments that evaluate their three: children wait unevaluated (0
// evaluations) in the database, survivors gather evaluations, each
// generation keeps the task's metrics over its tournaments' evaluations, and
// the run is the same for any workers and resumes exactly
TEST_F(Runs, TournamentsThatEvaluateAllAreTheSameForAnyWorkersAndResumeExactly) {
  std::string one = make("one", 4, kRiverConfig), two = make("two", 4, kRiverConfig);
  ASSERT_TRUE(drive_run(one, {1, true, 0}).ok());
  ASSERT_TRUE(drive_run(two, {2, true, 0}).ok());
  std::string expected = dump(one);
  EXPECT_EQ(expected, dump(two));
  const auto db = run_db_path(one);
  // 9 evaluated at the start, then 4 intervals of 3 tournaments: 9 + 4 x 9 evaluations
  EXPECT_EQ(bxtest::query(db, "SELECT evaluations FROM generation ORDER BY gen DESC LIMIT 1"), "45|\n");
  EXPECT_EQ(bxtest::query(db, "SELECT count(*) FROM individual"), "21|\n");
  EXPECT_EQ(bxtest::query(db, "SELECT sum(evaluations) FROM individual"), "45|\n");
  EXPECT_NE(bxtest::query(db, "SELECT count(*) FROM individual WHERE evaluations = 0"), "0|\n");
  EXPECT_NE(bxtest::query(db, "SELECT count(*) FROM individual WHERE evaluations > 1"), "0|\n");
  // every generation has the river's metrics: the share completing level 1, ...
  EXPECT_EQ(bxtest::query(db, "SELECT count(DISTINCT gen) FROM generation_metric WHERE name = 'level 1 completed'"),
            "5|\n");
  auto store = RunStore::open(db);
  ASSERT_TRUE(store.ok());
  auto gens = (*store)->generations();
  ASSERT_EQ(gens.size(), 5u);
  ASSERT_FALSE(gens.back().metrics.empty());
  EXPECT_EQ(gens.back().metrics.front().name, "level");
  EXPECT_EQ(gens.back().metrics.front().mean, 1);  // nobody completes level 1 in a second
  for (int stop : {1, 3}) {
    std::string dir = make("stop" + std::to_string(stop), 4, kRiverConfig);
    ASSERT_TRUE(drive_run(dir, {2, true, stop}).ok());
    ASSERT_TRUE(drive_run(dir, {1, true, 0}).ok());
    EXPECT_EQ(dump(dir), expected) << "stopped after " << stop;
  }
}

TEST_F(Runs, CreateRefusesAnExistingDirectory) {
  std::string dir = make("taken");
  auto cfg = read_run_config(kConfig, "test.toml");
  Status s = create_run(dir, *cfg, kConfig, "test.toml", 1);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), dir + ": already exists (resume it with `bestiary resume " + dir +
                           "`, or choose another --out)");
}

}  // namespace
}  // namespace bx
