// Rounding numbers for files that should stay small and print short (a
// replay's poses, signals and scene): to a power of ten, through decimal text.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace bx {

/// v rounded to the nearest multiple of q, a power of ten (1e-5): through
/// decimal text, so the result is the double nearest the rounded decimal,
/// which prints short; never -0.
inline double round_to(double v, double q) {
  int digits = static_cast<int>(std::lround(-std::log10(q)));
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  double r = std::strtod(buf, nullptr);
  return r == 0 ? 0.0 : r;  // no "-0.0"
}

}  // namespace bx
