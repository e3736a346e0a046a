// The turn task (lessin2015 V, skills 2 and 3): the turn rate of the root's
// heading, unwrapped across +-pi, in the wanted direction, scaled down by
// the travel of the centre of mass, against closed forms; then once end to
// end, through the config and the evaluation with real physics.
#include "task/turn.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "develop/creature_model.h"
#include "develop/develop.h"
#include "eval/evaluate.h"
#include "io/config.h"
#include "support/creatures.h"

namespace bx {
namespace {

// a one-part creature: its root at `com`, turned by `h` about +z
struct Spinner : Observation {
  double t = 0, h = 0;
  double tilt = 0;  // then pitched by this about its own y axis
  Vec3 com{0, 0, 0.5};
  double time() const override { return t; }
  Vec3 centre_of_mass() const override { return com; }
  int n_parts() const override { return 1; }
  Pose part_pose(int) const override { return {com, Mat3::rotation({0, 0, 1}, h) * Mat3::rotation({0, 1, 0}, tilt)}; }
  bool touches_part(int) const override { return false; }
};

constexpr double dt = 0.1;

// a task of `seconds` measured (at most two still steps to settle, from
// heading h0), then `pose(s, o)` sets the creature at s seconds into the
// measured span, each step until the task is done
TurnDef def_of(TurnDirection dir, double seconds = 4, int windows = 2) {
  TurnDef def;
  def.direction = dir;
  def.seconds = seconds;
  def.windows = windows;
  def.settle.seconds = 2 * dt;
  def.settle.speed = 0.1;
  def.settle.timeout = 5;
  return def;
}

void run(TurnTask& task, double h0, const std::function<void(double, Spinner&)>& pose) {
  Spinner o;
  o.h = h0;
  task.begin(o);
  // settling: still, the controller off
  EXPECT_FALSE(task.controller_on());
  while (task.phase() != Phase::Measure && !task.done()) {
    o.t += dt;
    task.observe(o);
  }
  ASSERT_EQ(task.phase(), Phase::Measure);
  EXPECT_TRUE(task.controller_on());
  const double t0 = o.t;
  while (!task.done()) {
    o.t += dt;
    pose(o.t - t0, o);
    task.observe(o);
  }
}

TEST(Turn, ALeftTurnScoresTheRootsTurnRate) {
  TurnTask task(def_of(TurnDirection::Left), dt, 1);
  run(task, 0.2, [](double s, Spinner& o) { o.h = 0.2 + 0.3 * s; });
  EXPECT_NEAR(task.measured_seconds(), 4, 1e-9);
  EXPECT_NEAR(task.turned(), 1.2, 1e-9);
  EXPECT_NEAR(task.scored_turn(), 1.2, 1e-9);
  EXPECT_NEAR(task.turn_rate(), 0.3, 1e-9);
  EXPECT_DOUBLE_EQ(task.travel(), 0);
  EXPECT_NEAR(task.fitness(), 0.3, 1e-9);
  const TaskScore s = task.score(CreatureModel{});
  EXPECT_NEAR(s.fitness, 0.3, 1e-9);
  EXPECT_DOUBLE_EQ(s.distance, 0);
  ASSERT_EQ(s.metrics.size(), 4u);
  EXPECT_EQ(s.metrics[0].name, "turn_rate");
  EXPECT_NEAR(s.metrics[0].value, 0.3, 1e-9);
  EXPECT_EQ(s.metrics[1].name, "turned");
  EXPECT_NEAR(s.metrics[1].value, 1.2, 1e-9);
  EXPECT_EQ(s.metrics[2].name, "travel");
  EXPECT_EQ(s.metrics[3].name, "muscle_work");
  EXPECT_TRUE(task.note().empty());
}

TEST(Turn, ARightTurnScoresTheMirroredTurnAndTheWrongWayScoresNothing) {
  auto clockwise = [](double s, Spinner& o) { o.h = -0.3 * s; };
  auto counterclockwise = [](double s, Spinner& o) { o.h = 0.3 * s; };
  TurnTask right(def_of(TurnDirection::Right), dt, 1);
  run(right, 0, clockwise);
  EXPECT_NEAR(right.turned(), -1.2, 1e-9);  // counterclockwise positive
  EXPECT_NEAR(right.turn_rate(), 0.3, 1e-9);
  EXPECT_NEAR(right.fitness(), 0.3, 1e-9);
  EXPECT_NEAR(right.score(CreatureModel{}).metrics[1].value, 1.2, 1e-9);  // turned, in the direction
  // a left turn asked to turn right, and the other way round: a negative rate, fitness 0
  TurnTask left(def_of(TurnDirection::Left), dt, 1);
  run(left, 0, clockwise);
  EXPECT_NEAR(left.turn_rate(), -0.3, 1e-9);
  EXPECT_DOUBLE_EQ(left.fitness(), 0);
  TurnTask wrong(def_of(TurnDirection::Right), dt, 1);
  run(wrong, 0, counterclockwise);
  EXPECT_NEAR(wrong.turn_rate(), -0.3, 1e-9);
  EXPECT_DOUBLE_EQ(wrong.fitness(), 0);
}

TEST(Turn, TravelDividesTheScoreByOnePlusTravelOverTheScale) {
  // the centre of mass goes 0.3 m east and 0.4 m north, then back: its
  // farthest, 0.5 m, counts (a circle that closes does not undo its travel)
  TurnDef def = def_of(TurnDirection::Left);
  def.travel_scale = 0.25;
  TurnTask task(def, dt, 1);
  run(task, 0, [](double s, Spinner& o) {
    o.h = 0.3 * s;
    const double f = s <= 2 ? s / 2 : (4 - s) / 2;  // out and back
    o.com = {0.3 * f, 0.4 * f, 0.5 + f};           // height does not count
  });
  EXPECT_NEAR(task.travel(), 0.5, 1e-9);
  EXPECT_NEAR(task.score(CreatureModel{}).distance, 0.5, 1e-9);
  EXPECT_NEAR(task.turn_rate(), 0.3, 1e-9);
  EXPECT_NEAR(task.fitness(), 0.3 / (1 + 0.5 / 0.25), 1e-9);  // a third of it
  // at travel_scale the score halves
  def.travel_scale = 0.5;
  TurnTask half(def, dt, 1);
  run(half, 0, [](double s, Spinner& o) {
    o.h = 0.3 * s;
    o.com = {0.5 * std::min(1.0, s), 0, 0.5};
  });
  EXPECT_NEAR(half.fitness(), 0.15, 1e-9);
}

TEST(Turn, TheHeadingUnwrapsAcrossPi) {
  // heading_step takes the short way round
  EXPECT_NEAR(heading_step(3.1, -3.1), 2 * kPi - 6.2, 1e-12);
  EXPECT_NEAR(heading_step(-3.1, 3.1), -(2 * kPi - 6.2), 1e-12);
  EXPECT_NEAR(heading_step(0.5, -0.25), -0.75, 1e-12);
  // 1 rad/s for 8 s from 3 rad: through +pi and once more round (heading()
  // jumps from near pi to near -pi each time), 8 rad turned
  TurnTask left(def_of(TurnDirection::Left, 8), dt, 1);
  run(left, 3.0, [](double s, Spinner& o) { o.h = 3.0 + s; });
  EXPECT_NEAR(left.turned(), 8, 1e-9);
  EXPECT_NEAR(left.turn_rate(), 1, 1e-9);
  // and clockwise through -pi
  TurnTask right(def_of(TurnDirection::Right, 8), dt, 1);
  run(right, -3.0, [](double s, Spinner& o) { o.h = -3.0 - s; });
  EXPECT_NEAR(right.turned(), -8, 1e-9);
  EXPECT_NEAR(right.turn_rate(), 1, 1e-9);
}

// a root pitched over the vertical comes out facing back (its heading
// flips by pi): no turn, since the heading counts only while level enough
TEST(Turn, ARootTippedOverTurnsNothing) {
  TurnTask task(def_of(TurnDirection::Left, 4, 1), dt, 1);
  run(task, 0.3, [](double s, Spinner& o) { o.tilt = std::min(s, 2.0) / 2.0 * kPi; });
  Spinner back;
  back.h = 0.3;
  back.tilt = kPi;
  EXPECT_NEAR(std::abs(std::remainder(heading(back) - 0.3, 2 * kPi)), kPi, 1e-9);  // it faces back
  EXPECT_EQ(task.turned(), 0);
  EXPECT_EQ(task.fitness(), 0);
  // a level root turning through the same span does count
  TurnTask level(def_of(TurnDirection::Left, 4, 1), dt, 1);
  run(level, 0.3, [](double s, Spinner& o) { o.h = 0.3 + std::min(s, 2.0) / 2.0 * kPi; });
  EXPECT_NEAR(level.turned(), kPi, 1e-9);
}

TEST(Turn, WindowsScoreOnlyATurnThatLasts) {
  // a twist of 1 rad in the first second, then still
  auto twist = [](double s, Spinner& o) { o.h = std::min(1.0, s); };
  TurnTask two(def_of(TurnDirection::Left, 4, 2), dt, 1);
  run(two, 0, twist);
  EXPECT_NEAR(two.turned(), 1, 1e-9);
  EXPECT_NEAR(two.scored_turn(), 0, 1e-9);  // the second half turned nothing
  EXPECT_NEAR(two.fitness(), 0, 1e-9);
  TurnTask one(def_of(TurnDirection::Left, 4, 1), dt, 1);
  run(one, 0, twist);
  EXPECT_NEAR(one.turn_rate(), 0.25, 1e-9);  // the whole turn over the 4 s
  // two windows: twice the lesser half's turn (0.2 rad/s, then 0.5 rad/s)
  TurnTask uneven(def_of(TurnDirection::Left, 4, 2), dt, 1);
  run(uneven, 0, [](double s, Spinner& o) { o.h = s <= 2 ? 0.2 * s : 0.4 + 0.5 * (s - 2); });
  EXPECT_NEAR(uneven.scored_turn(), 2 * 0.4, 1e-9);
  EXPECT_NEAR(uneven.turn_rate(), 0.2, 1e-9);
}

TEST(Turn, NeverSettlingScoresNothing) {
  TurnDef def = def_of(TurnDirection::Left);
  TurnTask task(def, dt, 1);
  EXPECT_EQ(task.max_steps(), std::lround((def.settle.timeout + def.seconds) / dt) + 1);
  Spinner o;
  task.begin(o);
  while (!task.done()) {
    o.t += dt;
    o.com.x += 1 * dt;  // 1 m/s, over settle_speed
    o.h += 0.3 * dt;
    task.observe(o);
  }
  EXPECT_FALSE(task.controller_on());
  EXPECT_EQ(task.note(), "never settled within settle_timeout");
  EXPECT_DOUBLE_EQ(task.turned(), 0);
  EXPECT_DOUBLE_EQ(task.fitness(), 0);
}

// end to end: task.kind = "turn" from a config, evaluated with real physics
TEST(TurnEval, AConfigPicksTheTurnAndACreatureThatDoesNotTurnScoresNothing) {
  auto cfg = read_run_config(
      "[genome]\ndialect = \"lessin2015\"\n[task]\nkind = \"turn\"\n"
      "[turn]\ndirection = \"right\"\nseconds = 6\ndrop_height = 0.01\ntravel_scale = 0.5\nwindows = 3\n"
      "[motor]\nresponse_time = 0.01\n",
      "run.toml");
  ASSERT_TRUE(cfg.ok()) << cfg.error();
  SimConfig c = cfg->sim;
  EXPECT_EQ(c.task_kind, TaskKind::Turn);
  EXPECT_EQ(c.turn.direction, TurnDirection::Right);
  EXPECT_EQ(c.turn.seconds, 6);
  EXPECT_EQ(c.turn.windows, 3);
  EXPECT_EQ(c.turn.travel_scale, 0.5);
  EXPECT_EQ(task_seconds(c), 6);
  EXPECT_EQ(task_drop_height(c), 0.01);
  EXPECT_EQ(task_drop_height_key(c), "turn.drop_height");
  // creatures/lessin_crawler.json rows along when its muscles pulse
  // (tests/eval/lessin_crawler_test.cpp); held at a constant activation it
  // lies still after the first pull, and turns nothing worth a score
  const Genome g = bxtest::load_creature("lessin_crawler.json");
  Development d = develop(g, c.develop);
  ASSERT_TRUE(d.viable()) << d.reason;
  for (TurnDirection dir : {TurnDirection::Left, TurnDirection::Right}) {
    c.turn.direction = dir;
    for (double a : {0.0, 0.5}) {
      SimConfig held = c;
      held.effector_clamp = {a};
      const EvalResult r = evaluate(*d.model, held, 1);
      ASSERT_FALSE(r.failed) << r.failure;
      EXPECT_TRUE(r.note.empty()) << r.note;  // it settled and was measured
      EXPECT_LT(r.fitness, 1e-3) << "activation " << a;
      EXPECT_GE(r.fitness, 0);
      ASSERT_TRUE(r.metric("turn_rate") && r.metric("turned"));
      // the first pull may twist it (the whole span's turn), but a later
      // window turns nothing: the rate that scores is at most 0
      EXPECT_LT(*r.metric("turn_rate"), 1e-3) << "activation " << a;
      EXPECT_LT(r.distance, 0.1 * d.model->body_length()) << "activation " << a;
      EXPECT_EQ(r.metric("travel"), r.distance);
      // settling, then the 6 s measured
      EXPECT_GT(r.seconds, 6);
      EXPECT_LT(r.seconds, 6 + c.turn.settle.timeout);
    }
  }
  // the first pull at 0.5 twists it about 0.1 rad clockwise (measured
  // 0.105): with one window that twist alone would score as a right turn
  SimConfig one = c;
  one.turn.direction = TurnDirection::Right;
  one.turn.windows = 1;
  one.effector_clamp = {0.5};
  const EvalResult r = evaluate(*d.model, one, 1);
  ASSERT_FALSE(r.failed) << r.failure;
  EXPECT_GT(*r.metric("turned"), 0.05);
  EXPECT_GT(r.fitness, 0.005);
}

}  // namespace
}  // namespace bx
