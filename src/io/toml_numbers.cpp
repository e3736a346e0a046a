#include "io/toml_numbers.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "core/text.h"

namespace bx {

namespace {

// line `line` (from 1) of `text`, without its newline ("" past the end)
std::string_view text_line(std::string_view text, std::size_t line) {
  std::size_t at = 0;
  for (std::size_t l = 1; l < line; ++l) {
    at = text.find('\n', at);
    if (at == std::string_view::npos) return {};
    ++at;
  }
  return text.substr(at, text.find('\n', at) - at);
}

bool number_char(char c) {
  return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '+' ||
         c == '-' || c == '.';
}

// the number as written where toml++ says a value begins (its column counts
// characters, not bytes)
std::string_view literal_at(std::string_view text, const toml::source_position& p) {
  const std::string_view line = text_line(text, p.line);
  std::size_t at = 0;
  for (std::size_t c = 1; c < p.column && at < line.size(); ++c)
    at += std::max<std::size_t>(1, utf8_sequence(line.substr(at)));
  at = std::min(at, line.size());
  std::size_t end = at;
  while (end < line.size() && number_char(line[end])) ++end;
  return line.substr(at, end - at);
}

// whether a float as written has a digit other than 0 before its exponent
bool written_nonzero(std::string_view literal) {
  for (char c : literal) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

Status check_node(const toml::node& n, const std::string& key, std::string_view text, std::string_view source) {
  if (const toml::table* t = n.as_table()) {
    for (auto&& [k, v] : *t)
      if (Status s = check_node(v, (key.empty() ? "" : key + ".") + one_line(k.str(), 100), text, source); !s) return s;
  } else if (const toml::array* a = n.as_array()) {
    for (std::size_t i = 0; i < a->size(); ++i)
      if (Status s = check_node(*a->get(i), key + "[" + std::to_string(i) + "]", text, source); !s) return s;
  } else if (n.is_floating_point()) {
    const double v = *n.value<double>();
    const std::string_view written = literal_at(text, n.source().begin);
    if ((v == 0 && written_nonzero(written)) || (v != 0 && std::abs(v) < DBL_MIN))
      return Error{std::string(source) + ": " + key +
                   ": underflows: below 2.2e-308 a number reads as 0 or loses digits (write 0, or a larger number), "
                   "got " + one_line(written, 100)};
  }
  return Ok{};
}

// the key a line sets, "section.key" with the table it is in ("" when the
// line sets none: an array's later line)
std::string key_on_line(std::string_view text, std::size_t line) {
  auto trim = [](std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
  };
  const std::string_view l = text_line(text, line);
  const std::size_t eq = l.find('=');
  const std::string_view key = trim(l.substr(0, eq == std::string_view::npos ? 0 : eq));
  if (key.empty() || key.find_first_of("#[]{}\"'") != std::string_view::npos) return "";
  // the table: the last [header] or [[header]] above it
  for (std::size_t k = line; k-- > 1;) {
    const std::string_view h = trim(text_line(text, k));
    if (h.empty() || h.front() != '[') continue;
    const std::size_t close = h.find(']');
    if (close == std::string_view::npos) break;
    const std::string_view name = trim(h.substr(h.find_first_not_of('['), close - h.find_first_not_of('[')));
    return one_line(std::string(name) + "." + std::string(key), 100);
  }
  return one_line(key, 100);
}

}  // namespace

Status check_number_range(const toml::table& root, std::string_view text, std::string_view source) {
  return check_node(root, "", text, source);
}

std::string toml_error_text(const toml::parse_error& e, std::string_view text, std::string_view source) {
  const auto& b = e.source().begin;
  const std::string where = std::string(source) + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) + ": ";
  // toml++ quotes what it saw, a newline included
  const std::string_view what = e.description();
  const bool too_large = what.find("' could not be interpreted as a value") != std::string_view::npos ||
                         what.find("' is not representable in 64 bits") != std::string_view::npos;
  const std::size_t q = what.find('\'');
  if (!too_large || q == std::string_view::npos) return where + one_line(what, 200);
  const std::string_view value = what.substr(q + 1, what.find('\'', q + 1) - q - 1);
  const std::string key = key_on_line(text, b.line);
  const bool integer = what.find("floating-point") == std::string_view::npos;
  return where + (key.empty() ? "" : key + ": ") + "overflows: " +
         (integer ? "an integer holds at most 9223372036854775807" : "a number holds at most 1.8e308") +
         " in magnitude, got " + one_line(value, 100);
}

}  // namespace bx
