// `bestiary plot RUN RUN... [--group-by preset|section.key]`: several runs on
// one chart, conditions as medians with a band; what it refuses, in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "support/run_command.h"

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
  // refused in one line: an unknown key, --metric with several runs, a folder that is no run
  for (const std::string& bad : {runs + " --group-by evolution.nothing", runs + " --metric level",
                                 runs + " " + (dir / "none").string()}) {
    r = bestiary("plot " + bad + " --out " + (dir / "x.svg").string());
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "x.svg"));
}

}  // namespace
