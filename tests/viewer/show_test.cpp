// `bestiary show`: a page holding exactly the replay `simulate` writes, next
// to the genome unless told where, and bad input as one error line, exit 2
// and no file.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "support/run_command.h"

namespace {

using namespace bxtest;
using nlohmann::json;

class ShowCommand : public InTempDir {};

TEST_F(ShowCommand, EmbedsTheSameReplayAsSimulate) {
  fs::path page = dir / "walker.html", replay = dir / "walker.replay.json";
  std::string flags = " --seconds 3 --seed 4";
  Outcome s = bestiary("show " + creature("walker.json") + flags + " --out " + page.string());
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_NE(s.out.find("viewer written to " + page.string()), std::string::npos) << s.out;
  ASSERT_EQ(bestiary("simulate " + creature("walker.json") + flags + " --replay " + replay.string()).code, 0);
  auto data = json::parse(embedded_data(slurp(page)));
  ASSERT_EQ(data["replays"].size(), 1u);
  EXPECT_EQ(data["replays"][0]["label"], "walker");
  EXPECT_EQ(data["replays"][0]["replay"], json::parse(slurp(replay)));
  EXPECT_TRUE(data["run"].is_null());
}

TEST_F(ShowCommand, WritesNextToTheGenomeByDefault) {
  fs::copy_file(creature("hinged_pair.json"), dir / "pair.json");
  Outcome s = bestiary("show " + (dir / "pair.json").string() + " --seconds 1");
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_TRUE(fs::exists(dir / "pair.html"));
  EXPECT_NE(s.out.find("viewer written to " + (dir / "pair.html").string()), std::string::npos);
}

// every kind of bad input: exit 2, exactly one line on stderr, no page
TEST_F(ShowCommand, BadInputGivesOneErrorLineAndNoFile) {
  fs::path page = dir / "out.html";
  fs::path overlap = write("overlap.json", R"({"format":"bestiary-genome","version":1,"dialect":"sims1994",
    "nodes":[{"size":[0.5,0.5,0.5],"edges":[{"to":1},{"to":1}]},{"size":[0.3,0.1,0.1]}]})");
  fs::path bad_cfg = write("bad.toml", "[physics]\nerp = 3\n");
  struct Case {
    std::string args, message;
  } cases[] = {
      {(dir / "missing.json").string(), "missing.json: cannot open file"},
      {creature("walker.json") + " --seconds -1", "--seconds: expected a number in (0, 1e6], got -1"},
      {creature("walker.json") + " --config " + bad_cfg.string(), "physics.erp"},
      {overlap.string(), "not viable: self-intersection"},
  };
  for (const auto& c : cases) {
    Outcome r = bestiary("show " + c.args + " --out " + page.string());
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(page)) << c.args;
  }
}

}  // namespace
