#include "brain/river/shunting_model.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>

#include "core/text.h"

namespace bx {

namespace {

// f[i, j], 0 outside the grid
double point(std::span<const double> f, int width, int height, int i, int j) {
  if (i < 0 || i >= width || j < 0 || j >= height) return 0;
  return f[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) + static_cast<std::size_t>(i)];
}


Error bad(const char* field, double value, const char* must) {
  return Error{"shunting model: " + std::string(field) + " is " + g_number(value) + ", must be " + must};
}

}  // namespace

Status check_shunting_def(const ShuntingDef& d) {
  if (d.width < 1) return bad("width", d.width, "at least 1");
  if (d.height < 1) return bad("height", d.height, "at least 1");
  if (d.sweeps < 0) return bad("sweeps", d.sweeps, "at least 0");
  if (!(d.max_activity > 0) || !std::isfinite(d.max_activity))
    return bad("max_activity", d.max_activity, "a finite number above 0");
  if (!(d.iota_scale > 0) || !std::isfinite(d.iota_scale))
    return bad("iota_scale", d.iota_scale, "a finite number above 0");
  return Ok{};
}

double bilinear(std::span<const double> f, int width, int height, double u, double v) {
  assert(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) == f.size());
  // beyond one unit outside, all four points are outside; this also keeps
  // floor() within int range and sends NaN to 0
  if (!(u > -1 && u < width && v > -1 && v < height)) return 0;
  const double fu = std::floor(u), fv = std::floor(v);
  const int i = static_cast<int>(fu), j = static_cast<int>(fv);
  const double du = u - fu, dv = v - fv;  // {u}, {v}
  // eq. 4 with ceil written as floor + 1: where {u} = 0 the ceil term has
  // weight 0 either way
  return point(f, width, height, i, j) * (1 - du) * (1 - dv) +
         point(f, width, height, i + 1, j) * du * (1 - dv) +
         point(f, width, height, i, j + 1) * (1 - du) * dv +
         point(f, width, height, i + 1, j + 1) * du * dv;
}

ShuntingModel::ShuntingModel(const ShuntingDef& def) : def_(def) {
  assert(check_shunting_def(def).ok());
  const std::size_t n = static_cast<std::size_t>(def.width) * static_cast<std::size_t>(def.height);
  input_.assign(n, 0.0);
  x_.assign(n, 0.0);
  next_.assign(n, 0.0);
  const std::size_t framed = static_cast<std::size_t>(def.width + 2) * static_cast<std::size_t>(def.height + 2);
  positive_.assign(framed, 0.0);
  positive_next_.assign(framed, 0.0);
}

void ShuntingModel::shape(std::span<const int> cells, const std::array<int, river_cell::kCount>& iota) {
  const int w = def_.width, h = def_.height;
  assert(cells.size() == x_.size());

  // external inputs from the iotas
  bool source = false;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    assert(cells[k] >= 0 && cells[k] < river_cell::kCount);
    input_[k] = iota[static_cast<std::size_t>(cells[k])] * def_.iota_scale;
    source = source || input_[k] > 0;
  }

  // from zero, every sweep reads only the previous one (Jacobi)
  std::fill(x_.begin(), x_.end(), 0.0);
  if (def_.sweeps == 0) return;
  // without a positive input nothing spreads: every sweep gives each cell
  // its own input (a negative one held, 0 elsewhere)
  if (!source) {
    std::copy(input_.begin(), input_.end(), x_.begin());
    return;
  }
  // the activity's positive parts [x]+, framed by a border of zeros one cell
  // wide (the neighbours outside the grid), as the sweeps read them
  const std::ptrdiff_t fw = w + 2;
  std::fill(positive_.begin(), positive_.end(), 0.0);
  for (int s = 0; s < def_.sweeps; ++s) {
    for (int j = 0; j < h; ++j) {
      const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(w);
      const std::size_t framed_row = static_cast<std::size_t>((j + 1) * fw + 1);
      for (int i = 0; i < w; ++i) {
        const std::size_t k = row + static_cast<std::size_t>(i), f = framed_row + static_cast<std::size_t>(i);
        // a cell of negative iota stays at its input; [x]+ keeps it from
        // pulling its neighbours down
        if (input_[k] < 0) {
          next_[k] = input_[k];
          positive_next_[f] = 0;
          continue;
        }
        // the eight Moore neighbours' [x]+, those outside the grid 0, over 8
        // whatever the count inside, so the border leaks activity (summed
        // row by row, left to right: the order fixes the rounding)
        const double* p = &positive_[f];
        double sum = 0;
        sum += p[-fw - 1];
        sum += p[-fw];
        sum += p[-fw + 1];
        sum += p[-1];
        sum += p[1];
        sum += p[fw - 1];
        sum += p[fw];
        sum += p[fw + 1];
        next_[k] = std::min(sum / 8 + input_[k], def_.max_activity);
        positive_next_[f] = std::max(0.0, next_[k]);
      }
    }
    std::swap(x_, next_);
    std::swap(positive_, positive_next_);
  }
}

double ShuntingModel::at(int i, int j) const { return point(x_, def_.width, def_.height, i, j); }

double ShuntingModel::activity_at(GridPoint p) const {
  // cell (i, j)'s value sits at its centre (i + 0.5, j + 0.5): shift by half
  // a cell into eq. 4's integer lattice
  return bilinear(x_, def_.width, def_.height, p.x - 0.5, p.y - 0.5);
}

}  // namespace bx
