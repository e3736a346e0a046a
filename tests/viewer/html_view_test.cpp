// The viewer page's data: the shape the page reads, a run's curves, and data
// that cannot break out of its script tag.
#include "io/html_view.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "support/run_command.h"

namespace {

using nlohmann::json;

const char* kTinyReplay = R"({"format":"bestiary-replay","version":1,"frames":[]})"
                          "\n";

TEST(ViewData, HoldsLabelledReplaysAndNoRun) {
  auto d = json::parse(bx::view_data_json({{"walker", kTinyReplay}}, std::nullopt));
  ASSERT_EQ(d["replays"].size(), 1u);
  EXPECT_EQ(d["replays"][0]["label"], "walker");
  EXPECT_EQ(d["replays"][0]["replay"], json::parse(kTinyReplay));
  EXPECT_TRUE(d["run"].is_null());
}

TEST(ViewData, HoldsARunsCurvesAndTheBestOfEachGeneration) {
  bx::RunCurves run;
  run.generations = {{0, 1.5, 0.5, 0.25}, {1, 2.5, 1.0, 0.75}};
  run.best_of_generation = {{0, 0}, {1, 1}};
  auto d = json::parse(bx::view_data_json({{"g0", kTinyReplay}, {"g1", kTinyReplay}}, run));
  EXPECT_EQ(d["run"]["generations"][1],
            json::parse(R"({"gen":1,"best":2.5,"mean":1.0,"median":0.75})"));
  EXPECT_EQ(d["run"]["best_of_generation"][1], json::parse(R"({"gen":1,"replay_index":1})"));
}

TEST(ViewHtml, EmbedsTheDataOnceInThePage) {
  std::string html = bx::make_view_html({{"walker", kTinyReplay}});
  EXPECT_EQ(html.rfind("<!doctype html>", 0), 0u);
  EXPECT_EQ(html.find("@BESTIARY_DATA@"), std::string::npos);
  auto d = json::parse(bxtest::embedded_data(html));
  EXPECT_EQ(d["replays"][0]["label"], "walker");
  // the page is whole: three.js and the viewer inlined, nothing fetched
  EXPECT_NE(html.find("</html>"), std::string::npos);
  EXPECT_EQ(html.find("<script src"), std::string::npos);
  EXPECT_GT(html.size(), 200000u);
}

TEST(ViewHtml, TextThatLooksLikeATagStaysInsideTheData) {
  std::string label = "</script><script>alert(1)</script><!--";
  std::string html = bx::make_view_html({{label, kTinyReplay}});
  std::string data = bxtest::embedded_data(html);
  EXPECT_EQ(data.find('<'), std::string::npos);
  EXPECT_EQ(json::parse(data)["replays"][0]["label"], label);
}

}  // namespace
