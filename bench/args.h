// The benchmarks' command lines: the number after a flag, checked, or the
// benchmark's usage and exit code 2.
#pragma once

#include <cstdlib>
#include <string>

namespace bxbench {

/// argv[i + 1] (i advances past it) as a number `ok` accepts; otherwise
/// exits with usage("NAME: missing value") or usage("NAME: expected WHAT").
template <class Usage, class Ok>
double number_after(int& i, int argc, char** argv, const char* name, Usage usage, Ok ok, const char* what) {
  if (i + 1 >= argc) std::exit(usage((std::string(name) + ": missing value").c_str()));
  char* end = nullptr;
  const double v = std::strtod(argv[++i], &end);
  if (*end || !ok(v)) std::exit(usage((std::string(name) + ": expected " + what).c_str()));
  return v;
}

}  // namespace bxbench
