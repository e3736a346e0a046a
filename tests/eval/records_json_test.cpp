// The evaluation outcome's one serialiser (eval/records_json.h): every field
// round-trips, bit for bit, and the process pool returns what the serial
// evaluator computes, field for field (it used to drop trial_fitness,
// brain_steps and the diagnostics).
#include "eval/records_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "eval/evaluator.h"
#include "genome/float_vector.h"
#include "genome/genome_json.h"
#include "genome/graph_genotype.h"

namespace bx {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same_nums(const std::vector<double>& a, const std::vector<double>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(same_bits(a[i], b[i])) << what << "[" << i << "]";
}

// every field of two outcomes, doubles by their bits
void expect_same(const EvalOutcome& a, const EvalOutcome& b) {
  EXPECT_EQ(a.viable, b.viable);
  EXPECT_EQ(a.reason, b.reason);
  const EvalResult &x = a.result, &y = b.result;
  EXPECT_EQ(x.failed, y.failed);
  EXPECT_EQ(x.failure, y.failure);
  EXPECT_EQ(x.note, y.note);
  EXPECT_TRUE(same_bits(x.fitness, y.fitness)) << x.fitness << " " << y.fitness;
  EXPECT_TRUE(same_bits(x.distance, y.distance));
  ASSERT_EQ(x.metrics.size(), y.metrics.size());
  for (std::size_t i = 0; i < x.metrics.size(); ++i) {
    EXPECT_EQ(x.metrics[i].name, y.metrics[i].name);
    EXPECT_TRUE(same_bits(x.metrics[i].value, y.metrics[i].value)) << x.metrics[i].name;
  }
  ASSERT_EQ(x.markers.size(), y.markers.size());
  for (std::size_t i = 0; i < x.markers.size(); ++i) {
    EXPECT_EQ(x.markers[i].name, y.markers[i].name);
    EXPECT_TRUE(same_bits(x.markers[i].t, y.markers[i].t)) << x.markers[i].name;
  }
  EXPECT_TRUE(same_bits(x.seconds, y.seconds));
  EXPECT_EQ(x.steps, y.steps);
  EXPECT_EQ(x.brain_steps, y.brain_steps);
  EXPECT_EQ(x.warnings, y.warnings);
  expect_same_nums(x.trial_fitness, y.trial_fitness, "trial_fitness");
  EXPECT_EQ(x.trial, y.trial);
  EXPECT_EQ(x.setup, y.setup);
  const EvalDiagnostics &d = x.diagnostics, &e = y.diagnostics;
  EXPECT_TRUE(same_bits(d.max_joint_gap, e.max_joint_gap));
  EXPECT_EQ(d.worst_joint, e.worst_joint);
  EXPECT_TRUE(same_bits(d.max_stop_overshoot, e.max_stop_overshoot));
  EXPECT_TRUE(same_bits(d.max_penetration, e.max_penetration));
  expect_same_nums(d.effector_mean, e.effector_mean, "effector_mean");
  expect_same_nums(d.effector_sd, e.effector_sd, "effector_sd");
  expect_same_nums(d.effector_hz, e.effector_hz, "effector_hz");
}

TEST(OutcomeJson, EveryFieldRoundTripsBitForBit) {
  EvalOutcome o;
  o.viable = false;
  o.reason = "self-intersection: parts 1 and 2 \"overlap\"\n";
  EvalResult& r = o.result;
  r.failed = true;
  r.failure = "numerical explosion at t=0.1 s";
  r.note = "never settled";
  r.fitness = 0.1 + 0.2;  // not the double nearest 0.3
  r.distance = -1e-300;
  r.metrics = {{"levels completed", 3}, {"food eaten", 1.0 / 7.0}, {"a \"quoted\" name", -0.0},
               {"target miss", 12345.678901234567}};
  r.markers = {{"begin", 0}, {"release", 0.4999999999999999}, {"touch end", 5e-324}};
  r.seconds = 1.0 / 3.0;
  r.steps = 1L << 40;
  r.brain_steps = 7;
  r.warnings = {"a", "b\tc"};
  r.trial_fitness = {0.3, 2.0 / 3.0, 5e-324};
  r.trial = 2;
  r.setup = "light at -135 degrees";
  r.diagnostics = {0.038123, 21, 0.138, 0.0335, {-1, 0.25, 1.0 / 7.0}, {0, 0.899, 0.57}, {0, 29.97, 1.0 / 3.0}};
  auto back = outcome_from_json(nlohmann::json::parse(outcome_to_json(o).dump()));
  ASSERT_TRUE(back.ok()) << back.error();
  expect_same(o, *back);
}

TEST(OutcomeJson, ANonFiniteNumberComesBackAsNaNAndAMissingFieldIsNamed) {
  EvalOutcome o;
  o.result.fitness = std::nan("");
  o.result.diagnostics.max_penetration = INFINITY;
  auto back = outcome_from_json(nlohmann::json::parse(outcome_to_json(o).dump()));
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_TRUE(std::isnan(back->result.fitness));
  EXPECT_TRUE(std::isnan(back->result.diagnostics.max_penetration));

  auto j = outcome_to_json(EvalOutcome{});
  j.erase("brain_steps");
  auto missing = outcome_from_json(j);
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error(), "evaluation outcome: no field brain_steps");
  j = outcome_to_json(EvalOutcome{});
  j["diagnostics"]["effector_sd"] = "x";
  auto typed = outcome_from_json(j);
  ASSERT_FALSE(typed.ok());
  EXPECT_EQ(typed.error(), "evaluation outcome: effector_sd is not an array");
}

TEST(OutcomeJson, ThePoolReturnsEveryFieldTheSerialEvaluatorComputesWithTwoTrials) {
  std::vector<GraphGenotype> gs;
  for (const char* name : {"walker.json", "snake.json"}) {
    auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name);
    ASSERT_TRUE(g.ok()) << g.error();
    gs.emplace_back(*g);
  }
  SimConfig cfg = default_sim_config(Dialect::Sims1994);
  cfg.task.seconds = 2;
  cfg.trials = 2;
  std::vector<EvalJob> jobs = {{&gs[0], 7}, {&gs[1], 8}};
  auto serial = SerialEvaluator(cfg).evaluate(jobs);
  auto pooled = ProcessPoolEvaluator(cfg, 2, 60).evaluate(jobs);
  ASSERT_EQ(pooled.size(), serial.size());
  for (std::size_t i = 0; i < serial.size(); ++i) {
    EXPECT_EQ(serial[i].result.trial_fitness.size(), 2u);
    EXPECT_FALSE(serial[i].result.diagnostics.effector_sd.empty());
    expect_same(serial[i], pooled[i]);
  }
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

TEST(JobJson, TheGenotypeItsKindAndEveryBitOfTheSeedRoundTrip) {
  std::vector<std::unique_ptr<Genotype>> genotypes;
  for (const char* name : {"walker.json", "catapult.json", "sims_recursive.json"}) {
    auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name);
    ASSERT_TRUE(g.ok()) << g.error();
    genotypes.push_back(std::make_unique<GraphGenotype>(*g));
  }
  // a float vector, whose genes must come back bit for bit
  genotypes.push_back(std::make_unique<FloatVector>(std::vector<double>{0.1, -1.0 / 3, 5e-310, 1e300}));
  for (const auto& g : genotypes) {
    for (std::uint64_t seed : {std::uint64_t{0}, std::uint64_t{1}, ~std::uint64_t{0}, std::uint64_t{14276982200636331862u}}) {
      // through text, as the pool's pipe carries it
      auto back = job_from_json(nlohmann::json::parse(job_to_json({g.get(), seed}).dump()));
      ASSERT_TRUE(back.ok()) << back.error();
      EXPECT_EQ(back->seed, seed);
      EXPECT_EQ(back->step_divisor, 1);
      for (int divisor : {2, 4})
        EXPECT_EQ(job_from_json(nlohmann::json::parse(job_to_json({g.get(), seed, divisor}).dump()))->step_divisor,
                  divisor);
      EXPECT_EQ(back->genotype->kind(), g->kind());
      EXPECT_TRUE(back->genotype->equals(*g)) << g->to_json().dump();
    }
  }
}

TEST(JobJson, ABadJobNamesWhatIsWrong) {
  auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/walker.json");
  ASSERT_TRUE(g.ok()) << g.error();
  GraphGenotype walker(*g);
  nlohmann::json j = job_to_json({&walker, 7});
  auto no_seed = j;
  no_seed.erase("seed");
  EXPECT_NE(job_from_json(no_seed).error().find("no field seed"), std::string::npos);
  auto negative = j;
  negative["seed"] = -1;
  EXPECT_NE(job_from_json(negative).error().find("seed is not a whole number"), std::string::npos);
  auto half = j;
  half["step_divisor"] = true;
  EXPECT_EQ(job_from_json(half).error(), "evaluation job: step_divisor has the wrong type");
  half["step_divisor"] = 3;
  EXPECT_EQ(job_from_json(half).error(), "evaluation job: step_divisor is 3, not 1, 2 or 4");
  auto bad_genome = j;
  bad_genome["genotype"]["nodes"] = 3;
  auto r = job_from_json(bad_genome);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("nodes"), std::string::npos) << r.error();
  auto unknown = j;
  unknown["kind"] = "tree";
  EXPECT_EQ(job_from_json(unknown).error(),
            "evaluation job: job: unknown genotype kind \"tree\" (expected graph or floats)");
  auto floats = j;
  floats["kind"] = "floats";  // a graph genome is no float vector
  EXPECT_EQ(job_from_json(floats).error(), "evaluation job: job: floats: no field genes");
}

}  // namespace
}  // namespace bx
