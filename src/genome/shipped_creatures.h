// The canonical creatures (creatures/*.json), built into the binary
// (cmake/creatures.cmake), so a config names one from any folder: a stage
// that starts from a file (io/syllabus.h, `start = "file"`) names a canonical
// creature or a path.
#pragma once

#include <string>
#include <vector>

#include "core/result.h"

namespace bx {

/// A canonical creature's genome file, by name (the file's name without .json).
struct ShippedCreature {
  std::string name;
  std::string text;
};

/// Every canonical creature, sorted by name (generated from creatures/*.json).
const std::vector<ShippedCreature>& shipped_creatures();

/// A genome file's text and what to call it in errors.
struct CreatureText {
  std::string text;
  std::string source;  ///< "creature NAME (shipped)" or the path
};

/// The text of the canonical creature named `name`, else of the file at
/// path `name`. An error names it, suggests a close canonical name, and lists
/// them; a file over 16 MiB is refused (a genome file is kilobytes).
Result<CreatureText> read_creature_text(const std::string& name);

}  // namespace bx
