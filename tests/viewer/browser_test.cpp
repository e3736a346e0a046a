// The viewer page in headless Chromium (Debian's chromium; viewer/tools/
// inspect.mjs drives it): it draws the creature, the creature moves, the
// panels are there (the signals panel: a trace per effector, sensor and joint
// dof with its range, "constant" on a constant signal), nothing sticks out
// of its panel, nothing is fetched from outside; and a run's page, at
// 800x600 and 1920x1080, with its lineage picker; a run of stages' syllabus
// graph and each stage's own curve. Screenshots go to BUILD/viewer-test/.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "genome/graph_genotype.h"
#include "run/run.h"
#include "genome/genome_json.h"
#include "io/html_view.h"
#include "io/run_page.h"
#include "support/run_command.h"

namespace {

using namespace bxtest;
using nlohmann::json;

const fs::path kShots = fs::path(BESTIARY_BUILD_DIR) / "viewer-test";

// what inspect.mjs saw of a page
json inspect(const fs::path& page, const std::string& name, const std::string& extra = "") {
  std::string viewer = std::string(BESTIARY_SOURCE_DIR) + "/viewer";
  Outcome r = run_command("node " + viewer + "/tools/inspect.mjs --html " + page.string() +
                          " --shots " + kShots.string() + " --name " + name + " " + extra);
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code == 0 ? json::parse(r.out) : json();
}

class ViewerInBrowser : public InTempDir {};

// the signals panel's group `key` as inspect.mjs read it
const json& group(const json& seen, const std::string& key) {
  for (const auto& g : seen["signals"]["groups"])
    if (g["key"] == key) return g;
  static const json none;
  ADD_FAILURE() << "no group " << key;
  return none;
}

// the badges of the traces of a group, all together
std::vector<std::string> badges(const json& g) {
  std::vector<std::string> out;
  for (const auto& t : g["traces"])
    for (const auto& b : t["badges"]) out.push_back(b.get<std::string>());
  return out;
}

// the panels hold their content, groups close and open, plots follow a resize
void expect_tidy_panels(const json& seen) {
  EXPECT_TRUE(seen["overflow"].empty()) << seen["overflow"];
  const json& c = seen["signals"]["collapse"];
  EXPECT_TRUE(c["closed"].get<bool>()) << c;
  EXPECT_TRUE(c["reopened"].get<bool>()) << c;
  const json& r = seen["signals"]["resize"];
  EXPECT_TRUE(r["fits"].get<bool>()) << r;
  EXPECT_TRUE(r["fitsAfter"].get<bool>()) << r;
  EXPECT_GT(r["width"].get<int>(), 200) << r;  // wider than the old fixed 200 px
}

TEST_F(ViewerInBrowser, DrawsTheWalkerAndItMoves) {
  fs::path page = dir / "walker.html";
  ASSERT_EQ(bestiary("show " + creature("walker.json") + " --out " + page.string()).code, 0);
  json seen = inspect(page, "walker", "--times 1,5");
  ASSERT_FALSE(seen.is_null());
  // offline: the page asked for nothing but itself, and raised no error
  EXPECT_EQ(seen["requests"].size(), 1u) << seen["requests"];
  EXPECT_TRUE(seen["errors"].empty()) << seen["errors"];
  // drawn: many colours, and the coloured parts take a visible share
  for (const auto& m : seen["moments"]) {
    EXPECT_GE(m["colours"]["distinct"].get<int>(), 32) << m;
    EXPECT_GT(m["colours"]["saturated"].get<double>(), 0.005) << m;
    EXPECT_TRUE(fs::exists(m["screenshot"].get<std::string>()));
  }
  // moved: the root part went more than half a metre, and under a still
  // camera the picture changed
  auto a = seen["moments"][0]["state"]["root"], b = seen["moments"][1]["state"]["root"];
  double d = std::hypot(b[0].get<double>() - a[0].get<double>(), b[1].get<double>() - a[1].get<double>());
  EXPECT_GT(d, 0.5);
  EXPECT_GT(seen["orbitChanged"].get<double>(), 0.002);
  // the panels: one plot per neuron (the walker has 4), the player's controls
  EXPECT_EQ(seen["sparklines"], 4);
  EXPECT_GE(seen["player"].get<int>(), 5);
  // the signals: 8 effectors (two per universal joint), 8 sensors (an angle
  // and a contact per leg), 8 joint dofs (4 universal joints), each with its
  // range as text; the oscillating effectors are not constant
  const std::regex range(R"(^-?[0-9.]+(°| m)? \.\. -?[0-9.]+(°| m)?$)");
  for (const char* key : {"effectors", "sensors", "joints"}) {
    const json& g = group(seen, key);
    ASSERT_EQ(g["traces"].size(), 8u) << key;
    EXPECT_NE(g["title"].get<std::string>().find("(8)"), std::string::npos) << g["title"];
    for (const auto& t : g["traces"]) {
      EXPECT_TRUE(std::regex_match(t["range"].get<std::string>(), range)) << t;
      EXPECT_EQ(t["cursor"], "50%") << t;  // the last moment drawn: 5 s of 10
    }
  }
  EXPECT_TRUE(badges(group(seen, "effectors")).empty()) << group(seen, "effectors");
  EXPECT_TRUE(group(seen, "effectors")["badge"].is_null());
  // the joint and dof it drives, and its signal's dominant frequency (the walker's 1.95 Hz gait)
  EXPECT_EQ(group(seen, "effectors")["traces"][3]["label"], "3: joint 1 · dof 1 · 1.95 Hz");
  EXPECT_EQ(group(seen, "joints")["traces"][0]["stops"], "stops -45.8° .. 45.8°");
  expect_tidy_panels(seen);
}

TEST_F(ViewerInBrowser, AConstantEffectorAndAJointHeldAtItsStopAreMarkedAt800x600) {
  // creatures/pinned.json: an effector fixed at -1 holds its hinge at
  // the stop (-0.5 rad); the contact sensor on the top face never touches
  fs::path page = dir / "pinned.html";
  ASSERT_EQ(bestiary("show " + creature("pinned.json") + " --out " + page.string()).code, 0);
  json seen = inspect(page, "pinned", "--times 2 --width 800 --height 600");
  ASSERT_FALSE(seen.is_null());
  EXPECT_TRUE(seen["errors"].empty()) << seen["errors"];
  const json& e = group(seen, "effectors");
  ASSERT_EQ(e["traces"].size(), 1u);
  EXPECT_EQ(e["traces"][0]["range"], "-1.000 .. -1.000");
  EXPECT_EQ(badges(e), std::vector<std::string>{"constant"});
  EXPECT_EQ(e["badge"], "1 constant");
  const json& s = group(seen, "sensors");
  ASSERT_EQ(s["traces"].size(), 2u);
  EXPECT_EQ(s["traces"][0]["label"], "0: contact · part 0 +z");
  EXPECT_EQ(s["traces"][0]["badges"], json::array({"constant"}));
  const json& j = group(seen, "joints");
  ASSERT_EQ(j["traces"].size(), 1u);
  EXPECT_EQ(j["traces"][0]["stops"], "stops -28.6° .. 28.6°");
  ASSERT_EQ(j["traces"][0]["badges"].size(), 1u);
  EXPECT_EQ(j["traces"][0]["badges"][0].get<std::string>().rfind("at stop", 0), 0u) << j;
  expect_tidy_panels(seen);
}

TEST_F(ViewerInBrowser, ACentipedesManySignalsFitAt1920x1080) {
  // 12 parts: 11 hinges and effectors, 24 sensors (the root's angle reads 0)
  fs::path page = dir / "centipede.html";
  ASSERT_EQ(bestiary("show " + creature("centipede.json") + " --seconds 3 --out " + page.string()).code, 0);
  json seen = inspect(page, "centipede", "--times 1 --width 1920 --height 1080");
  ASSERT_FALSE(seen.is_null());
  EXPECT_TRUE(seen["errors"].empty()) << seen["errors"];
  EXPECT_EQ(group(seen, "effectors")["traces"].size(), 11u);
  EXPECT_EQ(group(seen, "sensors")["traces"].size(), 24u);
  EXPECT_EQ(group(seen, "joints")["traces"].size(), 11u);
  EXPECT_EQ(group(seen, "sensors")["traces"][0]["label"], "0: angle · part 0 (root)");
  expect_tidy_panels(seen);
}

TEST_F(ViewerInBrowser, ACatapultsProjectileFliesAwayWithItsTrajectoryDrawn) {
  // creatures/catapult.json releases at 0.5 s and throws about 2.5 m
  fs::path page = dir / "catapult.html";
  ASSERT_EQ(bestiary("show " + creature("catapult.json") + " --out " + page.string()).code, 0);
  json seen = inspect(page, "catapult", "--times 0.2,2.5");
  ASSERT_FALSE(seen.is_null());
  EXPECT_TRUE(seen["errors"].empty()) << seen["errors"];
  const json& before = seen["moments"][0]["state"];
  const json& after = seen["moments"][1]["state"];
  ASSERT_TRUE(before["projectile"].is_array()) << before;
  ASSERT_TRUE(after["projectile"].is_array()) << after;
  // before the release no flight is drawn; after it the tube is there
  EXPECT_FALSE(before["flight"].get<bool>());
  EXPECT_TRUE(after["flight"].get<bool>());
  // the projectile left the arm: far from the root, while it rode near it
  auto gap = [](const json& s) {
    return std::hypot(s["projectile"][0].get<double>() - s["root"][0].get<double>(),
                      s["projectile"][1].get<double>() - s["root"][1].get<double>());
  };
  EXPECT_LT(gap(before) + 0.5, gap(after)) << before << after;
  EXPECT_GT(gap(after), 0.8) << after;
}

TEST_F(ViewerInBrowser, ARiverCrossingsGridStonesHeatMapAndCountersAreDrawn) {
  // a river creature of fixed genes on level 4: a river, 8 traps, 20 stones
  fs::path genes = dir / "river.json", cfg = dir / "river.toml", page = dir / "river.html";
  json g = {{"format", "bestiary-genotype"}, {"version", 1}, {"kind", "floats"}, {"genes", json::array()}};
  for (int k = 0; k < 181; ++k) g["genes"].push_back(std::round(3000 * std::sin(k * 1.7)) / 1000);
  std::ofstream(genes) << g.dump();
  std::ofstream(cfg) << "[genotype]\nkind = \"river\"\n[task]\nkind = \"river\"\n[river]\nseconds = 3\nfirst_level = 4\n"
                        "[motor]\nmodel = \"pd\"\n[physics]\npowered_stops = \"separate\"\n";
  Outcome shown = bestiary("show " + genes.string() + " --config " + cfg.string() + " --out " + page.string());
  ASSERT_EQ(shown.code, 0) << shown.err;
  json seen = inspect(page, "river", "--times 0.5,2.5 --width 800 --height 600");
  ASSERT_FALSE(seen.is_null());
  EXPECT_TRUE(seen["errors"].empty()) << seen["errors"];
  for (const auto& m : seen["moments"]) {
    const json& scene = m["state"]["scene"];
    ASSERT_TRUE(scene.is_object()) << m;
    EXPECT_EQ(scene["grid"], json::array({20, 20}));
    EXPECT_GE(scene["items"].get<int>(), 19) << scene;  // the stones, one perhaps carried
    EXPECT_TRUE(scene["field"].is_number()) << scene;   // the landscape's heat map
    EXPECT_TRUE(scene["heat"].get<bool>());
    EXPECT_EQ(m["state"]["counters"][0], json::array({"level", 4, ""})) << m["state"]["counters"];
    EXPECT_EQ(m["state"]["counters"][2][0], "deaths");
  }
  // the legend names the kinds and the heat map's scale, and fits its box
  ASSERT_TRUE(seen["cells"].is_array()) << seen["cells"];
  EXPECT_EQ(seen["cells"][0], "grass");
  EXPECT_EQ(seen["cells"][3], "stone");
  EXPECT_EQ(seen["cells"].back().get<std::string>().rfind("landscape -15", 0), 0u) << seen["cells"];
  EXPECT_TRUE(seen["overflow"].empty()) << seen["overflow"];
}

TEST_F(ViewerInBrowser, DevelopmentRemarksAreMutedNotesNotErrors) {
  // creatures/lcp_failure.json: two neuron inputs whose source the body
  // lacks (they read 0), as evolved genomes often have; it does not fail
  fs::path page = dir / "remarks.html";
  ASSERT_EQ(bestiary("show " + creature("lcp_failure.json") + " --seconds 1 --out " + page.string()).code, 0);
  json seen = inspect(page, "remarks", "--times 0.5");
  ASSERT_FALSE(seen.is_null());
  const json& info = seen["info"];
  ASSERT_EQ(info["notes"].size(), 2u) << info;
  EXPECT_EQ(info["notes"][0]["text"], "nodes[2].neurons[0].inputs[0]: its source does not exist in this body; it reads 0");
  for (const auto& n : info["notes"]) EXPECT_EQ(n["color"], "rgb(110, 119, 129)") << n;  // the muted grey, not red
  EXPECT_TRUE(info["warnings"].empty()) << info;
}

// ---- the run page, on a small real run ----

class RunPageInBrowser : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fs::temp_directory_path() / ("bx_run_page_browser_" + std::to_string(::getpid())));
    fs::remove_all(*dir_);
    Outcome r = small_run(*dir_);
    ASSERT_EQ(r.code, 0) << r.err;
    r = bestiary("show " + dir_->string());
    ASSERT_EQ(r.code, 0) << r.err;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static fs::path page() { return *dir_ / "view.html"; }
  std::unique_ptr<bx::RunStore> store() {
    auto s = bx::RunStore::open(bx::run_db_path(dir_->string()));
    EXPECT_TRUE(s.ok()) << s.error();
    return s.ok() ? std::move(*s) : nullptr;
  }
  static fs::path* dir_;
};
fs::path* RunPageInBrowser::dir_ = nullptr;

// what a run page must show at any size: nothing out of its panel, a chart
// as wide as its panel with a title, axis labels, readable ticks and a
// marker unlike any curve, the run's context, and per generation its
// rejected and failed counts
void expect_run_page_layout(const json& seen, const std::vector<bx::GenerationStats>& gens) {
  EXPECT_TRUE(seen["errors"].empty()) << seen["errors"];
  EXPECT_TRUE(seen["overflow"].empty()) << seen["overflow"];
  const json& r = seen["run"];
  ASSERT_TRUE(r["shown"].get<bool>());
  EXPECT_TRUE(r["overflow"].empty()) << r["overflow"];
  const json& c = r["chart"];
  EXPECT_NEAR(c["width"].get<double>(), c["panel"].get<double>(), 1) << c;
  EXPECT_GE(c["height"].get<double>(), 170) << c;
  EXPECT_EQ(c["title"], "Fitness per generation");
  EXPECT_EQ(c["axisLabels"], json::array({"generation", "fitness"}));
  EXPECT_GE(c["tickFont"].get<double>(), 11);
  ASSERT_EQ(c["curves"].size(), 3u);
  for (const auto& k : c["curves"]) {
    EXPECT_EQ(k["points"], static_cast<int>(gens.size())) << k;
    EXPECT_NE(k["stroke"], c["marker"]) << k;
  }
  EXPECT_EQ(r["legend"], json::array({"best", "mean", "median", "lineage", "shown"}));
  EXPECT_EQ(r["facts"]["preset"], "quick (chaumont2007, generational)");
  EXPECT_EQ(r["facts"]["master seed"], "1");
  EXPECT_EQ(r["facts"]["population"], "12");
  EXPECT_EQ(r["facts"]["generations"], "6 of 6");
  // the table: a header, then gen, best, mean, rejected, failed per generation
  ASSERT_EQ(r["table"].size(), gens.size() + 1);
  for (std::size_t g = 0; g < gens.size(); ++g) {
    const json& row = r["table"][g + 1];
    EXPECT_EQ(row[0], std::to_string(gens[g].generation));
    EXPECT_EQ(row[3], std::to_string(gens[g].rejected));
    EXPECT_EQ(row[4], std::to_string(gens[g].failed));
  }
}

TEST_F(RunPageInBrowser, FitsItsPanelsAt800x600) {
  json seen = inspect(page(), "run_800x600", "--times 1 --width 800 --height 600 --run");
  ASSERT_FALSE(seen.is_null());
  expect_run_page_layout(seen, store()->generations());
  expect_tidy_panels(seen);
}

TEST_F(RunPageInBrowser, FitsItsPanelsAt1920x1080) {
  json seen = inspect(page(), "run_1920x1080", "--times 1 --width 1920 --height 1080 --run");
  ASSERT_FALSE(seen.is_null());
  expect_run_page_layout(seen, store()->generations());
  expect_tidy_panels(seen);
  // the wider panel gives the chart more room
  EXPECT_GT(seen["run"]["chart"]["width"].get<double>(), 400);
}

TEST_F(RunPageInBrowser, OpensOnTheBestAndPlaysEachAncestorInItsLineage) {
  auto s = store();
  ASSERT_TRUE(s);
  const std::int64_t best = s->best_individual()->id;
  json seen = inspect(page(), "run_lineage", "--times 1 --run");
  ASSERT_FALSE(seen.is_null());
  EXPECT_TRUE(seen["errors"].empty()) << seen["errors"];
  const json& r = seen["run"];
  // opened on the overall best, its fitness the stored one (or, for an elite
  // evaluated again, the stored mean beside the replayed first evaluation)
  EXPECT_EQ(r["opened"]["individual"], best);
  EXPECT_EQ(r["opened"]["storedFitness"].get<double>(), s->best_individual()->fitness);
  EXPECT_EQ(r["opened"]["evaluations"], s->best_individual()->evaluations);
  if (s->best_individual()->evaluations == 1) {
    EXPECT_EQ(r["opened"]["fitness"], r["opened"]["storedFitness"]);
  }
  // its lineage: the best, then each first parent back to generation 0
  std::vector<std::int64_t> line;
  for (std::int64_t at = best; at >= 0; at = s->individual(at)->parent1) line.push_back(at);
  ASSERT_GE(line.size(), 2u) << "the small run's best should descend from generation 0";
  ASSERT_EQ(r["lineage"].size(), line.size()) << r["lineage"];
  for (std::size_t k = 0; k < line.size(); ++k) {
    EXPECT_EQ(r["lineage"][k]["id"], line[k]);
    EXPECT_TRUE(r["lineage"][k]["playable"].get<bool>());
    EXPECT_EQ(r["lineage"][k]["current"].get<bool>(), k == 0);
  }
  // each ancestor, clicked, is played: its id and replay, its stored fitness;
  // the list stays the best's, with the ancestor marked
  ASSERT_EQ(r["ancestors"].size(), line.size() - 1);
  std::set<int> replays{r["opened"]["replayIndex"].get<int>()};
  for (const auto& a : r["ancestors"]) {
    EXPECT_EQ(a["individual"], a["clicked"]) << a;
    EXPECT_TRUE(replays.insert(a["replayIndex"].get<int>()).second) << a;
    auto stored = s->individual(a["clicked"].get<std::int64_t>());
    EXPECT_EQ(a["storedFitness"].get<double>(), stored->fitness) << a;
    EXPECT_EQ(a["evaluations"], stored->evaluations) << a;
    if (stored->evaluations == 1) {
      EXPECT_EQ(a["fitness"].get<double>(), stored->fitness) << a;
    }
    EXPECT_EQ(a["label"], "individual " + std::to_string(a["clicked"].get<std::int64_t>()) + ", generation " +
                              std::to_string(s->individual(a["clicked"].get<std::int64_t>())->generation));
    EXPECT_EQ(a["anchor"], best) << a;
    EXPECT_EQ(a["current"], json::array({a["clicked"]})) << a;
  }
  EXPECT_EQ(r["ancestors"].back()["individual"], line[1]);  // the parent last
  // the list of generations: generation 0's best; the chart's right end: the last generation's
  auto gens = s->generations();
  EXPECT_EQ(r["afterSelect"]["individual"], gens.front().best_id);
  EXPECT_EQ(r["afterSelect"]["generation"], 0);
  EXPECT_EQ(r["afterClick"]["individual"], gens.back().best_id);
  // the download is the shown creature's genome file
  auto shown = s->individual(r["afterClick"]["individual"].get<std::int64_t>());
  EXPECT_EQ(r["download"]["name"], "individual-" + std::to_string(shown->id) + ".json");
  EXPECT_EQ(r["download"]["text"], bx::genome_to_string(*bx::graph_genome(*shown->genotype)));
}

TEST_F(RunPageInBrowser, MarksTheCreaturesItCouldNotReplayUnderACap) {
  // the same run with room for two replays: the best and its parent
  auto s = store();
  ASSERT_TRUE(s);
  auto cfg = bx::read_run_config(s->meta("config"), "run config");
  ASSERT_TRUE(cfg.ok()) << cfg.error();
  auto data = bx::gather_run_page(*s, dir_->string(), *cfg, cfg->sim, 1, 2);
  ASSERT_TRUE(data.ok()) << data.error();
  fs::path capped = *dir_ / "capped.html";
  ASSERT_TRUE(bx::save_view_html(capped.string(), data->replays, data->run).ok());
  json seen = inspect(capped, "run_capped", "--times 1 --run");
  ASSERT_FALSE(seen.is_null());
  EXPECT_TRUE(seen["errors"].empty()) << seen["errors"];
  const json& r = seen["run"];
  // the page says what it left out, and why
  ASSERT_EQ(r["notes"].size(), 1u);
  EXPECT_NE(r["notes"][0].get<std::string>().find("not replayed: the page holds at most 2 replays"), std::string::npos)
      << r["notes"];
  EXPECT_EQ(r["facts"]["replays"], "2 of the " + std::to_string(data->run.members.size()) +
                                       " creatures named (at most 2)");
  // the lineage's oldest members are listed but cannot be played; the parent can
  const json& line = r["lineage"];
  ASSERT_GE(line.size(), 3u) << line;
  EXPECT_TRUE(line[1]["playable"].get<bool>());
  EXPECT_FALSE(line.back()["playable"].get<bool>());
  EXPECT_NE(line.back()["text"].get<std::string>().find("not replayed"), std::string::npos);
  ASSERT_EQ(r["ancestors"].size(), 1u);
  EXPECT_EQ(r["ancestors"][0]["individual"], line[1]["id"]);
  // a generation whose best has no replay is offered but cannot be chosen
  int disabled = 0;
  for (const auto& o : r["options"]) disabled += o["disabled"].get<bool>() && o["value"] != "";
  EXPECT_GT(disabled, 0) << r["options"];
}

// ---- a run of several stages: its syllabus ----

// four stages of two generations, stopped in the third: two groups, an
// edge per use, a stage not begun
const char* kSyllabus = R"(
[genome]
dialect = "sims1994"
[evolution]
population = 6
generations = 2
[task]
seconds = 1

[[stage]]
name = "forward"

[[stage]]
name = "left"
group = "turn"

[[stage]]
name = "face"
uses = ["forward", "left"]
group = "aim"

[[stage]]
name = "fight"
uses = ["face"]
)";

TEST_F(ViewerInBrowser, ARunOfStagesShowsItsSyllabusAndEachStagesOwnCurveAt800x600) {
  const fs::path cfg = write("syllabus.toml", kSyllabus), run = dir / "r";
  Outcome r = bestiary("run " + cfg.string() + " --workers 0 --quiet --stop-after 5 --out " + run.string());
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(bestiary("show " + run.string()).code, 0);
  json seen = inspect(run / "view.html", "run_syllabus", "--times 0.5 --width 800 --height 600 --run");
  ASSERT_FALSE(seen.is_null());
  EXPECT_TRUE(seen["errors"].empty()) << seen["errors"];
  EXPECT_TRUE(seen["run"]["overflow"].empty()) << seen["run"]["overflow"];
  EXPECT_EQ(seen["run"]["facts"]["stages"], "3 of 4 begun");
  ASSERT_TRUE(seen["run"].contains("syllabus")) << "no syllabus graph";
  const json& sy = seen["run"]["syllabus"];
  // the graph: a box per stage in columns by depth, an edge per use, the groups
  const json& g = sy["opened"];
  ASSERT_EQ(g["stages"].size(), 4u);
  std::vector<std::string> names;
  for (const auto& st : g["stages"]) names.push_back(st["name"]);
  EXPECT_EQ(names, (std::vector<std::string>{"forward", "left", "face", "fight"}));
  EXPECT_EQ(g["stages"][0]["x"], g["stages"][1]["x"]);
  EXPECT_LT(g["stages"][1]["x"].get<double>(), g["stages"][2]["x"].get<double>());
  EXPECT_LT(g["stages"][2]["x"].get<double>(), g["stages"][3]["x"].get<double>());
  std::set<std::pair<int, int>> edges;
  for (const auto& e : g["edges"]) edges.insert({e[0].get<int>(), e[1].get<int>()});
  EXPECT_EQ(edges, (std::set<std::pair<int, int>>{{0, 2}, {1, 2}, {2, 3}}));
  EXPECT_EQ(g["groups"], json::array({"turn", "aim"}));
  EXPECT_NE(g["stages"][0]["stroke"], g["stages"][1]["stroke"]);  // no group, turn, aim: three colours
  EXPECT_NE(g["stages"][1]["stroke"], g["stages"][2]["stroke"]);
  EXPECT_FALSE(g["stages"][3]["begun"].get<bool>());
  EXPECT_EQ(g["stages"][3]["best"], "not begun");
  // it opens on the best's stage, face (the run's generation 4), its curve alone
  EXPECT_TRUE(g["stages"][2]["picked"].get<bool>());
  EXPECT_TRUE(g["stages"][2]["shown"].get<bool>());
  EXPECT_EQ(g["chart"]["axisLabels"], json::array({"generation of face", "fitness"}));
  EXPECT_EQ(g["chart"]["points"], json::array({1, 1, 1}));
  // each begun stage, picked: its own generations, and a click at the right
  // end plays its last generation's best (the run's generation 1, 3, 4)
  ASSERT_EQ(sy["picked"].size(), 3u);
  const int last_gen[] = {1, 3, 4}, gens[] = {2, 2, 1};
  for (int k = 0; k < 3; ++k) {
    const json& p = sy["picked"][k];
    EXPECT_EQ(p["chart"]["axisLabels"][0], "generation of " + names[k]) << k;
    EXPECT_NE(p["chart"]["title"].get<std::string>().find("stage " + names[k]), std::string::npos) << p["chart"];
    EXPECT_EQ(p["chart"]["points"], json::array({gens[k], gens[k], gens[k]})) << k;
    EXPECT_EQ(p["afterClick"]["generation"], last_gen[k]) << k;
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(p["graph"]["stages"][i]["picked"].get<bool>(), i == k) << k << " " << i;
      EXPECT_EQ(p["graph"]["stages"][i]["shown"].get<bool>(), i == k) << k << " " << i;
    }
  }
  // and the whole run's curve
  EXPECT_EQ(sy["whole"]["axisLabels"][0], "generation");
  EXPECT_EQ(sy["whole"]["points"], json::array({5, 5, 5}));
}

}  // namespace
