// Presets: the TOML configs in presets/, built into the binary so that
// `bestiary run NAME` works from anywhere.
#pragma once

#include <string>
#include <vector>

namespace bx {

/// One preset: its name (file name without .toml) and text.
struct Preset {
  std::string name;
  std::string text;
};

/// Every preset, by name.
const std::vector<Preset>& presets();

/// The preset of that name, or nullptr.
const Preset* find_preset(const std::string& name);

/// The preset's one-line summary: the first comment line of its text,
/// without a leading "NAME: ".
std::string preset_summary(const Preset& p);

/// The preset's time on 2 cores: its "# Time on 2 cores: ..." line ("" if none).
std::string preset_time(const Preset& p);

}  // namespace bx
