#include "io/fitness_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace bx {

namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// XML-safe text
std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// a "nice" tick step giving about n ticks over span
double tick_step(double span, int n) {
  double raw = span / n, p = std::pow(10, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * p) return m * p;
  return 10 * p;
}

}  // namespace

std::string fitness_svg(const std::vector<GenerationStats>& gens, const std::string& title, int width,
                        int height) {
  // plot area inside margins for title, axes and legend
  const double left = 70, right = 20, top = 40, bottom = 60;
  const double pw = width - left - right, ph = height - top - bottom;
  double g0 = gens.empty() ? 0 : gens.front().generation, g1 = gens.empty() ? 1 : gens.back().generation;
  if (g1 <= g0) g1 = g0 + 1;
  double lo = 0, hi = 0;
  for (const auto& g : gens) {
    for (double v : {g.best, g.mean, g.median}) {
      if (!std::isfinite(v)) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (hi <= lo) hi = lo + 1;
  auto X = [&](double g) { return left + (g - g0) / (g1 - g0) * pw; };
  auto Y = [&](double v) { return top + (hi - v) / (hi - lo) * ph; };

  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
                  "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) +
                  " " + std::to_string(height) + "\" font-family=\"sans-serif\" font-size=\"13\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s += "<text x=\"" + fmt("%.1f", left) + "\" y=\"24\" font-size=\"16\">" + escape(title) + "</text>\n";
  // grid and ticks
  double ys = tick_step(hi - lo, 5);
  for (double v = std::ceil(lo / ys) * ys; v <= hi + 1e-12; v += ys) {
    s += "<line x1=\"" + fmt("%.1f", left) + "\" x2=\"" + fmt("%.1f", left + pw) + "\" y1=\"" +
         fmt("%.1f", Y(v)) + "\" y2=\"" + fmt("%.1f", Y(v)) + "\" stroke=\"#e3e3e3\"/>\n";
    s += "<text x=\"" + fmt("%.1f", left - 8) + "\" y=\"" + fmt("%.1f", Y(v) + 4) +
         "\" text-anchor=\"end\">" + fmt("%.4g", std::abs(v) < 1e-12 ? 0.0 : v) + "</text>\n";
  }
  double xs = std::max(1.0, tick_step(g1 - g0, 8));
  for (double g = std::ceil(g0 / xs) * xs; g <= g1 + 1e-12; g += xs)
    s += "<text x=\"" + fmt("%.1f", X(g)) + "\" y=\"" + fmt("%.1f", top + ph + 20) +
         "\" text-anchor=\"middle\">" + fmt("%.0f", g) + "</text>\n";
  s += "<rect x=\"" + fmt("%.1f", left) + "\" y=\"" + fmt("%.1f", top) + "\" width=\"" + fmt("%.1f", pw) +
       "\" height=\"" + fmt("%.1f", ph) + "\" fill=\"none\" stroke=\"#888\"/>\n";
  s += "<text x=\"" + fmt("%.1f", left + pw / 2) + "\" y=\"" + fmt("%.1f", height - 12.0) +
       "\" text-anchor=\"middle\">generation</text>\n";
  s += "<text transform=\"translate(16," + fmt("%.1f", top + ph / 2) +
       ") rotate(-90)\" text-anchor=\"middle\">fitness</text>\n";
  // the three curves and their legend
  struct Curve {
    const char* name;
    const char* color;
    const char* dash;
    double GenerationStats::*field;
  };
  const Curve curves[] = {{"best", "#1f63b4", "", &GenerationStats::best},
                          {"mean", "#e07b20", "", &GenerationStats::mean},
                          {"median", "#2a9d4a", "6 4", &GenerationStats::median}};
  int k = 0;
  for (const Curve& c : curves) {
    std::string pts;
    for (const auto& g : gens)
      if (std::isfinite(g.*c.field)) pts += fmt("%.1f,", X(g.generation)) + fmt("%.1f ", Y(g.*c.field));
    s += std::string("<polyline fill=\"none\" stroke=\"") + c.color + "\" stroke-width=\"2\"" +
         (*c.dash ? std::string(" stroke-dasharray=\"") + c.dash + "\"" : "") + " points=\"" + pts + "\"/>\n";
    double lx = left + pw - 230 + 80 * k++;
    s += "<line x1=\"" + fmt("%.1f", lx) + "\" x2=\"" + fmt("%.1f", lx + 20) + "\" y1=\"24\" y2=\"24\" stroke=\"" +
         c.color + "\" stroke-width=\"2\"/><text x=\"" + fmt("%.1f", lx + 24) + "\" y=\"28\">" + c.name +
         "</text>\n";
  }
  s += "</svg>\n";
  return s;
}

}  // namespace bx
