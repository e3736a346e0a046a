// Evaluation: the hand-designed walker walks, equal inputs give bit-identical
// results, and blow-ups end an evaluation as a scored failure.
#include "eval/evaluate.h"

#include <gtest/gtest.h>

#include "develop/develop.h"
#include "genome/genome_json.h"
#include "io/replay_file.h"

namespace bx {
namespace {

CreatureModel grow(const std::string& name, SimConfig* cfg = nullptr) {
  auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/tests/creatures/" + name);
  EXPECT_TRUE(g.ok()) << g.error();
  if (cfg) *cfg = default_sim_config(g->dialect);
  Development d = develop(*g);
  EXPECT_TRUE(d.viable()) << d.reason;
  return *d.model;
}

TEST(Evaluate, WalkerMovesAtLeastOneBodyLengthInTenSeconds) {
  SimConfig cfg;
  CreatureModel m = grow("walker.json", &cfg);
  cfg.task.seconds = 10;
  for (std::uint64_t seed : {1, 2, 3}) {
    EvalResult r = evaluate(m, cfg, seed);
    EXPECT_FALSE(r.failed) << r.failure;
    EXPECT_GE(r.distance, m.body_length()) << "seed " << seed;
    EXPECT_EQ(r.fitness, r.distance);
    EXPECT_EQ(r.steps, 1000);
  }
}

TEST(Evaluate, MotionlessBoxScoresNothing) {
  SimConfig cfg;
  CreatureModel m = grow("box.json", &cfg);
  EvalResult r = evaluate(m, cfg, 1);
  EXPECT_FALSE(r.failed);
  EXPECT_LT(r.distance, 1e-3);
}

TEST(Evaluate, SameSeedGivesBitIdenticalResultsAndReplays) {
  SimConfig cfg;
  CreatureModel m = grow("walker.json", &cfg);
  cfg.task.seconds = 5;
  Replay ra, rb;
  EvalResult a = evaluate(m, cfg, 7, &ra);
  // another evaluation in between must not leak state into the next
  evaluate(grow("snake.json"), default_sim_config(Dialect::Sims1994), 3);
  EvalResult b = evaluate(m, cfg, 7, &rb);
  EXPECT_EQ(a.distance, b.distance);  // bit-identical, not merely close
  ReplayInfo info{"walker.json", 7, cfg.physics.dt, cfg.physics.friction};
  EXPECT_EQ(replay_to_string(m, ra, a, info), replay_to_string(m, rb, b, info));
  EXPECT_EQ(ra.frames.size(), 1u + 150u);  // t = 0 and 30 frames per second
}

TEST(Evaluate, ExplosionEndsTheEvaluationWithAFailingScore) {
  SimConfig cfg;
  CreatureModel m = grow("walker.json", &cfg);
  cfg.physics.max_speed = 0.05;  // any brisk motion counts as a blow-up
  EvalResult r = evaluate(m, cfg, 1);
  EXPECT_TRUE(r.failed);
  EXPECT_EQ(r.fitness, 0);
  EXPECT_LT(r.steps, 1000);
  EXPECT_NE(r.failure.find("numerical explosion at t="), std::string::npos) << r.failure;
  EXPECT_NE(r.failure.find("above max_speed 0.05"), std::string::npos) << r.failure;
}

TEST(Evaluate, MiconiTaskCountsDistanceAlongXAfterTheFirstEighth) {
  LocomotionDef def;
  def.seconds = 8;
  def.metric = DistanceMetric::AlongX;
  def.skip_fraction = 1.0 / 8;
  LocomotionScore s(def);
  s.observe(0, {0, 0, 0});
  s.observe(0.5, {5, 0, 0});  // falling over in the first second does not count
  s.observe(1.0, {6, 3, 0});
  s.observe(8.0, {4, 9, 0});
  EXPECT_DOUBLE_EQ(s.distance(), -2.0);
  def.metric = DistanceMetric::Planar;
  LocomotionScore p(def);
  p.observe(1.0, {6, 3, 0});
  p.observe(8.0, {9, 7, 0});
  EXPECT_DOUBLE_EQ(p.distance(), 5.0);
}

}  // namespace
}  // namespace bx
