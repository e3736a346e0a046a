// The shunting model (eq. 3) and its bilinear reading (eq. 4) against values
// worked out by hand.
#include "brain/river/shunting_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/rng.h"

namespace bx {
namespace {

using Iota = std::array<int, river_cell::kCount>;

ShuntingDef def(int width, int height, int sweeps, double iota_scale, double max_activity = 15) {
  ShuntingDef d;
  d.width = width;
  d.height = height;
  d.sweeps = sweeps;
  d.iota_scale = iota_scale;
  d.max_activity = max_activity;
  return d;
}

// A width x height grass grid with `cell` at (i, j).
std::vector<int> grid_with(int width, int height, int i, int j, int cell) {
  std::vector<int> g(static_cast<std::size_t>(width * height), river_cell::kGrass);
  g[static_cast<std::size_t>(j * width + i)] = cell;
  return g;
}

// A resource of iota 1 at the centre of a 3x3 grid, after `sweeps` sweeps.
ShuntingModel centre_source(int sweeps, double iota_scale, double max_activity = 15) {
  ShuntingModel sm(def(3, 3, sweeps, iota_scale, max_activity));
  sm.shape(grid_with(3, 3, 1, 1, river_cell::kResource), Iota{0, 1, 0, 0, 0});
  return sm;
}

TEST(ShuntingModel, StartsAtZero) {
  ShuntingModel sm(def(4, 3, 50, 15));
  ASSERT_EQ(sm.values().size(), 12u);
  for (double x : sm.values()) EXPECT_EQ(x, 0);
}

TEST(ShuntingModel, CheckNamesTheBadField) {
  EXPECT_TRUE(check_shunting_def(ShuntingDef{}).ok());
  ShuntingDef d;
  d.height = 0;
  EXPECT_EQ(check_shunting_def(d).error(), "shunting model: height is 0, must be at least 1");
  d = ShuntingDef{};
  d.sweeps = -1;
  EXPECT_EQ(check_shunting_def(d).error(), "shunting model: sweeps is -1, must be at least 0");
  d = ShuntingDef{};
  d.max_activity = 0;
  EXPECT_EQ(check_shunting_def(d).error(), "shunting model: max_activity is 0, must be a finite number above 0");
  d = ShuntingDef{};
  d.iota_scale = std::numeric_limits<double>::infinity();
  EXPECT_EQ(check_shunting_def(d).error(), "shunting model: iota_scale is inf, must be a finite number above 0");
}

TEST(ShuntingModel, InputIsIotaTimesScale) {
  ShuntingModel sm(def(5, 1, 0, 15));
  sm.shape(std::vector<int>{river_cell::kGrass, river_cell::kResource, river_cell::kStone, river_cell::kWater,
                            river_cell::kTrap},
           Iota{0, 1, -1, 0, 1});
  const std::vector<double> want{0, 15, -15, 0, 15};
  EXPECT_EQ(std::vector<double>(sm.inputs().begin(), sm.inputs().end()), want);
  // no sweeps: the activity is still the zero it starts from
  for (double x : sm.values()) EXPECT_EQ(x, 0);
}

// Each sweep reads only the previous one: activity moves one cell per sweep.
// In place, in row order, the cells after the source would already be
// non-zero after the first sweep.
TEST(ShuntingModel, OneSourceSweepBySweep) {
  // sweep 1: the source takes its input; its neighbours read the zeros before
  ShuntingModel s1 = centre_source(1, 8);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) EXPECT_EQ(s1.at(i, j), i == 1 && j == 1 ? 8.0 : 0.0) << i << "," << j;

  // sweep 2: every cell next to the source gets 8 / 8; the source's
  // neighbours were all 0, so it stays 8
  ShuntingModel s2 = centre_source(2, 8);
  EXPECT_EQ(s2.at(1, 1), 8);
  for (auto [i, j] : {std::pair{0, 0}, {1, 0}, {2, 0}, {0, 1}, {2, 1}, {0, 2}, {1, 2}, {2, 2}})
    EXPECT_EQ(s2.at(i, j), 1) << i << "," << j;

  // sweep 3: source (8 x 1) / 8 + 8; an edge cell sees the source, two edge
  // cells and two corners (12 / 8); a corner the source and two edges
  // (10 / 8). The cells outside count 0 and the sum is still over 8.
  ShuntingModel s3 = centre_source(3, 8);
  EXPECT_EQ(s3.at(1, 1), 9);
  EXPECT_EQ(s3.at(1, 0), 1.5);
  EXPECT_EQ(s3.at(0, 1), 1.5);
  EXPECT_EQ(s3.at(2, 1), 1.5);
  EXPECT_EQ(s3.at(1, 2), 1.5);
  EXPECT_EQ(s3.at(0, 0), 1.25);
  EXPECT_EQ(s3.at(2, 2), 1.25);
}

// Fifty sweeps on 3x3 against the grid's symmetry: centre c, edge e and
// corner k follow c' = min((4e + 4k) / 8 + I, maxI), e' = (c + 2e + 2k) / 8,
// k' = (c + 2e) / 8, from 0.
TEST(ShuntingModel, FiftySweepsMatchTheSymmetricRecurrence) {
  const double input = 1, max_activity = 15;
  double c = 0, e = 0, k = 0;
  for (int s = 0; s < 50; ++s) {
    const double c2 = std::min((4 * e + 4 * k) / 8 + input, max_activity);
    const double e2 = (c + 2 * e + 2 * k) / 8;
    const double k2 = (c + 2 * e) / 8;
    c = c2, e = e2, k = k2;
  }
  ShuntingModel sm = centre_source(50, input, max_activity);
  EXPECT_NEAR(sm.at(1, 1), c, 1e-12);  // the source
  EXPECT_NEAR(sm.at(1, 0), e, 1e-12);  // a neighbour
  EXPECT_NEAR(sm.at(2, 2), k, 1e-12);  // a diagonal
  EXPECT_NEAR(sm.at(0, 1), e, 1e-12);
  EXPECT_NEAR(sm.at(0, 2), k, 1e-12);
  // the leak through the border keeps it well under the cap
  EXPECT_GT(c, 1.2);
  EXPECT_LT(c, 2);
}

TEST(ShuntingModel, ActivityIsCappedAtMaxI) {
  // an input of 20 is held to 15 at once, and its neighbours then see 15
  EXPECT_EQ(centre_source(1, 20).at(1, 1), 15);
  EXPECT_EQ(centre_source(2, 20).at(1, 0), 15.0 / 8);
  ShuntingModel sm(def(20, 20, 50, 20));
  std::vector<int> g(400, river_cell::kGrass);
  for (int k : {0, 1, 2, 21, 22, 210, 211}) g[static_cast<std::size_t>(k)] = river_cell::kResource;
  sm.shape(g, Iota{0, 1, 0, 0, 0});
  EXPECT_EQ(*std::max_element(sm.values().begin(), sm.values().end()), 15);
  EXPECT_EQ(sm.at(1, 1), 15);
}

TEST(ShuntingModel, NegativeCellIsHeldAtItsInputAndDoesNotSpread) {
  // a lone trap: it holds -8 from the first sweep on; nothing else moves
  ShuntingModel lone(def(5, 5, 50, 8));
  lone.shape(grid_with(5, 5, 2, 2, river_cell::kTrap), Iota{0, 0, 0, 0, -1});
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) EXPECT_EQ(lone.at(i, j), i == 2 && j == 2 ? -8.0 : 0.0) << i << "," << j;
  ShuntingModel once(def(5, 5, 1, 8));
  once.shape(grid_with(5, 5, 2, 2, river_cell::kTrap), Iota{0, 0, 0, 0, -1});
  EXPECT_EQ(once.at(2, 2), -8);

  // resource, trap, grass in a row: the trap passes the source nothing and
  // takes nothing from it, so the grass beyond it stays 0
  ShuntingModel row(def(3, 1, 50, 8));
  row.shape(std::vector<int>{river_cell::kResource, river_cell::kTrap, river_cell::kGrass}, Iota{0, 1, 0, 0, -1});
  EXPECT_EQ(row.at(0, 0), 8);
  EXPECT_EQ(row.at(1, 0), -8);
  EXPECT_EQ(row.at(2, 0), 0);
}

TEST(ShuntingModel, OutsideTheGridCountsZeroWithoutWrapping) {
  // a source in the corner has three neighbours inside, one in the middle eight
  ShuntingModel corner(def(20, 20, 3, 8));
  corner.shape(grid_with(20, 20, 0, 0, river_cell::kResource), Iota{0, 1, 0, 0, 0});
  EXPECT_EQ(corner.at(0, 0), 8 + 3.0 / 8);
  ShuntingModel middle(def(20, 20, 3, 8));
  middle.shape(grid_with(20, 20, 10, 10, river_cell::kResource), Iota{0, 1, 0, 0, 0});
  EXPECT_EQ(middle.at(10, 10), 9);

  // the far edges are not the corner's neighbours: (1, 1) sees the source
  // and its two neighbours inside, (8 + 1 + 1) / 8; the far side nothing
  EXPECT_EQ(corner.at(1, 1), 1.25);
  EXPECT_EQ(corner.at(19, 19), 0);
  EXPECT_EQ(corner.at(19, 0), 0);
  EXPECT_EQ(corner.at(0, 19), 0);
  // and reading outside gives 0
  EXPECT_EQ(corner.at(-1, 0), 0);
  EXPECT_EQ(corner.at(0, 20), 0);
}

TEST(ShuntingModel, ReshapingStartsFromZero) {
  ShuntingModel sm(def(6, 6, 50, 15));
  const std::vector<int> g = grid_with(6, 6, 2, 3, river_cell::kStone);
  sm.shape(g, Iota{0, 0, 1, 0, 0});
  const std::vector<double> first(sm.values().begin(), sm.values().end());
  sm.shape(g, Iota{0, 0, 1, 0, 0});
  EXPECT_EQ(std::vector<double>(sm.values().begin(), sm.values().end()), first);
  sm.shape(g, Iota{0, 0, 0, 0, 0});
  for (double x : sm.values()) EXPECT_EQ(x, 0);
}

// Eq. 3 read plainly, as docs/rivercrossing.md states it: from zero, each
// sweep from the last one, each cell's eight neighbours' [x]+ (0 outside the
// grid) in row order, over 8, plus its input, capped at maxI; a cell of
// negative input held at it.
std::vector<double> plain_sweeps(const ShuntingDef& d, const std::vector<int>& cells, const Iota& iota) {
  const int w = d.width, h = d.height;
  std::vector<double> in(cells.size()), x(cells.size(), 0.0), next(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) in[k] = iota[static_cast<std::size_t>(cells[k])] * d.iota_scale;
  auto at = [&](int i, int j) { return i < 0 || i >= w || j < 0 || j >= h ? 0.0 : x[static_cast<std::size_t>(j * w + i)]; };
  for (int s = 0; s < d.sweeps; ++s) {
    for (int j = 0; j < h; ++j) {
      for (int i = 0; i < w; ++i) {
        const std::size_t k = static_cast<std::size_t>(j * w + i);
        if (in[k] < 0) {
          next[k] = in[k];
          continue;
        }
        double sum = 0;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di)
            if (di != 0 || dj != 0) sum += std::max(0.0, at(i + di, j + dj));
        next[k] = std::min(sum / 8 + in[k], d.max_activity);
      }
    }
    std::swap(x, next);
  }
  return x;
}

// The model's sweeps (a frame of zeros around the grid, no source: no
// sweeps) give exactly the plain reading's doubles, whatever the grid.
TEST(ShuntingModel, SweepsGiveThePlainReadingOfEq3BitForBit) {
  Rng rng(32);
  for (int trial = 0; trial < 200; ++trial) {
    const int w = 1 + static_cast<int>(rng.below(22)), h = 1 + static_cast<int>(rng.below(22));
    const ShuntingDef d = def(w, h, static_cast<int>(rng.below(60)), trial % 3 == 0 ? 1 : 15, trial % 5 == 0 ? 4 : 15);
    std::vector<int> cells(static_cast<std::size_t>(w * h));
    for (int& c : cells) c = static_cast<int>(rng.below(river_cell::kCount));
    Iota iota{0, 0, 0, 0, 0};
    for (std::size_t c = 1; c < iota.size(); ++c) iota[c] = static_cast<int>(rng.below(3)) - 1;
    ShuntingModel sm(d);
    sm.shape(cells, iota);
    const std::vector<double> want = plain_sweeps(d, cells, iota);
    ASSERT_EQ(sm.values().size(), want.size());
    for (std::size_t k = 0; k < want.size(); ++k)
      ASSERT_EQ(std::bit_cast<std::uint64_t>(sm.values()[k]), std::bit_cast<std::uint64_t>(want[k]))
          << "cell " << k << " of " << w << " x " << h << ", " << d.sweeps << " sweeps, trial " << trial;
  }
}

// f on a 3 x 2 lattice, f[i, j] at f[j * 3 + i]
const std::vector<double> kF{1, 2, 4,     // j = 0
                             8, 16, 32};  // j = 1

TEST(Bilinear, AtALatticePointReadsIt) {
  EXPECT_EQ(bilinear(kF, 3, 2, 0, 0), 1);
  EXPECT_EQ(bilinear(kF, 3, 2, 1, 1), 16);
  EXPECT_EQ(bilinear(kF, 3, 2, 2, 0), 4);
  EXPECT_EQ(bilinear(kF, 3, 2, 2, 1), 32);
}

TEST(Bilinear, AtAnEdgeMidpointReadsTheMeanOfItsTwoEnds) {
  EXPECT_EQ(bilinear(kF, 3, 2, 0.5, 1), (8 + 16) / 2.0);
  EXPECT_EQ(bilinear(kF, 3, 2, 1, 0.5), (2 + 16) / 2.0);
}

TEST(Bilinear, AtASquaresMiddleReadsTheMeanOfItsFourCorners) {
  EXPECT_EQ(bilinear(kF, 3, 2, 0.5, 0.5), (1 + 2 + 8 + 16) / 4.0);
  EXPECT_EQ(bilinear(kF, 3, 2, 1.5, 0.5), (2 + 4 + 16 + 32) / 4.0);
}

TEST(Bilinear, AnyPointIsEq4) {
  // {x} = 0.25, {y} = 0.75 in the square from (1, 0)
  const double want = 2 * 0.75 * 0.25 + 4 * 0.25 * 0.25 + 16 * 0.75 * 0.75 + 32 * 0.25 * 0.75;
  EXPECT_DOUBLE_EQ(bilinear(kF, 3, 2, 1.25, 0.75), want);
}

TEST(Bilinear, PointsOutsideTheLatticeCountZero) {
  const std::vector<double> ones(4, 1.0);  // 2 x 2
  EXPECT_EQ(bilinear(ones, 2, 2, -0.5, 0), 0.5);
  EXPECT_EQ(bilinear(ones, 2, 2, 1.5, 1), 0.5);
  EXPECT_EQ(bilinear(ones, 2, 2, 0, 1.25), 0.75);
  EXPECT_EQ(bilinear(ones, 2, 2, -0.5, -0.5), 0.25);
  EXPECT_EQ(bilinear(ones, 2, 2, -1, 0), 0);
  EXPECT_EQ(bilinear(ones, 2, 2, 2, 0), 0);
  EXPECT_EQ(bilinear(ones, 2, 2, 50, -1e300), 0);
  EXPECT_EQ(bilinear(ones, 2, 2, std::numeric_limits<double>::quiet_NaN(), 0.5), 0);
}

// A cell's value sits at its centre: the one-source 3x3 after three sweeps
// (centre 9, edges 1.5, corners 1.25) read at points in cell widths.
TEST(Bilinear, ShuntingModelPlacesCellValuesAtCellCentres) {
  ShuntingModel sm = centre_source(3, 8);
  EXPECT_EQ(sm.activity_at({1.5, 1.5}), 9);                             // the source cell's centre
  EXPECT_EQ(sm.activity_at({0.5, 1.5}), 1.5);                           // its left neighbour's centre
  EXPECT_EQ(sm.activity_at({1.0, 1.5}), (1.5 + 9) / 2);                 // the edge between them
  EXPECT_EQ(sm.activity_at({1.0, 1.0}), (1.25 + 1.5 + 1.5 + 9) / 4);    // the corner four cells share
  EXPECT_EQ(sm.activity_at({0.25, 1.5}), 0.75 * 1.5);                   // toward the outside, which is 0
  EXPECT_EQ(sm.activity_at({3.5, 1.5}), 0);                             // beyond the grid
}

}  // namespace
}  // namespace bx
