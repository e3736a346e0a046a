// Paths of any bytes (issue 37): a genome file, a replay, a run folder or a
// config whose name holds a byte that is not UTF-8 (0xFF) is read as named,
// and written into JSON, pages and configs as text that still names it
// ("\xff"); no command aborts on it (nlohmann's dump() threw: exit 134).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using bxtest::bestiary;
using bxtest::Outcome;
using bxtest::slurp;

const std::string kByte = "\xff";      // never part of UTF-8
const std::string kEscaped = "\\xff";  // as JSON, pages and configs name it

class AnyPathCli : public bxtest::InTempDir {};

// a path as one shell word
std::string word(const fs::path& p) { return "'" + p.string() + "'"; }

// `path` as the text that names it
std::string named(const fs::path& p) {
  std::string s;
  for (char c : p.string()) s += c == kByte[0] ? kEscaped : std::string(1, c);
  return s;
}

bool is_utf8(const std::string& text) {
  try {
    (void)nlohmann::json(text).dump();
    return true;
  } catch (const nlohmann::json::type_error&) {
    return false;
  }
}

TEST_F(AnyPathCli, AGenomeFileSimulatesToJsonReplaysAndShows) {
  const fs::path g = dir / ("walker" + kByte + ".json");
  fs::copy_file(bxtest::creature("walker.json"), g);

  Outcome s = bestiary("simulate " + word(g) + " --seconds 1 --json");
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_EQ(nlohmann::json::parse(s.out)["genome"], named(g));

  const fs::path r = dir / ("replay" + kByte + ".json");
  Outcome rp = bestiary("simulate " + word(g) + " --seconds 1 --replay " + word(r) + " --json");
  ASSERT_EQ(rp.code, 0) << rp.err;
  EXPECT_EQ(nlohmann::json::parse(rp.out)["replay"], named(r));
  EXPECT_EQ(nlohmann::json::parse(slurp(r))["genome"], named(g));

  Outcome v = bestiary("show " + word(g) + " --seconds 1");
  ASSERT_EQ(v.code, 0) << v.err;
  const std::string page = slurp(dir / ("walker" + kByte + ".html"));  // beside it, as always
  ASSERT_FALSE(page.empty()) << v.out;
  EXPECT_TRUE(is_utf8(page));
  EXPECT_EQ(nlohmann::json::parse(bxtest::embedded_data(page))["replays"][0]["label"], "walker" + kEscaped);
}

TEST_F(AnyPathCli, ARunFolderShowsSimulatesChecksAndWritesItsBest) {
  const fs::path run = dir / ("run" + kByte);
  ASSERT_EQ(bxtest::small_run(run).code, 0);

  Outcome v = bestiary("show " + word(run));
  ASSERT_EQ(v.code, 0) << v.err;
  const std::string page = slurp(run / "view.html");
  EXPECT_TRUE(is_utf8(page));
  // each replay names its creature: "RUN individual N"
  const auto data = nlohmann::json::parse(bxtest::embedded_data(page));
  EXPECT_EQ(data["replays"][0]["replay"]["genome"].get<std::string>().rfind(named(run) + " individual ", 0), 0u);

  Outcome s = bestiary("simulate " + word(run) + " --json");
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_EQ(nlohmann::json::parse(s.out)["genome"], named(run));

  Outcome c = bestiary("check " + word(run) + " --json");
  EXPECT_TRUE(c.code == 0 || c.code == 1) << c.code << c.err;  // its verdict, not an abort
  EXPECT_FALSE(nlohmann::json::parse(c.out, nullptr, false).is_discarded()) << c.out;

  // its best with its provenance, which then replays the scored evaluation
  const fs::path best = dir / "best.json";
  Outcome b = bestiary("best " + word(run) + " --out " + word(best));
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(best))["provenance"]["run"], named(run));
  Outcome again = bestiary("simulate " + word(best) + " --json");
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(nlohmann::json::parse(again.out)["as_scored"], true);
}

// The run's config records where it came from in a comment: the name as it
// was made it text TOML refuses, so the run was refused once created, and
// left a folder that resume and show refused too.
TEST_F(AnyPathCli, ARunOfAConfigFileRunsResumesShowsAndPlots) {
  const fs::path cfg = write("small" + kByte + ".toml",
                             "[evolution]\npopulation = 12\ngenerations = 3\n[task]\nseconds = 2\n");
  const fs::path run = dir / "run";
  Outcome r = bestiary("run " + word(cfg) + " --out " + word(run) + " --workers 0 --quiet --stop-after 2");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string config = slurp(run / "config.toml");
  EXPECT_EQ(config.substr(0, config.find('\n')), "# Resolved config of this run (from " + named(cfg) + ")");
  Outcome resumed = bestiary("resume " + word(run) + " --workers 0 --quiet");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_EQ(bxtest::query(run / "run.sqlite", "SELECT count(*) FROM generation"), "3|\n");
  Outcome v = bestiary("show " + word(run));
  ASSERT_EQ(v.code, 0) << v.err;
  // the plot's title is the run's name: the config's path
  Outcome p = bestiary("plot " + word(run) + " --out " + word(dir / "fitness.svg"));
  ASSERT_EQ(p.code, 0) << p.err;
  const std::string svg = slurp(dir / "fitness.svg");
  EXPECT_TRUE(is_utf8(svg));
  EXPECT_NE(svg.find(named(cfg)), std::string::npos);
}

}  // namespace
