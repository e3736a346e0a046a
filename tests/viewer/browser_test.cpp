// The viewer page in headless Chromium (Debian's chromium; viewer/tools/
// inspect.mjs drives it): it draws the creature, the creature moves, the
// panels are there (the signals panel: a trace per effector, sensor and joint
// dof with its range, "constant" on a constant signal), nothing sticks out
// of its panel and nothing is fetched from outside. Screenshots go to
// BUILD/viewer-test/.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <regex>
#include <string>

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
  EXPECT_EQ(group(seen, "effectors")["traces"][3]["label"], "3: joint 1 · dof 1");
  EXPECT_EQ(group(seen, "joints")["traces"][0]["stops"], "stops -45.8° .. 45.8°");
  expect_tidy_panels(seen);
}

TEST_F(ViewerInBrowser, AConstantEffectorAndAJointHeldAtItsStopAreMarkedAt800x600) {
  // tests/creatures/pinned.json: an effector fixed at -1 holds its hinge at
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
  // tests/creatures/catapult.json releases at 0.5 s and throws about 2.5 m
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

}  // namespace
