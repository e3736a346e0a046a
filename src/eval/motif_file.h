// Motif files: the river crossing's pre-evolved CTRNN motif as a file that a
// config names (motif.file), so a run records which motif it used and the
// hash of the file it came from (motif.hash). A motif file is a genotype
// file of the motif kind's genes (what `bestiary best --out` writes for a
// run of genotype.kind = "motif"), decoded by motif_from_genes:
//   {"format": "bestiary-genotype", "version": 1, "kind": "floats",
//    "genes": [15 numbers in [-1, 1]], "motif": {...}}
// The optional "motif" object says what the genes decode to and score
// (w, tau, alpha, input, output, fitness, oscillation, quiescence); the
// reader checks it against the genes. The files in motifs/ are built into
// the binary and named without their folder and extension
// ("stanton2015-found"). docs/rivercrossing.md, "The motif file".
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "brain/river/motif_fitness.h"
#include "core/result.h"
#include "eval/sim_config.h"

namespace bx {

/// A motif file shipped in motifs/: its name (the file's, without .json) and text.
struct ShippedMotif {
  std::string name;
  std::string text;
};

/// Every shipped motif file, by name (generated from motifs/*.json).
const std::vector<ShippedMotif>& shipped_motifs();

/// A motif read from a motif file.
struct MotifFile {
  Motif motif;                ///< its genes decoded
  std::vector<double> genes;  ///< as the file gives them
  std::string hash;           ///< FNV-1a 64 of the file's text (fnv1a64_hex)
};

/// Reads a motif file's text, its genes decoded by `d`; errors name
/// `source` and the field and value: not JSON, not a genotype file of
/// floats, a gene count other than 15, a gene outside [-1, 1], a "motif"
/// object that disagrees with the genes (its score: under the default
/// MotifFitnessDef, to 1e-9).
Result<MotifFile> parse_motif_file(std::string_view text, std::string_view source, const MotifGeneDef& d);

/// Reads the motif file `file` names: a shipped motif's name, else a path
/// (relative to the working folder) to a regular file of at most 1 MiB.
Result<MotifFile> read_motif_file(const std::string& file, const MotifGeneDef& d);

/// The [motif] keys' rule for one config layer that set `keys` (the river
/// creature row's resolve):
/// - motif.file without motif.hash reads the file: its motif becomes the
///   [motif] values and its hash motif.hash ("" reads nothing and clears the
///   hash); motif values beside it in the same layer are an error;
/// - motif.file with motif.hash is a record of a file read before (a run's
///   resolved config, `bestiary config`'s output): the layer's own motif
///   values stand, all of them given, and the file is not read again, so a
///   run keeps its motif whatever becomes of the file;
/// - motif values without motif.file: the motif is no longer a file's, and
///   motif.file and motif.hash become "";
/// - motif.hash without motif.file is an error.
Status resolve_motif_keys(SimConfig& cfg, const std::vector<std::string>& keys);

}  // namespace bx
