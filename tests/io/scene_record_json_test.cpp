// The scene record's JSON form: every item and event comes back as it was
// written (at the file's precision), an empty list is left out, a prop's
// pose is written as a frame's, and a bad record is refused with the path of
// the field and what was wrong.
#include "io/scene_record_json.h"

#include <gtest/gtest.h>

namespace bx {
namespace {

using nlohmann::json;

// one of everything, at values the file's rounding keeps
SceneRecord everything() {
  SceneRecord r;
  r.markers = {{"begin", 0}, {"release", 0.5}};
  r.points = {{"target", {3, -1.25, 0.075}, 0.12, "#d6336c"}};
  // a disc lying on the ground (its axis, x, turned up: a quaternion the
  // file keeps) and a box standing on it turning at 2 rad/s, from 2 s on
  const Mat3 up = from_quat({0.707107, 0, -0.707107, 0});
  r.props = {{"disc", "cylinder", {0.02, 0.6, 0.6}, {{2, 0, 0.01}, up}, 0, 2, "#3b82c4"},
             {"stack", "box", {0.1, 0.1, 0.3}, {{2, 0, 0.17}, Mat3::identity()}, 2, 2, "#e8590c"}};
  r.parts = {{"projectile", 2, "#ffc61a", true}, {"arm", 1, "#3b82c4"}};  // the first scored
  r.cell_kinds = {{"grass", "#a3c98a", false}, {"stone", "#7c838b", true}};
  r.add(0, SceneGrid{{-0.05, 1.5, 0}, 0.1, 3, 2, {0, 1, 0, 0, 0, 1}});
  r.add(0, SceneCounter{"level", 1, {}});
  r.add(0, SceneField{"landscape", 3, 2, -15, 15, {0, 1.5, -15, 0.125, 2.5, 15}});
  r.add(1.25, SceneCell{1, 0, 0});
  r.add(1.25, SceneCarry{0, 1});
  r.add(2, SceneCarry{0, -1});
  r.add(2, SceneCounter{"score", 101, {}});
  r.add(2.5, SceneCounter{"distance", 0.25, "m"});
  return r;
}

TEST(SceneRecordJson, EveryItemAndEventRoundTrips) {
  const SceneRecord r = everything();
  const json j = scene_record_to_json(r);
  // through text, as a replay file carries it
  auto back = scene_record_from_json(json::parse(j.dump()));
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(*back, r);
  EXPECT_EQ(scene_record_to_json(*back), j);
  // the events' form: a time and one payload under its type's name
  EXPECT_EQ(j["events"][3], json::parse(R"({"t": 1.25, "cell": {"x": 1, "y": 0, "kind": 0}})"));
  EXPECT_EQ(j["events"][2]["field"]["range"], json::parse("[-15, 15]"));
  // a counter's unit only where it has one
  EXPECT_EQ(j["events"][6], json::parse(R"({"t": 2, "counter": {"name": "score", "value": 101}})"));
  EXPECT_EQ(j["events"][7], json::parse(R"({"t": 2.5, "counter": {"name": "distance", "value": 0.25, "unit": "m"}})"));
}

TEST(SceneRecordJson, RoundsTimesAndFieldValuesAndLeavesEmptyListsOut) {
  SceneRecord r;
  r.markers = {{"release", 0.5000000001}};
  r.add(1.0 / 3, SceneField{"f", 1, 1, 0, 1, {0.123456}});
  const json j = scene_record_to_json(r);
  EXPECT_EQ(j["markers"][0]["t"], 0.5);
  EXPECT_EQ(j["events"][0]["t"], 0.333333);
  EXPECT_EQ(j["events"][0]["field"]["values"][0], 0.123);
  EXPECT_FALSE(j.contains("points"));
  EXPECT_FALSE(j.contains("props"));
  EXPECT_FALSE(j.contains("cell_kinds"));
  EXPECT_EQ(scene_record_to_json(SceneRecord{}), json::object());
  auto empty = scene_record_from_json(json::object());
  ASSERT_TRUE(empty.ok()) << empty.error();
  EXPECT_TRUE(empty->empty());
}

TEST(SceneRecordJson, APropsPoseIsWrittenAsAFramesIs) {
  const json j = scene_record_to_json(everything());
  EXPECT_EQ(j["props"][0], json::parse(R"({"name": "disc", "shape": "cylinder", "size": [0.02, 0.6, 0.6],
    "pose": [2, 0, 0.01, 0.707107, 0, -0.707107, 0], "spin": 0, "t": 2, "color": "#3b82c4"})"));
  // a hand-written quaternion of 4 digits is near enough unit length: a
  // quarter turn about the vertical, its x axis turned to y
  json hand = j;
  hand["props"][1]["pose"] = json::parse("[1, 2, 3, 0.7071, 0, 0, 0.7071]");
  auto back = scene_record_from_json(hand);
  ASSERT_TRUE(back.ok()) << back.error();
  const Pose& p = back->props[1].pose;
  EXPECT_EQ(p.p, (Vec3{1, 2, 3}));
  const Vec3 x = p.R * Vec3{1, 0, 0};
  EXPECT_NEAR(x.x, 0, 1e-12);
  EXPECT_NEAR(x.y, 1, 1e-12);
  EXPECT_NEAR(x.z, 0, 1e-12);
}

// the error of reading `j` with its part at json pointer `where` replaced by `with`
std::string error_with(const char* where, const json& with) {
  json j = scene_record_to_json(everything());
  j[json::json_pointer(where)] = with;
  auto r = scene_record_from_json(j);
  return r.ok() ? "(read)" : r.error();
}

TEST(SceneRecordJson, ABadRecordNamesTheFieldAndWhatWasWrong) {
  EXPECT_EQ(error_with("/markers/1/t", "soon"), "scene.record.markers[1].t: expected a number, got \"soon\"");
  EXPECT_EQ(error_with("/points/0/color", "red"), "scene.record.points[0].color: expected \"#rrggbb\", got \"red\"");
  EXPECT_EQ(error_with("/props/0/shape", "cone"),
            "scene.record.props[0].shape: expected one of box, sphere, capsule, cylinder, got \"cone\"");
  EXPECT_EQ(error_with("/props/1/size/2", 0), "scene.record.props[1].size: expected extents > 0, got [0.1,0.1,0]");
  EXPECT_EQ(error_with("/props/1/color", "orange"), "scene.record.props[1].color: expected \"#rrggbb\", got \"orange\"");
  EXPECT_EQ(error_with("/props/1/t", -1), "scene.record.props[1].t: expected a time >= 0, got -1");
  EXPECT_EQ(error_with("/props/1/spin", "fast"), "scene.record.props[1].spin: expected a number, got \"fast\"");
  EXPECT_EQ(error_with("/props/1/pose", json::parse("[0, 0, 0, 0.5, 0, 0, 0]")),
            "scene.record.props[1].pose: expected [x, y, z, qw, qx, qy, qz] with a unit quaternion, got [0,0,0,0.5,0,0,0]");
  EXPECT_EQ(error_with("/parts/0/part", -1), "scene.record.parts[0].part: expected a part index >= 0, got -1");
  EXPECT_EQ(error_with("/parts/1/scored", 1), "scene.record.parts[1].scored: expected true or false, got 1");
  EXPECT_EQ(error_with("/cell_kinds/1/item", 1), "scene.record.cell_kinds[1].item: expected true or false, got 1");
  EXPECT_EQ(error_with("/events/0/grid/cells/4", 2),
            "scene.record.events[0].grid.cells[4]: no such cell kind (the record has 2), got 2");
  EXPECT_EQ(error_with("/events/0/grid/cells", json::array({0})),
            "scene.record.events[0].grid.cells: expected 6 cell kinds, got 1");
  EXPECT_EQ(error_with("/events/3/cell/y", 2), "scene.record.events[3].cell.y: outside the grid's 2 rows, got 2");
  EXPECT_EQ(error_with("/events/4/carry/kind", 5),
            "scene.record.events[4].carry.kind: no such cell kind (the record has 2) or -1 for nothing, got 5");
  EXPECT_EQ(error_with("/events/2/field/range", json::array({1, 1})),
            "scene.record.events[2].field.range: expected [lo, hi] with lo < hi, got [1,1]");
  EXPECT_EQ(error_with("/events/5/t", 1), "scene.record.events[5].t: expected a time >= 1.25, got 1");
  EXPECT_EQ(error_with("/events/6", json::parse(R"({"t": 3, "light": {}})")),
            "scene.record.events[6]: expected one of grid, cell, carry, field, counter, got {\"light\":{},\"t\":3}");
  EXPECT_EQ(error_with("/events/1/counter", json::object()), "scene.record.events[1].counter.name: missing");
  EXPECT_EQ(error_with("/events", json::object()), "scene.record.events: expected an array, got {}");
  // a cell cannot change before a grid is laid
  json j = scene_record_to_json(everything());
  j["events"].erase(0);
  EXPECT_EQ(scene_record_from_json(j).error(), "scene.record.events[2].cell: a cell changed before any grid was laid");
}

}  // namespace
}  // namespace bx
