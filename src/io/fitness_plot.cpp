#include "io/fitness_plot.h"

#include <algorithm>
#include <cmath>

#include "io/line_chart.h"

namespace bx {

std::string fitness_svg(const std::vector<GenerationStats>& gens, const std::string& title, int width,
                        int height) {
  LineChart c{title, "generation", "fitness", {}, {}};
  ChartSeries best{"best", "#1f63b4", "", {}}, mean{"mean", "#e07b20", "", {}}, median{"median", "#2a9d4a", "6 4", {}};
  for (const GenerationStats& g : gens) {
    c.xs.push_back(g.generation);
    best.ys.push_back(g.best);
    mean.ys.push_back(g.mean);
    median.ys.push_back(g.median);
  }
  c.series = {best, mean, median};
  return line_chart_svg(c, width, height);
}

std::string metric_svg(const std::vector<GenerationStats>& gens, const std::vector<std::string>& names,
                       double per_generation, const std::string& x_label, const std::string& title, int width,
                       int height) {
  // a metric that is 0 or 1 in every evaluation (a count of levels
  // completed) has its mean equal to its share of evaluations: drawn as that
  // share (%) when every metric drawn is such; else every one as its mean
  bool shares = true;
  for (const GenerationStats& g : gens)
    for (const MetricStat& m : g.metrics)
      if (std::find(names.begin(), names.end(), m.name) != names.end() && !(std::abs(m.mean - m.nonzero) <= 1e-12))
        shares = false;
  LineChart c = shares ? LineChart{title, x_label, "share of evaluations (%)", {}, {}, 0, 100}
                       : LineChart{title, x_label, "mean over the evaluations", {}, {}};
  for (const GenerationStats& g : gens) c.xs.push_back(g.generation * per_generation);
  int k = 0;
  for (const std::string& name : names) {
    ChartSeries s{name, chart_color(k++), "", {}};
    for (const GenerationStats& g : gens) {
      double v = 0;  // a generation that lacks it: none of its evaluations had it
      for (const MetricStat& m : g.metrics)
        if (m.name == name) v = shares ? 100 * m.nonzero : m.mean;
      s.ys.push_back(v);
    }
    c.series.push_back(std::move(s));
  }
  return line_chart_svg(c, width, height);
}

}  // namespace bx
