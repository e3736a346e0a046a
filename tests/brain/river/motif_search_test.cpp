// The offline search that found the motif in motif_fitness_test.cpp
// (MotifFitness.FoundMotif...): the paper's motif run in small, a
// steady-state evolution of motif genes (motif_from_genes) under
// motif_fitness. Disabled, since it takes about two and a half CPU-minutes
// and its answer is checked in; run it with
//   ./build/test_brain --gtest_filter='MotifSearch.*' --gtest_also_run_disabled_tests
// and it prints the best motif to full precision.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <vector>

#include "brain/river/motif_fitness.h"
#include "core/rng.h"

namespace bx {
namespace {

using Genes = std::array<double, kMotifGenes>;

struct Individual {
  Genes genes{};
  double fitness = 0;
};

double evaluate(const Genes& g) {
  const Result<Motif> m = motif_from_genes(g, MotifGeneDef{});
  EXPECT_TRUE(m.ok()) << m.error();
  return motif_fitness(*m, MotifFitnessDef{});
}

// The paper's motif run as far as it describes it: a population of 1000
// random real-valued genotypes and three-genome tournaments, here with the
// controller's scheme (the tournament's worst replaced by a mutated
// single-point crossover of the other two). Mutation: each gene with
// probability 0.2 moves by N(0, 0.1), clamped into [-1, 1]; the float vector
// genotype's operators, which this layer cannot see, do the same.
TEST(MotifSearch, DISABLED_EvolveAMotif) {
  constexpr int kPopulation = 1000;     // the paper's
  constexpr int kTournaments = 1000000;  // about 2.5 CPU-minutes
  constexpr double kRate = 0.2, kSigma = 0.1;
  Rng rng(20150720);
  std::vector<Individual> pop(kPopulation);
  for (Individual& ind : pop) {
    for (double& g : ind.genes) g = rng.uniform(-1, 1);
    ind.fitness = evaluate(ind.genes);
  }
  const auto fitter = [](const Individual& x, const Individual& y) { return x.fitness < y.fitness; };
  const auto draw = [&rng] { return static_cast<std::size_t>(rng.uniform() * kPopulation); };
  for (int t = 0; t < kTournaments; ++t) {
    // three different individuals, fittest first
    std::array<std::size_t, 3> pick{};
    pick[0] = draw();
    do pick[1] = draw();
    while (pick[1] == pick[0]);
    do pick[2] = draw();
    while (pick[2] == pick[0] || pick[2] == pick[1]);
    std::sort(pick.begin(), pick.end(),
              [&](std::size_t a, std::size_t b) { return pop[a].fitness > pop[b].fitness; });
    const Genes& a = pop[pick[0]].genes;
    const Genes& b = pop[pick[1]].genes;
    Individual child;
    const std::size_t cut = 1 + static_cast<std::size_t>(rng.uniform() * (kMotifGenes - 1));
    for (std::size_t i = 0; i < child.genes.size(); ++i) child.genes[i] = i < cut ? a[i] : b[i];
    for (double& g : child.genes)
      if (rng.chance(kRate)) g = std::clamp(g + kSigma * rng.normal(), -1.0, 1.0);
    child.fitness = evaluate(child.genes);
    pop[pick[2]] = child;
    if (t % 50000 == 0) {
      double mean = 0;
      for (const Individual& ind : pop) mean += ind.fitness;
      std::printf("tournament %d: best %.6f mean %.6f\n", t,
                  std::max_element(pop.begin(), pop.end(), fitter)->fitness, mean / kPopulation);
      std::fflush(stdout);
    }
  }

  const Individual& best = *std::max_element(pop.begin(), pop.end(), fitter);
  const Motif m = *motif_from_genes(best.genes, MotifGeneDef{});
  const MotifScore s = score_motif(m, MotifFitnessDef{});
  std::printf("genes:");
  for (double g : best.genes) std::printf(" %.17g", g);
  std::printf("\nw:");
  for (const auto& row : m.w)
    for (double w : row) std::printf(" %.17g", w);
  std::printf("\ntau:");
  for (double v : m.tau) std::printf(" %.17g", v);
  std::printf("\nalpha:");
  for (double v : m.alpha) std::printf(" %.17g", v);
  std::printf("\nfitness %.6f (oscillation %.6f, quiescence %.6f), under input %.3f Hz with target power %.6f and "
              "other %.6f; without input power %.3g, range %.3g\n",
              s.fitness, s.oscillation, s.quiescence, s.dominant_hz, s.target_power, s.other_power, s.quiet_power,
              s.quiet_range);
}

}  // namespace
}  // namespace bx
