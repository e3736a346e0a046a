#include "task/river/layout.h"

#include <array>
#include <cassert>
#include <vector>

namespace bx {
namespace {

// a cell's place in a row-by-row array over the grid
std::size_t slot(const Grid& g, CellIndex c) { return static_cast<std::size_t>(c.y) * g.width() + c.x; }

// the cells an agent reaches from `from` by 4-neighbour steps without dying,
// flagged at their slot
std::vector<bool> safe_reach(const Grid& g, CellIndex from) {
  std::vector<bool> reached(g.cells().size(), false);
  std::vector<CellIndex> open{from};
  reached[slot(g, from)] = true;
  constexpr std::array<CellIndex, 4> steps{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
  while (!open.empty()) {
    CellIndex c = open.back();
    open.pop_back();
    for (CellIndex s : steps) {
      CellIndex n{c.x + s.x, c.y + s.y};
      if (!g.contains(n) || reached[slot(g, n)]) continue;
      if (g.at(n) == Cell::Water || g.at(n) == Cell::Trap) continue;
      reached[slot(g, n)] = true;
      open.push_back(n);
    }
  }
  return reached;
}

Layout draw_layout(int level, Rng& rng) {
  Layout l;
  Grid& g = l.grid;
  l.river_width = river_width(level);

  // the river: full columns from kRiverColumn
  for (int x = kRiverColumn; x < kRiverColumn + l.river_width; ++x)
    for (int y = 0; y < g.height(); ++y) g.set({x, y}, Cell::Water);
  l.resource = kResourceCell;
  g.set(l.resource, Cell::Resource);

  // column 0 holds nothing yet, so every row is free for the start
  l.start = {0, static_cast<int>(rng.below(g.height()))};
  auto is_free = [&](CellIndex c) { return g.at(c) == Cell::Grass && c != l.start; };

  if (level == 1) {
    for (int y = 0; y < g.height(); ++y)
      for (int x = 0; x < g.width(); ++x)
        if (is_free({x, y}) && rng.chance(kFoodChance)) g.set({x, y}, Cell::Food);
  }

  if (level >= 3) {
    // traps anywhere off the water, the resource and the start; each draw
    // again until free, so the eight are distinct
    for (int n = 0; n < kTrapCount; ++n) {
      CellIndex c;
      do {
        c.x = static_cast<int>(rng.below(g.width()));
        c.y = static_cast<int>(rng.below(g.height()));
      } while (!is_free(c));
      g.set(c, Cell::Trap);
    }
    // stones on the start side, columns 0..kRiverColumn as in the Keele code:
    // column kRiverColumn is water on a river level, so there they land on
    // columns 0..kRiverColumn-1; never on water, a trap, a stone or the start
    for (int n = 0; n < kStoneCount; ++n) {
      CellIndex c;
      do {
        c.x = static_cast<int>(rng.below(kRiverColumn + 1));
        c.y = static_cast<int>(rng.below(g.height()));
      } while (!is_free(c));
      g.set(c, Cell::Stone);
    }
  }
  return l;
}

}  // namespace

int river_width(int level) {
  assert(level >= 1 && level <= kRiverLevels);
  constexpr std::array<int, kRiverLevels> widths{0, 0, 0, 1, 2, 4};
  return widths[level - 1];
}

Layout make_layout(int level, Rng& rng) {
  // 8 traps rarely cut the start, a stone or the resource off, so this loop
  // ends after a try or two; the redraw continues the same stream, so the
  // layout stays a function of the stream
  for (;;) {
    Layout l = draw_layout(level, rng);
    if (solvable(l)) return l;
  }
}

bool solvable(const Layout& layout) {
  const Grid& g = layout.grid;
  auto in = [&](const std::vector<bool>& reached, CellIndex c) -> bool { return reached[slot(g, c)]; };
  const std::vector<bool> from_start = safe_reach(g, layout.start);
  const int w = layout.river_width;
  if (w == 0) return in(from_start, layout.resource);

  // enough stones within reach to bridge the river
  int stones = 0;
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x)
      if (g.at({x, y}) == Cell::Stone && in(from_start, {x, y})) ++stones;
  if (stones < w) return false;

  // a row whose bank and far bank both connect
  const std::vector<bool> from_resource = safe_reach(g, layout.resource);
  for (int y = 0; y < g.height(); ++y)
    if (in(from_start, {kRiverColumn - 1, y}) && in(from_resource, {kRiverColumn + w, y})) return true;
  return false;
}

}  // namespace bx
