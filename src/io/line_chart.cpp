#include "io/line_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/text.h"

namespace bx {

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}


// a "nice" tick step giving about n ticks over span
double tick_step(double span, int n) {
  double raw = span / n, p = std::pow(10, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * p) return m * p;
  return 10 * p;
}

}  // namespace

const char* chart_color(int k) {
  static const char* colors[] = {"#1f63b4", "#e07b20", "#2a9d4a", "#c23b3b", "#7b4fb0", "#8c6239", "#d45fa8", "#6b6b6b"};
  return colors[((k % 8) + 8) % 8];
}

std::string line_chart_svg(const LineChart& chart, int width, int height) {
  // plot area inside margins for title, axes and legend; the legend in rows
  // of up to four entries, each as wide as the longest name needs
  std::size_t longest = 0;
  for (const ChartSeries& c : chart.series) longest = std::max(longest, c.name.size());
  const double left = 70, right = 20, bottom = 60;
  const double pw = width - left - right;
  const double slot = std::max(chart.series.size() > 3 ? 150.0 : 80.0, 34 + 7.2 * static_cast<double>(longest));
  const int per_row = std::clamp(static_cast<int>(pw / slot), 1, 4);
  const int n_series = static_cast<int>(chart.series.size());
  const int rows = (n_series + per_row - 1) / per_row;
  // a legend wider than the space beside the title (16 px text: about 8.8 px
  // a character) goes below it
  const double title_width = 10 + 8.8 * static_cast<double>(chart.title.size());
  const bool below = rows > 0 && slot * std::min(per_row, n_series) > pw - std::max(220.0, title_width);
  const double top = 40 + 18.0 * std::max(0, rows - 1) + (below ? 18.0 : 0), ph = height - top - bottom;
  const std::vector<double>& xs = chart.xs;
  double x0 = xs.empty() ? 0 : xs.front(), x1 = xs.empty() ? 1 : xs.back();
  if (x1 <= x0) x1 = x0 + 1;
  double lo = 0, hi = 0;
  if (chart.y_min != 0 || chart.y_max != 0) {
    lo = chart.y_min;
    hi = chart.y_max;
  } else {
    for (const ChartSeries& c : chart.series)
      for (const std::vector<double>* vs : {&c.ys, &c.lo, &c.hi})
        for (double v : *vs)
          if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
          }
  }
  if (hi <= lo) hi = lo + 1;
  auto X = [&](double x) { return left + (x - x0) / (x1 - x0) * pw; };
  auto Y = [&](double v) { return top + (hi - v) / (hi - lo) * ph; };

  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
                  "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) +
                  " " + std::to_string(height) + "\" font-family=\"sans-serif\" font-size=\"13\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s += "<text x=\"" + fmt("%.1f", left) + "\" y=\"24\" font-size=\"16\">" + xml_text(chart.title) + "</text>\n";
  // grid and ticks
  double ys = tick_step(hi - lo, 5);
  for (double v = std::ceil(lo / ys) * ys; v <= hi + 1e-12; v += ys) {
    s += "<line x1=\"" + fmt("%.1f", left) + "\" x2=\"" + fmt("%.1f", left + pw) + "\" y1=\"" +
         fmt("%.1f", Y(v)) + "\" y2=\"" + fmt("%.1f", Y(v)) + "\" stroke=\"#e3e3e3\"/>\n";
    s += "<text x=\"" + fmt("%.1f", left - 8) + "\" y=\"" + fmt("%.1f", Y(v) + 4) +
         "\" text-anchor=\"end\">" + fmt("%.4g", std::abs(v) < 1e-12 ? 0.0 : v) + "</text>\n";
  }
  double xstep = std::max(1.0, tick_step(x1 - x0, 8));
  for (double x = std::ceil(x0 / xstep) * xstep; x <= x1 + 1e-12; x += xstep)
    s += "<text x=\"" + fmt("%.1f", X(x)) + "\" y=\"" + fmt("%.1f", top + ph + 20) +
         "\" text-anchor=\"middle\">" + fmt("%.0f", x) + "</text>\n";
  s += "<rect x=\"" + fmt("%.1f", left) + "\" y=\"" + fmt("%.1f", top) + "\" width=\"" + fmt("%.1f", pw) +
       "\" height=\"" + fmt("%.1f", ph) + "\" fill=\"none\" stroke=\"#888\"/>\n";
  s += "<text x=\"" + fmt("%.1f", left + pw / 2) + "\" y=\"" + fmt("%.1f", height - 12.0) +
       "\" text-anchor=\"middle\">" + xml_text(chart.x_label) + "</text>\n";
  s += "<text transform=\"translate(16," + fmt("%.1f", top + ph / 2) + ") rotate(-90)\" text-anchor=\"middle\">" +
       xml_text(chart.y_label) + "</text>\n";
  // the bands under every curve: hi left to right, then lo back, over each
  // stretch where both are known
  for (const ChartSeries& c : chart.series) {
    const std::size_t n = std::min({c.lo.size(), c.hi.size(), xs.size()});
    for (std::size_t i = 0; i < n;) {
      std::size_t j = i;
      while (j < n && std::isfinite(c.lo[j]) && std::isfinite(c.hi[j])) ++j;
      if (j > i) {
        std::string pts;
        for (std::size_t t = i; t < j; ++t) pts += fmt("%.1f,", X(xs[t])) + fmt("%.1f ", Y(c.hi[t]));
        for (std::size_t t = j; t-- > i;) pts += fmt("%.1f,", X(xs[t])) + fmt("%.1f ", Y(c.lo[t]));
        s += "<polygon fill=\"" + c.color + "\" fill-opacity=\"0.18\" stroke=\"none\" points=\"" + pts + "\"/>\n";
      }
      i = j + 1;
    }
  }
  // the curves, and their legend in rows of four at the top right
  int k = 0;
  for (const ChartSeries& c : chart.series) {
    std::string pts;
    for (std::size_t i = 0; i < c.ys.size() && i < xs.size(); ++i)
      if (std::isfinite(c.ys[i])) pts += fmt("%.1f,", X(xs[i])) + fmt("%.1f ", Y(c.ys[i]));
    s += "<polyline fill=\"none\" stroke=\"" + c.color + "\" stroke-width=\"2\"" +
         (c.dash.empty() ? std::string() : " stroke-dasharray=\"" + c.dash + "\"") + " points=\"" + pts + "\"/>\n";
    const int row = k / per_row, col = k % per_row;
    const int in_row = std::min(per_row, n_series - per_row * row);
    const double lx = left + pw - slot * in_row + slot * col, ly = 24 + 18.0 * (row + (below ? 1 : 0));
    s += "<line x1=\"" + fmt("%.1f", lx) + "\" x2=\"" + fmt("%.1f", lx + 20) + "\" y1=\"" + fmt("%.1f", ly) +
         "\" y2=\"" + fmt("%.1f", ly) + "\" stroke=\"" + c.color + "\" stroke-width=\"2\"" +
         (c.dash.empty() ? std::string() : " stroke-dasharray=\"" + c.dash + "\"") + "/><text x=\"" +
         fmt("%.1f", lx + 24) + "\" y=\"" + fmt("%.1f", ly + 4) + "\">" + xml_text(c.name) + "</text>\n";
    ++k;
  }
  s += "</svg>\n";
  return s;
}

}  // namespace bx
