// A run of several stages from the command line: run prints each stage's
// progress and best; an individual of a later stage is re-simulated on its
// own stage's config, bit for bit, and so is the genome file `best --out`
// writes, and the run page replays each on its own; lengthening, not yet
// made for several stages, refuses with a line.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/general_esp.h"
#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using bxtest::bestiary;
using bxtest::Outcome;

// two stages whose task lengths differ: an individual simulated on the wrong
// one's config would not give its stored fitness
const char* kTwoStages = R"(
[genome]
dialect = "sims1994"
[evolution]
population = 6
generations = 2
[task]
seconds = 1

[[stage]]
name = "short"

[[stage]]
name = "long"
start = "population"
[stage.task]
seconds = 2
)";

class StagesRun : public bxtest::InTempDir {};

TEST_F(StagesRun, EachStageIsRunAndReplayedOnItsOwnConfig) {
  const fs::path cfg = write("staged.toml", kTwoStages), run = dir / "r";
  Outcome r = bestiary("run " + cfg.string() + " --workers 0 --out " + run.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("2 stages"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stage 2/2 long  gen 1/1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stage 1 short: best fitness"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stage 2 long: best fitness"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("watch the run: "), std::string::npos) << r.out;
  // the second stage's first individual (id 12: 6 + 6 before it) is a copy of
  // the first stage's best, scored on 2 s
  const std::string row = bxtest::query(run / "run.sqlite", "SELECT operator FROM individual WHERE id = 12");
  EXPECT_EQ(row, "copy|\n");
  for (const char* id : {"3", "12", "17"}) {
    Outcome s = bestiary("simulate " + run.string() + ":" + id);
    ASSERT_EQ(s.code, 0) << s.err;
    EXPECT_NE(s.out.find("(the stored fitness, bit for bit)"), std::string::npos) << id << ": " << s.out;
    EXPECT_NE(s.out.find(std::string(id == std::string("3") ? "simulated 1" : "simulated 2")), std::string::npos)
        << id << ": " << s.out;
  }
  // its best, as a genome file that carries its stage's config
  const fs::path best = dir / "best.json";
  Outcome b = bestiary("best " + run.string() + " --out " + best.string());
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_NE(b.err.find("best so far: individual 1"), std::string::npos) << b.err;  // of the second stage: ids 12-23
  Outcome s = bestiary("simulate " + best.string());
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_NE(s.out.find("(the stored fitness, bit for bit)"), std::string::npos) << s.out;
  // its page: each replay simulated on its stage's config, the best the last stage's
  Outcome page = bestiary("show " + run.string());
  ASSERT_EQ(page.code, 0) << page.err;
  const std::string html = bxtest::slurp(run / "view.html");
  EXPECT_NE(html.find(", stage short"), std::string::npos);
  EXPECT_NE(html.find(", stage long"), std::string::npos);
  EXPECT_NE(page.out.find("(individual 1"), std::string::npos) << page.out;  // of the second stage: ids 12-23
  // not yet for several stages: lengthening
  Outcome longer = bestiary("resume " + run.string() + " --set evolution.generations=5");
  EXPECT_EQ(longer.code, 2);
  EXPECT_NE(longer.err.find("cannot be lengthened"), std::string::npos) << longer.err;
}

TEST_F(StagesRun, ABadStageIsRefusedWithItsNameAndKeyAndLeavesNothing) {
  std::string text = kTwoStages;
  text += "\n[[stage]]\nname = \"third\"\nuses = [\"fourth\"]\n";
  const fs::path cfg = write("bad.toml", text), run = dir / "r";
  Outcome r = bestiary("run " + cfg.string() + " --workers 0 --out " + run.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(bxtest::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("stage \"third\".uses: \"fourth\": no earlier stage has this name"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(run));
}

TEST_F(StagesRun, AGeneralStagesSummarySaysHowManyChildrenFellBelowARetest) {
  const fs::path cfg = write("general.toml", bxtest::general_syllabus()), run = dir / "g";
  Outcome r = bestiary("run " + cfg.string() + " --workers 0 --quiet --out " + run.string());
  ASSERT_EQ(r.code, 0) << r.err;
  std::string fell =
      bxtest::query(run / "run.sqlite", "SELECT count(*) FROM individual WHERE id >= 7 AND failure LIKE 'retest %'");
  fell = fell.substr(0, fell.find('|'));
  // the strike stage: 4, then 3 children of the one elite (ids 7-13); forward's has no retest
  const std::size_t strike = r.out.find("stage 2 strike: best fitness");
  ASSERT_NE(strike, std::string::npos) << r.out;
  EXPECT_NE(r.out.find("; " + fell + " of its 7 children fell below a retest\n", strike), std::string::npos) << r.out;
  EXPECT_EQ(r.out.substr(0, strike).find("fell below"), std::string::npos) << r.out;
}

}  // namespace
