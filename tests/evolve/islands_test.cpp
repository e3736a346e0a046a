// evolution.islands: the steady state's population split into islands that
// hold their own tournaments, batched together so workers get islands x batch
// evaluations at once, with ring migration at fixed counts of births. Run on
// a float vector bred towards a target point, so every check is exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "evolve/evolution.h"
#include "genome/float_vector.h"
#include "io/config.h"

namespace bx {
namespace {

// fitness 1 / (1 + |genes - target|^2); records each call's job count
class Target : public Evaluator {
 public:
  std::vector<EvalOutcome> evaluate(const std::vector<EvalJob>& jobs) override {
    calls.push_back(jobs.size());
    std::vector<EvalOutcome> out(jobs.size());
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      double d2 = 0;
      for (double x : static_cast<const FloatVector&>(*jobs[i].genotype).genes) d2 += (x - 0.3) * (x - 0.3);
      out[i].result.fitness = 1 / (1 + d2);
    }
    return out;
  }
  int workers() const override { return 1; }
  std::vector<std::size_t> calls;
};

EvolutionDef islands_def(int islands) {
  EvolutionDef e;
  e.algorithm = Algorithm::SteadyState;
  e.population = 30;
  e.evaluations = 1200;
  e.batch = 2;
  e.islands = islands;
  e.migration_every = 20;
  e.report_every = 2 * islands;  // one batch a step, so each step can be checked
  e.p_asexual = 0.5;
  e.p_crossover = 0.5;
  e.p_graft = 0;
  e.mutation_rate = 0.2;
  e.asexual_mutations = 1;
  return e;
}

std::shared_ptr<FloatVectorOps> ops() { return std::make_shared<FloatVectorOps>(FloatVectorDef{10, -1, 1, 0.1}); }

TEST(Islands, EachBatchHoldsBatchTournamentsOnEveryIslandAndBreedsWithinIt) {
  const EvolutionDef e = islands_def(3);
  const int isle = e.population / e.islands;
  Evolution evo(ops(), e, 5);
  Target problem;
  EvolutionState s;
  std::map<std::int64_t, int> island;  // where each member stood after the last step
  long children = 0;
  while (!evo.finished(s)) {
    problem.calls.clear();
    GenerationResult r = *evo.step(s, problem);
    if (s.generation > 0) {
      // one call of islands x batch children (fewer at the budget's end)
      ASSERT_EQ(problem.calls.size(), 1u);
      if (!evo.finished(s)) {
        EXPECT_EQ(problem.calls[0], static_cast<std::size_t>(e.islands * e.batch));
      }
      for (const Individual& c : r.born) {
        if (c.op == "migrant") continue;
        auto at = std::find_if(s.population.begin(), s.population.end(),
                               [&](const Individual& m) { return m.id == c.id; });
        if (at == s.population.end()) continue;  // replaced by a migrant
        const int home = static_cast<int>(at - s.population.begin()) / isle;
        // its parents stood on its island
        EXPECT_EQ(island.at(c.parent1), home) << c.id;
        if (c.parent2 >= 0) {
          EXPECT_EQ(island.at(c.parent2), home) << c.id;
        }
        ++children;
      }
    }
    island.clear();
    for (std::size_t i = 0; i < s.population.size(); ++i)
      island[s.population[i].id] = static_cast<int>(i) / isle;
  }
  EXPECT_GT(children, 1000);
}

Individual member(std::int64_t id, double fitness, int evaluations = 1) {
  Individual m;
  m.id = id;
  m.fitness = fitness;
  m.evaluations = evaluations;
  m.seed = 1000 + id;
  m.genotype = std::make_shared<FloatVector>(FloatVector{{static_cast<double>(id)}});
  m.op = "mutation";
  return m;
}

TEST(Islands, MigrationCopiesEachIslandsBestOverTheNextIslandsWorstEvaluatedMember) {
  // three islands of three; island 1's worst by fitness (id 5) was never
  // evaluated, so its worst evaluated member (id 3) gives way
  std::vector<Individual> pop = {member(0, 0.2), member(1, 0.9), member(2, 0.5),
                                 member(3, 0.1), member(4, 0.3), member(5, 0, 0),
                                 member(6, 0.7), member(7, 0.7), member(8, 0.05)};
  std::int64_t next = 9;
  const std::vector<Individual> m = migrate(pop, 3, next, 4);
  EXPECT_EQ(next, 12);
  ASSERT_EQ(m.size(), 3u);
  // island 0's best is 1, island 1's 4, island 2's 6 (the older of two at 0.7)
  const std::int64_t from[] = {1, 4, 6};
  for (int k = 0; k < 3; ++k) {
    const Individual src = member(from[k], k == 0 ? 0.9 : k == 1 ? 0.3 : 0.7);
    EXPECT_EQ(m[k].id, 9 + k);
    EXPECT_EQ(m[k].parent1, from[k]);
    EXPECT_EQ(m[k].parent2, -1);
    EXPECT_EQ(m[k].op, "migrant");
    EXPECT_EQ(m[k].generation, 4);
    EXPECT_EQ(m[k].fitness, src.fitness);
    EXPECT_EQ(m[k].seed, src.seed);  // so its replay is the evaluation it was scored on
    EXPECT_EQ(m[k].evaluations, 1);
  }
  // 1 over island 1's 3, 4 over island 2's 8, 6 over island 0's 0; the best stay home
  std::vector<std::int64_t> ids;
  for (const Individual& x : pop) ids.push_back(x.id);
  EXPECT_EQ(ids, (std::vector<std::int64_t>{11, 1, 2, 9, 4, 5, 6, 7, 10}));
  EXPECT_EQ(pop[3].genotype, pop[1].genotype);  // a copy shares the immutable genotype
}

TEST(Islands, MigrateEveryMigrationEveryBirthsAnIslandWhileTheBudgetLasts) {
  const EvolutionDef e = islands_def(3);
  Evolution evo(ops(), e, 7);
  Target problem;
  EvolutionState s;
  std::map<std::int64_t, Individual> seen;
  long migrations = 0;
  std::int64_t last = e.population;  // the first birth after the initial population
  while (!evo.finished(s)) {
    GenerationResult r = *evo.step(s, problem);
    std::vector<Individual> migrants;
    for (const Individual& m : r.born) {
      if (m.op == "migrant") migrants.push_back(m);
      else seen[m.id] = m;
    }
    if (migrants.empty()) continue;
    ++migrations;
    ASSERT_EQ(migrants.size(), 3u);
    // after a batch of 6 that passed the next multiple of 60 births (20 an island)
    const std::int64_t births = migrants[0].id - last;
    EXPECT_GE(births, 3 * e.migration_every - 3) << migrants[0].id;
    EXPECT_LE(births, 3 * e.migration_every + 6) << migrants[0].id;
    last = migrants[0].id;
    for (const Individual& m : migrants) {
      const Individual& src = seen.at(m.parent1);
      EXPECT_EQ(m.genotype, src.genotype);
      EXPECT_EQ(m.fitness, src.fitness);
      EXPECT_EQ(m.seed, src.seed);
      seen[m.id] = m;
    }
  }
  // 1,200 births after the initial 30: a migration at each of 60, 120, ..., 1,140
  EXPECT_EQ(migrations, 19);
  EXPECT_EQ(s.next_id, e.population + e.evaluations);
}

TEST(Islands, BreedTowardsTheTargetAndTheSameSeedGivesTheSameRun) {
  auto once = [](std::uint64_t seed) {
    EvolutionDef e = islands_def(3);
    e.report_every = 120;
    Evolution evo(ops(), e, seed);
    Target problem;
    EvolutionState s;
    std::vector<GenerationStats> st;
    while (!evo.finished(s)) st.push_back(evo.step(s, problem)->stats);
    return st;
  };
  const auto a = once(3), b = once(3), c = once(4);
  EXPECT_LT(a.front().best, 0.6);
  EXPECT_GT(a.back().best, 0.9) << "from " << a.front().best;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t g = 0; g < a.size(); ++g) {
    EXPECT_EQ(a[g].best, b[g].best);
    EXPECT_EQ(a[g].mean, b[g].mean);
  }
  EXPECT_NE(a.back().mean, c.back().mean);
}

TEST(Islands, AreRefusedWhereTheyCannotHoldTournaments) {
  const auto refused = [](const std::string& more) {
    auto r = read_run_config("[genome]\ndialect = \"miconi2006\"\n[evolution]\npopulation = 30\n" + more, "t.toml", {});
    return r ? std::string() : r.error();
  };
  EXPECT_EQ(refused("islands = 3\n"), "");
  EXPECT_EQ(refused("islands = 4\n"),
            "t.toml: evolution.islands: 4 must divide evolution.population (30) into islands of at least 3 members");
  EXPECT_EQ(refused("islands = 15\n"),
            "t.toml: evolution.islands: 15 must divide evolution.population (30) into islands of at least 3 members");
  EXPECT_EQ(refused("islands = 3\nalgorithm = \"generational\"\n"),
            "t.toml: evolution.islands: 3 needs evolution.algorithm = \"steady_state\" (a generational run evaluates "
            "its whole population at once)");
  EXPECT_NE(refused("islands = 0\n"), "");
  EXPECT_NE(refused("migration_every = 0\n"), "");
}

}  // namespace
}  // namespace bx
