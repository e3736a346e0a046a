// Small text helpers for messages: "did you mean" suggestions, user text
// quoted on one line.
#pragma once

#include <algorithm>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace bx {

/// A number as printf's %g prints it, for messages.
inline std::string g_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// Levenshtein distance (insertions, deletions, substitutions).
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

/// " (did you mean \"X\"?)" for the candidate nearest to `word` when it is
/// near enough to be a typo (one edit in a short word, two or a third of the
/// letters in a longer one), else "".
inline std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string* best = nullptr;
  std::size_t best_d = 0;
  for (const auto& c : candidates) {
    std::size_t d = edit_distance(word, c);
    if (!best || d < best_d) best = &c, best_d = d;
  }
  std::size_t near = word.size() < 4 ? 1 : std::max<std::size_t>(2, word.size() / 3);
  if (!best || best_d == 0 || best_d > near) return "";
  return " (did you mean \"" + *best + "\"?)";
}

/// `text` as one line of a message: control characters (a newline, a tab,
/// ...) written as escapes (\n, \t, \x01), and cut to `max_chars` bytes
/// (if nonzero) ending in "...". User input quoted in an error can then
/// neither end the error's line nor make it unbounded.
inline std::string one_line(std::string_view text, std::size_t max_chars = 0) {
  std::string out;
  for (unsigned char c : text) {
    if (max_chars > 3 && out.size() > max_chars) break;
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (c < 0x20 || c == 0x7f) {
      const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  if (max_chars > 3 && out.size() > max_chars) out = out.substr(0, max_chars - 3) + "...";
  return out;
}

}  // namespace bx
