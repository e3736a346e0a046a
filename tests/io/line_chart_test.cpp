// The line chart's layout: its legend never writes over its title.
#include "io/line_chart.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace bx {
namespace {

// the y of the <text> element whose content is `label`
double text_y(const std::string& svg, const std::string& label) {
  const std::size_t at = svg.find(">" + label + "</text>");
  if (at == std::string::npos) return -1;
  const std::size_t open = svg.rfind("<text", at);
  const std::size_t y = svg.find(" y=\"", open) + 4;
  return std::stod(svg.substr(y, svg.find('"', y) - y));
}

LineChart chart(const std::string& title, int n_series) {
  LineChart c;
  c.title = title;
  c.xs = {0, 1};
  for (int k = 0; k < n_series; ++k)
    c.series.push_back({"level " + std::to_string(k) + " completed", chart_color(k), "", {0, 1}, {}, {}});
  return c;
}

TEST(LineChart, ALegendAsWideAsTheTitlesRoomGoesBelowTheTitle) {
  // eight series: two rows of four reach from the right edge to x = 180, into a 28-character title
  const std::string svg = line_chart_svg(chart("rivercrossing-small (seed 1)", 8));
  const double title_y = text_y(svg, "rivercrossing-small (seed 1)");
  ASSERT_GT(title_y, 0);
  for (int k = 0; k < 8; ++k) EXPECT_GT(text_y(svg, "level " + std::to_string(k) + " completed"), title_y + 10) << k;
  // two series with a short title: beside it, on its line
  const std::string beside = line_chart_svg(chart("t", 2));
  EXPECT_NEAR(text_y(beside, "level 0 completed"), text_y(beside, "t") + 4, 1e-9);
}

}  // namespace
}  // namespace bx
