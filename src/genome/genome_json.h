// The genome's file form (docs/genome-format.md): JSON with a format name and
// version, parsed strictly (unknown fields, wrong types and bad values are
// errors naming the file, the field's path and the value) and written in a
// canonical form, so that parse(write(g)) == g.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "core/result.h"
#include "genome/genome.h"

namespace bx {

/// The "format" field of a genome file.
inline constexpr std::string_view kGenomeFormat = "bestiary-genome";
/// The "version" this build reads and writes.
inline constexpr int kGenomeVersion = 1;

/// Largest genome text read (bytes): a 300,000-neuron genome in canonical form
/// is about 20 MB, and the parsed JSON takes roughly ten times its text in memory.
inline constexpr std::size_t kMaxGenomeBytes = 64u << 20;
/// Deepest nesting of arrays and objects read. A genome nests 6 deep
/// (nodes[].neurons[].inputs[]); the rest is room for a provenance. Checked
/// while parsing, before anything that recurses sees the value.
inline constexpr int kMaxGenomeDepth = 64;

/// Genome from its JSON form, checked by validate(). Errors read
/// "<source>: <path>: <what is wrong>, got <value>".
Result<Genome> genome_from_json(const nlohmann::json& j, std::string_view source);

/// The JSON value of a genome file's text (or another genotype file's:
/// genome/genotype_file.h), read strictly: text longer than kMaxGenomeBytes,
/// nesting deeper than kMaxGenomeDepth and a field given twice are errors, and
/// a syntax error names `source`, the line, column and byte where the parser
/// stopped. Linear in the text's length.
Result<nlohmann::json> strict_json_from_string(std::string_view text, std::string_view source);

/// Genome from JSON text; a syntax error names `source`, the line, column and
/// byte where the parser stopped. Text longer than kMaxGenomeBytes, nesting
/// deeper than kMaxGenomeDepth and a field given twice are errors. Linear in
/// the text's length.
Result<Genome> genome_from_string(std::string_view text, std::string_view source);

/// Genome from a file; errors name the path.
Result<Genome> load_genome(const std::string& path);

/// Canonical JSON form: every field written explicitly (parameters by name),
/// so that genome_from_json(genome_to_json(g)) == g for a valid genome.
/// Fields that do not apply are left out (an input's "edge" unless it reads a
/// child, a sensor's "dof" or "face" for the other sensor type).
nlohmann::json genome_to_json(const Genome& g);

/// Canonical text: the JSON form in file order, indented by 2, short arrays
/// and objects on one line, ending with a newline. Stable: writing a genome
/// read from this text gives the same text.
std::string genome_to_string(const Genome& g);

/// Writes `path` atomically: the text goes to `path`.tmp, which is then
/// renamed over `path`.
Status save_genome(const std::string& path, const Genome& g);

/// A JSON value on one line as error messages quote it ([1.0, -2.0],
/// {"to": 1}); non-finite numbers as nan, inf, -inf. Longer than `max_chars`
/// (if nonzero) is cut and ends in "..." (the rest is not rendered); values
/// nested deeper than kMaxGenomeDepth show as [...] or {...}.
std::string json_one_line(const nlohmann::json& v, std::size_t max_chars = 0);

}  // namespace bx
