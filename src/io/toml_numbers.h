// Numbers in a config's TOML that a double (or a 64-bit integer) cannot hold,
// refused with the key and the value as written, never rounded: toml++ reads
// 1e-400 as 0 (for a limit, "no limit") and refuses 1e400 without naming its
// key.
#pragma once

#include <toml++/toml.h>

#include <string>
#include <string_view>

#include "core/result.h"

namespace bx {

/// Refuses the first number of `root` (parsed from `text`) that underflows:
/// written with a digit other than 0, it reads as 0 or, below the least
/// normal double (2.2e-308), keeps only some of its digits. The error reads
/// "SOURCE: KEY: underflows: ..., got 1e-400" (an array's element as KEY[i]).
Status check_number_range(const toml::table& root, std::string_view text, std::string_view source);

/// A parse error of `text` as a config's error: "SOURCE:LINE:COLUMN: what
/// toml++ says", on one line. A number too large for a double or a 64-bit
/// integer also names its key when its line gives one: "SOURCE:LINE:COLUMN:
/// KEY: overflows: ..., got 1e400".
std::string toml_error_text(const toml::parse_error& e, std::string_view text, std::string_view source);

}  // namespace bx
