#include "genome/graph_genotype.h"

#include "genome/float_vector.h"
#include "genome/genome_edit.h"
#include "genome/genome_json.h"

namespace bx {

nlohmann::json GraphGenotype::to_json() const { return genome_to_json(genome); }

bool GraphGenotype::equals(const Genotype& other) const {
  const Genome* g = graph_genome(other);
  return g && *g == genome;
}

double GraphGenotype::cost_hint() const { return count_parts(genome, 1000); }

const Genome* graph_genome(const Genotype& g) {
  return g.kind() == GraphGenotype::kKind ? &static_cast<const GraphGenotype&>(g).genome : nullptr;
}

// the kinds a run database or a job can hold; a new kind adds its reader here
Result<std::unique_ptr<Genotype>> read_genotype(std::string_view kind, const nlohmann::json& j,
                                                std::string_view source) {
  if (kind == GraphGenotype::kKind) {
    auto g = genome_from_json(j, source);
    if (!g) return Error{g.error()};
    return std::unique_ptr<Genotype>(std::make_unique<GraphGenotype>(std::move(*g)));
  }
  if (kind == "floats") {
    auto v = FloatVector::from_json(j, source);
    if (!v) return Error{v.error()};
    return std::unique_ptr<Genotype>(std::make_unique<FloatVector>(std::move(*v)));
  }
  return Error{std::string(source) + ": unknown genotype kind \"" + std::string(kind) +
               "\" (expected graph or floats)"};
}

Result<std::unique_ptr<Genotype>> parse_genotype(std::string_view kind, std::string_view text,
                                                 std::string_view source) {
  if (kind == GraphGenotype::kKind) {
    auto g = genome_from_string(text, source);
    if (!g) return Error{g.error()};
    return std::unique_ptr<Genotype>(std::make_unique<GraphGenotype>(std::move(*g)));
  }
  auto j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded()) return Error{std::string(source) + ": its genotype is not JSON"};
  return read_genotype(kind, j, source);
}

}  // namespace bx
