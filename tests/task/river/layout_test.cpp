// The river crossing's six levels (Stanton & Channon 2015, "Environment and
// Physical Model"; docs/papers.md S4; docs/rivercrossing.md): what each layout
// holds and where, its determinism, and the solvability check.
#include "task/river/layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace bx {
namespace {

TEST(RiverLayout, RiverWidthsPerLevel) {
  const std::vector<int> widths{0, 0, 0, 1, 2, 4};
  for (int level = 1; level <= kRiverLevels; ++level) EXPECT_EQ(river_width(level), widths[level - 1]);
}

TEST(RiverLayout, ASeedGivesOneLayout) {
  for (int level = 1; level <= kRiverLevels; ++level) {
    Rng a(42), b(42);
    EXPECT_EQ(make_layout(level, a), make_layout(level, b)) << "level " << level;
  }
}

TEST(RiverLayout, SeedsGiveDifferentLayouts) {
  for (int level = 1; level <= kRiverLevels; ++level) {
    std::vector<Layout> layouts;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      Rng rng(seed);
      layouts.push_back(make_layout(level, rng));
    }
    int distinct_pairs = 0;
    for (std::size_t i = 0; i < layouts.size(); ++i)
      for (std::size_t j = i + 1; j < layouts.size(); ++j) distinct_pairs += layouts[i] != layouts[j];
    if (level == 2) {
      // the dash level differs only in its start row (1 of 20): most pairs differ
      EXPECT_GE(distinct_pairs, 30) << "level 2";
    } else {
      EXPECT_EQ(distinct_pairs, 45) << "level " << level;
    }
  }
}

// every level's cells, over many seeds: the river's full columns, the
// resource's cell, the start, and the counts; no two things share a cell, so
// each count is exact
TEST(RiverLayout, EachLevelHoldsWhatThePaperSays) {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    Rng rng(seed);
    for (int level = 1; level <= kRiverLevels; ++level) {
      SCOPED_TRACE(testing::Message() << "seed " << seed << " level " << level);
      const Layout l = make_layout(level, rng);
      const Grid& g = l.grid;
      const int w = river_width(level);
      EXPECT_EQ(l.river_width, w);
      ASSERT_EQ(g.width(), 20);
      ASSERT_EQ(g.height(), 20);

      // the river: columns 14 .. 13 + w, every row, and no other water
      for (int y = 0; y < g.height(); ++y)
        for (int x = 0; x < g.width(); ++x)
          EXPECT_EQ(g.at({x, y}) == Cell::Water, x >= 14 && x < 14 + w) << x << "," << y;
      EXPECT_EQ(g.count(Cell::Water), 20 * w);

      EXPECT_EQ(l.resource, (CellIndex{18, 10}));
      EXPECT_EQ(g.at(l.resource), Cell::Resource);
      EXPECT_EQ(g.count(Cell::Resource), 1);
      EXPECT_GT(l.resource.x, 13 + w);  // beyond the river

      EXPECT_EQ(l.start.x, 0);
      EXPECT_EQ(g.at(l.start), Cell::Grass);

      const bool stones_and_traps = level >= 3;
      EXPECT_EQ(g.count(Cell::Trap), stones_and_traps ? 8 : 0);
      EXPECT_EQ(g.count(Cell::Stone), stones_and_traps ? 20 : 0);
      if (level != 1) {
        EXPECT_EQ(g.count(Cell::Food), 0);
      }
      if (level == 2) {
        EXPECT_EQ(g.count(Cell::Grass), 399);
      }
      for (int y = 0; y < g.height(); ++y)
        for (int x = 0; x < g.width(); ++x)
          if (g.at({x, y}) == Cell::Stone) {
            EXPECT_LE(x, w > 0 ? 13 : 14) << x << "," << y;
          }
      EXPECT_TRUE(solvable(l));
    }
  }
}

// level 1: each of the 398 cells that are neither the resource nor the start
// holds food with p = 1/20; over 200 layouts the share is within 6 standard
// errors of 1/20
TEST(RiverLayout, FoodCoversOneFreeCellInTwenty) {
  long food = 0;
  const int layouts = 200;
  for (std::uint64_t seed = 1; seed <= layouts; ++seed) {
    Rng rng(seed);
    const Layout l = make_layout(1, rng);
    food += l.grid.count(Cell::Food);
    EXPECT_EQ(l.grid.count(Cell::Food) + l.grid.count(Cell::Grass), 399);
  }
  const double share = static_cast<double>(food) / (398.0 * layouts);
  EXPECT_NEAR(share, 1.0 / 20, 6 * std::sqrt(0.05 * 0.95 / (398.0 * layouts)));
}

// the stones are drawn over columns 0..14 (the Keele code's start side), so
// without a river some land on column 14; with one, none can
TEST(RiverLayout, StonesUseColumnFourteenOnlyWithoutARiver) {
  int on_14 = 0;
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    Rng rng(seed);
    const Layout l = make_layout(3, rng);
    for (int y = 0; y < 20; ++y) on_14 += l.grid.at({14, y}) == Cell::Stone;
  }
  EXPECT_GT(on_14, 0);
}

// a hand-made layout, w water columns from column 14, the resource and the
// start as the generator places them
Layout hand_layout(int w) {
  Layout l;
  l.river_width = w;
  for (int x = kRiverColumn; x < kRiverColumn + w; ++x)
    for (int y = 0; y < 20; ++y) l.grid.set({x, y}, Cell::Water);
  l.resource = kResourceCell;
  l.grid.set(l.resource, Cell::Resource);
  l.start = {0, 5};
  return l;
}

TEST(RiverLayout, SolvableNeedsAPathWithoutARiver) {
  Layout l = hand_layout(0);
  EXPECT_TRUE(solvable(l));
  // traps close the start in
  for (CellIndex c : {CellIndex{1, 5}, CellIndex{0, 4}, CellIndex{0, 6}}) l.grid.set(c, Cell::Trap);
  EXPECT_FALSE(solvable(l));
  l.grid.set({0, 6}, Cell::Stone);  // a stone does not block
  EXPECT_TRUE(solvable(l));
  // traps close the resource in
  for (CellIndex c : {CellIndex{17, 10}, CellIndex{19, 10}, CellIndex{18, 9}, CellIndex{18, 11}})
    l.grid.set(c, Cell::Trap);
  EXPECT_FALSE(solvable(l));
}

TEST(RiverLayout, SolvableNeedsEnoughStonesWithinReachAndABridgeableRow) {
  Layout l = hand_layout(2);
  l.grid.set({3, 3}, Cell::Stone);
  EXPECT_FALSE(solvable(l));  // one stone for a river of width 2
  l.grid.set({3, 4}, Cell::Stone);
  EXPECT_TRUE(solvable(l));
  // a stone walled in by traps is out of reach
  for (CellIndex c : {CellIndex{2, 4}, CellIndex{4, 4}, CellIndex{3, 5}}) l.grid.set(c, Cell::Trap);
  l.grid.set({3, 2}, Cell::Trap);
  l.grid.set({2, 3}, Cell::Trap);
  l.grid.set({4, 3}, Cell::Trap);
  EXPECT_FALSE(solvable(l));
  l.grid.set({10, 10}, Cell::Stone);
  l.grid.set({11, 10}, Cell::Stone);
  EXPECT_TRUE(solvable(l));
  // the far bank (column 16) trapped in every row whose near bank is open
  for (int y = 0; y < 20; ++y) l.grid.set({16, y}, Cell::Trap);
  EXPECT_FALSE(solvable(l));
  l.grid.set({16, 0}, Cell::Grass);  // one row crosses
  EXPECT_TRUE(solvable(l));
  l.grid.set({13, 0}, Cell::Trap);  // its near bank closed
  EXPECT_FALSE(solvable(l));
}

// the generator draws again until solvable(): about 1 first draw in 15000 is
// not (measured over 200000 seeds). Seed 579's first draw on levels 3-6 starts
// the agent in corner (0, 0) with traps on (1, 0) and (0, 1); the layout
// returned is a later, solvable draw
TEST(RiverLayout, EveryLayoutIsSolvable) {
  std::vector<std::uint64_t> seeds{579};
  for (std::uint64_t seed = 1; seed <= 300; ++seed) seeds.push_back(seed);
  for (std::uint64_t seed : seeds) {
    for (int level = 3; level <= kRiverLevels; ++level) {
      Rng rng(seed);
      EXPECT_TRUE(solvable(make_layout(level, rng))) << "seed " << seed << " level " << level;
    }
  }
}

}  // namespace
}  // namespace bx
