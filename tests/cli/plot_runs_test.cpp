// `bestiary plot RUN RUN... [--group-by preset|section.key]`: several runs on
// one chart, conditions as medians with a band; what it refuses, in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "support/run_command.h"
#include "support/tiny_runs.h"

namespace {

namespace fs = std::filesystem;
using bxtest::bestiary;
using bxtest::Outcome;

std::string config(int population) {
  return "[genome]\ndialect = \"sims1994\"\n[evolution]\nalgorithm = \"generational\"\npopulation = " +
         std::to_string(population) + "\ngenerations = 2\n[task]\nseconds = 0.5\n";
}

class PlotRuns : public bxtest::InTempDir {};

TEST_F(PlotRuns, ConditionsByAConfigKeyAreMediansWithTheirBand) {
  const fs::path small = write("small.toml", config(6)), big = write("big.toml", config(8));
  ASSERT_EQ(bestiary("run " + small.string() + " --seeds 1-2 --workers 0 --quiet --out " + (dir / "s").string()).code, 0);
  ASSERT_EQ(bestiary("run " + big.string() + " --workers 0 --quiet --out " + (dir / "b").string()).code, 0);
  const std::string runs = (dir / "s/seed-1").string() + " " + (dir / "s/seed-2").string() + " " + (dir / "b").string();
  Outcome r = bestiary("plot " + runs + " --group-by evolution.population --out " + (dir / "c.svg").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("3 runs -> "), std::string::npos) << r.out;
  const std::string svg = bxtest::slurp(dir / "c.svg");
  EXPECT_NE(svg.find("evolution.population = 6 best (median of 2)"), std::string::npos);
  EXPECT_NE(svg.find("evolution.population = 8 best<"), std::string::npos);
  EXPECT_NE(svg.find("<polygon"), std::string::npos);  // the band of the two runs of 6
  // no --group-by: each run its own line, labelled by its folder
  r = bestiary("plot " + runs + " --out " + (dir / "each.svg").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(bxtest::slurp(dir / "each.svg").find((dir / "b").string() + " best"), std::string::npos);
  // refused in one line: an unknown key, a metric these runs lack, a folder that is no run
  for (const std::string& bad : {runs + " --group-by evolution.nothing", runs + " --metric level",
                                 runs + " " + (dir / "none").string()}) {
    r = bestiary("plot " + bad + " --out " + (dir / "x.svg").string());
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "x.svg"));
}

// With --metric, several runs' task metrics: each condition's median per
// report with its interquartile band (rivercrossing-small's Fig. 5 over seeds)
TEST_F(PlotRuns, ATasksMetricOverSeveralRunsIsTheirMedianWithItsBand) {
  const fs::path river = write("river.toml", bxtest::kTinyRiverRun);
  ASSERT_EQ(bestiary("run " + river.string() + " --seeds 1-2 --workers 0 --quiet --out " + (dir / "r").string()).code, 0);
  const std::string runs = (dir / "r/seed-1").string() + " " + (dir / "r/seed-2").string();
  Outcome r = bestiary("plot " + runs + " --group-by preset --metric \"level 1 completed\" --metric food --out " +
                       (dir / "m.svg").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string svg = bxtest::slurp(dir / "m.svg");
  EXPECT_NE(svg.find(">level 1 completed (median of 2)</text>"), std::string::npos) << svg;
  EXPECT_NE(svg.find(">food eaten (median of 2)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">tournaments</text>"), std::string::npos);
  EXPECT_NE(svg.find("<polygon"), std::string::npos);  // the band of the two runs
  // in 1-second evaluations no level and no food: both 0 or 1 throughout, drawn as shares
  EXPECT_NE(svg.find(">share of evaluations (%)</text>"), std::string::npos);
  // runs that report at different intervals have no common x axis
  ASSERT_EQ(bestiary("run " + river.string() + " --set evolution.report_every=4 --workers 0 --quiet --out " +
                     (dir / "r4").string()).code, 0);
  r = bestiary("plot " + runs + " " + (dir / "r4").string() + " --metric level --out " + (dir / "x.svg").string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("reports every 4 tournaments, the first run every 3"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.svg"));
}

}  // namespace
