#include "genome/float_vector.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

#include "genome/genome_json.h"

namespace bx {

namespace {

const FloatVector& as_floats(const Genotype& g) {
  assert(g.kind() == "floats");
  return static_cast<const FloatVector&>(g);
}

}  // namespace

nlohmann::json FloatVector::to_json() const { return {{"genes", genes}}; }

bool FloatVector::equals(const Genotype& other) const {
  return other.kind() == kind() && as_floats(other).genes == genes;
}

std::unique_ptr<Genotype> FloatVectorOps::random(Rng& rng) const {
  std::vector<double> g(static_cast<std::size_t>(def_.length));
  for (double& x : g) x = rng.uniform(def_.lo, def_.hi);
  return std::make_unique<FloatVector>(std::move(g));
}

std::unique_ptr<Genotype> FloatVectorOps::mutate(const Genotype& g, double rate, Rng& rng) const {
  std::vector<double> out = as_floats(g).genes;
  for (double& x : out)
    if (rng.chance(rate)) x = std::clamp(x + def_.sigma * rng.normal(), def_.lo, def_.hi);
  return std::make_unique<FloatVector>(std::move(out));
}

std::unique_ptr<Genotype> FloatVectorOps::crossover(const Genotype& a, const Genotype& b, Rng& rng) const {
  const std::vector<double>&x = as_floats(a).genes, &y = as_floats(b).genes;
  assert(x.size() == y.size());
  std::vector<double> out = x;
  if (out.size() < 2) return std::make_unique<FloatVector>(std::move(out));
  const std::size_t cut = 1 + rng.below(out.size() - 1);
  std::copy(y.begin() + static_cast<std::ptrdiff_t>(cut), y.end(), out.begin() + static_cast<std::ptrdiff_t>(cut));
  return std::make_unique<FloatVector>(std::move(out));
}

Result<FloatVector> FloatVector::from_json(const nlohmann::json& j, std::string_view source) {
  const std::string at = source.empty() ? std::string("floats") : std::string(source) + ": floats";
  if (!j.is_object() || !j.contains("genes")) return Error{at + ": no field genes"};
  const auto& a = j.at("genes");
  if (!a.is_array()) return Error{at + ": genes: not an array, got " + json_one_line(a, 60)};
  std::vector<double> g;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a[i].is_number() || !std::isfinite(a[i].get<double>()))
      return Error{at + ": genes[" + std::to_string(i) + "]: not a finite number, got " + json_one_line(a[i], 60)};
    g.push_back(a[i].get<double>());
  }
  return FloatVector(std::move(g));
}

Result<std::unique_ptr<Genotype>> FloatVectorOps::from_json(const nlohmann::json& j) const {
  auto v = FloatVector::from_json(j, "");
  if (!v) return Error{v.error()};
  const std::vector<double>& g = v->genes;
  if (static_cast<int>(g.size()) != def_.length)
    return Error{"floats: genes: need " + std::to_string(def_.length) + " values, got " +
                 std::to_string(g.size())};
  for (std::size_t i = 0; i < g.size(); ++i)
    if (g[i] < def_.lo || g[i] > def_.hi)
      return Error{"floats: genes[" + std::to_string(i) + "]: must lie in [" +
                   nlohmann::json(def_.lo).dump() + ", " + nlohmann::json(def_.hi).dump() + "], got " +
                   nlohmann::json(g[i]).dump()};
  return std::unique_ptr<Genotype>(std::make_unique<FloatVector>(std::move(*v)));
}

}  // namespace bx
