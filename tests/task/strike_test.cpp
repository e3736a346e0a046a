// The strike task (lessin2015 V, skill 6; task/strike.h): an impact is the
// largest rise of the centre of mass's vertical velocity within a short
// span, measured against closed forms (a body falling freely and stopped,
// one walking, one rising slowly) and, with real physics, on the crawler.
#include "task/strike.h"

#include <gtest/gtest.h>

#include <cmath>

#include "develop/develop.h"
#include "eval/evaluate.h"
#include "io/config.h"
#include "support/creatures.h"

namespace bx {
namespace {

constexpr double g = 9.81;

// a body falling freely from rest for t1 seconds, then stopped dead on the ground
TEST(ImpactMeter, AFallStoppedDeadIsItsFallingSpeed) {
  for (double dt : {1.0 / 60, 0.005, 0.001}) {
    ImpactMeter m(0.1, 0.5, dt);
    const double h = std::lround(0.05 / dt) * dt;  // half the window
    const double t1 = 0.4, z0 = 2;
    m.start(0, z0);
    const long steps = std::lround(1.0 / dt);
    for (long k = 1; k <= steps; ++k) {
      const double t = k * dt, tf = std::min(t, t1);
      m.observe(t, z0 - 0.5 * g * tf * tf);
    }
    // the mean falling speed over the half window before the stop, g (t1 - h/2)
    EXPECT_NEAR(m.peak(), g * (t1 - h / 2), g * dt) << "dt " << dt;
    EXPECT_NEAR(m.peak_time(), t1 + h, 1.5 * dt) << "dt " << dt;
    EXPECT_LT(m.first_strike(), t1 + h) << "dt " << dt;  // 0.5 m/s reached on the way
    EXPECT_GT(m.first_strike(), t1) << "dt " << dt;
  }
}

TEST(ImpactMeter, WalkingOrRisingSlowlyIsNoStrike) {
  const double dt = 0.01;
  ImpactMeter walk(0.1, 0.5, dt), rise(0.1, 0.5, dt);
  walk.start(0, 0.3);
  rise.start(0, 0.3);
  for (int k = 1; k <= 300; ++k) {
    const double t = k * dt;
    walk.observe(t, 0.3 + 0.02 * std::sin(2 * kPi * 2 * t));  // a 2 Hz bob of 2 cm
    rise.observe(t, 0.3 + 0.25 * t * t);                     // speeding up at 0.5 m/s^2
  }
  // the bob's mean velocities half a window apart differ by at most about
  // 2 cm (2 pi 2)^2 x 0.05 s: 0.16 m/s
  EXPECT_LT(walk.peak(), 0.17);
  EXPECT_GT(walk.peak(), 0.1);
  EXPECT_NEAR(rise.peak(), 0.5 * 0.05, 1e-6);  // a steady rise's: its acceleration over half the window
  EXPECT_EQ(walk.first_strike(), -1);
  EXPECT_EQ(rise.first_strike(), -1);
}

// end to end: task.kind = "strike" from a config, with real physics
TEST(StrikeEval, TheCrawlersStrokesStrikeAndHeldStillItDoesNot) {
  auto cfg = read_run_config(
      "[genome]\ndialect = \"lessin2015\"\n[task]\nkind = \"strike\"\n"
      "[strike]\nseconds = 3\ndrop_height = 0.01\nwindow = 0.1\nthreshold = 0.3\n[motor]\nresponse_time = 0.01\n",
      "run.toml");
  ASSERT_TRUE(cfg.ok()) << cfg.error();
  SimConfig c = cfg->sim;
  EXPECT_EQ(c.task_kind, TaskKind::Strike);
  EXPECT_EQ(c.strike.seconds, 3);
  EXPECT_EQ(c.strike.threshold, 0.3);
  const Genome gen = bxtest::load_creature("lessin_crawler.json");
  Development d = develop(gen, c.develop);
  ASSERT_TRUE(d.viable()) << d.reason;
  // rowing, its body bumps the ground (measured 0.4-0.7 m/s)
  const EvalResult r = evaluate(*d.model, c, 1);
  ASSERT_FALSE(r.failed) << r.failure;
  EXPECT_TRUE(r.note.empty()) << r.note;
  EXPECT_GT(r.fitness, 0.3);
  // held at a constant activation it lies still after its first pull
  SimConfig held = c;
  held.effector_clamp = {0.0};
  const EvalResult still = evaluate(*d.model, held, 1);
  ASSERT_FALSE(still.failed) << still.failure;
  EXPECT_LT(still.fitness, 0.1);
}

}  // namespace
}  // namespace bx
