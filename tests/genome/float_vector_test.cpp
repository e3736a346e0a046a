// The float vector genotype: random genes in their box, per-gene Gaussian
// mutation at its rate and sigma, single-point crossover, an exact JSON form.
#include "genome/float_vector.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bx {
namespace {

const std::vector<double>& genes(const Genotype& g) { return static_cast<const FloatVector&>(g).genes; }

TEST(FloatVector, RandomGenesFillTheirBox) {
  FloatVectorOps ops({.length = 1000, .lo = -2, .hi = 3, .sigma = 0.1});
  Rng rng(1);
  auto g = ops.random(rng);
  EXPECT_EQ(g->kind(), "floats");
  double sum = 0, lo = 1e9, hi = -1e9;
  for (double x : genes(*g)) sum += x, lo = std::min(lo, x), hi = std::max(hi, x);
  EXPECT_GE(lo, -2);
  EXPECT_LT(hi, 3);
  EXPECT_NEAR(sum / 1000, 0.5, 0.15);  // uniform mean, 1000 draws: s.d. 0.046
  EXPECT_LT(lo, -1.9);
  EXPECT_GT(hi, 2.9);
}

TEST(FloatVector, MutationMovesAShareRateOfGenesByGaussianSteps) {
  const double sigma = 0.05, rate = 0.2;
  FloatVectorOps ops({.length = 20000, .lo = -10, .hi = 10, .sigma = sigma});
  Rng rng(2);
  FloatVector zero(std::vector<double>(20000, 0.0));
  auto m = ops.mutate(zero, rate, rng);
  int moved = 0;
  double sq = 0, within_1sd = 0;
  for (double x : genes(*m))
    if (x != 0) {
      ++moved;
      sq += x * x;
      within_1sd += std::abs(x) < sigma;
    }
  EXPECT_NEAR(moved / 20000.0, rate, 0.015);
  EXPECT_NEAR(std::sqrt(sq / moved), sigma, 0.003);
  EXPECT_NEAR(within_1sd / moved, 0.6827, 0.03);  // a normal's share within one s.d.
  // clamped into the box
  FloatVectorOps narrow({.length = 100, .lo = 0, .hi = 0.01, .sigma = 1});
  auto c = narrow.mutate(FloatVector(std::vector<double>(100, 0.005)), 1.0, rng);
  for (double x : genes(*c)) EXPECT_TRUE(x >= 0 && x <= 0.01) << x;
  // rate 0 changes nothing
  EXPECT_TRUE(ops.mutate(zero, 0.0, rng)->equals(zero));
}

TEST(FloatVector, CrossoverTakesAHeadOfOneAndTheTailOfTheOther) {
  const int n = 10;
  FloatVectorOps ops({.length = n, .lo = -1, .hi = 1, .sigma = 0.1});
  FloatVector a(std::vector<double>(n, -1.0)), b(std::vector<double>(n, 1.0));
  Rng rng(3);
  std::vector<int> cuts(n, 0);
  for (int k = 0; k < 2000; ++k) {
    auto c = ops.crossover(a, b, rng);
    const auto& g = genes(*c);
    int cut = 0;
    while (cut < n && g[cut] == -1.0) ++cut;
    for (int i = cut; i < n; ++i) ASSERT_EQ(g[i], 1.0) << "one cut only";
    ASSERT_GE(cut, 1);
    ASSERT_LE(cut, n - 1);
    ++cuts[cut];
  }
  // every cut point in [1, n-1], about equally often
  for (int c = 1; c < n; ++c) EXPECT_NEAR(cuts[c], 2000.0 / (n - 1), 70) << c;
}

TEST(FloatVector, JsonRoundTripsEveryBitAndNamesABadGene) {
  FloatVectorOps ops({.length = 3, .lo = -1, .hi = 1, .sigma = 0.1});
  Rng rng(4);
  auto g = ops.random(rng);
  auto back = ops.from_json(nlohmann::json::parse(g->to_json().dump()));
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_TRUE((*back)->equals(*g));
  EXPECT_EQ(ops.from_json({{"genes", {0.1, 0.2}}}).error(), "floats: genes: need 3 values, got 2");
  EXPECT_EQ(ops.from_json({{"genes", {0.1, 2.5, 0.0}}}).error(), "floats: genes[1]: must lie in [-1.0, 1.0], got 2.5");
  EXPECT_EQ(ops.from_json({{"genes", {0.1, "x", 0.0}}}).error(), "floats: genes[1]: not a finite number, got \"x\"");
  EXPECT_EQ(ops.from_json(nlohmann::json::object()).error(), "floats: no field genes");
  EXPECT_FALSE(ops.can_graft());
}

}  // namespace
}  // namespace bx
