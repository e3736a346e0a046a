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
    if (text == std::string::npos) continue;
    std::string summary = line.substr(text);
    if (summary.rfind(p.name + ": ", 0) == 0) summary = summary.substr(p.name.size() + 2);
    return summary;
  }
  return "";
}

std::string preset_time(const Preset& p) {
  const std::string key = "# Time on 2 cores: ";
  auto at = p.text.find(key);
  if (at == std::string::npos) return "";
  std::string t = p.text.substr(at + key.size(), p.text.find('\n', at) - at - key.size());
  while (!t.empty() && (t.back() == '.' || t.back() == ' ' || t.back() == '\r')) t.pop_back();
  return t;
}

}  // namespace bx
