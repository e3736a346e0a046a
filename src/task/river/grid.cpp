#include "task/river/grid.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace bx {

CellIndex cell_under(double x, double y) {
  // fmax before fmin: fmax(NaN, lo) is lo, so NaN lands on a defined index
  constexpr double far = 1e6;
  auto floor_cell = [](double v) { return static_cast<int>(std::fmin(std::fmax(std::floor(v), -far), far)); };
  return {floor_cell(x), floor_cell(y)};
}

Grid::Grid(int width, int height)
    : width_(width), height_(height), cells_(static_cast<std::size_t>(width) * height, Cell::Grass) {
  assert(width > 0 && height > 0);
}

CellIndex Grid::clamp(CellIndex c) const {
  return {std::clamp(c.x, 0, width_ - 1), std::clamp(c.y, 0, height_ - 1)};
}

int Grid::count(Cell kind) const {
  return static_cast<int>(std::count(cells_.begin(), cells_.end(), kind));
}

std::size_t Grid::index(CellIndex c) const {
  assert(contains(c));
  return static_cast<std::size_t>(c.y) * width_ + c.x;
}

}  // namespace bx
