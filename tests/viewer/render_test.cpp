// `bestiary render`: a playable video of the requested size and length
// (ffprobe), in mp4 and gif, with progress lines; a run's individual replayed
// as scored; and bad input as one error line, exit 2 and no file, not even a
// partial one.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include "run/run.h"
#include "io/run_store.h"
#include "support/run_command.h"

namespace {

using namespace bxtest;
using nlohmann::json;

// what ffprobe says of a video's first stream and container
json probe(const fs::path& video) {
  Outcome r = run_command("ffprobe -v error -select_streams v:0 -count_frames -show_entries "
                          "stream=codec_name,width,height,nb_read_frames,pix_fmt:format=duration "
                          "-of json " + video.string());
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code == 0 ? json::parse(r.out) : json();
}

class RenderCommand : public InTempDir {};

TEST_F(RenderCommand, Mp4HasTheRequestedSizeAndLength) {
  fs::path out = dir / "walker.mp4";
  Outcome r = bestiary("render " + creature("walker.json") + " --out " + out.string() +
                       " --seconds 2 --width 320 --height 240 --fps 10");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("video written to " + out.string()), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out.string() + ".tmp"));
  json p = probe(out);
  ASSERT_FALSE(p.is_null());
  const json& s = p["streams"][0];
  EXPECT_EQ(s["codec_name"], "h264");
  EXPECT_EQ(s["pix_fmt"], "yuv420p");
  EXPECT_EQ(s["width"], 320);
  EXPECT_EQ(s["height"], 240);
  EXPECT_EQ(s["nb_read_frames"], "20");
  double seconds = std::stod(p["format"]["duration"].get<std::string>());
  EXPECT_NEAR(seconds, 2.0, 1.0 / 10);
}

// and 15 fps unless told otherwise
TEST_F(RenderCommand, GifHasTheRequestedSizeAndLength) {
  fs::path out = dir / "pair.gif";
  Outcome r = bestiary("render " + creature("hinged_pair.json") + " --out " + out.string() +
                       " --seconds 1 --width 200 --height 150");
  ASSERT_EQ(r.code, 0) << r.err;
  json p = probe(out);
  ASSERT_FALSE(p.is_null());
  const json& s = p["streams"][0];
  EXPECT_EQ(s["codec_name"], "gif");
  EXPECT_EQ(s["width"], 200);
  EXPECT_EQ(s["height"], 150);
  EXPECT_EQ(s["nb_read_frames"], "15");
  double seconds = std::stod(p["format"]["duration"].get<std::string>());
  EXPECT_NEAR(seconds, 1.0, 1.0 / 15);
  // output not a terminal: whole progress lines, at least the last one, no \r
  EXPECT_NE(r.out.find("\nframe 15/15 (100%)  elapsed "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\r'), std::string::npos) << r.out;
}

// a run's individual, RUN_DIR:ID: the fitness render reports is the stored one,
// bit for bit; --quiet leaves out the progress
TEST_F(RenderCommand, ARunsIndividualHasItsStoredFitness) {
  fs::path run = dir / "run";
  Outcome r = bestiary("run quick --out " + run.string() +
                       " --set evolution.population=12 --set evolution.generations=2 --set task.seconds=1"
                       " --workers 0 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  auto store = bx::RunStore::open(bx::run_db_path(run.string()));
  ASSERT_TRUE(store.ok()) << store.error();
  auto gens = (*store)->generations();
  ASSERT_EQ(gens.size(), 2u);
  std::string id = std::to_string(gens.back().best_id);
  auto stored = (*store)->individual(gens.back().best_id);
  ASSERT_TRUE(stored.ok()) << stored.error();

  fs::path out = dir / "one.gif";
  r = bestiary("render " + run.string() + ":" + id + " --out " + out.string() +
               " --width 64 --height 48 --fps 5 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream lines(r.out);
  int as_scored = 0;
  for (std::string line; std::getline(lines, line);) {
    const std::string end = "(the stored fitness, bit for bit)";
    if (line.size() >= end.size() && line.compare(line.size() - end.size(), end.size(), end) == 0) {
      EXPECT_NE(line.find("individual " + id + " "), std::string::npos) << line;
      ++as_scored;
    }
  }
  // an elite evaluated again (quick: 3 times) is rendered as its first evaluation and says so
  const int n = stored->evaluations;
  EXPECT_EQ(as_scored, n == 1 ? 1 : 0) << r.out;
  if (n > 1) {
    EXPECT_NE(r.out.find("(evaluation 1 of " + std::to_string(n) + "; the stored fitness "), std::string::npos)
        << r.out;
  }
  // the settings, said once
  EXPECT_NE(r.out.find("as scored: "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("as scored: "), r.out.rfind("as scored: ")) << r.out;
  EXPECT_NE(r.out.find("video written to " + out.string()), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("frame "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("rendering"), std::string::npos) << r.out;
}

// every kind of bad input: exit 2, exactly one line on stderr, no video
TEST_F(RenderCommand, BadInputGivesOneErrorLineAndNoFile) {
  fs::path mp4 = dir / "out.mp4";
  std::string walker = creature("walker.json");
  struct Case {
    std::string args, message;
    fs::path out;
  } cases[] = {
      {walker + " --out " + (dir / "out.avi").string(), "--out: expected a file name ending in .mp4 or .gif", dir / "out.avi"},
      {walker + " --out " + mp4.string() + " --width 321", "--width: an mp4 needs an even number of pixels, got 321", mp4},
      {walker + " --out " + mp4.string() + " --height 8", "--height: expected a number of pixels in [16, 3840], got 8", mp4},
      {walker + " --out " + mp4.string() + " --fps 0", "--fps: expected frames per second in [1, 60], got 0", mp4},
      {walker + " --out " + mp4.string() + " --seconds 0", "--seconds: expected a number in (0, 1e6], got 0", mp4},
      {(dir / "missing.json").string() + " --out " + mp4.string(), "missing.json: cannot open file", mp4},
  };
  for (const auto& c : cases) {
    Outcome r = bestiary("render " + c.args);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(c.out)) << c.args;
  }
}

TEST_F(RenderCommand, MissingToolsAreNamed) {
  fs::path mp4 = dir / "out.mp4";
  // a viewer folder without render.mjs
  Outcome r = run_command("BESTIARY_VIEWER_DIR=" + dir.string() + " " + BESTIARY_BINARY + " render " +
                          creature("walker.json") + " --out " + mp4.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("render.mjs and node_modules are not in " + dir.string()), std::string::npos) << r.err;
  // a browser that is not there
  r = run_command("BESTIARY_CHROMIUM=" + (dir / "no-chromium").string() + " " + BESTIARY_BINARY +
                  " render " + creature("walker.json") + " --out " + mp4.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("BESTIARY_CHROMIUM: no such program: " + (dir / "no-chromium").string()),
            std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(mp4));
}

TEST_F(RenderCommand, ABrowserThatFailsLeavesNoFile) {
  fs::path mp4 = dir / "out.mp4";
  Outcome r = run_command("BESTIARY_CHROMIUM=/bin/false " + std::string(BESTIARY_BINARY) + " render " +
                          creature("walker.json") + " --seconds 1 --out " + mp4.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("bestiary: render: ", 0), 0u) << r.err;
  EXPECT_FALSE(fs::exists(mp4));
  EXPECT_FALSE(fs::exists(mp4.string() + ".tmp"));
}

}  // namespace
