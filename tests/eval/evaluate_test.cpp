// Evaluation: the hand-designed walker walks, equal inputs give bit-identical
// results, and blow-ups end an evaluation as a scored failure.
#include "eval/evaluate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "develop/develop.h"
#include "genome/genome_json.h"
#include "io/replay_file.h"

namespace bx {
namespace {

CreatureModel grow(const std::string& name, SimConfig* cfg = nullptr) {
  auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name);
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

// A box whose brain counts its own steps: n0 is a constant 0.5 (sigmoid of
// nothing), n1 adds 2 n0 to itself each step (n1 = brain steps - 1), n2
// integrates 2 n0 over brain time, n3 oscillates at 1 Hz of brain time.
CreatureModel counting_box() {
  auto g = genome_from_string(R"({"format": "bestiary-genome", "version": 1, "dialect": "sims1994",
    "nodes": [{"size": [0.4, 0.4, 0.4], "neurons": [
      {"fn": "sigmoid"},
      {"fn": "sum", "inputs": [{"from": "self", "neuron": 1}, {"from": "self", "neuron": 0, "weight": 2}]},
      {"fn": "integrate", "inputs": [{"from": "self", "neuron": 0, "weight": 2}]},
      {"fn": "oscillate-wave", "params": {"freq": 1}}]}]})",
                              "counting_box");
  EXPECT_TRUE(g.ok()) << g.error();
  Development d = develop(*g);
  EXPECT_TRUE(d.viable()) << d.reason;
  return *d.model;
}

TEST(Evaluate, BrainStepsDueCountWholeBrainStepsWithoutRoundingSlips) {
  for (long n = 0; n <= 100000; ++n) {
    ASSERT_EQ(brain_steps_due(n, 0.01, 200), 2 * n) << n;       // sims1994: two per step
    ASSERT_EQ(brain_steps_due(n, 1.0 / 60, 60), n) << n;        // chaumont2007: one per step
    ASSERT_EQ(brain_steps_due(n, 0.01, 50), (n + 1) / 2) << n;  // one every other step
    ASSERT_EQ(brain_steps_due(n, 1.0 / 240, 60), (n + 3) / 4) << n;
  }
}

TEST(Evaluate, TheBrainRunsAtBrainHzWhateverThePhysicsStep) {
  // sims1994's 200 Hz brain under physics steps of 0.01, 0.005 and 0.0025 s:
  // the same 200 brain steps per second, and the same brain at every frame
  CreatureModel m = counting_box();
  SimConfig cfg = default_sim_config(Dialect::Sims1994);
  ASSERT_EQ(cfg.brain_hz, 200);
  cfg.task.seconds = 1;
  cfg.replay_fps = 10;  // frames at multiples of 0.1 s, a whole number of steps at each dt
  Replay first;
  for (double dt : {0.01, 0.005, 0.0025}) {
    cfg.physics.dt = dt;
    Replay r;
    EvalResult res = evaluate(m, cfg, 1, &r);
    ASSERT_FALSE(res.failed) << res.failure;
    EXPECT_EQ(res.steps, std::lround(1 / dt)) << dt;
    EXPECT_EQ(res.brain_steps, 200) << dt;
    ASSERT_EQ(r.frames.size(), 11u) << dt;
    for (std::size_t j = 1; j < r.frames.size(); ++j) {
      const std::vector<double>& n = r.frames[j].neurons;
      const double steps = 20.0 * static_cast<double>(j);  // 200 Hz for 0.1 j s
      EXPECT_EQ(n[1], steps - 1) << "dt " << dt << ", frame " << j;
      EXPECT_NEAR(n[2], (steps - 1) / 200, 1e-12) << "dt " << dt << ", frame " << j;
      if (!first.frames.empty()) {
        EXPECT_EQ(n, first.frames[j].neurons) << "dt " << dt << ", frame " << j;
      }
    }
    if (first.frames.empty()) first = r;
  }
}

TEST(Evaluate, ABrainSlowerThanThePhysicsHoldsItsOutputsBetweenItsSteps) {
  // 50 Hz under 0.01 s steps: a brain step before every other physics step
  CreatureModel m = counting_box();
  SimConfig cfg = default_sim_config(Dialect::Sims1994);
  cfg.brain_hz = 50;
  cfg.task.seconds = 1;
  cfg.replay_fps = 100;  // a frame after every physics step
  Replay r;
  EvalResult res = evaluate(m, cfg, 1, &r);
  EXPECT_EQ(res.steps, 100);
  EXPECT_EQ(res.brain_steps, 50);
  ASSERT_EQ(r.frames.size(), 101u);
  // frames 2j - 1 and 2j follow brain step j - 1: held through two steps
  for (std::size_t j = 1; j <= 50; ++j) {
    EXPECT_EQ(r.frames[2 * j - 1].neurons, r.frames[2 * j].neurons) << j;
    EXPECT_EQ(r.frames[2 * j].neurons[1], static_cast<double>(j) - 1) << j;
    EXPECT_NEAR(r.frames[2 * j].neurons[3], std::sin(2 * std::numbers::pi * (j - 1) / 50.0), 1e-9) << j;
  }
}

TEST(Evaluate, ChaumontSettlingOfARestingBoxLastsHalfASecondAtAnyStep) {
  // a box resting on the ground from the start: each settle phase ends after
  // 0.5 s of stillness (30 steps at 60 Hz, 60 at 120 Hz, 120 at 240 Hz), so
  // the sequence is settle 0.5 s, burst 1 s, settle 0.5 s, measure 1 s
  CreatureModel m = grow("box.json");
  m.dialect = Dialect::Chaumont2007;
  SimConfig cfg = default_sim_config(Dialect::Chaumont2007);
  cfg.task.seconds = 1;
  cfg.task.drop_height = 0;
  for (int hz : {60, 120, 240}) {
    cfg.physics.dt = 1.0 / hz;
    EvalResult r = evaluate(m, cfg, 1);
    ASSERT_FALSE(r.failed) << r.failure;
    EXPECT_EQ(r.note, "") << hz;
    EXPECT_NEAR(r.seconds, 0.5 + 1 + 0.5 + 1, cfg.physics.dt + 1e-9) << hz << " Hz";
  }
  // dropped 0.1 m (the default), it falls and bounces a few steps sooner or
  // later at each step length (0.04 s here), then rests 0.5 s twice; windows
  // counted in steps would end the sequence 0.5 s sooner at 120 Hz and
  // 0.75 s sooner at 240 Hz
  cfg.task.drop_height = 0.1;
  std::vector<double> ends;
  for (int hz : {60, 120, 240}) {
    cfg.physics.dt = 1.0 / hz;
    ends.push_back(evaluate(m, cfg, 1).seconds);
  }
  EXPECT_NEAR(ends[1], ends[0], 0.1);
  EXPECT_NEAR(ends[2], ends[0], 0.1);
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
  cfg.task.settle.speed = 0;
  r = evaluate(m, cfg, 1);
  EXPECT_EQ(r.fitness, 0);
  EXPECT_EQ(r.note, "never settled within settle_timeout");
  EXPECT_NEAR(r.seconds, cfg.task.settle.timeout, 2 * cfg.physics.dt);
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

TEST(Evaluate, AnOdeInternalErrorFailsTheEvaluationNotTheProcess) {
  // ode_fault.json (17 blocks, from a quick run at dt 1/120) makes the exact
  // solver's factorisation meet a zero pivot: ODE's assertion, which aborted
  // the process, now fails this one evaluation
  SimConfig snake_cfg;
  CreatureModel snake = grow("snake.json", &snake_cfg);
  EvalResult before = evaluate(snake, snake_cfg, 3);
  SimConfig cfg;
  CreatureModel m = grow("ode_fault.json", &cfg);
  ASSERT_EQ(cfg.physics.solver, Solver::Exact);
  Replay replay;
  EvalResult r = evaluate(m, cfg, 1, &replay);
  EXPECT_TRUE(r.failed);
  EXPECT_NE(r.failure.find("ODE internal error"), std::string::npos) << r.failure;
  EXPECT_EQ(r.fitness, 0.0);
  EXPECT_FALSE(replay.frames.empty());
  // and ODE is sound after it: the same evaluation as before the fault
  EvalResult after = evaluate(snake, snake_cfg, 3);
  EXPECT_EQ(after.fitness, before.fitness);
  EXPECT_EQ(after.steps, before.steps);
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

// motor.response_time_jitter: each seed draws the motors' lag within +-the
// share of response_time, and its evaluation is that of a config with that
// lag, bit for bit; without the jitter nothing is drawn.
TEST(Evaluate, EachSeedDrawsTheMotorsLagWithinItsJitter) {
  SimConfig cfg;
  CreatureModel m = grow("walker.json", &cfg);
  cfg.task.seconds = 3;
  cfg.motor.response_time = 0.02;
  EXPECT_EQ(seed_draw(cfg, 5).response_time, 0.02);
  SimConfig jit = cfg;
  jit.motor.response_time_jitter = 0.5;
  double lo = 1, hi = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const SeedDraw d = seed_draw(jit, seed);
    EXPECT_EQ(d.yaw, seed_draw(cfg, seed).yaw);  // the start is drawn as before
    EXPECT_GE(d.response_time, 0.01);
    EXPECT_LE(d.response_time, 0.03);
    lo = std::min(lo, d.response_time);
    hi = std::max(hi, d.response_time);
    if (seed <= 3) {
      SimConfig fixed = cfg;
      fixed.motor.response_time = d.response_time;
      EXPECT_EQ(evaluate(m, jit, seed).distance, evaluate(m, fixed, seed).distance) << seed;
    }
  }
  EXPECT_LT(lo, 0.015);  // 12 draws spread over the range
  EXPECT_GT(hi, 0.025);
}

}  // namespace
}  // namespace bx
