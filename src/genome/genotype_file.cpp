#include "genome/genotype_file.h"

#include "genome/genome_json.h"
#include "genome/graph_genotype.h"
#include "genome/json_text.h"

namespace bx {

namespace {

using nlohmann::json;

std::string at(std::string_view source, const std::string& what) {
  return source.empty() ? what : std::string(source) + ": " + what;
}

}  // namespace

Result<std::unique_ptr<Genotype>> genotype_from_file_text(std::string_view text, std::string_view source) {
  auto parsed = strict_json_from_string(text, source);
  if (!parsed) return Error{parsed.error()};
  json& j = *parsed;
  const json* kind = j.is_object() ? (j.contains("kind") ? &j["kind"] : nullptr) : nullptr;
  if (kind && !kind->is_string())
    return Error{at(source, "kind: expected a genotype kind's name (graph, floats), got " + json_one_line(*kind, 60))};

  // a graph genome: the genome file, read by its own reader
  if (!kind || kind->get<std::string>() == GraphGenotype::kKind) {
    if (kind) j.erase("kind");
    auto g = genome_from_json(j, source);
    if (!g) return Error{g.error()};
    return std::unique_ptr<Genotype>(std::make_unique<GraphGenotype>(std::move(*g)));
  }

  // another kind: its JSON form beside the file's own fields
  const std::string name = kind->get<std::string>();
  if (const auto f = j.find("format"); f != j.end() && (!f->is_string() || f->get<std::string>() != kGenotypeFormat))
    return Error{at(source, "format: not a genotype file (expected \"" + std::string(kGenotypeFormat) + "\"), got " +
                                json_one_line(*f, 60))};
  if (const auto v = j.find("version"); v != j.end() && (!v->is_number_integer() || v->get<std::int64_t>() != kGenotypeVersion))
    return Error{at(source, "version: unsupported version " + json_one_line(*v, 60) + " (this build reads " +
                                std::to_string(kGenotypeVersion) + "), got " + json_one_line(*v, 60))};
  if (const auto p = j.find("provenance"); p != j.end() && !p->is_object())
    return Error{at(source, "provenance: expected an object, got " + json_one_line(*p, 60))};
  json form = j;
  for (const char* k : {"format", "version", "kind", "provenance"}) form.erase(k);
  return read_genotype(name, form, source);
}

std::string genotype_file_string(const Genotype& g, const json& provenance) {
  if (const Genome* genome = graph_genome(g)) {
    json j = genome_to_json(*genome);
    if (provenance.is_object()) j["provenance"] = provenance;
    return json_text(j, 2) + "\n";
  }
  nlohmann::ordered_json j;
  j["format"] = std::string(kGenotypeFormat);
  j["version"] = kGenotypeVersion;
  j["kind"] = std::string(g.kind());
  const json form = g.to_json();
  for (const auto& [k, v] : form.items()) j[k] = v;
  if (provenance.is_object()) j["provenance"] = provenance;
  return json_text(j, 2) + "\n";
}

std::string genotype_text(const Genotype& g) {
  if (const Genome* genome = graph_genome(g)) return genome_to_string(*genome);
  return genotype_file_string(g);
}

}  // namespace bx
