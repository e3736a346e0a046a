// Comparing runs on one chart (`bestiary plot RUN... --group-by`): each
// condition the median of its runs per generation with the interquartile band
// of its best, checked against hand-computed quantiles in the SVG's points.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/fitness_plot.h"
#include "io/line_chart.h"

namespace bx {
namespace {

GenerationStats gen(int g, double best, double mean) {
  GenerationStats s;
  s.generation = g;
  s.evaluations = 10L * (g + 1);
  s.best = best;
  s.mean = mean;
  return s;
}

// the points of the SVG element starting with `tag` whose attributes hold `with`
std::string points_of(const std::string& svg, const std::string& tag, const std::string& with) {
  for (std::size_t at = svg.find(tag); at != std::string::npos; at = svg.find(tag, at + 1)) {
    const std::size_t end = svg.find("/>", at);
    const std::string el = svg.substr(at, end - at);
    if (el.find(with) == std::string::npos) continue;
    const std::size_t p = el.find("points=\"") + 8;
    return el.substr(p, el.find('"', p) - p);
  }
  return "";
}

TEST(ComparePlot, EachConditionIsItsRunsMedianWithTheirInterquartileBand) {
  // condition A: three runs whose bests at generation 0 are 1, 2, 4 (median 2,
  // quartiles 1.5 and 3); at generation 1: 2, 3, 8 (median 3, quartiles 2.5, 5.5);
  // condition B: one run (no band)
  std::vector<PlottedRun> runs = {{"A", {gen(0, 1, 0.5), gen(1, 2, 1)}},
                                  {"B", {gen(0, 6, 1), gen(1, 7, 2)}},
                                  {"A", {gen(0, 4, 0.5), gen(1, 8, 1)}},
                                  {"A", {gen(0, 2, 0.5), gen(1, 3, 1)}}};
  LineChart expect{"t", "generation", "fitness", {0, 1}, {}};
  ChartSeries a{"A best (median of 3)", chart_color(0), "", {2, 3}, {1.5, 2.5}, {3, 5.5}};
  ChartSeries am{"A mean (median of 3)", chart_color(0), "6 4", {0.5, 1}, {}, {}};
  ChartSeries b{"B best", chart_color(1), "", {6, 7}, {}, {}};
  ChartSeries bm{"B mean", chart_color(1), "6 4", {1, 2}, {}, {}};
  expect.series = {a, am, b, bm};
  const std::string got = compare_svg(runs, false, "t");
  EXPECT_EQ(got, line_chart_svg(expect));
  // one band, condition A's, in its colour
  EXPECT_NE(got.find("<polygon fill=\"" + std::string(chart_color(0)) + "\""), std::string::npos);
  EXPECT_EQ(got.find("<polygon fill=\"" + std::string(chart_color(1)) + "\""), std::string::npos);
  EXPECT_NE(points_of(got, "<polygon", "fill-opacity"), "");
  // per evaluation: x is the evaluations done (10, 20), the axis says so
  const std::string per_eval = compare_svg(runs, true, "t");
  EXPECT_NE(per_eval.find(">evaluations</text>"), std::string::npos);
}

TEST(ComparePlot, RunsOfDifferentLengthsShareTheGenerationsTheyHave) {
  // a longer run alone at generation 2: its value is the median there, no band
  std::vector<PlottedRun> runs = {{"A", {gen(0, 1, 0), gen(1, 2, 0)}}, {"A", {gen(0, 3, 0), gen(1, 4, 0), gen(2, 9, 0)}}};
  LineChart expect{"t", "generation", "fitness", {0, 1, 2}, {}};
  const double nan = std::nan("");
  ChartSeries a{"A best (median of 2)", chart_color(0), "", {2, 3, 9}, {1.5, 2.5, nan}, {2.5, 3.5, nan}};
  ChartSeries am{"A mean (median of 2)", chart_color(0), "6 4", {0, 0, 0}, {}, {}};
  expect.series = {a, am};
  EXPECT_EQ(compare_svg(runs, false, "t"), line_chart_svg(expect));
}

}  // namespace
}  // namespace bx
