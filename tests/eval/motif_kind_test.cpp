// The motif kind (genotype.kind = "motif"): a creature kind without a body.
// Its float vector of 15 genes is scored by the motif's fitness through the
// same evaluate_genotype every evaluator calls, dispatched by its row of the
// creature table, with no physics world.
#include "eval/motif_kind.h"

#include <gtest/gtest.h>

#include "brain/river/found_motif.h"
#include "brain/river/motif_fitness.h"
#include "core/rng.h"
#include "eval/creature.h"
#include "eval/evaluate.h"
#include "eval/evaluator.h"
#include "eval/motif_file.h"
#include "genome/float_vector.h"
#include "io/config.h"
#include "physics/world.h"

namespace bx {
namespace {

RunConfig motif_config(const std::vector<std::string>& sets = {}) {
  auto cfg = read_run_config("[genotype]\nkind = \"motif\"\n", "motif.toml", sets);
  EXPECT_TRUE(cfg.ok()) << cfg.error();
  return cfg.ok() ? *cfg : RunConfig{};
}

FloatVector random_genes(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> g(static_cast<std::size_t>(motif_gene_count()));
  for (double& x : g) x = rng.uniform(-1, 1);
  return FloatVector(g);
}

TEST(MotifKind, ItsGenesAreFifteenInTheUnitBoxMutatedAsTheSearchDid) {
  const SimConfig cfg = motif_config().sim;
  EXPECT_EQ(cfg.creature, CreatureKind::Motif);
  const CreatureKindRow& row = creature_kind_row(CreatureKind::Motif);
  EXPECT_EQ(row.name, "motif");
  EXPECT_EQ(row.genotype_kind, "floats");
  ASSERT_NE(row.float_genes, nullptr);
  const FloatVectorDef d = row.float_genes(cfg);
  EXPECT_EQ(d.length, 15);
  EXPECT_EQ(d.lo, -1);
  EXPECT_EQ(d.hi, 1);
  EXPECT_EQ(d.sigma, 0.1);  // MotifSearch.DISABLED_EvolveAMotif's
  // the only kind without a body, and it says so
  EXPECT_FALSE(has_body(CreatureKind::Motif));
  EXPECT_TRUE(has_body(CreatureKind::Graph));
  EXPECT_TRUE(has_body(CreatureKind::River));
  EXPECT_EQ(row.develop, nullptr);
  auto dev = develop_creature(random_genes(1), cfg);
  ASSERT_FALSE(dev.ok());
  EXPECT_EQ(dev.error(), "genotype.kind \"motif\" has no body: nothing to develop");
}

TEST(MotifKind, ItsFitnessThroughEvaluateGenotypeIsMotifFitnessOfTheDecodedGenes) {
  const SimConfig cfg = motif_config().sim;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const FloatVector g = random_genes(seed);
    const Motif m = *motif_from_genes(g.genes, MotifGeneDef{});
    const EvalOutcome o = evaluate_genotype(g, cfg, seed);
    ASSERT_TRUE(o.viable) << o.reason;
    EXPECT_FALSE(o.result.failed);
    EXPECT_EQ(o.result.fitness, motif_fitness(m, MotifFitnessDef{})) << seed;  // bit for bit
    // its parts as named metrics, from score_motif
    const MotifScore s = score_motif(m, MotifFitnessDef{});
    ASSERT_EQ(o.result.metrics.size(), 4u);
    EXPECT_EQ(o.result.metrics[0], (Metric{"oscillation", s.oscillation}));
    EXPECT_EQ(o.result.metrics[1], (Metric{"quiescence", s.quiescence}));
    EXPECT_EQ(o.result.metrics[2], (Metric{"dominant hz", s.dominant_hz}));
    EXPECT_EQ(o.result.metrics[3], (Metric{"quiet power", s.quiet_power}));
    // two runs of 10 s of 0.01 s Euler steps, and no physics step
    EXPECT_EQ(o.result.seconds, 20);
    EXPECT_EQ(o.result.brain_steps, 2000);
    EXPECT_EQ(o.result.steps, 0);
    // a pure function of the genes: another seed, the same
    EXPECT_EQ(evaluate_genotype(g, cfg, seed + 1000).result.fitness, o.result.fitness);
  }
  // the found motif's genes score as docs/rivercrossing.md says
  auto found = read_motif_file("stanton2015-found", MotifGeneDef{});
  ASSERT_TRUE(found.ok()) << found.error();
  const EvalOutcome o = evaluate_genotype(FloatVector(found->genes), cfg, 1);
  EXPECT_EQ(o.result.fitness, motif_fitness(found_motif(), MotifFitnessDef{}));
  EXPECT_NEAR(o.result.fitness, 0.899, 0.0005);
  EXPECT_NEAR(o.result.metrics[2].value, 1.0, 1e-12);  // dominant at 1 Hz under input
}

TEST(MotifKind, ItsEvaluationBuildsNoWorld) {
  // physics keys that no world could step (a part faster than 1 mm/s or
  // moving 1 um in a step explodes) change nothing: there is no world
  const SimConfig cfg =
      motif_config({"physics.max_speed=0.001", "physics.max_step_jump=0.000001", "task.seconds=0"}).sim;
  const FloatVector g = random_genes(3);
  const long worlds = World::made();
  const EvalOutcome o = evaluate_genotype(g, cfg, 3);
  EXPECT_EQ(World::made(), worlds);
  ASSERT_TRUE(o.viable) << o.reason;
  EXPECT_FALSE(o.result.failed) << o.result.failure;
  EXPECT_EQ(o.result.fitness, evaluate_genotype(g, motif_config().sim, 3).result.fitness);
  // the serial evaluator too (the pool's workers run the same function)
  SerialEvaluator serial(cfg);
  const auto out = serial.evaluate({{&g, 3}});
  EXPECT_EQ(World::made(), worlds);
  EXPECT_EQ(out[0].result.fitness, o.result.fitness);
  // while a bodied kind's evaluation does make one (the count works)
  SimConfig river = motif_config({"genotype.kind=river", "river.seconds=0.02"}).sim;
  Rng rng(1);
  std::vector<double> w(static_cast<std::size_t>(creature_kind_row(CreatureKind::River).float_genes(river).length));
  for (double& x : w) x = rng.uniform(-1, 1);
  ASSERT_TRUE(evaluate_genotype(FloatVector(w), river, 1).viable);
  EXPECT_EQ(World::made(), worlds + 1);
}

TEST(MotifKind, GenesItCannotDecodeAreNotViableWithTheReason) {
  const SimConfig cfg = motif_config().sim;
  std::vector<double> g = random_genes(5).genes;
  g.pop_back();
  EvalOutcome o = evaluate_genotype(FloatVector(g), cfg, 1);
  EXPECT_FALSE(o.viable);
  EXPECT_EQ(o.reason, "motif genes: 14 given, 15 expected");
  g.push_back(1.5);
  o = evaluate_genotype(FloatVector(g), cfg, 1);
  EXPECT_FALSE(o.viable);
  EXPECT_EQ(o.reason, "motif genes: gene 14 is 1.5, not a finite number in [-1, 1]");
  EXPECT_EQ(o.result.fitness, 0);
}

TEST(MotifKind, ItsFitnessConstantsAreConfigKeysWithTheDocumentedDefaults) {
  const RunConfig d = motif_config();
  EXPECT_EQ(d.sim.motif_kind.fitness, MotifFitnessDef{});
  EXPECT_EQ(d.sim.motif_kind.fitness.seconds, 10);
  EXPECT_EQ(d.sim.motif_kind.fitness.dt, 0.01);
  EXPECT_EQ(d.sim.motif_kind.fitness.high_input, 1);
  EXPECT_EQ(d.sim.motif_kind.fitness.target_hz, 1);
  EXPECT_EQ(d.sim.motif_kind.fitness.amplitude, 0.5);
  const std::string text = config_to_toml(d);
  EXPECT_NE(text.find("[motif_fitness]\nseconds = 10\ndt = 0.01\nhigh_input = 1\ntarget_hz = 1\namplitude = 0.5\n"),
            std::string::npos)
      << text;
  // each one scores
  const RunConfig two = motif_config({"motif_fitness.target_hz=2", "motif_fitness.seconds=5",
                                      "motif_fitness.high_input=0.5", "motif_fitness.amplitude=0.25"});
  const MotifFitnessDef want{5, 0.01, 0.5, 2, 0.25};
  EXPECT_EQ(two.sim.motif_kind.fitness, want);
  const FloatVector g = random_genes(7);
  EXPECT_EQ(evaluate_genotype(g, two.sim, 1).result.fitness,
            motif_fitness(*motif_from_genes(g.genes, MotifGeneDef{}), want));
  // keys that cannot score together are refused once the config is read, naming them
  auto bad = read_run_config("[genotype]\nkind = \"motif\"\n[motif_fitness]\ntarget_hz = 1.05\n", "motif.toml");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error(),
            "motif.toml: motif fitness: target_hz is 1.05, not a whole number of cycles in 10 s (a bin of the "
            "transform)");
  // ... but a --set may pass through a state that cannot: the rule holds for the result
  EXPECT_TRUE(read_run_config("", "x.toml", {"motif_fitness.dt=0.03", "motif_fitness.seconds=9"}).ok());
}

}  // namespace
}  // namespace bx
