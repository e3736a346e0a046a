// Creature kinds: a genotype develops into its kind's body and controller
// together, and evaluation takes the pair, whatever the kind.
#include "eval/creature.h"

#include <gtest/gtest.h>

#include "develop/develop.h"
#include "eval/evaluate.h"
#include "genome/float_vector.h"
#include "genome/genome_json.h"
#include "genome/graph_genotype.h"

namespace bx {
namespace {

GraphGenotype load(const std::string& name) {
  auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name);
  EXPECT_TRUE(g.ok()) << g.error();
  return GraphGenotype(*g);
}

TEST(Creature, AGraphGenotypeGrowsItsBodyAndItsOwnBrainDrivesIt) {
  GraphGenotype g = load("walker.json");
  SimConfig cfg = default_sim_config(g.genome);
  cfg.task.seconds = 2;
  auto c = develop_creature(g, cfg);
  ASSERT_TRUE(c.ok()) << c.error();
  const CreatureModel grown = *develop(g.genome, cfg.develop).model;
  EXPECT_EQ(c->body->n_parts(), grown.n_parts());
  EXPECT_EQ(c->controller->n_effectors(), static_cast<int>(c->body->effectors.size()));
  EXPECT_EQ(c->controller->n_sensors(), static_cast<int>(c->body->sensors.size()));
  EXPECT_EQ(c->controller->n_task_outputs(), 0);  // no catapult, no release
  // the pair scores what the body with its own brain scores, to the bit
  const EvalResult a = evaluate(*c, cfg, 7), b = evaluate(grown, cfg, 7);
  EXPECT_EQ(a.fitness, b.fitness);
  EXPECT_GT(a.distance, 0.1);
}

TEST(Creature, ACatapultsReleaseIsItsControllersOneTaskOutput) {
  GraphGenotype g = load("catapult.json");
  SimConfig cfg = default_sim_config(g.genome);
  auto c = develop_creature(g, cfg);
  ASSERT_TRUE(c.ok()) << c.error();
  EXPECT_EQ(c->controller->n_task_outputs(), 1);
}

TEST(Creature, AGenotypeThatGrowsNoBodyIsNotViableAndSaysWhy) {
  GraphGenotype g = load("walker.json");
  g.genome.nodes[0].edges.push_back(g.genome.nodes[0].edges[0]);  // a second pair of legs on the first
  auto c = develop_creature(g, default_sim_config(g.genome));
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().find("self-intersection"), std::string::npos) << c.error();
}

TEST(Creature, AGenotypeOfAnotherKindThanTheCreaturesIsNotViable) {
  auto c = develop_creature(FloatVector({0.5}), SimConfig{});
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.error(), "a genotype of kind floats, but genotype.kind \"graph\" develops graph genotypes");
}

}  // namespace
}  // namespace bx
