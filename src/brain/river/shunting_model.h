// The river crossing's shunting model (SM; Stanton & Channon 2015, "The
// Shunting Model", eq. 3, after Meng & Yang 1998 and Robinson et al. 2007):
// one neuron per grid cell; activity spreads from cells of positive iota to
// their Moore neighbours, giving a landscape whose uphill leads to salient
// cells. Cells of negative iota hold their negative input and pass nothing
// on. The landscape is read at the agent's sensors by bilinear interpolation
// (eq. 4).
#pragma once

#include <array>
#include <span>
#include <vector>

#include "brain/river/river_cell.h"
#include "core/result.h"

namespace bx {

/// The SM's constants. Defaults are the paper's.
struct ShuntingDef {
  int width = 20;   ///< cells along x
  int height = 20;  ///< cells along y
  int sweeps = 50;  ///< iterations of eq. 3 from zero
  /// maxI: the cap on every activation (eq. 3); the physical network divides
  /// its readings by it.
  double max_activity = 15;
  /// A cell's external input is its kind's iota (-1, 0 or 1) times this.
  /// The sources differ between 1 and maxI; 15 follows the paper's naming
  /// of maxI the "maximum iota value", and maps a source to exactly 1 after
  /// the PN's division by maxI.
  double iota_scale = 15;
  friend bool operator==(const ShuntingDef&, const ShuntingDef&) = default;
};

/// An error naming the field and value if the SM cannot run: a size below 1,
/// negative sweeps, or a cap or iota scale not a finite number above 0.
Status check_shunting_def(const ShuntingDef& d);

/// A point on the grid in cell widths: cell (i, j) covers
/// [i, i + 1) x [j, j + 1), so its centre is (i + 0.5, j + 0.5).
struct GridPoint {
  double x = 0;
  double y = 0;
};

/// Eq. 4: the bilinear interpolation at (u, v) of values f[i, j] that sit at
/// the integer points (i, j), 0 <= i < width, 0 <= j < height, stored
/// row-major (f[j * width + i]). Points outside count 0, so the value fades
/// to 0 within one unit beyond the outermost points; a non-finite (u, v)
/// reads 0.
double bilinear(std::span<const double> f, int width, int height, double u, double v);

/// The SM of one grid: its inputs and its activity after the sweeps.
class ShuntingModel {
 public:
  /// An SM of all zeros (any grid whose iotas are all 0 shapes to this).
  explicit ShuntingModel(const ShuntingDef& def);

  /// Recomputes the landscape from zero: `cells` holds a river_cell code per
  /// cell, row-major (cell (i, j) at j * width + i); `iota` the iota of each
  /// code. Each cell's input is iota[code] * iota_scale; then `sweeps`
  /// synchronous sweeps of eq. 3, every cell from the previous sweep's values
  /// (see docs/rivercrossing.md ("The controller") for why not in place).
  void shape(std::span<const int> cells, const std::array<int, river_cell::kCount>& iota);

  /// The activity of cell (i, j); 0 outside the grid.
  double at(int i, int j) const;
  /// Every cell's activity, row-major.
  std::span<const double> values() const { return x_; }
  /// Every cell's external input I, row-major.
  std::span<const double> inputs() const { return input_; }
  /// The activity at a point in cell widths: eq. 4 over the cells' values
  /// placed at their centres, so a point at a cell's centre reads that cell
  /// exactly and a point at a cell's corner reads the mean of the four cells
  /// that meet there.
  double activity_at(GridPoint p) const;
  /// The constants it was made with.
  const ShuntingDef& def() const { return def_; }

 private:
  ShuntingDef def_;
  std::vector<double> input_;
  std::vector<double> x_;
  std::vector<double> next_;  // the sweep being computed
  // [x]+ of x_ and of next_, (width + 2) x (height + 2) with a border of
  // zeros: the sweeps read neighbours without testing the grid's edge
  std::vector<double> positive_, positive_next_;
};

}  // namespace bx
