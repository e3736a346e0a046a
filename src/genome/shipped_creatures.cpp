#include "genome/shipped_creatures.h"

#include <filesystem>

#include "core/files.h"
#include "core/text.h"

namespace bx {

namespace fs = std::filesystem;

namespace {
constexpr std::uintmax_t kMaxGenomeFileBytes = 16u << 20;
}

Result<CreatureText> read_creature_text(const std::string& name) {
  for (const ShippedCreature& s : shipped_creatures())
    if (s.name == name) return CreatureText{s.text, "creature " + s.name + " (shipped)"};
  std::error_code ec;
  const fs::file_status st = fs::status(name, ec);
  if (ec || !fs::exists(st)) {
    std::vector<std::string> names;
    for (const ShippedCreature& s : shipped_creatures()) names.push_back(s.name);
    // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "x" + string&&
    std::string quoted = "\"";
    quoted.append(one_line(name, 200)).append("\"");
    return Error{quoted + ": no canonical creature of that name" + did_you_mean(name, names) +
                 " (creatures/ has " + std::to_string(names.size()) + ") and no such file"};
  }
  if (!fs::is_regular_file(st)) return Error{one_line(name, 200) + ": not a regular file"};
  if (fs::file_size(name, ec) > kMaxGenomeFileBytes)
    return Error{one_line(name, 200) + ": larger than 16 MiB, not a genome file"};
  auto text = read_file(name);
  if (!text) return Error{text.error()};
  return CreatureText{std::move(*text), name};
}

}  // namespace bx
