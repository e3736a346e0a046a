#include "eval/motif_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <system_error>

#include "core/files.h"
#include "core/hash.h"
#include "core/text.h"
#include "genome/float_vector.h"
#include "genome/genome_json.h"
#include "genome/genotype_file.h"

namespace bx {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// the largest file read as a motif file: a motif file is about 1 kB
constexpr std::uintmax_t kMaxMotifFileBytes = 1 << 20;

// the [motif] keys that give the motif's values
constexpr const char* kValueKeys[] = {"motif.w0",  "motif.w1",    "motif.w2",    "motif.tau",
                                      "motif.alpha", "motif.input", "motif.output"};

// exact equality of a JSON value with the decoded one: a number, or an
// array of numbers (or of such arrays) of the same shape
bool same(const json& j, double v) { return j.is_number() && j.get<double>() == v; }

template <class Array>
bool same(const json& j, const Array& a) {
  if (!j.is_array() || j.size() != a.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same(j[i], a[i])) return false;
  return true;
}

// The "motif" object: what the genes decode to and score, checked against them.
Status check_motif_block(const json& block, const Motif& m, std::string_view source) {
  const std::string at = std::string(source) + ": motif";
  if (!block.is_object()) return Error{at + ": expected an object, got " + json_one_line(block, 60)};
  const MotifScore s = score_motif(m, MotifFitnessDef{});
  for (const auto& [key, v] : block.items()) {
    const std::string where = at + "." + key;
    const auto disagree = [&](const json& want) {
      return Status(Error{where + ": " + json_one_line(v, 120) + ", but the genes give " + json_one_line(want, 120)});
    };
    if (key == "about") {
      if (!v.is_string()) return Error{where + ": expected text, got " + json_one_line(v, 60)};
    } else if (key == "w") {
      if (!same(v, m.w)) return disagree(m.w);
    } else if (key == "tau") {
      if (!same(v, m.tau)) return disagree(m.tau);
    } else if (key == "alpha") {
      if (!same(v, m.alpha)) return disagree(m.alpha);
    } else if (key == "input" || key == "output") {
      const int n = key == "input" ? m.input : m.output;
      if (!v.is_number_integer() || v.get<std::int64_t>() != n) return disagree(n);
    } else if (key == "fitness" || key == "oscillation" || key == "quiescence") {
      // the score under the default fitness constants, to rounding
      const double want = key == "fitness" ? s.fitness : key == "oscillation" ? s.oscillation : s.quiescence;
      if (!v.is_number() || !(std::abs(v.get<double>() - want) <= 1e-9))
        return Error{where + ": " + json_one_line(v, 60) + ", but the genes score " + json(want).dump() +
                     " (under the default motif_fitness keys)"};
    } else {
      return Error{where + ": unknown field (about, w, tau, alpha, input, output, fitness, oscillation, quiescence)"};
    }
  }
  return Ok{};
}

bool has(const std::vector<std::string>& keys, std::string_view key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

}  // namespace

Result<MotifFile> parse_motif_file(std::string_view text, std::string_view source, const MotifGeneDef& d) {
  auto g = genotype_from_file_text(text, source);
  if (!g) return Error{g.error()};
  if ((*g)->kind() != "floats")
    return Error{std::string(source) + ": kind: a " + std::string((*g)->kind()) +
                 " genotype, not a motif's genes (expected \"kind\": \"floats\" with " +
                 std::to_string(motif_gene_count()) + " genes)"};
  MotifFile out;
  out.genes = static_cast<const FloatVector&>(**g).genes;
  auto m = motif_from_genes(out.genes, d);
  if (!m) return Error{std::string(source) + ": genes: " + m.error()};
  out.motif = *m;
  // the file's own account of its motif, when it gives one (strict JSON: it parses)
  const json j = json::parse(text);
  if (j.contains("motif"))
    if (Status s = check_motif_block(j["motif"], out.motif, source); !s) return Error{s.error()};
  out.hash = fnv1a64_hex(text);
  return out;
}

Result<MotifFile> read_motif_file(const std::string& file, const MotifGeneDef& d) {
  for (const ShippedMotif& s : shipped_motifs())
    if (s.name == file) return parse_motif_file(s.text, "motif " + s.name + " (shipped)", d);
  std::error_code ec;
  const fs::file_status st = fs::status(file, ec);
  if (ec || !fs::exists(st)) {
    std::vector<std::string> names;
    std::string list;
    for (const ShippedMotif& s : shipped_motifs()) {
      names.push_back(s.name);
      list += (list.empty() ? "" : ", ") + s.name;
    }
    // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "x" + string&&
    std::string quoted = "\"";
    quoted.append(one_line(file, 200)).append("\"");
    return Error{quoted + ": no shipped motif of that name" + did_you_mean(file, names) + " (shipped: " + list +
                 ") and no such file"};
  }
  if (!fs::is_regular_file(st)) return Error{one_line(file, 200) + ": not a regular file"};
  if (fs::file_size(file, ec) > kMaxMotifFileBytes)
    return Error{one_line(file, 200) + ": larger than 1 MiB, not a motif file"};
  auto text = read_file(file);
  if (!text) return Error{text.error()};
  return parse_motif_file(*text, file, d);
}

Status resolve_motif_keys(SimConfig& cfg, const std::vector<std::string>& keys) {
  const bool file = has(keys, "motif.file"), hash = has(keys, "motif.hash");
  std::vector<std::string> values;
  for (const char* k : kValueKeys)
    if (has(keys, k)) values.emplace_back(k);
  MotifSource& src = cfg.motif_source;
  if (hash && !file)
    return Error{"motif.hash: \"" + one_line(src.hash, 60) +
                 "\" without motif.file (the reader writes it, with the file it read)"};
  if (file && hash && src.file.empty() && !src.hash.empty())
    return Error{"motif.hash: \"" + one_line(src.hash, 60) + "\" with motif.file \"\" (no file to be the hash of)"};
  if (file && hash && !src.hash.empty()) {
    // a record of a file read before: its values stand, every one given
    for (const char* k : kValueKeys)
      if (!has(keys, k))
        return Error{std::string(k) + ": not given beside motif.file and motif.hash (a resolved config gives "
                     "every motif key; drop motif.hash to read motif.file again)"};
    return Ok{};
  }
  if (file && !src.file.empty()) {
    if (!values.empty())
      return Error{values.front() + ": given beside motif.file \"" + one_line(src.file, 200) +
                   "\", which gives the motif (give one or the other)"};
    auto m = read_motif_file(src.file, cfg.motif_kind.genes);
    if (!m) return Error{"motif.file: " + m.error()};
    cfg.motif = m->motif;
    src.hash = m->hash;
    return Ok{};
  }
  // no file ("" with or without an empty hash), or values given as keys
  // alone: the motif is no file's
  if (file || !values.empty()) src = MotifSource{};
  return Ok{};
}

}  // namespace bx
