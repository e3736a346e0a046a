// The river crossing's six levels (Stanton & Channon 2015, "Environment and
// Physical Model"; docs/papers.md S4): what each level's grid holds and where,
// drawn from a random stream. Where the paper is silent, the Keele group's
// public 2D code decides (the river's columns, where stones may lie, the
// resource's row); docs/rivercrossing.md lists each choice.
#pragma once

#include "core/rng.h"
#include "task/river/grid.h"

namespace bx {

/// The paper's levels: 1 food, 2 dash, 3 stones and traps, 4-6 rivers of width
/// 1, 2 and 4; after level 6 comes level 1 again.
inline constexpr int kRiverLevels = 6;
/// The river's first column; it runs down every row (the Keele 2D code's
/// 20/2 + (20/2 - 2)/2 = 14).
inline constexpr int kRiverColumn = 14;
/// The resource, on every level: mid-height, and beyond the widest river
/// (columns 14..17), so level 6 leaves it one column of bank (column 18) and
/// one behind it.
inline constexpr CellIndex kResourceCell{18, 10};
/// Levels 3-6 (paper: "eight traps and twenty stones").
inline constexpr int kTrapCount = 8;
inline constexpr int kStoneCount = 20;
/// Level 1: each free cell holds food with this probability (paper: 1/20).
inline constexpr double kFoodChance = 1.0 / 20;

/// The river's width at a level (1..6): 0, 0, 0, 1, 2, 4.
int river_width(int level);

/// One level's grid and where its agent starts.
struct Layout {
  Grid grid;
  CellIndex start;           ///< the agent's first cell: column 0, a grass row
  CellIndex resource;        ///< kResourceCell
  int river_width = 0;       ///< the water columns: kRiverColumn .. kRiverColumn + river_width - 1
  friend bool operator==(const Layout&, const Layout&) = default;
};

/// Level `level`'s layout (1..6) on a 20x20 grid, every draw from `rng`, and
/// always solvable(): a layout that is not is drawn again from the same stream.
/// Draw order: the start row; level 1's food, cell by cell row by row; levels
/// 3-6's traps, then stones, each a column then a row, drawn again until free.
Layout make_layout(int level, Rng& rng);

/// Whether an agent that walks 4-neighbour steps can reach the resource. With
/// no river: a path from the start to the resource over cells that do not
/// kill (neither water nor trap). With a river of width w: at least w stones
/// reachable from the start, and a row whose bank cell (column
/// kRiverColumn - 1) is reachable from the start and whose far-bank cell
/// (column kRiverColumn + w) reaches the resource, so that w stones laid
/// across that row make a path. (A layout crossable only by a longer, bent
/// bridge counts as unsolvable: the generator then draws again.)
bool solvable(const Layout& layout);

}  // namespace bx
