// The river crossing's world as a replay records it: the grid when a level
// is laid, then only what changed between calls: a stone picked up (its
// cell turns grass, the torso carries it), put down on water (a bridge cell,
// nothing carried), the level, score and deaths. A scripted agent plays the
// grid world; the scene is recorded between its moves.
#include "task/river/river_scene.h"

#include <gtest/gtest.h>

#include <variant>

#include "task/river/scripted_agent.h"

namespace bx {
namespace {

constexpr Vec3 kOrigin{-0.05, -1.05, 0};
constexpr double kCell = 0.1;

// the events appended since `from`
std::vector<SceneEvent> since(const SceneRecord& r, std::size_t from) {
  return {r.events.begin() + static_cast<std::ptrdiff_t>(from), r.events.end()};
}

TEST(RiverScene, TheKindsAreTheCellsInTheirOrderThenTheBridge) {
  const std::vector<SceneCellKind> kinds = river_scene_kinds();
  ASSERT_EQ(kinds.size(), 7u);
  const char* names[] = {"grass", "resource", "food", "stone", "water", "trap", "bridge"};
  for (std::size_t k = 0; k < kinds.size(); ++k) EXPECT_EQ(kinds[k].name, names[k]);
  EXPECT_EQ(kinds[static_cast<int>(Cell::Stone)].name, "stone");
  EXPECT_EQ(kinds[kBridgeKind].name, "bridge");
  // only a stone is an item: a box on its cell, or carried
  for (std::size_t k = 0; k < kinds.size(); ++k) EXPECT_EQ(kinds[k].item, k == 3) << kinds[k].name;
}

TEST(RiverScene, TheFirstCallLaysTheGridAndTheCounters) {
  GridWorld w{Rng(12), 4};
  RiverScene scene(0);
  SceneRecord r;
  scene.record(0, w, kOrigin, kCell, r);
  EXPECT_EQ(r.cell_kinds, river_scene_kinds());
  ASSERT_EQ(r.events.size(), 4u);
  ASSERT_TRUE(std::holds_alternative<SceneGrid>(r.events[0].what));
  const SceneGrid& g = std::get<SceneGrid>(r.events[0].what);
  EXPECT_EQ(g.origin, kOrigin);
  EXPECT_EQ(g.cell, kCell);
  EXPECT_EQ(g.width, 20);
  EXPECT_EQ(g.height, 20);
  ASSERT_EQ(g.cells.size(), 400u);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) ASSERT_EQ(g.cells[static_cast<std::size_t>(20 * y + x)], static_cast<int>(w.grid().at({x, y})));
  EXPECT_EQ(std::get<SceneCounter>(r.events[1].what), (SceneCounter{"level", 4, {}}));
  EXPECT_EQ(std::get<SceneCounter>(r.events[2].what), (SceneCounter{"score", 0, {}}));
  EXPECT_EQ(std::get<SceneCounter>(r.events[3].what), (SceneCounter{"deaths", 0, {}}));
  // nothing changed: nothing more
  scene.record(0.5, w, kOrigin, kCell, r);
  EXPECT_EQ(r.events.size(), 4u);
}

TEST(RiverScene, AStonePickedUpAndPutDownAsABridgeIsRecordedWithItsCarrying) {
  GridWorld w{Rng(12), 4};
  test::ScriptedAgent agent(w);
  RiverScene scene(0);
  SceneRecord r;
  scene.record(0, w, kOrigin, kCell, r);
  // picked up: its cell turns grass, the torso carries a stone
  const std::optional<CellIndex> stone = agent.nearest(Cell::Stone);
  ASSERT_TRUE(stone);
  ASSERT_TRUE(agent.go_to(*stone, 1.0));
  ASSERT_TRUE(w.carrying());
  std::size_t from = r.events.size();
  scene.record(1.5, w, kOrigin, kCell, r);
  EXPECT_EQ(since(r, from), (std::vector<SceneEvent>{{1.5, SceneCell{stone->x, stone->y, static_cast<int>(Cell::Grass)}},
                                                     {1.5, SceneCarry{0, static_cast<int>(Cell::Stone)}}}));
  // put down on the river: a bridge cell, nothing carried
  const std::optional<int> row = agent.crossing_row();
  ASSERT_TRUE(row);
  ASSERT_TRUE(agent.go_to({kRiverColumn, *row}, -1.0));
  ASSERT_FALSE(w.carrying());
  from = r.events.size();
  scene.record(3.25, w, kOrigin, kCell, r);
  EXPECT_EQ(since(r, from), (std::vector<SceneEvent>{{3.25, SceneCell{kRiverColumn, *row, kBridgeKind}},
                                                     {3.25, SceneCarry{0, -1}}}));
  EXPECT_EQ(river_scene_cells(w)[static_cast<std::size_t>(*row * 20 + kRiverColumn)], kBridgeKind);
  // the level completed: the next grid is laid where the caller says, the level and score move on
  ASSERT_TRUE(agent.complete_level());
  const Vec3 moved{1, 2, 0};
  from = r.events.size();
  scene.record(9, w, moved, kCell, r);
  const std::vector<SceneEvent> next = since(r, from);
  ASSERT_EQ(next.size(), 3u);
  ASSERT_TRUE(std::holds_alternative<SceneGrid>(next[0].what));
  EXPECT_EQ(std::get<SceneGrid>(next[0].what).origin, moved);
  EXPECT_EQ(std::get<SceneGrid>(next[0].what).cells, river_scene_cells(w));
  EXPECT_EQ(next[1], (SceneEvent{9, SceneCounter{"level", 5, {}}}));
  EXPECT_EQ(next[2], (SceneEvent{9, SceneCounter{"score", 100, {}}}));
}

TEST(RiverScene, ADeathIsCounted) {
  GridWorld w{Rng(12), 4};
  test::ScriptedAgent agent(w);
  RiverScene scene(0);
  SceneRecord r;
  scene.record(0, w, kOrigin, kCell, r);
  const std::optional<int> row = agent.crossing_row();
  ASSERT_TRUE(row);
  EXPECT_FALSE(agent.go_to({kRiverColumn, *row}, 0.0));
  const std::size_t from = r.events.size();
  scene.record(2, w, kOrigin, kCell, r);
  EXPECT_EQ(since(r, from), (std::vector<SceneEvent>{{2, SceneCounter{"deaths", 1, {}}}}));
}

}  // namespace
}  // namespace bx
