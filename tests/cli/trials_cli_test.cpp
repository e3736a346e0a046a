// An evaluation of several trials on the command line (task.trials: the
// light tasks' headings, fight-or-flight's targets): `--trial K` watches
// trial K (its replay and measures; the fitness stays the whole
// evaluation's), and `show` puts each trial's scenario on its page, labelled
// with what the trial sets up (Task::describe).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "support/run_command.h"

namespace bx {
namespace {

using nlohmann::json;

class TrialsCli : public bxtest::InTempDir {
 protected:
  // lessin_eyes (no muscles: it sits where it lands) facing a light at each
  // of the four default headings, 45, 135, -135 and -45 degrees
  static std::string eyes(int trials = 4) {
    return bxtest::creature("lessin_eyes.json") + " --set task.kind=light --set task.trials=" +
           std::to_string(trials) + " --set light.seconds=2";
  }
  // the number after `name ` in a line of text (NaN if absent)
  static double number_after(const std::string& out, const std::string& name) {
    const auto at = out.find(name + " ");
    return at == std::string::npos ? std::nan("") : std::stod(out.substr(at + name.size() + 1));
  }
  static std::string line_of(const std::string& out, const std::string& start) {
    const auto at = out.find("\n" + start);
    return at == std::string::npos ? "" : out.substr(at + 1, out.find('\n', at + 1) - at - 1);
  }
};

TEST_F(TrialsCli, SimulateTrialKReportsThatTrialsBearingAndTheWholeEvaluationsFitness) {
  auto first = bxtest::bestiary("simulate " + eyes());
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_NEAR(number_after(first.out, "bearing"), 45, 0.5) << first.out;
  auto third = bxtest::bestiary("simulate " + eyes() + " --trial 3");
  ASSERT_EQ(third.code, 0) << third.err;
  // the light at light.headings[2]; the box does not turn
  EXPECT_NEAR(number_after(third.out, "bearing"), -135, 0.5) << third.out;
  EXPECT_NE(third.out.find("\ntrial 3 of 4: light at -135 degrees\n"), std::string::npos) << third.out;
  // the fitness is the four trials' mean, whichever is watched
  EXPECT_FALSE(line_of(third.out, "fitness ").empty()) << third.out;
  EXPECT_EQ(line_of(third.out, "fitness "), line_of(first.out, "fitness "));
  EXPECT_NE(third.out.find("fitness is the mean (the light task averages its headings) of 4 trials (the other lines above are trial 3's)"), std::string::npos)
      << third.out;
  // the same in JSON, and its replay says which trial it is
  const std::string replay = (dir / "third.json").string();
  auto j = bxtest::bestiary("simulate " + eyes() + " --trial 3 --json --replay " + replay);
  ASSERT_EQ(j.code, 0) << j.err;
  const json out = json::parse(j.out);
  EXPECT_EQ(out["trial"], 3);
  EXPECT_EQ(out["setup"], "light at -135 degrees");
  EXPECT_NEAR(out["metrics"]["bearing"].get<double>(), -135, 0.5);
  EXPECT_EQ(out["trial_fitness"].size(), 4u);
  const json r = json::parse(bxtest::slurp(replay));
  EXPECT_EQ(r["result"]["trial"], 3);
  EXPECT_EQ(r["result"]["fitness"], out["fitness"]);
}

TEST_F(TrialsCli, ATrialTheEvaluationDoesNotHaveIsRefusedNamingTheFlag) {
  auto five = bxtest::bestiary("simulate " + eyes() + " --trial 5");
  EXPECT_EQ(five.code, 2);
  EXPECT_EQ(five.err, "bestiary: --trial: 5, but the evaluation has 4 trials (task.trials = 4): expected 1 to 4\n");
  EXPECT_EQ(five.out, "");
  // one trial: only the first
  auto single = bxtest::bestiary("simulate " + bxtest::creature("lessin_eyes.json") + " --trial 2");
  EXPECT_EQ(single.code, 2);
  EXPECT_NE(single.err.find("--trial: 2, but the evaluation has one trial"), std::string::npos) << single.err;
  // show and render refuse it before any work (render before looking for its tools)
  auto show = bxtest::bestiary("show " + eyes() + " --trial 5 --out " + (dir / "x.html").string());
  EXPECT_EQ(show.code, 2);
  EXPECT_NE(show.err.find("--trial: 5"), std::string::npos) << show.err;
  EXPECT_FALSE(bxtest::fs::exists(dir / "x.html"));
  auto render = bxtest::bestiary("render " + eyes() + " --trial 5 --out " + (dir / "x.mp4").string());
  EXPECT_EQ(render.code, 2);
  EXPECT_NE(render.err.find("--trial: 5"), std::string::npos) << render.err;
  // check's gates are the whole evaluation's: no --trial
  EXPECT_EQ(bxtest::bestiary("check " + eyes() + " --trial 1").code, 2);
}

TEST_F(TrialsCli, ShowPutsEachTrialsScenarioOnThePageLabelledWithWhatItSetsUp) {
  const bxtest::fs::path page = dir / "eyes.html";
  auto r = bxtest::bestiary("show " + eyes() + " --out " + page.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("4 trials, each its own replay"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("trial 1 of 4 (light at 45 degrees)"), std::string::npos) << r.out;
  const json data = json::parse(bxtest::embedded_data(bxtest::slurp(page)));
  ASSERT_EQ(data["replays"].size(), 4u);
  const char* headings[] = {"45", "135", "-135", "-45"};
  for (int k = 0; k < 4; ++k) {
    const json& e = data["replays"][k];
    EXPECT_EQ(e["label"], "lessin_eyes, trial " + std::to_string(k + 1) + " of 4: light at " + headings[k] + " degrees");
    EXPECT_NEAR(e["replay"]["result"]["metrics"]["bearing"].get<double>(), std::stod(headings[k]), 0.5) << k;
    // the first trial's replay reads as before; a later one says which it is
    if (k == 0)
      EXPECT_FALSE(e["replay"]["result"].contains("trial"));
    else
      EXPECT_EQ(e["replay"]["result"]["trial"], k + 1);
  }
  // --trial: that trial alone
  auto one = bxtest::bestiary("show " + eyes() + " --trial 2 --out " + page.string());
  ASSERT_EQ(one.code, 0) << one.err;
  const json only = json::parse(bxtest::embedded_data(bxtest::slurp(page)));
  ASSERT_EQ(only["replays"].size(), 1u);
  EXPECT_EQ(only["replays"][0]["label"], "lessin_eyes, trial 2 of 4: light at 135 degrees");
}

TEST_F(TrialsCli, ShowLeavesOutTheTrialsPastSixteenAndSaysSo) {
  const bxtest::fs::path page = dir / "many.html";
  auto r = bxtest::bestiary("show " + eyes(20) + " --set light.seconds=0.5 --out " + page.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("the first 16 of the 20 trials are on the page; the other 4 were left out"), std::string::npos)
      << r.out;
  const json data = json::parse(bxtest::embedded_data(bxtest::slurp(page)));
  ASSERT_EQ(data["replays"].size(), 16u);
  EXPECT_EQ(data["replays"][15]["label"], "lessin_eyes, trial 16 of 20: light at -45 degrees");
}

}  // namespace
}  // namespace bx
