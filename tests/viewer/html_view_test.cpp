// The viewer page's data: the shape the page reads, a run with its members
// and their genomes (and its stages when it has several), and data that
// cannot break out of its script tag.
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

TEST(ViewData, HoldsARunItsMembersAndGenomes) {
  bx::RunView run;
  run.name = "quick";
  run.seed = "18446744073709551615";
  run.population = 10;
  run.generations = {{0, 1.5, 0.5, 0.25, 3, 10, 2, 1}, {1, 2.5, 1.0, 0.75, 12, 20, 0, 0}};
  run.members = {{3, 0, 1.5, -1, -1, "random", 0}, {12, 1, 2.5, 3, 7, "crossover", 1, 3}, {7, 0, 0.5, -1, -1, "random", -1}};
  run.best_id = 12;
  run.replay_cap = 2;
  auto d = json::parse(bx::view_data_json({{"g0", kTinyReplay}, {"g1", kTinyReplay, "{\"format\": \"bestiary-genome\"}\n"}}, run));
  EXPECT_EQ(d["replays"][0].count("genome"), 0u);  // none given: none written
  EXPECT_EQ(d["replays"][1]["genome"], "{\"format\": \"bestiary-genome\"}\n");
  EXPECT_EQ(d["run"]["seed"], "18446744073709551615");
  EXPECT_EQ(d["run"]["generations"][0],
            json::parse(R"({"gen":0,"best":1.5,"mean":0.5,"median":0.25,"best_id":3,"evaluations":10,"rejected":2,"failed":1})"));
  EXPECT_EQ(d["run"]["members"][1],
            json::parse(R"({"id":12,"gen":1,"fitness":2.5,"parent1":3,"parent2":7,"operator":"crossover","replay_index":1,"evaluations":3})"));
  // no parent, no replay: null
  EXPECT_TRUE(d["run"]["members"][2]["parent1"].is_null());
  EXPECT_TRUE(d["run"]["members"][2]["replay_index"].is_null());
  EXPECT_EQ(d["run"]["best_id"], 12);
  EXPECT_EQ(d["run"]["replay_cap"], 2);
}

TEST(ViewData, ARunOfSeveralStagesListsThemAPlainRunNone) {
  bx::RunView run;
  run.generations = {{0, 1.5, 0.5, 0.25, 3, 10, 0, 0}, {1, 0.5, 0.25, 0.25, 9, 20, 0, 0}};
  run.members = {{3, 0, 1.5, -1, -1, "random", 0}};
  run.best_id = 3;
  // a plain run's data is as it was before stages
  EXPECT_FALSE(json::parse(bx::view_data_json({{"g0", kTinyReplay}}, run))["run"].contains("stages"));
  run.stages = {{"left", {}, "turn", 0, 1, 1.5}, {"face", {"left"}, "", 1, 1, 0.5}, {"fight", {"left", "face"}, "react"}};
  auto d = json::parse(bx::view_data_json({{"g0", kTinyReplay}}, run));
  ASSERT_EQ(d["run"]["stages"].size(), 3u);
  EXPECT_EQ(d["run"]["stages"][0],
            json::parse(R"({"name":"left","uses":[],"group":"turn","first_gen":0,"generations":1,"best":1.5})"));
  EXPECT_EQ(d["run"]["stages"][1],
            json::parse(R"({"name":"face","uses":["left"],"group":"","first_gen":1,"generations":1,"best":0.5})"));
  // not begun: no first generation, no best
  EXPECT_EQ(d["run"]["stages"][2], json::parse(R"({"name":"fight","uses":["left","face"],"group":"react",)"
                                               R"("first_gen":null,"generations":0,"best":null})"));
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
