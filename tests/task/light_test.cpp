// The light tasks (lessin2015 V, skills 4, 5, 8 and 9): where each trial's
// light goes, and each goal's score against closed forms with a fake
// observation; then the config's keys and rules, and once end to end with
// real physics: lessin_eyes under the four headings, its eyes seeing the
// light once it is on.
#include "physics/world.h"
#include "task/light.h"

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

// a one-part creature: its root at `com`, turned by `h` about +z, then
// pitched by `tilt` about its own y axis
struct Creature : Observation {
  double t = 0, h = 0, tilt = 0;
  Vec3 com{1, 2, 0.5};
  double time() const override { return t; }
  Vec3 centre_of_mass() const override { return com; }
  int n_parts() const override { return 1; }
  Pose part_pose(int) const override { return {com, Mat3::rotation({0, 0, 1}, h) * Mat3::rotation({0, 1, 0}, tilt)}; }
  bool touches_part(int) const override { return false; }
};

// steps of an eighth of a second: every time is exact in binary
constexpr double dt = 0.125;
constexpr double deg = kPi / 180;

// 4 s measured after two still steps of settling, the light 3 m off at 0.5 m
LightDef def_of(LightGoal goal, std::vector<double> headings = {45, 135, -135, -45}) {
  LightDef def;
  def.goal = goal;
  def.headings = std::move(headings);
  def.seconds = 4;
  def.settle.seconds = 2 * dt;
  def.settle.speed = 0.1;
  def.settle.timeout = 5;
  def.early_seconds = 1;
  return def;
}

// Runs `task` from the creature `o` at rest: settling (no light: act()
// places none), then `pose(s, o)` sets it s seconds into the measured span,
// each step until the task is done; act() runs before each step with `w`.
void run(LightTask& task, Creature& o, World& w, const std::function<void(double, Creature&)>& pose) {
  task.begin(o);
  EXPECT_FALSE(task.controller_on());
  while (task.phase() != Phase::Measure && !task.done()) {
    task.act(CreatureModel{}, {}, w, o);
    EXPECT_TRUE(w.lights().empty());  // dark while settling
    o.t += dt;
    task.observe(o);
  }
  ASSERT_EQ(task.phase(), Phase::Measure);
  const double t0 = o.t;
  while (!task.done()) {
    task.act(CreatureModel{}, {}, w, o);
    o.t += dt;
    pose(o.t - t0, o);
    task.observe(o);
  }
}

void run(LightTask& task, Creature& o, const std::function<void(double, Creature&)>& pose) {
  World w{PhysicsDef{}};
  run(task, o, w, pose);
}

// the creature facing `a` radians off the light (counterclockwise), its
// centre of mass where it began
std::function<void(double, Creature&)> facing_off(double h0, double bearing, double a) {
  return [=](double, Creature& o) { o.h = h0 + bearing - a; };
}

TEST(Light, TrialKPutsTheLightAtTheKthHeadingFromTheForward) {
  const LightDef def = def_of(LightGoal::Face);
  const double h0 = 0.3;
  for (int k = 0; k < 6; ++k) {
    LightTask task(def, StrikeDef{}, dt, 1, k);
    const double b = def.headings[static_cast<std::size_t>(k) % 4];  // trials 4 and 5 take headings 0 and 1
    EXPECT_EQ(task.bearing(), b);
    Creature o;
    o.h = h0;
    World w{PhysicsDef{}};
    EXPECT_FALSE(task.light());
    run(task, o, w, [](double, Creature&) {});
    ASSERT_EQ(w.lights().size(), 1u);
    const Light& l = w.lights()[0];
    // 3 m on the ground from the centre of mass (1, 2), at the heading plus the bearing, 0.5 m up
    EXPECT_NEAR(l.position.x, 1 + 3 * std::cos(h0 + b * deg), 1e-12) << "trial " << k;
    EXPECT_NEAR(l.position.y, 2 + 3 * std::sin(h0 + b * deg), 1e-12) << "trial " << k;
    EXPECT_EQ(l.position.z, 0.5);
    EXPECT_EQ(l.strength, def.strength);
    EXPECT_EQ(l.range, def.range);
    ASSERT_TRUE(task.light());
    EXPECT_EQ(*task.light(), l);
    // the creature stood still: the light where it was put
    EXPECT_NEAR(task.end_bearing(), b * deg, 1e-12);
    EXPECT_NEAR(task.score(CreatureModel{}).metrics[0].value, b, 1e-9);  // bearing, degrees
    EXPECT_NEAR(task.start_distance(), 3, 1e-12);
    EXPECT_NEAR(task.end_distance(), 3, 1e-12);
  }
}

// what a viewer labels each trial's replay with (Task::describe)
TEST(Light, DescribeSaysWhereEachTrialsLightIsOrThatThereIsNone) {
  LightDef def = def_of(LightGoal::Attack);
  def.dark_trials = 1;  // trials 0-3 lit at the four headings, 4 dark, then again
  const char* want[] = {"light at 45 degrees", "light at 135 degrees", "light at -135 degrees",
                        "light at -45 degrees", "no light", "light at 45 degrees"};
  for (int k = 0; k < 6; ++k) EXPECT_EQ(LightTask(def, StrikeDef{}, dt, 1, k).describe(), want[k]) << "trial " << k;
  // a bearing as it was given, a fraction included
  EXPECT_EQ(LightTask(def_of(LightGoal::Face, {-22.5, 0}), StrikeDef{}, dt, 1, 0).describe(), "light at -22.5 degrees");
  EXPECT_EQ(LightTask(def_of(LightGoal::Face, {-22.5, 0}), StrikeDef{}, dt, 1, 1).describe(), "light at 0 degrees");
}

TEST(Light, TheLightGoesOnOnceMeasuringBeginsAndTheSceneShowsIt) {
  LightTask task(def_of(LightGoal::Face), StrikeDef{}, dt, 1, 0);
  Creature o;
  World w{PhysicsDef{}};
  SceneRecord scene;
  task.begin(o);
  task.record(o, scene);
  EXPECT_TRUE(scene.empty());  // nothing to show while settling
  double t_on = -1;
  while (!task.done()) {
    task.act(CreatureModel{}, {}, w, o);
    if (t_on < 0 && !w.lights().empty()) t_on = o.t;
    o.t += dt;
    task.observe(o);
    task.record(o, scene);
  }
  EXPECT_EQ(t_on, 2 * dt);  // the step after settling ended (two still steps)
  ASSERT_EQ(scene.points.size(), 1u);  // recorded once
  EXPECT_EQ(scene.points[0].name, "light");
  EXPECT_EQ(scene.points[0].p, task.light()->position);
  EXPECT_EQ(scene.points[0].color, "#ffd200");
  EXPECT_GT(scene.points[0].size, 0.1);
  EXPECT_EQ(scene.marker("light on"), 2 * dt);
}

TEST(Light, FaceScoresOneFacingTheLightAndZeroFacingAway) {
  const double h0 = -2.9, b = 135;
  auto score = [&](double off) {
    LightTask task(def_of(LightGoal::Face, {b}), StrikeDef{}, dt, 1, 0);
    Creature o;
    o.h = h0;
    run(task, o, facing_off(h0, b * deg, off));
    return task.fitness();
  };
  EXPECT_NEAR(score(0), 1, 1e-12);
  EXPECT_NEAR(score(kPi), 0, 1e-12);
  EXPECT_NEAR(score(kPi / 2), 0.5, 1e-12);
  EXPECT_NEAR(score(-kPi / 3), 0.75, 1e-12);  // (1 + cos a) / 2 on either side
  // doing nothing: (1 + cos bearing) / 2, 0.146 at 135 degrees
  LightTask still(def_of(LightGoal::Face, {b}), StrikeDef{}, dt, 1, 0);
  Creature o;
  run(still, o, [](double, Creature&) {});
  EXPECT_NEAR(still.fitness(), (1 + std::cos(b * deg)) / 2, 1e-12);
  EXPECT_NEAR(still.facing(), still.fitness(), 1e-12);
}

TEST(Light, FaceIsTheMeanOverTheSecondHalfAndATippedRootFacesNowhere) {
  // facing away for the first half (not counted), then at 90 degrees until
  // 3 s, then facing it: of the 17 steps at s = 2, 2.125, ..., 4, eight
  // score a half and nine score 1
  const double b = 45;
  auto turner = [&](double s, Creature& o) { o.h = s < 2 ? b * deg + kPi : s < 3 ? b * deg - kPi / 2 : b * deg; };
  LightTask task(def_of(LightGoal::Face, {b}), StrikeDef{}, dt, 1, 0);
  Creature o;
  o.h = 0;
  run(task, o, turner);
  EXPECT_NEAR(task.fitness(), (8 * 0.5 + 9 * 1.0) / 17, 1e-12);
  // from the start of the span (score_from = 0): the first half's 15 steps facing away count 0
  LightDef all = def_of(LightGoal::Face, {b});
  all.score_from = 0;
  LightTask whole(all, StrikeDef{}, dt, 1, 0);
  Creature o2;
  run(whole, o2, turner);
  EXPECT_NEAR(whole.fitness(), (8 * 0.5 + 9 * 1.0) / 32, 1e-12);
  // facing the light with its root pitched up 70 degrees (x axis 0.34 of
  // its length on the ground, under min_level) from 3 s on: those steps count 0
  LightTask tipped(def_of(LightGoal::Face, {b}), StrikeDef{}, dt, 1, 0);
  Creature o3;
  run(tipped, o3, [&](double s, Creature& o) {
    o.h = b * deg;
    o.tilt = s < 3 ? 0 : -70 * deg;
  });
  EXPECT_NEAR(tipped.fitness(), 8.0 / 17, 1e-12);
}

TEST(Light, FaceAwayScoresTheOppositeAndPunishesAnInitialTurnTowardsTheLight) {
  const double b = 30;  // ahead and to the left: the way away is a right turn
  auto run_with = [&](const LightDef& def, const std::function<void(double, Creature&)>& pose) {
    LightTask task(def, StrikeDef{}, dt, 1, 0);
    Creature o;
    run(task, o, pose);
    return task;
  };
  const LightDef def = def_of(LightGoal::FaceAway, {b});
  // facing away scores 1, facing the light 0
  EXPECT_NEAR(run_with(def, facing_off(0, b * deg, kPi)).fitness(), 1, 1e-12);
  EXPECT_NEAR(run_with(def, facing_off(0, b * deg, 0)).fitness(), 0, 1e-12);
  // turning right (away) from the start to face away: no penalty
  auto right = [&](double s, Creature& o) { o.h = -std::min(s, 1.5) / 1.5 * (kPi - b * deg); };
  const LightTask good = run_with(def, right);
  EXPECT_FALSE(good.penalized());
  EXPECT_EQ(good.wrong_turn(), 0);
  EXPECT_NEAR(good.fitness(), 1, 1e-12);
  // 20 degrees left first (towards the light's side, past it), then round
  // to face away: the wrong turn halves the score
  auto wrong_h = [&](double s) {
    return s <= 0.5 ? 20 * deg * s / 0.5 : 20 * deg - std::min(s - 0.5, 1.0) * (kPi + 20 * deg - b * deg);
  };
  auto wrong = [&](double s, Creature& o) { o.h = wrong_h(s); };
  const LightTask bad = run_with(def, wrong);
  EXPECT_NEAR(bad.wrong_turn(), 20, 1e-9);
  EXPECT_TRUE(bad.penalized());
  EXPECT_NEAR(bad.facing(), 1, 1e-12);
  EXPECT_NEAR(bad.fitness(), 0.5, 1e-12);
  EXPECT_NEAR(bad.score(CreatureModel{}).metrics[5].value, 20, 1e-9);  // wrong_turn
  // under the threshold it goes unpunished
  LightDef lenient = def;
  lenient.wrong_turn = 25;
  EXPECT_NEAR(run_with(lenient, wrong).fitness(), 1, 1e-12);
  // the same turn after the early span is no wrong start
  LightDef short_early = def;
  short_early.early_seconds = 0.25;
  const LightTask late = run_with(short_early, wrong);
  EXPECT_NEAR(late.wrong_turn(), 10, 1e-9);  // 10 degrees by 0.25 s
  EXPECT_FALSE(late.penalized());
  // mirrored: with a light on the right, a right turn first is wrong and a left turn right
  const LightDef mirrored = def_of(LightGoal::FaceAway, {-b});
  const LightTask mirror_bad = run_with(mirrored, [&](double s, Creature& o) { o.h = -wrong_h(s); });
  EXPECT_NEAR(mirror_bad.wrong_turn(), 20, 1e-9);
  EXPECT_NEAR(mirror_bad.fitness(), 0.5, 1e-12);
  const LightTask mirror_good = run_with(mirrored, [&](double s, Creature& o) {
    right(s, o);
    o.h = -o.h;
  });
  EXPECT_FALSE(mirror_good.penalized());
  EXPECT_NEAR(mirror_good.fitness(), 1, 1e-12);
  // a light dead ahead has no wrong side
  const LightDef ahead = def_of(LightGoal::FaceAway, {0});
  const LightTask either = run_with(ahead, wrong);
  EXPECT_EQ(either.wrong_turn(), 0);
  EXPECT_FALSE(either.penalized());
  // face ignores the wrong turn
  EXPECT_FALSE(run_with(def_of(LightGoal::Face, {b}), wrong).penalized());
}

TEST(Light, ApproachScoresTheShareOfTheDistanceClosed) {
  const double b = -72;
  auto approach = [&](double share_closed_at_most, bool back) {
    LightTask task(def_of(LightGoal::Approach, {b}), StrikeDef{}, dt, 1, 0);
    Creature o;
    o.h = 0.4;
    const Vec3 c0 = o.com, to{std::cos(0.4 + b * deg), std::sin(0.4 + b * deg), 0};
    run(task, o, [&](double s, Creature& c) {
      // towards the light at 3 m in 2 s times the share, then (back) away again
      const double f = std::min(s, 2.0) / 2 - (back ? std::max(0.0, s - 2) / 2 : 0);
      c.com = c0 + (3 * share_closed_at_most * f) * to;
    });
    return task;
  };
  const LightTask half = approach(0.5, true);
  EXPECT_NEAR(half.least_distance(), 1.5, 1e-12);
  EXPECT_NEAR(half.end_distance(), 3, 1e-12);
  EXPECT_NEAR(half.fitness(), 0.5, 1e-12);  // the least distance counts, not the end's
  EXPECT_NEAR(approach(1, false).fitness(), 1, 1e-12);
  EXPECT_NEAR(approach(-0.5, false).fitness(), 0, 1e-12);  // away: nothing closed
  // approach ignores moves towards the light early on (they are the task)
  EXPECT_FALSE(approach(1, false).penalized());
  EXPECT_NEAR(approach(1, false).wrong_move(), 1.5, 1e-12);  // closed by the end of the early second
}

TEST(Light, RetreatScoresTheMeanDistanceGainedAndPunishesAnInitialMoveTowardsTheLight) {
  const double b = 10;
  auto retreat = [&](const LightDef& def, const std::function<double(double)>& gain) {
    LightTask task(def, StrikeDef{}, dt, 1, 0);
    Creature o;
    const Vec3 c0 = o.com, from{-std::cos(b * deg), -std::sin(b * deg), 0};  // away from the light
    run(task, o, [&](double s, Creature& c) { c.com = c0 + gain(s) * from; });
    return task;
  };
  const LightDef def = def_of(LightGoal::Retreat, {b});
  // straight away at 0.5 m/s: over the 32 steps s_i = i / 8 the mean gain
  // is 0.5 (dt (32 + 1) / 2) = 1.03125 m, over the light's 3 m
  const LightTask away = retreat(def, [](double s) { return 0.5 * s; });
  EXPECT_NEAR(away.mean_gain(), 0.5 * dt * 33 / 2, 1e-12);
  EXPECT_NEAR(away.fitness(), 0.5 * dt * 33 / 2 / 3, 1e-12);
  EXPECT_NEAR(away.end_distance(), 5, 1e-12);
  EXPECT_EQ(away.wrong_move(), 0);
  // towards it: nothing
  EXPECT_EQ(retreat(def, [](double s) { return -0.5 * s; }).fitness(), 0);
  // 0.2 m towards it in the first half second, then away at 0.5 m/s: the
  // wrong start halves the score
  auto lunge = [](double s) { return s <= 0.5 ? -0.4 * s : -0.2 + 0.5 * (s - 0.5); };
  const LightTask bad = retreat(def, lunge);
  EXPECT_NEAR(bad.wrong_move(), 0.2, 1e-12);
  EXPECT_TRUE(bad.penalized());
  double sum = 0;
  for (int i = 1; i <= 32; ++i) sum += lunge(i * dt);
  EXPECT_NEAR(bad.mean_gain(), sum / 32, 1e-12);
  EXPECT_NEAR(bad.fitness(), 0.5 * sum / 32 / 3, 1e-12);
  // under wrong_move it goes unpunished
  LightDef lenient = def;
  lenient.wrong_move = 0.25;
  EXPECT_NEAR(retreat(lenient, lunge).fitness(), sum / 32 / 3, 1e-12);
}

TEST(Light, NeverSettlingScoresNothingAndNoLightComesOn) {
  const LightDef def = def_of(LightGoal::Face, {0});
  LightTask task(def, StrikeDef{}, dt, 1, 0);
  EXPECT_EQ(task.max_steps(), std::lround((def.settle.timeout + def.seconds) / dt) + 1);
  Creature o;
  World w{PhysicsDef{}};
  task.begin(o);
  while (!task.done()) {
    task.act(CreatureModel{}, {}, w, o);
    o.t += dt;
    o.com.x += 1 * dt;  // 1 m/s, over settle_speed
    task.observe(o);
  }
  EXPECT_EQ(task.note(), "never settled within settle_timeout");
  EXPECT_TRUE(w.lights().empty());
  EXPECT_FALSE(task.light());
  EXPECT_EQ(task.fitness(), 0);
  SceneRecord scene;
  task.record(o, scene);
  EXPECT_TRUE(scene.empty());
}

TEST(Light, TheConfigReadsTheLightKeysAndTrialsMustCoverTheHeadings) {
  const std::string base = "[genome]\ndialect = \"lessin2015\"\n[task]\nkind = \"light\"\n";
  auto cfg = read_run_config(base +
                                 "trials = 5\n[light]\ngoal = \"approach\"\nheadings = [0, 72, 144, -144, -72.5]\n"
                                 "distance = 2\nheight = 0.25\nwrong_factor = 0.25\n",
                             "run.toml");
  ASSERT_TRUE(cfg.ok()) << cfg.error();
  const SimConfig& c = cfg->sim;
  EXPECT_EQ(c.task_kind, TaskKind::Light);
  EXPECT_EQ(c.light.goal, LightGoal::Approach);
  EXPECT_EQ(c.light.headings, (std::vector<double>{0, 72, 144, -144, -72.5}));
  EXPECT_EQ(c.light.distance, 2);
  EXPECT_EQ(c.light.height, 0.25);
  EXPECT_EQ(c.light.wrong_factor, 0.25);
  SimConfig s = c;
  EXPECT_EQ(task_seconds(s), 20);
  EXPECT_EQ(task_drop_height_key(c), "light.drop_height");
  // written and read back alike
  const std::string toml = config_to_toml(*cfg);
  EXPECT_NE(toml.find("headings = [0, 72, 144, -144, -72.5]\n"), std::string::npos) << toml;
  auto again = read_run_config(toml, "again.toml");
  ASSERT_TRUE(again.ok()) << again.error();
  EXPECT_EQ(again->sim, c);
  // twice the headings: each heading twice, under other seeds
  EXPECT_TRUE(read_run_config(base + "trials = 8\n", "run.toml").ok());
  // as many trials as headings, or a whole multiple, else an error naming both keys
  EXPECT_EQ(read_run_config(base, "run.toml").error(),
            "run.toml: task.trials: the light task runs trial k with the (k mod n)-th of light.headings' n = 4 "
            "headings, so task.trials must be a whole multiple of 4, got 1");
  EXPECT_EQ(read_run_config(base + "trials = 4\n", "run.toml", {"light.headings=[0, 90, 180]"}).error(),
            "run.toml: task.trials: the light task runs trial k with the (k mod n)-th of light.headings' n = 3 "
            "headings, so task.trials must be a whole multiple of 3, got 4");
  EXPECT_TRUE(read_run_config(base + "trials = 3\n", "run.toml", {"light.headings=[0, 90, 180]"}).ok());
  EXPECT_EQ(read_run_config(base + "trials = 4\n[light]\nheadings = []\n", "run.toml").error(),
            "run.toml: light.headings: needs at least one heading, got []");
  EXPECT_EQ(read_run_config(base + "trials = 4\n[light]\nheadings = [0, \"left\"]\n", "run.toml").error(),
            "run.toml: light.headings: expected an array of numbers, got [0, \"left\"]");
  EXPECT_EQ(read_run_config(base + "trials = 4\n[light]\nheadings = 45\n", "run.toml").error(),
            "run.toml: light.headings: expected an array of numbers, got 45");
  EXPECT_EQ(read_run_config(base + "trials = 2\n[light]\nheadings = [0, 400]\n", "run.toml").error(),
            "run.toml: light.headings: each out of range [-360, 360], got [0, 400]");
  // another task does not care
  EXPECT_TRUE(read_run_config("[genome]\ndialect = \"lessin2015\"\n[light]\nheadings = [0, 90, 180]\n", "run.toml").ok());
}

// creatures/lessin_eyes.json: a box with two eyes looking forward,
// 26.6 degrees to either side; it has no muscles and sits where it lands
Development eyes(const SimConfig& c) {
  Development d = develop(bxtest::load_creature("lessin_eyes.json"), c.develop);
  EXPECT_TRUE(d.viable()) << d.reason;
  return d;
}

SimConfig light_config(const std::string& goal, int trials, const std::vector<std::string>& sets = {}) {
  std::vector<std::string> all = {"task.kind=light", "light.goal=" + goal, "task.trials=" + std::to_string(trials),
                                  "light.seconds=4"};
  all.insert(all.end(), sets.begin(), sets.end());
  auto cfg = read_run_config("[genome]\ndialect = \"lessin2015\"\n", "run.toml", all);
  EXPECT_TRUE(cfg.ok()) << cfg.error();
  return cfg.ok() ? cfg->sim : SimConfig{};
}

// end to end: four trials, each its heading; the eyes read the light once it is on
TEST(LightEval, EachTrialHasItsHeadingAndTheEyesSeeTheLightOnceItIsOn) {
  const SimConfig c = light_config("face", 4);
  Development d = eyes(c);
  Replay replay;
  const EvalResult r = evaluate(*d.model, c, 1, &replay);
  ASSERT_FALSE(r.failed) << r.failure;
  EXPECT_TRUE(r.note.empty()) << r.note;
  // the box stays as it landed: each trial scores (1 + cos bearing) / 2
  ASSERT_EQ(r.trial_fitness.size(), 4u);
  const double h[] = {45, 135, -135, -45};
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(r.trial_fitness[k], (1 + std::cos(h[k] * deg)) / 2, 1e-3) << "trial " << k;
  EXPECT_NEAR(r.fitness, 0.5, 1e-3);
  // the first trial's metrics: the light 45 degrees off, 3 m away
  EXPECT_NEAR(*r.metric("bearing"), 45, 0.1);
  EXPECT_NEAR(*r.metric("start_distance"), 3, 1e-9);
  EXPECT_NEAR(r.distance, 3, 1e-3);
  // the replay's scene: the light, 0.5 m up, and when it came on
  ASSERT_EQ(replay.scene.points.size(), 1u);
  EXPECT_EQ(replay.scene.points[0].name, "light");
  EXPECT_EQ(replay.scene.points[0].p.z, 0.5);
  const std::optional<double> on = r.marker("light on");
  ASSERT_TRUE(on);
  EXPECT_GT(*on, 0.4);  // after settling (0.5 s still)
  // dark before, then both eyes see it (the left eye more: it looks 18.4
  // degrees off the light, the right one 71.6)
  bool lit = false;
  for (const ReplayFrame& f : replay.frames) {
    ASSERT_EQ(f.sensors.size(), 2u);
    if (f.t <= *on) {
      EXPECT_EQ(f.sensors[0], 0);
      EXPECT_EQ(f.sensors[1], 0);
    } else if (f.t > *on + 0.1) {
      lit = true;
      EXPECT_GT(f.sensors[0], f.sensors[1]);
      EXPECT_GT(f.sensors[1], 0);
      // strength 1 / (1 + (3 / 3)^2) times the cosine, the eye a little nearer
      EXPECT_NEAR(f.sensors[0], 0.5 * std::cos(18.4 * deg), 0.05);
    }
  }
  EXPECT_TRUE(lit);
  // behind the eyes (a light at 135 degrees is 108 off the left eye): dark
  Replay behind;
  const EvalResult r2 = evaluate(*d.model, light_config("face", 1, {"light.headings=[135]"}), 1, &behind);
  ASSERT_FALSE(r2.failed);
  EXPECT_NEAR(r2.fitness, (1 + std::cos(135 * deg)) / 2, 1e-3);
  for (const ReplayFrame& f : behind.frames) EXPECT_EQ(f.sensors[0] + f.sensors[1], 0) << f.t;
  // task.front = "+y": the creature's front is its root's y axis, so the
  // light dead ahead of it sits on the world's +y side
  Replay side;
  const EvalResult r3 = evaluate(*d.model, light_config("face", 1, {"light.headings=[0]", "task.front=+y"}), 1, &side);
  ASSERT_FALSE(r3.failed);
  ASSERT_EQ(side.scene.points.size(), 1u);
  const Vec3 com = side.frames.front().com;
  EXPECT_NEAR(side.scene.points[0].p.x - com.x, 0, 0.1);
  EXPECT_NEAR(side.scene.points[0].p.y - com.y, 3, 0.1);
}

// evaluate_trial: trial k's replay and measures, the whole evaluation's
// fitness; evaluate_trials: every trial's at once, each as evaluate_trial's
TEST(LightEval, EvaluateTrialShowsTrialKOfTheSameEvaluation) {
  const SimConfig c = light_config("face", 4);
  Development d = eyes(c);
  const GraphBrain brain(d.model->brain);
  Replay first;
  const EvalResult whole = evaluate(*d.model, c, 1, &first);
  EXPECT_EQ(whole.trial, 0);
  EXPECT_EQ(whole.setup, "light at 45 degrees");
  Replay third;
  const EvalResult r = evaluate_trial(*d.model, brain, c, 1, 2, &third);
  ASSERT_FALSE(r.failed) << r.failure;
  // the evaluation's score, bit for bit, and its steps
  EXPECT_EQ(r.fitness, whole.fitness);
  EXPECT_EQ(r.trial_fitness, whole.trial_fitness);
  EXPECT_EQ(r.steps, whole.steps);
  EXPECT_EQ(r.brain_steps, whole.brain_steps);
  // trial 3's own: the light at -135 degrees, seen in its replay
  EXPECT_EQ(r.trial, 2);
  EXPECT_EQ(r.setup, "light at -135 degrees");
  EXPECT_NEAR(*r.metric("bearing"), -135, 0.1);
  // the light's bearing from the box's forward (its root's x axis) at the end of a replay (degrees)
  auto bearing_in = [](const Replay& rp) {
    EXPECT_EQ(rp.scene.points.size(), 1u);
    const ReplayFrame& f = rp.frames.back();
    const Vec3 x = from_quat({f.poses[3], f.poses[4], f.poses[5], f.poses[6]}) * Vec3{1, 0, 0};
    const Vec3 l = rp.scene.points.at(0).p;
    return heading_step(std::atan2(x.y, x.x), std::atan2(l.y - f.com.y, l.x - f.com.x)) / deg;
  };
  EXPECT_NEAR(bearing_in(third), -135, 0.5);
  EXPECT_NEAR(bearing_in(first), 45, 0.5);
  // without a replay, the same trial alike
  const EvalResult quiet = evaluate_trial(*d.model, brain, c, 1, 2);
  EXPECT_EQ(quiet.fitness, r.fitness);
  EXPECT_EQ(*quiet.metric("bearing"), *r.metric("bearing"));
  // all four at once, from one evaluation
  std::vector<Replay> replays(4);
  const std::vector<EvalResult> all = evaluate_trials(*d.model, brain, c, 1, replays);
  ASSERT_EQ(all.size(), 4u);
  const double h[] = {45, 135, -135, -45};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(all[k].trial, k);
    EXPECT_EQ(all[k].fitness, whole.fitness) << "trial " << k;
    EXPECT_NEAR(*all[k].metric("bearing"), h[k], 0.1) << "trial " << k;
    EXPECT_FALSE(replays[k].frames.empty());
  }
  ASSERT_EQ(replays[2].frames.size(), third.frames.size());
  EXPECT_EQ(replays[2].frames.back().poses, third.frames.back().poses);
  EXPECT_EQ(replays[0].frames.back().poses, first.frames.back().poses);
  // a trial the evaluation does not have is a caller's mistake
  EXPECT_THROW(evaluate_trial(*d.model, brain, c, 1, 4), std::logic_error);
}

}  // namespace
}  // namespace bx
