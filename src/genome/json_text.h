// JSON text for files and output (a replay, a viewer page's data, a genotype
// file, `--json`) that any string can go into: a path the user named may hold
// bytes that are not UTF-8 ("run\xff"), on which nlohmann's dump() throws.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace bx {

/// `v` as v.dump(indent) writes it, except that a string or key that is not
/// UTF-8 is written as utf8_text() makes it (each stray byte as \xNN): the
/// text still names the file, and writing it cannot fail.
std::string json_text(const nlohmann::json& v, int indent = -1);
std::string json_text(const nlohmann::ordered_json& v, int indent = -1);

}  // namespace bx
