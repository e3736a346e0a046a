// The river crossing's grid (docs/rivercrossing.md): the cell under a point,
// the edge clamp, the cells' order.
#include "task/river/grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace bx {
namespace {

TEST(RiverGrid, TheCellUnderAPointFloorsEachCoordinate) {
  EXPECT_EQ(cell_under(0.0, 0.0), (CellIndex{0, 0}));
  EXPECT_EQ(cell_under(0.999, 3.5), (CellIndex{0, 3}));
  EXPECT_EQ(cell_under(1.0, 3.0), (CellIndex{1, 3}));  // [i, i+1): a cell owns its low edge
  EXPECT_EQ(cell_under(19.999, 19.0), (CellIndex{19, 19}));
  EXPECT_EQ(cell_under(20.0, 5.2), (CellIndex{20, 5}));   // beyond the grid: the caller's edge rule
  EXPECT_EQ(cell_under(-0.01, 2.0), (CellIndex{-1, 2}));  // floor, not truncation
}

// a blown-up simulation's position converts without overflow: each
// coordinate is held within +-1e6 cells first
TEST(RiverGrid, ABlownUpPositionStillGivesADefinedCell) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(cell_under(inf, -inf), (CellIndex{1000000, -1000000}));
  EXPECT_EQ(cell_under(3e300, 2.5), (CellIndex{1000000, 2}));
  const CellIndex c = cell_under(nan, nan);
  EXPECT_LE(std::abs(c.x), 1000000);
  EXPECT_LE(std::abs(c.y), 1000000);
}

TEST(RiverGrid, ClampTakesTheNearestCellInside) {
  const Grid g;
  EXPECT_EQ(g.width(), 20);
  EXPECT_EQ(g.height(), 20);
  EXPECT_EQ(g.clamp({5, 6}), (CellIndex{5, 6}));
  EXPECT_EQ(g.clamp({-1, 6}), (CellIndex{0, 6}));
  EXPECT_EQ(g.clamp({20, 25}), (CellIndex{19, 19}));
  EXPECT_EQ(g.clamp({-3, -7}), (CellIndex{0, 0}));
}

TEST(RiverGrid, CellsAreRowByRow) {
  Grid g(4, 3);
  g.set({3, 1}, Cell::Stone);
  EXPECT_EQ(g.cells()[1 * 4 + 3], Cell::Stone);
  EXPECT_EQ(g.count(Cell::Stone), 1);
  EXPECT_EQ(g.count(Cell::Grass), 11);
}

}  // namespace
}  // namespace bx
