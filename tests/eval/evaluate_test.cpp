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
    EXPECT_NEAR(r.fitness, r.distance / 10.0, 1e-9);  // sims1994: speed
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

TEST(Evaluate, AReplayKeepsALargeSeedExactForJavaScript) {
  // seeds of evolved individuals are 64-bit; above 2^53 a JSON number loses
  // digits in the viewer, so the replay writes them as strings
  SimConfig cfg;
  CreatureModel m = grow("walker.json", &cfg);
  cfg.task.seconds = 0.1;
  Replay r;
  EvalResult res = evaluate(m, cfg, 1, &r);
  auto seed_of = [&](std::uint64_t seed) {
    std::string text = replay_to_string(m, r, res, {"walker.json", seed, cfg.physics.dt, 1.0});
    auto at = text.find("\"seed\":");
    return text.substr(at, text.find(',', at) - at);
  };
  EXPECT_EQ(seed_of(7), "\"seed\":7");
  EXPECT_EQ(seed_of(16362424434296498360ULL), "\"seed\":\"16362424434296498360\"");
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

TEST(Evaluate, ChaumontSequenceSettlesBurstsSettlesThenMeasures) {
  SimConfig cfg = default_sim_config(Dialect::Chaumont2007);
  CreatureModel m = grow("box.json");
  m.dialect = Dialect::Chaumont2007;
  cfg.task.seconds = 2;
  EvalResult r = evaluate(m, cfg, 1);
  // a box dropped 0.1 m settles, sits through the burst, settles, then 2 s measured
  EXPECT_FALSE(r.failed) << r.failure;
  EXPECT_EQ(r.note, "");
  EXPECT_GT(r.seconds, 2 + 1.0 + 2 * 30 / 60.0 - 1e-9);
  EXPECT_LT(r.distance, 1e-3);
  // a creature that never stops moving is never measured and scores 0
  cfg.task.settle_speed = 0;
  r = evaluate(m, cfg, 1);
  EXPECT_EQ(r.fitness, 0);
  EXPECT_EQ(r.note, "never settled within settle_timeout");
  EXPECT_NEAR(r.seconds, cfg.task.settle_timeout, 2 * cfg.physics.dt);
}

}  // namespace
}  // namespace bx
