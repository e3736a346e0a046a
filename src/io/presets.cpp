#include "io/presets.h"

#include <sstream>

namespace bx {

const Preset* find_preset(const std::string& name) {
  for (const auto& p : presets())
    if (p.name == name) return &p;
  return nullptr;
}

std::string preset_summary(const Preset& p) {
  std::istringstream in(p.text);
  std::string line;
  while (std::getline(in, line)) {
    auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] != '#') continue;
    auto text = line.find_first_not_of("# \t", start);
    if (text != std::string::npos) return line.substr(text);
  }
  return "";
}

}  // namespace bx
