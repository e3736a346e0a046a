#include "io/fitness_plot.h"

#include <algorithm>
#include <cmath>

#include "io/line_chart.h"

namespace bx {

std::string fitness_svg(const std::vector<GenerationStats>& gens, const std::string& title, int width,
                        int height) {
  LineChart c{title, "generation", "fitness", {}, {}};
  ChartSeries best{"best", "#1f63b4", "", {}, {}, {}}, mean{"mean", "#e07b20", "", {}, {}, {}}, median{"median", "#2a9d4a", "6 4", {}, {}, {}};
  for (const GenerationStats& g : gens) {
    c.xs.push_back(g.generation);
    best.ys.push_back(g.best);
    mean.ys.push_back(g.mean);
    median.ys.push_back(g.median);
  }
  c.series = {best, mean, median};
  return line_chart_svg(c, width, height);
}

namespace {

// the q-quantile of v (linear between order statistics), NaN for none
double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double at = q * static_cast<double>(v.size() - 1);
  const std::size_t i = static_cast<std::size_t>(at);
  return i + 1 < v.size() ? v[i] + (at - static_cast<double>(i)) * (v[i + 1] - v[i]) : v[i];
}

}  // namespace

std::string compare_svg(const std::vector<PlottedRun>& runs, bool per_evaluation, const std::string& title,
                        int width, int height) {
  std::vector<std::string> conditions;
  std::size_t longest = 0;
  for (const PlottedRun& r : runs) {
    if (std::find(conditions.begin(), conditions.end(), r.condition) == conditions.end())
      conditions.push_back(r.condition);
    longest = std::max(longest, r.gens.size());
  }
  LineChart c{title, per_evaluation ? "evaluations" : "generation", "fitness", {}, {}};
  // x per generation index: the median over every run that has it
  for (std::size_t i = 0; i < longest; ++i) {
    std::vector<double> x;
    for (const PlottedRun& r : runs)
      if (i < r.gens.size())
        x.push_back(per_evaluation ? static_cast<double>(r.gens[i].evaluations) : r.gens[i].generation);
    c.xs.push_back(quantile(x, 0.5));
  }
  int k = 0;
  for (const std::string& cond : conditions) {
    int members = 0;
    for (const PlottedRun& r : runs) members += r.condition == cond;
    const std::string color = chart_color(k++);
    const std::string n = members > 1 ? " (median of " + std::to_string(members) + ")" : "";
    ChartSeries best{cond + " best" + n, color, "", {}, {}, {}}, mean{cond + " mean" + n, color, "6 4", {}, {}, {}};
    for (std::size_t i = 0; i < longest; ++i) {
      std::vector<double> b, m;
      for (const PlottedRun& r : runs)
        if (r.condition == cond && i < r.gens.size()) {
          b.push_back(r.gens[i].best);
          m.push_back(r.gens[i].mean);
        }
      best.ys.push_back(quantile(b, 0.5));
      mean.ys.push_back(quantile(m, 0.5));
      if (members > 1) {
        best.lo.push_back(b.size() > 1 ? quantile(b, 0.25) : std::nan(""));
        best.hi.push_back(b.size() > 1 ? quantile(b, 0.75) : std::nan(""));
      }
    }
    c.series.push_back(std::move(best));
    c.series.push_back(std::move(mean));
  }
  return line_chart_svg(c, width, height);
}

namespace {

// Whether every named metric is 0 or 1 in every evaluation (a count of
// levels completed): its mean is then its share of evaluations.
bool metrics_are_shares(const std::vector<const std::vector<GenerationStats>*>& runs,
                        const std::vector<std::string>& names) {
  for (const auto* gens : runs)
    for (const GenerationStats& g : *gens)
      for (const MetricStat& m : g.metrics)
        if (std::find(names.begin(), names.end(), m.name) != names.end() && !(std::abs(m.mean - m.nonzero) <= 1e-12))
          return false;
  return true;
}

// a metric's value in a generation: its share (%) or its mean; a generation
// that lacks it: none of its evaluations had it
double metric_value(const GenerationStats& g, const std::string& name, bool shares) {
  for (const MetricStat& m : g.metrics)
    if (m.name == name) return shares ? 100 * m.nonzero : m.mean;
  return 0;
}

LineChart metric_chart(bool shares, const std::string& x_label, const std::string& title) {
  return shares ? LineChart{title, x_label, "share of evaluations (%)", {}, {}, 0, 100}
                : LineChart{title, x_label, "mean over the evaluations", {}, {}};
}

}  // namespace

std::string metric_svg(const std::vector<GenerationStats>& gens, const std::vector<std::string>& names,
                       double per_generation, const std::string& x_label, const std::string& title, int width,
                       int height) {
  // shares when every metric drawn is 0 or 1 in every evaluation; else every one as its mean
  const bool shares = metrics_are_shares({&gens}, names);
  LineChart c = metric_chart(shares, x_label, title);
  for (const GenerationStats& g : gens) c.xs.push_back(g.generation * per_generation);
  int k = 0;
  for (const std::string& name : names) {
    ChartSeries s{name, chart_color(k++), "", {}, {}, {}};
    for (const GenerationStats& g : gens) s.ys.push_back(metric_value(g, name, shares));
    c.series.push_back(std::move(s));
  }
  return line_chart_svg(c, width, height);
}

std::string compare_metric_svg(const std::vector<PlottedRun>& runs, const std::vector<std::string>& names,
                               double per_generation, const std::string& x_label, const std::string& title,
                               int width, int height) {
  std::vector<const std::vector<GenerationStats>*> all;
  std::vector<std::string> conditions;
  std::size_t longest = 0;
  for (const PlottedRun& r : runs) {
    all.push_back(&r.gens);
    if (std::find(conditions.begin(), conditions.end(), r.condition) == conditions.end())
      conditions.push_back(r.condition);
    longest = std::max(longest, r.gens.size());
  }
  const bool shares = metrics_are_shares(all, names);
  LineChart c = metric_chart(shares, x_label, title);
  for (std::size_t i = 0; i < longest; ++i) {
    std::vector<double> x;
    for (const PlottedRun& r : runs)
      if (i < r.gens.size()) x.push_back(r.gens[i].generation * per_generation);
    c.xs.push_back(quantile(x, 0.5));
  }
  int k = 0;
  for (const std::string& cond : conditions) {
    int members = 0;
    for (const PlottedRun& r : runs) members += r.condition == cond;
    const std::string n = members > 1 ? " (median of " + std::to_string(members) + ")" : "";
    for (const std::string& name : names) {
      ChartSeries s{(conditions.size() > 1 ? cond + " " : "") + name + n, chart_color(k++), "", {}, {}, {}};
      for (std::size_t i = 0; i < longest; ++i) {
        std::vector<double> v;
        for (const PlottedRun& r : runs)
          if (r.condition == cond && i < r.gens.size()) v.push_back(metric_value(r.gens[i], name, shares));
        s.ys.push_back(quantile(v, 0.5));
        if (members > 1) {
          s.lo.push_back(v.size() > 1 ? quantile(v, 0.25) : std::nan(""));
          s.hi.push_back(v.size() > 1 ? quantile(v, 0.75) : std::nan(""));
        }
      }
      c.series.push_back(std::move(s));
    }
  }
  return line_chart_svg(c, width, height);
}

}  // namespace bx
