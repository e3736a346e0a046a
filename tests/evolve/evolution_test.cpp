// The evolutionary loops: selection statistics, elitism, bookkeeping and
// determinism, on small real runs.
#include "evolve/evolution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>
#include <set>

#include "io/config.h"

namespace bx {
namespace {

RunConfig small(Dialect d, Algorithm a) {
  RunConfig c = default_run_config(d);
  c.evolution.algorithm = a;
  c.evolution.population = 12;
  c.evolution.generations = 4;
  c.evolution.evaluations = 36;
  c.evolution.batch = 4;
  c.sim.task.seconds = 1;
  c.sim.task.settle_timeout = 2;
  return c;
}

std::vector<GenerationResult> run(const RunConfig& c, std::uint64_t seed, Evaluator& ev,
                                  EvolutionState& s) {
  Evolution evo(c.dialect, c.evolution, c.operators, c.sim.develop, seed);
  std::vector<GenerationResult> out;
  while (!evo.finished(s)) out.push_back(evo.step(s, ev));
  return out;
}

TEST(Selection, DrawsByRankByFitnessOrUniformly) {
  std::vector<Individual> sv(4);
  double fit[] = {4, 3, 2, 0};
  for (int i = 0; i < 4; ++i) sv[i].fitness = fit[i], sv[i].id = i;
  const int n = 40000;
  auto freq = [&](Selection how) {
    Rng rng(7);
    std::vector<double> f(4);
    for (int k = 0; k < n; ++k) f[select_survivor(sv, how, rng)] += 1.0 / n;
    return f;
  };
  auto rank = freq(Selection::Rank);  // weights 4:3:2:1
  auto prop = freq(Selection::Proportionate);  // fitness shifted by the worst, + 1% of the range
  auto uni = freq(Selection::Uniform);
  double wsum = 4.04 + 3.04 + 2.04 + 0.04;
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(rank[i], (4 - i) / 10.0, 0.01) << i;
    EXPECT_NEAR(prop[i], (fit[i] + 0.04) / wsum, 0.01) << i;
    EXPECT_NEAR(uni[i], 0.25, 0.01) << i;
  }
}

class Loops : public ::testing::TestWithParam<std::pair<Dialect, Algorithm>> {};

TEST_P(Loops, KeepThePopulationTheBestAndTheBooksStraight) {
  RunConfig c = small(GetParam().first, GetParam().second);
  SerialEvaluator ev(c.sim);
  EvolutionState s;
  auto gens = run(c, 3, ev, s);
  ASSERT_FALSE(gens.empty());
  std::set<std::int64_t> ids;
  double best = -1e300;
  long evals = 0;
  for (const auto& g : gens) {
    EXPECT_EQ(static_cast<int>(s.population.size()), c.evolution.population);
    // elitism: the best never gets worse
    EXPECT_GE(g.stats.best, best);
    best = g.stats.best;
    EXPECT_LE(g.stats.median, g.stats.best);
    evals += static_cast<long>(g.born.size());
    EXPECT_EQ(g.stats.evaluations, evals);
    for (const auto& ind : g.born) {
      EXPECT_TRUE(ids.insert(ind.id).second) << "id " << ind.id << " reused";
      // parents are earlier individuals; children name their operator
      if (ind.parent1 >= 0) {
        EXPECT_TRUE(ids.count(ind.parent1)) << ind.id;
      }
      if (ind.parent2 >= 0) {
        EXPECT_TRUE(ids.count(ind.parent2)) << ind.id;
      }
      EXPECT_EQ(ind.op == "random", ind.parent1 < 0);
      EXPECT_EQ(ind.generation, g.stats.generation);
    }
  }
  EXPECT_EQ(s.next_id, evals);
  EXPECT_TRUE(Evolution(c.dialect, c.evolution, c.operators, c.sim.develop, 3).finished(s));
}

TEST_P(Loops, SameSeedSameRunAnotherSeedAnotherRun) {
  RunConfig c = small(GetParam().first, GetParam().second);
  SerialEvaluator ev(c.sim);
  EvolutionState a, b, d;
  auto ga = run(c, 5, ev, a);
  auto gb = run(c, 5, ev, b);
  auto gd = run(c, 6, ev, d);
  ASSERT_EQ(ga.size(), gb.size());
  for (std::size_t i = 0; i < ga.size(); ++i) {
    EXPECT_EQ(ga[i].stats.best, gb[i].stats.best);
    EXPECT_EQ(ga[i].stats.mean, gb[i].stats.mean);
    ASSERT_EQ(ga[i].born.size(), gb[i].born.size());
    for (std::size_t k = 0; k < ga[i].born.size(); ++k)
      EXPECT_TRUE(ga[i].born[k].genome == gb[i].born[k].genome);
  }
  EXPECT_FALSE(a.population[0].genome == d.population[0].genome);
}

// Each algorithm breeds in the shares p_asexual, p_crossover and p_graft
// (the steady state used to draw a third each whatever they said).
TEST_P(Loops, BreedInTheConfiguredShares) {
  for (auto [pa, pc, pg] : {std::tuple{1.0, 0.0, 0.0}, std::tuple{0.0, 1.0, 0.0}, std::tuple{0.0, 0.0, 1.0},
                            std::tuple{0.5, 0.5, 0.0}}) {
    RunConfig c = small(GetParam().first, GetParam().second);
    c.evolution.p_asexual = pa;
    c.evolution.p_crossover = pc;
    c.evolution.p_graft = pg;
    SerialEvaluator ev(c.sim);
    EvolutionState s;
    std::map<std::string, int> ops;
    for (const auto& g : run(c, 7, ev, s))
      for (const auto& ind : g.born)
        if (ind.op != "random") ++ops[ind.op];
    int bred = 0;
    for (auto& [op, n] : ops) bred += n;
    ASSERT_GT(bred, 0);
    const std::string shares = std::to_string(pa) + "/" + std::to_string(pc) + "/" + std::to_string(pg);
    EXPECT_EQ(ops["mutation"] > 0, pa > 0) << shares;
    EXPECT_EQ(ops["crossover"] > 0, pc > 0) << shares;
    EXPECT_EQ(ops["graft"] > 0, pg > 0) << shares;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Paper, Loops,
    ::testing::Values(std::pair{Dialect::Chaumont2007, Algorithm::Generational},
                      std::pair{Dialect::Miconi2006, Algorithm::SteadyState},
                      std::pair{Dialect::Sims1994, Algorithm::Generational}),
    [](const auto& info) { return std::string(to_string(info.param.first)); });

}  // namespace
}  // namespace bx
