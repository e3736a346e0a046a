// The river crossing's grid world (Stanton & Channon 2015, "Environment and
// Physical Model"; docs/papers.md S4; docs/rivercrossing.md): the rules one by
// one, and a scripted agent that walks every level to its resource.
#include "task/river/grid_world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>

#include "task/river/scripted_agent.h"

namespace bx {
namespace {

// the first cell of a kind, row by row
std::optional<CellIndex> first_cell(const Grid& g, Cell kind) {
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x)
      if (g.at({x, y}) == kind) return CellIndex{x, y};
  return std::nullopt;
}

// a grass cell of the start side (column < kRiverColumn) that is not the agent's
CellIndex grass_cell(const GridWorld& w) {
  for (int y = 0; y < w.grid().height(); ++y)
    for (int x = 0; x < kRiverColumn; ++x)
      if (w.grid().at({x, y}) == Cell::Grass && CellIndex{x, y} != w.agent()) return {x, y};
  ADD_FAILURE() << "no grass cell";
  return {};
}

// a world on `level` whose agent carries the first stone of its layout
GridWorld carrying_a_stone(std::uint64_t seed, int level) {
  GridWorld w(Rng(seed), level);
  const std::optional<CellIndex> stone = first_cell(w.grid(), Cell::Stone);
  if (!stone) {
    ADD_FAILURE() << "no stone";
    return w;
  }
  w.enter(*stone);
  w.act(1.0);
  EXPECT_TRUE(w.carrying());
  return w;
}

// --- the rules

TEST(RiverGridWorld, StartsOnItsFirstLevelsStartCell) {
  GridWorld w{Rng(3)};
  EXPECT_EQ(w.level(), 1);
  EXPECT_EQ(w.agent(), w.layout().start);
  EXPECT_EQ(w.under_agent(), Cell::Grass);
  EXPECT_EQ(w.score(), 0);
  EXPECT_TRUE(w.alive());
  EXPECT_FALSE(w.carrying());
  EXPECT_EQ(w.changes(), 0);
  EXPECT_EQ(w.levels_completed(), 0);
  Rng rng(3);
  EXPECT_EQ(w.layout(), make_layout(1, rng));
  EXPECT_EQ(GridWorld(Rng(3), 5).level(), 5);
}

TEST(RiverGridWorld, ATrapKills) {
  GridWorld w{Rng(4), 3};
  const std::optional<CellIndex> trap = first_cell(w.grid(), Cell::Trap);
  ASSERT_TRUE(trap);
  w.enter(*trap);
  EXPECT_TRUE(w.alive());  // its death test comes with the action
  w.act(1.0);              // no action saves an agent on a trap
  EXPECT_FALSE(w.alive());
  EXPECT_EQ(w.killed_by(), Cell::Trap);
}

TEST(RiverGridWorld, WaterKills) {
  GridWorld w{Rng(4), 4};
  w.enter({14, 7});
  w.act(0.0);
  EXPECT_FALSE(w.alive());
  EXPECT_EQ(w.killed_by(), Cell::Water);
}

TEST(RiverGridWorld, LeavingWaterWithoutAnActionDrowns) {
  GridWorld w{Rng(4), 4};
  w.enter({14, 7});
  w.enter({13, 7});
  EXPECT_FALSE(w.alive());
  EXPECT_EQ(w.killed_by(), Cell::Water);
  EXPECT_EQ(w.agent(), (CellIndex{14, 7}));  // it died where it stood
}

TEST(RiverGridWorld, ADeathEndsTheEvaluation) {
  GridWorld w{Rng(4), 4};
  w.enter({14, 7});
  w.act(0.0);
  ASSERT_FALSE(w.alive());
  const long changes = w.changes();
  w.enter(w.layout().resource);
  w.act(0.0);
  EXPECT_EQ(w.score(), 0);
  EXPECT_EQ(w.level(), 4);
  EXPECT_EQ(w.agent(), (CellIndex{14, 7}));
  EXPECT_EQ(w.changes(), changes);
}

TEST(RiverGridWorld, PickUpAtAnActionOfOneTenthOnAStone) {
  GridWorld w{Rng(5), 3};
  const std::optional<CellIndex> stone = first_cell(w.grid(), Cell::Stone);
  ASSERT_TRUE(stone);
  w.enter(*stone);
  w.act(std::nextafter(kPickUpAction, 0.0));
  EXPECT_FALSE(w.carrying());
  EXPECT_EQ(w.grid().at(*stone), Cell::Stone);
  EXPECT_EQ(w.changes(), 0);
  w.act(0.1);
  EXPECT_TRUE(w.carrying());
  EXPECT_EQ(w.grid().at(*stone), Cell::Grass);
  EXPECT_EQ(w.grid().count(Cell::Stone), 19);
  EXPECT_EQ(w.changes(), 1);
}

TEST(RiverGridWorld, NothingToPickUpOffAStone) {
  GridWorld w{Rng(5), 3};
  w.enter(grass_cell(w));
  w.act(1.0);
  EXPECT_FALSE(w.carrying());
  EXPECT_EQ(w.changes(), 0);
}

TEST(RiverGridWorld, OneStoneAtATime) {
  GridWorld w = carrying_a_stone(5, 3);
  const std::optional<CellIndex> second = first_cell(w.grid(), Cell::Stone);
  ASSERT_TRUE(second);
  const long changes = w.changes();
  w.enter(*second);
  w.act(1.0);
  EXPECT_TRUE(w.carrying());
  EXPECT_EQ(w.grid().at(*second), Cell::Stone);
  EXPECT_EQ(w.grid().count(Cell::Stone), 19);
  EXPECT_EQ(w.changes(), changes);
}

// the put-down comes before the death test: the agent stands on its bridge
TEST(RiverGridWorld, PutDownOnWaterAtMinusOneTenthBuildsABridgeCell) {
  GridWorld w = carrying_a_stone(6, 4);
  const long changes = w.changes();
  w.enter({14, 9});
  w.act(-0.1);
  EXPECT_TRUE(w.alive());
  EXPECT_FALSE(w.carrying());
  EXPECT_EQ(w.grid().at({14, 9}), Cell::Grass);
  EXPECT_EQ(w.grid().count(Cell::Water), 19);
  ASSERT_EQ(w.bridges().size(), 1u);
  EXPECT_EQ(w.bridges()[0], (CellIndex{14, 9}));
  EXPECT_EQ(w.changes(), changes + 1);
  w.enter(grass_cell(w));  // and walks off it alive
  w.act(0.0);
  EXPECT_TRUE(w.alive());
}

TEST(RiverGridWorld, AnActionJustAboveMinusOneTenthDrowns) {
  GridWorld w = carrying_a_stone(6, 4);
  w.enter({14, 9});
  w.act(std::nextafter(kPutDownAction, 0.0));
  EXPECT_FALSE(w.alive());
  EXPECT_EQ(w.killed_by(), Cell::Water);
  EXPECT_TRUE(w.carrying());
  EXPECT_TRUE(w.bridges().empty());
}

TEST(RiverGridWorld, APutDownOffWaterBuildsNothingAndKeepsTheStone) {
  GridWorld w = carrying_a_stone(6, 4);
  const long changes = w.changes();
  const CellIndex grass = grass_cell(w);
  w.enter(grass);
  w.act(-1.0);
  EXPECT_TRUE(w.carrying());
  EXPECT_EQ(w.grid().at(grass), Cell::Grass);
  EXPECT_TRUE(w.bridges().empty());
  EXPECT_EQ(w.changes(), changes);
}

TEST(RiverGridWorld, FoodGivesOneAndIsEaten) {
  GridWorld w{Rng(7), 1};
  const std::optional<CellIndex> food = first_cell(w.grid(), Cell::Food);
  ASSERT_TRUE(food);
  const int foods = w.grid().count(Cell::Food);
  w.enter(*food);
  EXPECT_EQ(w.score(), 1);
  EXPECT_EQ(w.food_eaten(), 1);
  EXPECT_EQ(w.grid().at(*food), Cell::Grass);
  EXPECT_EQ(w.grid().count(Cell::Food), foods - 1);
  EXPECT_EQ(w.changes(), 1);
  // leaving and coming back finds grass
  w.enter(w.layout().start);
  w.enter(*food);
  EXPECT_EQ(w.score(), 1);
  EXPECT_EQ(w.food_eaten(), 1);
}

TEST(RiverGridWorld, TheResourceGivesOneHundredAndTheNextLevel) {
  GridWorld w{Rng(8), 2};
  w.enter(w.layout().resource);
  EXPECT_EQ(w.score(), 100);
  EXPECT_EQ(w.level(), 3);
  EXPECT_EQ(w.levels_completed(), 1);
  EXPECT_EQ(w.completions(2), 1);
  EXPECT_EQ(w.completions(3), 0);
  EXPECT_EQ(w.changes(), 1);
  EXPECT_EQ(w.agent(), w.layout().start);
  EXPECT_EQ(w.grid().count(Cell::Trap), 8);
  // the new layout continues the world's stream
  Rng rng(8);
  make_layout(2, rng);
  EXPECT_EQ(w.layout(), make_layout(3, rng));
}

TEST(RiverGridWorld, AfterLevelSixComesLevelOne) {
  GridWorld w{Rng(9), 6};
  w.enter(w.layout().resource);
  EXPECT_EQ(w.level(), 1);
  EXPECT_EQ(w.completions(6), 1);
  EXPECT_EQ(w.score(), 100);
  EXPECT_GT(w.grid().count(Cell::Food), 0);
}

TEST(RiverGridWorld, ANewLevelStartsWithoutAStoneOrBridges) {
  GridWorld w = carrying_a_stone(10, 3);
  w.enter(w.layout().resource);
  EXPECT_EQ(w.level(), 4);
  EXPECT_FALSE(w.carrying());
  EXPECT_TRUE(w.bridges().empty());
}

TEST(RiverGridWorld, TheEdgeIsAWall) {
  GridWorld w{Rng(11), 2};  // the dash level: nothing on the edge but grass
  const CellIndex start = w.agent();
  w.enter({-1, start.y});
  EXPECT_EQ(w.agent(), start);
  EXPECT_TRUE(w.alive());
  w.enter({25, -4});
  EXPECT_EQ(w.agent(), (CellIndex{19, 0}));
  w.act(0.0);
  w.enter({20, 30});
  EXPECT_EQ(w.agent(), (CellIndex{19, 19}));
  w.act(0.0);
  EXPECT_TRUE(w.alive());
  EXPECT_EQ(w.score(), 0);
}

// --- a scripted agent

// a perfect walker completes levels 1 to 6 in turn, twice, and every layout
// on the way is one it can solve
TEST(ScriptedRiverAgent, CompletesEveryLevelInTurn) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    GridWorld w{Rng(seed)};
    test::ScriptedAgent agent(w);
    for (int round = 0; round < 2; ++round) {
      for (int level = 1; level <= kRiverLevels; ++level) {
        SCOPED_TRACE(testing::Message() << "seed " << seed << " level " << level);
        ASSERT_EQ(w.level(), level);
        const int stones = w.grid().count(Cell::Stone);
        const int water = w.grid().count(Cell::Water);
        const long changes = w.changes();
        const int width = river_width(level);
        // bridge first, watching the stones move, then reach the resource
        if (width > 0) {
          const std::optional<int> row = agent.crossing_row();
          ASSERT_TRUE(row);
          for (int laid = 0; laid < width; ++laid) {
            const std::optional<CellIndex> stone = agent.nearest(Cell::Stone);
            ASSERT_TRUE(stone);
            ASSERT_TRUE(agent.go_to(*stone, 1.0));
            ASSERT_TRUE(w.carrying());
            ASSERT_TRUE(agent.go_to({kRiverColumn + laid, *row}, -1.0));
            ASSERT_FALSE(w.carrying());
          }
          EXPECT_EQ(w.grid().count(Cell::Stone), stones - width);
          EXPECT_EQ(w.grid().count(Cell::Water), water - width);
          EXPECT_EQ(static_cast<int>(w.bridges().size()), width);
          EXPECT_EQ(w.changes(), changes + 2 * width);
        }
        const int score = w.score();
        const int food = w.food_eaten();
        ASSERT_TRUE(agent.complete_level());
        EXPECT_TRUE(w.alive());
        EXPECT_EQ(w.score(), score + 100 + (w.food_eaten() - food));
        if (level != 1) {
          EXPECT_EQ(w.food_eaten(), food);
        }
      }
    }
    EXPECT_EQ(w.level(), 1);
    EXPECT_EQ(w.levels_completed(), 12);
    for (int level = 1; level <= kRiverLevels; ++level) EXPECT_EQ(w.completions(level), 2);
    EXPECT_EQ(w.score(), 1200 + w.food_eaten());
  }
}

TEST(ScriptedRiverAgent, CompleteLevelBridgesTheRiverItself) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    GridWorld w{Rng(seed), 6};
    test::ScriptedAgent agent(w);
    EXPECT_TRUE(agent.complete_level()) << "seed " << seed;
    EXPECT_EQ(w.level(), 1);
    EXPECT_EQ(w.score(), 100);
  }
}

TEST(ScriptedRiverAgent, WalkingIntoWaterDrowns) {
  GridWorld w{Rng(12), 4};
  test::ScriptedAgent agent(w);
  const std::optional<int> row = agent.crossing_row();
  ASSERT_TRUE(row);
  EXPECT_FALSE(agent.go_to({kRiverColumn, *row}, 0.0));
  EXPECT_FALSE(w.alive());
  EXPECT_EQ(w.killed_by(), Cell::Water);
  EXPECT_EQ(w.agent(), (CellIndex{kRiverColumn, *row}));
}

TEST(ScriptedRiverAgent, CarryingAStoneIntoWaterWithoutPuttingItDownDrowns) {
  GridWorld w{Rng(12), 4};
  test::ScriptedAgent agent(w);
  const std::optional<CellIndex> stone = agent.nearest(Cell::Stone);
  ASSERT_TRUE(stone);
  ASSERT_TRUE(agent.go_to(*stone, 1.0));
  ASSERT_TRUE(w.carrying());
  const std::optional<int> row = agent.crossing_row();
  ASSERT_TRUE(row);
  EXPECT_FALSE(agent.go_to({kRiverColumn, *row}, 0.0));
  EXPECT_EQ(w.killed_by(), Cell::Water);
}

TEST(ScriptedRiverAgent, PuttingAStoneDownOnGrassBuildsNothing) {
  GridWorld w{Rng(13), 4};
  test::ScriptedAgent agent(w);
  const std::optional<CellIndex> stone = agent.nearest(Cell::Stone);
  ASSERT_TRUE(stone);
  ASSERT_TRUE(agent.go_to(*stone, 1.0));
  ASSERT_TRUE(w.carrying());
  const long changes = w.changes();
  const std::optional<int> row = agent.crossing_row();
  ASSERT_TRUE(row);
  const CellIndex bank{kRiverColumn - 1, *row};
  ASSERT_TRUE(agent.go_to(bank, -1.0));
  EXPECT_TRUE(w.carrying());
  EXPECT_EQ(w.grid().at(bank), Cell::Grass);
  EXPECT_TRUE(w.bridges().empty());
  EXPECT_EQ(w.changes(), changes);
  EXPECT_EQ(w.grid().count(Cell::Water), 20);
}

}  // namespace
}  // namespace bx
