// lessin2015's FIGHT OR FLIGHT (skill 10): each direction's two trials (the
// vulnerable disc to attack, the dangerous spinning stack to flee), the
// stack shining as its discs together, touching it destroying the
// creature, and the fold (f+ + 2n f-) / (2n + 1) against hand-computed cases.
#include "task/fight_or_flight.h"

#include <gtest/gtest.h>

#include <cmath>

#include "eval/step.h"
#include "eval/task_table.h"
#include "io/config.h"
#include "physics/world.h"
#include "support/parts.h"

namespace bx {
namespace {

TEST(Fight, TheFoldWeighsTheWorseOfEachPairTwoNTimesTheBetter) {
  // two directions: f+ = (0.8 + 0.6) / 2, f- = (0.2 + 0.4) / 2, n = 2
  const double two[] = {0.8, 0.2, 0.4, 0.6};
  EXPECT_NEAR(fight_fold(two), (0.7 + 4 * 0.3) / 5, 1e-12);
  // the paper's weighting: one perfect minimum is worth more than perfect
  // maxima everywhere (always attacking, say)
  const double always_attack[] = {1, 0, 1, 0};
  const double one_right[] = {1, 1, 0, 0};
  EXPECT_NEAR(fight_fold(always_attack), 1.0 / 5, 1e-12);
  EXPECT_NEAR(fight_fold(one_right), (0.5 + 4 * 0.5) / 5, 1e-12);
  EXPECT_GT(fight_fold(one_right), fight_fold(always_attack));
  const double perfect[] = {1, 1, 1, 1};
  EXPECT_NEAR(fight_fold(perfect), 1, 1e-12);
  EXPECT_EQ(fight_fold(std::span<const double>()), 0);
}

// a one-part creature: a 0.2 m cube of 1 kg resting on the ground at the
// origin, facing +x
CreatureModel cube() {
  CreatureModel m;
  m.parts.push_back(bxtest::box_part({0.2, 0.2, 0.2}, 1, {0, 0, 0.1}));
  return m;
}

// the light 3 m off at 0.5 m, measured for 1 s after 0.05 s still
LightDef light_def(double distance = 3) {
  LightDef l;
  l.distance = distance;
  l.seconds = 1;
  l.settle = {0.05, 0.05, 2};
  return l;
}

// runs trial `trial` of the task with the cube in a real world until done;
// returns the task
FightOrFlightTask run(const FightDef& fight, const LightDef& light, int trial, World& w, int* steps = nullptr) {
  const CreatureModel m = cube();
  FightOrFlightTask task(fight, light, StrikeDef{}, w.def().dt, 1, trial);
  w.add_creature(m, {{0, 0, 0}, Mat3::identity()});
  const WorldObservation o(m, w);
  task.begin(o);
  int n = 0;
  while (!task.done() && n < task.max_steps()) {
    task.act(m, {}, w, o);
    w.step();
    task.observe(o);
    ++n;
  }
  if (steps) *steps = n;
  return task;
}

TEST(Fight, EachDirectionHasTheDiscThenTheStackUnderTheLight) {
  FightDef fight;
  fight.headings = {0, 90};
  const LightDef light = light_def();
  for (int trial = 0; trial < 4; ++trial) {
    World w{PhysicsDef{}};
    const FightOrFlightTask t = run(fight, light, trial, w);
    SCOPED_TRACE(trial);
    EXPECT_EQ(t.dangerous(), trial % 2 == 1);
    EXPECT_FALSE(t.destroyed());
    // the light at the direction's heading, 3 m off, 0.5 m up
    ASSERT_EQ(w.lights().size(), 1u);
    const Light& l = w.lights()[0];
    const double h = (trial / 2 == 0 ? 0 : 90) * kPi / 180;
    EXPECT_NEAR(l.position.x, 3 * std::cos(h), 1e-3);
    EXPECT_NEAR(l.position.y, 3 * std::sin(h), 1e-3);
    EXPECT_EQ(l.position.z, 0.5);
    // the stack's three discs shine together
    EXPECT_EQ(l.strength, t.dangerous() ? 3 * light.strength : light.strength);
    // the target under it: a disc lying on the ground, or three spinning ones
    ASSERT_EQ(w.n_props(), t.dangerous() ? 3 : 1);
    ASSERT_EQ(t.discs().size(), static_cast<std::size_t>(w.n_props()));
    for (int k = 0; k < w.n_props(); ++k) {
      const Prop& d = t.discs()[static_cast<std::size_t>(k)];
      EXPECT_EQ(d.shape, Shape::Cylinder);
      EXPECT_EQ(d.size, (Vec3{fight.disc_height, fight.disc_diameter, fight.disc_diameter}));
      EXPECT_NEAR((d.pose.R * Vec3{1, 0, 0}).z, 1, 1e-12);  // its axis upright
      EXPECT_EQ(d.pose.p.x, l.position.x);
      EXPECT_EQ(d.pose.p.y, l.position.y);
      EXPECT_NEAR(d.pose.p.z, (k + 0.5) * fight.disc_height, 1e-12);
      EXPECT_EQ(d.spin, t.dangerous() ? fight.spin : 0);
    }
    // the inner task: attack the disc, flee the stack
    EXPECT_EQ(t.inner().fitness(), t.fitness());
  }
}

// what a viewer labels each trial's replay with (Task::describe): each
// direction's disc, then its stack
TEST(Fight, DescribeSaysWhichTargetEachTrialShowsAndWhere) {
  FightDef fight;
  fight.headings = {0, 90, -22.5};
  const char* want[] = {"vulnerable target at 0 degrees",    "dangerous target at 0 degrees",
                        "vulnerable target at 90 degrees",   "dangerous target at 90 degrees",
                        "vulnerable target at -22.5 degrees", "dangerous target at -22.5 degrees",
                        "vulnerable target at 0 degrees"};
  for (int trial = 0; trial < 7; ++trial)
    EXPECT_EQ(FightOrFlightTask(fight, light_def(), StrikeDef{}, 0.01, 1, trial).describe(), want[trial])
        << "trial " << trial;
}

TEST(Fight, TheReplayShowsTheTargetFromWhenItAppeared) {
  FightDef fight;
  fight.headings = {90};
  World w{PhysicsDef{}};
  FightOrFlightTask t = run(fight, light_def(), 1, w);
  const CreatureModel m = cube();
  SceneRecord scene;
  t.record(WorldObservation(m, w), scene);
  ASSERT_EQ(scene.props.size(), 3u);
  const std::optional<double> on = scene.marker("light on");
  ASSERT_TRUE(on);
  for (std::size_t k = 0; k < 3; ++k) {
    const SceneProp& p = scene.props[k];
    EXPECT_EQ(p.name, k == 0 ? "target" : "target " + std::to_string(k + 1));
    EXPECT_EQ(p.shape, "cylinder");
    EXPECT_EQ(p.size, t.discs()[k].size);
    EXPECT_EQ(p.pose, t.discs()[k].pose);
    EXPECT_EQ(p.spin, fight.spin);
    EXPECT_NEAR(p.t, *on, w.def().dt + 1e-12);  // placed in the step after the light came on
    EXPECT_EQ(p.color, "#d03030");
  }
  ASSERT_EQ(scene.points.size(), 1u);  // the light over it
  // recorded once
  t.record(WorldObservation(m, w), scene);
  EXPECT_EQ(scene.props.size(), 3u);
}

TEST(Fight, TouchingTheStackDestroysTheCreatureButTouchingTheDiscDoesNot) {
  FightDef fight;
  fight.headings = {0};
  // the target 0.2 m ahead: a disc 0.5 m across reaches under the cube
  const LightDef near = light_def(0.2);
  World safe{PhysicsDef{}};
  const FightOrFlightTask disc = run(fight, near, 0, safe);
  EXPECT_FALSE(disc.destroyed());
  World deadly{PhysicsDef{}};
  int steps = 0;
  const FightOrFlightTask stack = run(fight, near, 1, deadly, &steps);
  EXPECT_TRUE(stack.destroyed());
  EXPECT_EQ(stack.fitness(), 0);
  EXPECT_TRUE(stack.done());
  // it ended at the touch, long before its 1 s was up
  EXPECT_LT(steps * deadly.def().dt, 0.5);
  const TaskScore s = stack.score(CreatureModel{});
  EXPECT_EQ(s.fitness, 0);
  bool said = false;
  for (const Metric& m : s.metrics) said |= m.name == "destroyed" && m.value == 1;
  EXPECT_TRUE(said);
  // 3 m off, the stack touches nothing and the creature stays whole
  World far{PhysicsDef{}};
  EXPECT_FALSE(run(fight, light_def(), 1, far).destroyed());
}

TEST(Fight, TheConfigPairsTheTrialsAndFoldsThemItsWay) {
  const std::string base = "[genome]\ndialect = \"lessin2015\"\n[task]\nkind = \"fight_or_flight\"\n";
  EXPECT_EQ(read_run_config(base + "trials = 4\n", "run.toml").error(),
            "run.toml: task.trials: the fight_or_flight task runs two trials (the vulnerable target, then the "
            "dangerous one) for each of fight.headings' n = 4 headings, so task.trials must be a whole multiple of 8, "
            "got 4");
  auto cfg = read_run_config(base + "trials = 4\n[fight]\nheadings = [30, -30]\nstack_discs = 2\nspin = 1\n", "run.toml");
  ASSERT_TRUE(cfg.ok()) << cfg.error();
  EXPECT_EQ(cfg->sim.task_kind, TaskKind::Fight);
  EXPECT_EQ(cfg->sim.fight.headings, (std::vector<double>{30, -30}));
  EXPECT_EQ(cfg->sim.fight.stack_discs, 2);
  EXPECT_EQ(cfg->sim.fight.spin, 1);
  const double trials[] = {0.8, 0.2, 0.4, 0.6};
  EXPECT_EQ(fold_trials(cfg->sim, trials), fight_fold(trials));
  EXPECT_EQ(trial_fold_name(cfg->sim).rfind("fight-or-flight fold", 0), 0u);
  auto again = read_run_config(config_to_toml(*cfg), "again.toml");
  ASSERT_TRUE(again.ok()) << again.error();
  EXPECT_EQ(again->sim, cfg->sim);
}

}  // namespace
}  // namespace bx
