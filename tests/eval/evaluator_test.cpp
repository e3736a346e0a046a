// Evaluators: the process pool gives exactly the serial results, and survives
// a worker that aborts or hangs.
#include "eval/evaluator.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>

#include "genome/float_vector.h"
#include "genome/genome_json.h"
#include "genome/graph_genotype.h"

namespace bx {
namespace {

std::vector<GraphGenotype> creatures() {
  std::vector<GraphGenotype> out;
  for (const char* name : {"walker.json", "snake.json", "hinged_pair.json", "sims_both.json"}) {
    auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name);
    EXPECT_TRUE(g.ok()) << g.error();
    out.emplace_back(*g);
  }
  return out;
}

SimConfig short_config() {
  SimConfig cfg = default_sim_config(Dialect::Sims1994);
  cfg.task.seconds = 2;
  return cfg;
}

std::vector<EvalJob> jobs_for(const std::vector<GraphGenotype>& gs) {
  std::vector<EvalJob> jobs;
  for (std::size_t i = 0; i < gs.size(); ++i) jobs.push_back({&gs[i], 100 + i});
  return jobs;
}

TEST(Evaluator, PoolGivesBitIdenticalResultsToSerialForAnyWorkerCount) {
  auto gs = creatures();
  auto jobs = jobs_for(gs);
  auto serial = SerialEvaluator(short_config()).evaluate(jobs);
  for (int k : {1, 2, 3}) {
    ProcessPoolEvaluator pool(short_config(), k, 60);
    auto got = pool.evaluate(jobs);
    ASSERT_EQ(got.size(), serial.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].result.fitness, serial[i].result.fitness) << "k=" << k << " job " << i;
      EXPECT_EQ(got[i].result.distance, serial[i].result.distance);
      EXPECT_EQ(got[i].result.steps, serial[i].result.steps);
      EXPECT_FALSE(got[i].result.failed);
    }
    // and again with the same pool: workers carry nothing over
    auto again = pool.evaluate(jobs);
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(again[i].result.fitness, got[i].result.fitness);
  }
}

// A job with a step_divisor is evaluated at physics.dt / step_divisor, in
// this process or in a worker (an elite evaluated again so,
// evolution.elite_half_step and elite_quarter_step).
class FinerStep : public ::testing::TestWithParam<int> {};

TEST_P(FinerStep, AJobStepsAtItsDivisorOfTheStepInAnyEvaluator) {
  const int divisor = GetParam();
  auto gs = creatures();
  std::vector<EvalJob> jobs = jobs_for(gs);
  for (auto& j : jobs) j.step_divisor = divisor;
  SimConfig finer = short_config();
  finer.physics.dt /= divisor;
  auto want = SerialEvaluator(finer).evaluate(jobs_for(gs));
  auto at_dt = SerialEvaluator(short_config()).evaluate(jobs_for(gs));
  auto serial = SerialEvaluator(short_config()).evaluate(jobs);
  auto pooled = ProcessPoolEvaluator(short_config(), 2, 60).evaluate(jobs);
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    EXPECT_EQ(serial[i].result.steps, divisor * at_dt[i].result.steps) << i;
    EXPECT_EQ(serial[i].result.fitness, want[i].result.fitness) << i;
    EXPECT_EQ(pooled[i].result.fitness, want[i].result.fitness) << i;
    EXPECT_EQ(pooled[i].result.steps, want[i].result.steps) << i;
  }
}

INSTANTIATE_TEST_SUITE_P(HalfAndQuarter, FinerStep, ::testing::Values(2, 4));

TEST(Evaluator, AWorkerThatAbortsCostsOnlyItsJob) {
  auto gs = creatures();
  auto jobs = jobs_for(gs);
  // the worker aborts on the job with seed 101
  ProcessPoolEvaluator pool(short_config(), 2, 60, [](const Genotype& g, const SimConfig& c, std::uint64_t seed) {
    if (seed == 101) std::abort();
    return evaluate_genotype(g, c, seed);
  });
  auto got = pool.evaluate(jobs);
  auto serial = SerialEvaluator(short_config()).evaluate(jobs);
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (i == 1) {
      EXPECT_TRUE(got[i].result.failed);
      EXPECT_EQ(got[i].result.failure, "worker crashed: signal 6 (Aborted) (twice)");
      EXPECT_EQ(got[i].result.fitness, 0);
    } else {
      EXPECT_FALSE(got[i].result.failed) << got[i].result.failure;
      EXPECT_EQ(got[i].result.fitness, serial[i].result.fitness);
    }
  }
  // the crashed worker was replaced: a second batch runs in full
  EXPECT_EQ(pool.workers(), 2);
  jobs.erase(jobs.begin() + 1);
  for (const auto& o : pool.evaluate(jobs)) EXPECT_FALSE(o.result.failed) << o.result.failure;
}

TEST(Evaluator, AWorkerThatHangsTimesOutAndTheBatchGoesOn) {
  auto gs = creatures();
  auto jobs = jobs_for(gs);
  // the worker hangs on the job with seed 102 (and so does the one given it again)
  ProcessPoolEvaluator pool(short_config(), 2, 1.0, [](const Genotype& g, const SimConfig& c, std::uint64_t seed) {
    if (seed == 102) ::pause();
    return evaluate_genotype(g, c, seed);
  });
  auto got = pool.evaluate(jobs);
  EXPECT_TRUE(got[2].result.failed);
  EXPECT_EQ(got[2].result.failure, "timed out after 1 s (twice)");
  for (std::size_t i : {0u, 1u, 3u}) EXPECT_FALSE(got[i].result.failed) << got[i].result.failure;
}

TEST(Evaluator, NonViableGenomesComeBackAsValues) {
  auto gs = creatures();
  gs[0].genome.nodes[0].edges.push_back(gs[0].genome.nodes[0].edges[0]);  // a second pair of legs on the first
  std::vector<EvalJob> jobs = {{&gs[0], 1}};
  ProcessPoolEvaluator pool(short_config(), 1, 60);
  auto got = pool.evaluate(jobs);
  EXPECT_FALSE(got[0].viable);
  EXPECT_NE(got[0].reason.find("self-intersection"), std::string::npos) << got[0].reason;
}

TEST(Evaluator, AGenotypeTravelsWithItsKindAndOneOfAnotherKindThanTheCreaturesIsNotViable) {
  // a float vector crosses the pipe as a float vector (the worker's reading
  // of a graph genome would fail on it), and a graph creature does not
  // develop from it
  FloatVector v({0.5, -0.25});
  std::vector<EvalJob> jobs = {{&v, 1}};
  ProcessPoolEvaluator pool(short_config(), 1, 60);
  for (const auto& out : {pool.evaluate(jobs), SerialEvaluator(short_config()).evaluate(jobs)}) {
    ASSERT_EQ(out.size(), 1u);
    EXPECT_FALSE(out[0].result.failed) << out[0].result.failure;
    EXPECT_FALSE(out[0].viable);
    EXPECT_EQ(out[0].reason,
              "a genotype of kind floats, but genotype.kind \"graph\" develops graph genotypes");
  }
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

TEST(Evaluator, PoolsCanEndInAnyOrder) {
  // workers of a later pool must not hold an earlier pool's pipes open
  auto gs = creatures();
  auto a = std::make_unique<ProcessPoolEvaluator>(short_config(), 1, 60);
  auto b = std::make_unique<ProcessPoolEvaluator>(short_config(), 1, 60);
  std::vector<EvalJob> jobs = {{&gs[2], 1}};
  EXPECT_FALSE(b->evaluate(jobs)[0].result.failed);
  a.reset();  // hung in waitpid before workers closed inherited descriptors
  EXPECT_FALSE(b->evaluate(jobs)[0].result.failed);
}

}  // namespace
}  // namespace bx
