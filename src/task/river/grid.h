// The river crossing's grid (rivercrossing, docs/rivercrossing.md): a
// rectangle of cells, each of one kind, which the agent walks over. The 3D
// agent's cell is the one under its torso's centre (cell_under).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace bx {

/// What a cell holds (Stanton & Channon 2015, "Environment and Physical
/// Model"; food is level 1's).
enum class Cell : std::uint8_t {
  Grass,     ///< neutral; also a picked-up stone's cell and a bridge cell
  Resource,  ///< the goal: +100 and the next level
  Food,      ///< level 1: +1, then grass
  Stone,     ///< can be picked up
  Water,     ///< kills, unless a stone is put down on it
  Trap,      ///< kills
};

/// A cell's column x and row y.
struct CellIndex {
  int x = 0;
  int y = 0;
  friend bool operator==(const CellIndex&, const CellIndex&) = default;
};

/// The cell under a continuous position (x, y) in cell widths: cell (i, j)
/// spans [i, i+1) x [j, j+1), so the index is (floor(x), floor(y)). It may lie
/// outside any grid (the caller applies the edge rule, GridWorld::enter).
/// Coordinates are held within +-1e6 before the conversion, so a blown-up
/// simulation (inf, NaN) still gives a defined index.
CellIndex cell_under(double x, double y);

/// A width x height field of cells, all grass at first; cell (x, y) is column x
/// (0 .. width-1) of row y (0 .. height-1).
class Grid {
 public:
  /// The paper's world is 20x20 ("a discrete, 20x20 bounded grid world").
  explicit Grid(int width = 20, int height = 20);

  int width() const { return width_; }
  int height() const { return height_; }
  /// Whether c is a cell of the grid.
  bool contains(CellIndex c) const { return c.x >= 0 && c.x < width_ && c.y >= 0 && c.y < height_; }
  /// The grid's cell nearest to c (c itself when it is inside).
  CellIndex clamp(CellIndex c) const;

  /// The kind of cell c, which must be inside.
  Cell at(CellIndex c) const { return cells_[index(c)]; }
  /// Sets cell c, which must be inside.
  void set(CellIndex c, Cell kind) { cells_[index(c)] = kind; }
  /// How many cells are of this kind.
  int count(Cell kind) const;
  /// Every cell, row by row: cell (x, y) at y * width + x (for a viewer).
  std::span<const Cell> cells() const { return cells_; }

  friend bool operator==(const Grid&, const Grid&) = default;

 private:
  std::size_t index(CellIndex c) const;
  int width_;
  int height_;
  std::vector<Cell> cells_;
};

}  // namespace bx
