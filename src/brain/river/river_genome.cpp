#include "brain/river/river_genome.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <string>
#include <utility>

#include "brain/river/decision_network.h"
#include "brain/river/physical_network.h"

namespace bx {

namespace {

constexpr int kMatrices = 6;

// (rows, cols) of each matrix, in genome order
std::array<std::pair<int, int>, kMatrices> sizes(const RiverShape& s) {
  return {{{s.dn_hidden, kDecisionInputs},
           {kDecisionOutputs, s.dn_hidden},
           {s.pn_hidden, kPhysicalInputs},
           {s.motifs, s.pn_hidden},
           {s.motifs, s.motifs},
           {s.motors, s.motifs}}};
}

// the matrices, in genome order
std::array<WeightMatrix*, kMatrices> matrices(RiverWeights& w) {
  return {&w.dn_input_hidden, &w.dn_hidden_output, &w.pn_input_hidden,
          &w.pn_hidden_output, &w.pg_input, &w.pg_motor};
}

}  // namespace

Status check_river_shape(const RiverShape& s) {
  const std::pair<const char*, int> fields[] = {
      {"dn_hidden", s.dn_hidden}, {"pn_hidden", s.pn_hidden}, {"motifs", s.motifs}, {"motors", s.motors}};
  for (const auto& [name, value] : fields)
    if (value < 1)
      return Error{"river controller: " + std::string(name) + " is " + std::to_string(value) +
                   ", must be at least 1"};
  return Ok{};
}

int river_gene_count(const RiverShape& s) {
  assert(check_river_shape(s).ok());
  int n = 0;
  for (const auto& [rows, cols] : sizes(s)) n += rows * cols;
  return n;
}

std::string river_shape_name(const RiverShape& s) {
  return "DN " + std::to_string(kDecisionInputs) + "-" + std::to_string(s.dn_hidden) + "-" +
         std::to_string(kDecisionOutputs) + ", PN " + std::to_string(kPhysicalInputs) + "-" +
         std::to_string(s.pn_hidden) + "-" + std::to_string(s.motifs) + ", " + std::to_string(s.motifs) +
         " motifs, " + std::to_string(s.motors) + " motors";
}

Result<RiverWeights> unpack_river_genes(const RiverShape& s, std::span<const double> genes) {
  if (Status ok = check_river_shape(s); !ok) return Error{ok.error()};
  const int expected = river_gene_count(s);
  if (static_cast<int>(genes.size()) != expected)
    return Error{"river controller genome: " + std::to_string(genes.size()) + " genes given, " +
                 std::to_string(expected) + " expected (" + river_shape_name(s) + ")"};

  // each matrix takes the next rows * cols genes, row by row
  RiverWeights w;
  const auto shape = sizes(s);
  const auto into = matrices(w);
  std::size_t at = 0;
  for (int k = 0; k < kMatrices; ++k) {
    WeightMatrix& m = *into[static_cast<std::size_t>(k)];
    m = WeightMatrix(shape[static_cast<std::size_t>(k)].first, shape[static_cast<std::size_t>(k)].second);
    std::copy_n(genes.begin() + static_cast<std::ptrdiff_t>(at), m.w.size(), m.w.begin());
    at += m.w.size();
  }
  assert(at == genes.size());
  return w;
}

}  // namespace bx
