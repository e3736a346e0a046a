// Curves over one x axis as a standalone SVG image: what `bestiary plot`
// draws (fitness per generation, a task's metrics per report interval).
#pragma once

#include <string>
#include <vector>

namespace bx {

/// One curve: a y per x of its chart (NaN: no point there).
struct ChartSeries {
  std::string name;
  std::string color;  ///< any SVG colour
  std::string dash;   ///< stroke-dasharray, or empty: solid
  std::vector<double> ys;
  /// A band around the curve (an interquartile range, say), drawn shaded in
  /// its colour under the curves: lo[i] to hi[i] at xs[i] (NaN: none there);
  /// both empty: no band.
  std::vector<double> lo, hi;
};

/// Curves and their labels; y spans 0 and every value, or [y_min, y_max] when given.
struct LineChart {
  std::string title, x_label, y_label;
  std::vector<double> xs;
  std::vector<ChartSeries> series;
  double y_min = 0, y_max = 0;  ///< both 0: from the data
};

/// The chart as SVG, `width` x `height` pixels, with a legend.
std::string line_chart_svg(const LineChart& chart, int width = 800, int height = 500);

/// The k-th of a set of distinguishable colours (cycles).
const char* chart_color(int k);

}  // namespace bx
