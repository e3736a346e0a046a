// lessin2015's ATTACK (skill 7) as the light task's attack goal: the first
// strike (an impact reaching strike.threshold) ends the trial and scores how
// much of the way to the light the creature had come; a dark trial scores
// whether it held back; attack_fold() folds them, and evaluate() folds an
// attack's trials by it, not by their mean.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "develop/develop.h"
#include "eval/evaluate.h"
#include "eval/task_table.h"
#include "io/config.h"
#include "support/creatures.h"
#include "physics/world.h"
#include "task/light.h"

namespace bx {
namespace {

// a one-part creature standing level at `com`, facing +x
struct Creature : Observation {
  double t = 0;
  Vec3 com{0, 0, 0.5};
  double time() const override { return t; }
  Vec3 centre_of_mass() const override { return com; }
  int n_parts() const override { return 1; }
  Pose part_pose(int) const override { return {com, Mat3::identity()}; }
  bool touches_part(int) const override { return false; }
};

constexpr double dt = 0.125;  // every time exact in binary

// the light dead ahead at 3 m; 4 s measured after two still steps; one dark trial after it
LightDef attack_def() {
  LightDef def;
  def.goal = LightGoal::Attack;
  def.headings = {0};
  def.dark_trials = 1;
  def.seconds = 4;
  def.settle = {0.1, 2 * dt, 5};
  return def;
}

// an impact is the rise of the vertical velocity over the window (one step
// each half at this dt): falling at 2 m/s for one step, then resting, is
// an impact of 2 m/s, over the 0.5 m/s threshold
StrikeDef strike() {
  StrikeDef s;
  s.window = 2 * dt;
  s.threshold = 0.5;
  return s;
}

// runs trial `trial`: the centre of mass walks towards +x at `speed` (m/s)
// and, when `strike_at` >= 0 s into the measured span, drops 2 m/s x dt
// in one step and stays down; returns the task, its steps counted
LightTask run(int trial, double speed, double strike_at, World& w, int* measured_steps = nullptr) {
  LightTask task(attack_def(), strike(), dt, 1, trial);
  Creature o;
  task.begin(o);
  while (task.phase() != Phase::Measure) {
    task.act(CreatureModel{}, {}, w, o);
    o.t += dt;
    task.observe(o);
  }
  const double t0 = o.t;
  int n = 0;
  while (!task.done()) {
    task.act(CreatureModel{}, {}, w, o);
    o.t += dt;
    const double s = o.t - t0;
    o.com.x = speed * s;
    if (strike_at >= 0 && s > strike_at && s <= strike_at + dt + 1e-9) o.com.z -= 2 * dt;
    task.observe(o);
    ++n;
  }
  if (measured_steps) *measured_steps = n;
  return task;
}

TEST(Attack, TheFirstStrikeEndsTheTrialAndScoresTheShareOfTheWayCome) {
  World w{PhysicsDef{}};
  int steps = 0;
  // 1 m/s towards the light 3 m off, the drop in the step ending at 2.125 s,
  // the impact seen once the window holds the rest after it, at 2.25 s:
  // 0.75 m to go of 3, so 1 - 0.75 / 3
  const LightTask hit = run(0, 1, 2, w, &steps);
  ASSERT_FALSE(w.lights().empty());  // the light came on
  EXPECT_TRUE(hit.struck());
  EXPECT_NEAR(hit.strike_distance(), 0.75, 1e-12);
  EXPECT_NEAR(hit.fitness(), 1 - 0.75 / 3, 1e-12);
  EXPECT_EQ(steps, 18);  // it ended at the strike, not after the 32 steps of 4 s
  const TaskScore sc = hit.score(CreatureModel{});
  const auto metric = [&](const char* name) {
    for (const Metric& m : sc.metrics)
      if (m.name == name) return m.value;
    return -99.0;
  };
  EXPECT_NEAR(metric("strike_time"), 2.25, 1e-12);
  EXPECT_NEAR(metric("strike_distance"), 0.75, 1e-12);
  // walking without a strike scores nothing, however near it came
  World w2{PhysicsDef{}};
  const LightTask walk = run(0, 1, -1, w2, &steps);
  EXPECT_FALSE(walk.struck());
  EXPECT_EQ(walk.fitness(), 0);
  EXPECT_EQ(steps, 32);
  // a strike where it stands scores nothing either
  World w3{PhysicsDef{}};
  EXPECT_NEAR(run(0, 0, 1, w3).fitness(), 0, 1e-12);
}

TEST(Attack, ADarkTrialHasNoLightAndScoresWhetherItHeldBack) {
  World w{PhysicsDef{}};
  const LightTask calm = run(1, 0, -1, w);
  EXPECT_TRUE(calm.dark());
  EXPECT_TRUE(w.lights().empty());
  EXPECT_FALSE(calm.light());
  EXPECT_EQ(calm.fitness(), 1);
  SceneRecord scene;
  Creature o;
  LightTask again = run(1, 0, -1, w);
  again.record(o, scene);
  EXPECT_TRUE(scene.points.empty());  // no light to show
  World w2{PhysicsDef{}};
  const LightTask struck = run(1, 0, 1, w2);
  EXPECT_TRUE(struck.struck());
  EXPECT_EQ(struck.fitness(), 0);
  // trial 2 is lit again (the cycle: one heading, one dark)
  World w3{PhysicsDef{}};
  EXPECT_FALSE(run(2, 0, -1, w3).dark());
}

TEST(Attack, TheFoldIsTheLitMeanTimesTheDarkTrialsPenalty) {
  LightDef def = attack_def();
  def.headings = {0, 90};
  def.wrong_factor = 0.5;
  const double calm[] = {0.4, 0.8, 1};
  EXPECT_NEAR(attack_fold(def, calm), 0.6, 1e-12);
  const double struck[] = {0.4, 0.8, 0};
  EXPECT_NEAR(attack_fold(def, struck), 0.3, 1e-12);
  // two cycles: one dark trial of two struck in
  const double twice[] = {0.4, 0.8, 1, 0.2, 0.6, 0};
  EXPECT_NEAR(attack_fold(def, twice), 0.5 * 0.75, 1e-12);
  def.dark_trials = 0;
  const double lit[] = {0.4, 0.8};
  EXPECT_NEAR(attack_fold(def, lit), 0.6, 1e-12);
}

SimConfig attack_config(const std::vector<std::string>& sets) {
  std::vector<std::string> all = {"task.kind=light", "light.goal=attack", "light.seconds=3"};
  all.insert(all.end(), sets.begin(), sets.end());
  auto cfg = read_run_config("[genome]\ndialect = \"lessin2015\"\n", "run.toml", all);
  EXPECT_TRUE(cfg.ok()) << cfg.error();
  return cfg.ok() ? cfg->sim : SimConfig{};
}

TEST(Attack, TheConfigCountsTheDarkTrialsAndOnlyAttackHasThem) {
  const std::string base = "[genome]\ndialect = \"lessin2015\"\n[task]\nkind = \"light\"\ntrials = 4\n[light]\n";
  EXPECT_EQ(read_run_config(base + "goal = \"attack\"\ndark_trials = 1\n", "run.toml").error(),
            "run.toml: task.trials: the light task runs trial k with the (k mod n)-th of light.headings' n = 4 "
            "headings (then light.dark_trials = 1 dark ones), so task.trials must be a whole multiple of 5, got 4");
  EXPECT_EQ(read_run_config(base + "goal = \"face\"\ndark_trials = 1\n", "run.toml").error(),
            "run.toml: light.dark_trials: only the attack goal has dark trials, got 1");
  auto ok = read_run_config(base + "goal = \"attack\"\ndark_trials = 1\nheadings = [0, 90, 180]\n", "run.toml");
  ASSERT_TRUE(ok.ok()) << ok.error();
  EXPECT_EQ(ok->sim.light.goal, LightGoal::Attack);
  EXPECT_EQ(ok->sim.light.dark_trials, 1);
  EXPECT_EQ(trial_fold_name(ok->sim).rfind("attack fold", 0), 0u);
  EXPECT_EQ(trial_fold_name(attack_config({"light.goal=face", "task.trials=4"})),
            "mean (the light task averages its headings)");
  // the other goals average their headings, even with task.trial_score =
  // min (which folds the elite's repeated evaluations, not the headings)
  const SimConfig face = attack_config({"light.goal=face", "task.trials=4", "task.trial_score=min"});
  const double headings[] = {0.2, 0.8, 0.4, 0.6};
  EXPECT_NEAR(fold_trials(face, headings), 0.5, 1e-12);
}

// end to end: lessin_eyes has no muscles, so it never strikes: each lit
// trial scores 0 and the dark one 1, which the attack's fold makes 0 (their
// mean would be 0.2)
TEST(Attack, EvaluateFoldsAnAttacksTrialsByTheAttackFold) {
  const SimConfig c = attack_config({"task.trials=5", "light.dark_trials=1"});
  Development d = develop(bxtest::load_creature("lessin_eyes.json"), c.develop);
  ASSERT_TRUE(d.viable()) << d.reason;
  const EvalResult r = evaluate(*d.model, c, 1);
  ASSERT_FALSE(r.failed) << r.failure;
  ASSERT_EQ(r.trial_fitness.size(), 5u);
  EXPECT_EQ(r.trial_fitness, (std::vector<double>{0, 0, 0, 0, 1}));
  EXPECT_EQ(r.fitness, 0);
  EXPECT_EQ(r.fitness, attack_fold(c.light, r.trial_fitness));
}

}  // namespace
}  // namespace bx
