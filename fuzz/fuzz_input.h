// The input format both fuzz targets share (and tests/fuzz_regressions keeps):
// a text (a genome's JSON, or a config's TOML), then any number of
// `--set section.key=value` overrides, each after a NUL byte.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace bxfuzz {

/// The text and the overrides of one input.
struct Input {
  std::string_view text;
  std::vector<std::string> overrides;
};

inline Input split(const std::uint8_t* data, std::size_t size) {
  std::string_view all(reinterpret_cast<const char*>(data), size);
  Input in;
  auto nul = all.find('\0');
  in.text = all.substr(0, nul);
  while (nul != std::string_view::npos) {
    auto next = all.find('\0', nul + 1);
    in.overrides.emplace_back(all.substr(nul + 1, next == std::string_view::npos ? next : next - nul - 1));
    nul = next;
  }
  return in;
}

/// A property the code promises does not hold: abort, so libFuzzer keeps the input.
[[noreturn]] inline void broken(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz: %s: %s\n", what, detail.c_str());
  std::abort();
}

/// An error message must be one line (the command prints it as `bestiary: ...`).
inline void check_one_line(const std::string& message) {
  if (message.empty()) broken("empty error message", "");
  if (message.find('\n') != std::string::npos) broken("error message on several lines", message);
}

}  // namespace bxfuzz
