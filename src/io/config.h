// TOML configs: sections map one to one onto the definition structs of
// SimConfig. Unknown keys, wrong types and out-of-range values are errors that
// name the key and the value.
#pragma once

#include <string>
#include <string_view>

#include "core/result.h"
#include "eval/sim_config.h"

namespace bx {

/// Overlays the TOML text onto `cfg`. `source` names the text in errors.
Status apply_config_toml(SimConfig& cfg, std::string_view text, std::string_view source);

/// Reads a TOML file and overlays it onto `cfg`.
Status apply_config_file(SimConfig& cfg, const std::string& path);

/// The config as TOML (every key), for run directories and `--print-config`.
std::string config_to_toml(const SimConfig& cfg);

}  // namespace bx
