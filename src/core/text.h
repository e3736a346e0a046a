// Small text helpers for messages: "did you mean" suggestions.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace bx {

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

}  // namespace bx
