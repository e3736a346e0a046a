// Small text helpers for messages: "did you mean" suggestions, user text
// quoted on one line, any bytes (a path) as UTF-8 text.
#pragma once

#include <charconv>

#include <algorithm>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace bx {

/// The shortest text that reads back as the same double (std::to_chars).
inline std::string shortest_number(double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

/// A number as printf's %g prints it, for messages.
inline std::string g_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// `s` with the ASCII letters A-Z lowered (file extensions, keywords); other
/// bytes, UTF-8 included, as they are.
inline std::string ascii_lower(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
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

/// The length of the well-formed UTF-8 sequence that starts `text` (1 to 4
/// bytes), or 0 if none does: a stray continuation byte, an overlong form, a
/// surrogate, past U+10FFFF, or cut short.
inline std::size_t utf8_sequence(std::string_view text) {
  if (text.empty()) return 0;
  auto byte = [&](std::size_t i) { return i < text.size() ? static_cast<unsigned char>(text[i]) : 0u; };
  const unsigned c = byte(0);
  if (c < 0x80) return 1;
  // the length a lead byte announces, and the range of the byte after it
  // (narrowed where the sequence would be overlong, a surrogate or past U+10FFFF)
  std::size_t n = 0;
  unsigned lo = 0x80, hi = 0xbf;
  if (c >= 0xc2 && c <= 0xdf) {
    n = 2;
  } else if (c >= 0xe0 && c <= 0xef) {
    n = 3;
    if (c == 0xe0) lo = 0xa0;
    if (c == 0xed) hi = 0x9f;
  } else if (c >= 0xf0 && c <= 0xf4) {
    n = 4;
    if (c == 0xf0) lo = 0x90;
    if (c == 0xf4) hi = 0x8f;
  } else {
    return 0;
  }
  for (std::size_t i = 1; i < n; ++i, lo = 0x80, hi = 0xbf)
    if (byte(i) < lo || byte(i) > hi) return 0;
  return n;
}

/// `bytes` (a path or a name as the user gave it: any bytes) as UTF-8 text,
/// which JSON, TOML and the viewer's pages must hold: each byte that is not
/// part of a well-formed UTF-8 sequence is written as \xNN (as one_line
/// writes control characters), the rest as it is. The text still names the
/// file ("run\xff"), and writing it cannot fail.
inline std::string utf8_text(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size());
  for (std::size_t i = 0; i < bytes.size();) {
    if (std::size_t n = utf8_sequence(bytes.substr(i))) {
      out.append(bytes.substr(i, n));
      i += n;
      continue;
    }
    const char* hex = "0123456789abcdef";
    const auto c = static_cast<unsigned char>(bytes[i++]);
    out += "\\x";
    out += hex[c >> 4];
    out += hex[c & 15];
  }
  return out;
}

/// `bytes` as text inside an XML (or SVG, MJCF) attribute or element:
/// UTF-8 as utf8_text makes it, with & < > " escaped.
inline std::string xml_text(std::string_view bytes) {
  std::string out;
  for (char c : utf8_text(bytes)) {
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

}  // namespace bx
