// A genotype's file, of any kind: what `bestiary best --out` writes and every
// command that takes a creature reads. A graph genome's file is the genome
// file (docs/genome-format.md), unchanged; a genotype of another kind is its
// JSON form (Genotype::to_json) with its kind and a format name and version:
//   {"format": "bestiary-genotype", "version": 1, "kind": "floats",
//    "genes": [...], "provenance": {...}}
// Either may carry a "provenance" (where it came from: the run, its config,
// the seed), which the command line reads; it is not part of the genotype.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "core/result.h"
#include "genome/genotype.h"

namespace bx {

/// The "format" of a genotype file of a kind other than graph.
inline constexpr std::string_view kGenotypeFormat = "bestiary-genotype";
/// The "version" of such a file this build reads and writes.
inline constexpr int kGenotypeVersion = 1;

/// Reads a genotype file's text: a field "kind" other than "graph" makes it a
/// genotype of that kind (read_genotype; "format" and "version", when given,
/// must be this build's), else it is a graph genome file, read as
/// genome_from_string reads it (a "kind": "graph" is allowed). The JSON is
/// read strictly (strict_json_from_string). Errors name `source`.
Result<std::unique_ptr<Genotype>> genotype_from_file_text(std::string_view text, std::string_view source);

/// The file's text, indented by 2 and ending with a newline, with
/// `provenance` when it is an object (else without). A graph genome: its
/// canonical form's fields (genome_to_json) and the provenance, keys in
/// alphabetical order, as `best --out` has always written it; another kind:
/// format, version, kind, its JSON form's fields, then the provenance.
std::string genotype_file_string(const Genotype& g, const nlohmann::json& provenance = nullptr);

/// The genotype's canonical text, without provenance, which a provenance's
/// hash covers: a graph genome's genome_to_string, else genotype_file_string.
std::string genotype_text(const Genotype& g);

}  // namespace bx
