// The river crossing through the generic channels: a float vector develops,
// by its creature kind's row, into the quadruped and its hybrid controller;
// the task table makes the river task per trial; evaluation runs them on
// real physics and reports the task's named metrics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <variant>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "core/rng.h"
#include "eval/creature.h"
#include "eval/evaluate.h"
#include "eval/evaluator.h"
#include "eval/task_table.h"
#include "genome/float_vector.h"
#include "io/config.h"
#include "task/river/grid.h"
#include <nlohmann/json.hpp>

namespace bx {
namespace {

SimConfig river_config(double seconds) {
  SimConfig cfg;
  apply_creature_kind(cfg, CreatureKind::River);  // the kind's physics, PD motors, task and brain rate
  cfg.river.task.seconds = seconds;
  return cfg;
}

FloatVector random_genes(const SimConfig& cfg, std::uint64_t seed) {
  const FloatVectorDef def = creature_kind_row(cfg.creature).float_genes(cfg);
  Rng rng(seed);
  std::vector<double> g(static_cast<std::size_t>(def.length));
  for (double& x : g) x = rng.uniform(def.lo, def.hi);
  return FloatVector(g);
}

TEST(RiverEval, AConfigPicksTheQuadrupedAndTheRiverTask) {
  auto cfg = read_run_config("[genotype]\nkind = \"river\"\n[task]\nkind = \"river\"\n[river]\nseconds = 30\n"
                             "[motor]\nmodel = \"pd\"\n[physics]\npowered_stops = \"separate\"\n"
                             "[motif]\ntau = [1, 0.5, 0.25]\n",
                             "run.toml");
  ASSERT_TRUE(cfg.ok()) << cfg.error();
  EXPECT_EQ(cfg->sim.creature, CreatureKind::River);
  EXPECT_EQ(cfg->sim.task_kind, TaskKind::River);
  EXPECT_EQ(cfg->sim.river.task.seconds, 30);
  EXPECT_EQ(cfg->sim.motif.tau[1], 0.5);
  // and writes them back as it read them
  const std::string text = config_to_toml(*cfg);
  EXPECT_NE(text.find("[motif]\nw0 = "), std::string::npos) << text;
  auto again = read_run_config(text, "config.toml");
  ASSERT_TRUE(again.ok()) << again.error();
  EXPECT_EQ(again->sim, cfg->sim);
  // a PD motor needs its own motor row
  auto ode_stops = read_run_config("[motor]\nmodel = \"pd\"\n[physics]\npowered_stops = \"ode\"\n", "run.toml");
  ASSERT_FALSE(ode_stops.ok());
  EXPECT_EQ(ode_stops.error(), "run.toml: motor.model: \"pd\" needs physics.powered_stops = \"separate\", got \"ode\"");
  // a motif's time constant is checked like any key
  auto bad = read_run_config("[motif]\ntau = [1, 0, 1]\n", "run.toml");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error(), "run.toml: motif.tau: each out of range [1e-06, 1000000], got [1, 0, 1]");
}

TEST(RiverEval, AFloatVectorDevelopsIntoTheQuadrupedAndItsController) {
  const SimConfig cfg = river_config(5);
  const FloatVectorDef genes = creature_kind_row(cfg.creature).float_genes(cfg);
  EXPECT_EQ(genes.length, 181);  // the paper's shape (docs/rivercrossing.md)
  auto c = develop_creature(random_genes(cfg, 1), cfg);
  ASSERT_TRUE(c.ok()) << c.error();
  EXPECT_EQ(c->body->n_parts(), 9);
  EXPECT_EQ(c->controller->n_effectors(), 12);
  EXPECT_EQ(c->controller->n_task_outputs(), 1);
  // a vector of another length is not viable, and says both counts
  auto short_one = develop_creature(FloatVector(std::vector<double>(180, 0.0)), cfg);
  ASSERT_FALSE(short_one.ok());
  EXPECT_NE(short_one.error().find("180"), std::string::npos) << short_one.error();
  EXPECT_NE(short_one.error().find("181"), std::string::npos) << short_one.error();
}

TEST(RiverEval, TheRiverTaskNeedsTheQuadruped) {
  SimConfig cfg;
  cfg.task_kind = TaskKind::River;
  auto t = make_task(CreatureModel{}, cfg, 1, 0);
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error(), "the river crossing's task needs its quadruped: genotype.kind = \"river\"");
}

TEST(RiverEval, ARandomControllerWalksTheGridOnRealPhysicsAndReportsItsMetrics) {
  const SimConfig cfg = river_config(10);
  const FloatVector g = random_genes(cfg, 3);
  const EvalOutcome out = evaluate_genotype(g, cfg, 42);
  ASSERT_TRUE(out.viable) << out.reason;
  const EvalResult& r = out.result;
  EXPECT_FALSE(r.failed) << r.failure;
  EXPECT_GE(r.fitness, 0);
  ASSERT_GE(r.metrics.size(), 5u);
  EXPECT_EQ(r.metrics[0].name, "level");
  EXPECT_GE(r.metrics[0].value, 1);
  // the controller drives the joints: its signals move
  double moving = 0;
  for (double sd : r.diagnostics.effector_sd) moving = std::max(moving, sd);
  EXPECT_GT(moving, 0.01);
  // the same genes and seed give the same evaluation, in a worker too
  std::vector<EvalJob> jobs = {{&g, 42}};
  ProcessPoolEvaluator pool(cfg, 1, 120);
  const EvalOutcome again = pool.evaluate(jobs)[0];
  EXPECT_EQ(again.result.fitness, r.fitness);
  EXPECT_EQ(again.result.metrics, r.metrics);
  EXPECT_EQ(again.result.steps, r.steps);
}

// The scale of the body decides whether an evolved gait is the solver's or
// the step's (docs/rivercrossing.md, "Unit and density"): under the paper's
// CFM a foot slips at CFM times its friction force, which in cell widths
// goes as 1 / unit^2. creatures/river_walker.json, a 1 Hz walker evolved in
// 0.1 m cells at 0.01 s (rivercrossing-small seed 1's best before the
// default became 1 m), walks a minute over a quarter farther at 0.005 s than
// at 0.01 s in 0.1 m cells of water's density; in the default 1 m cells as
// far at 0.005 s and 0.0025 s as at 0.01 s.
TEST(RiverEval, InTheDefaultCellsAnEvolvedGaitConvergesWithTheStepWhereInTenCentimetreCellsItDidNot) {
  std::ifstream in(std::string(BESTIARY_SOURCE_DIR) + "/creatures/river_walker.json");
  const FloatVector g(nlohmann::json::parse(in)["genes"].get<std::vector<double>>());
  // the torso's travel in cell widths over a minute at dt / div
  auto travel = [&](const QuadrupedDef& body, int div) {
    SimConfig cfg;
    cfg.river.body = body;
    apply_creature_kind(cfg, CreatureKind::River);  // the physics scaled to this body's unit
    cfg.river.task.seconds = 60;
    cfg.physics.dt /= div;
    const EvalOutcome out = evaluate_genotype(g, cfg, 101);
    EXPECT_TRUE(out.viable) << out.reason;
    EXPECT_FALSE(out.result.failed) << out.result.failure;
    return out.result.distance / body.unit;
  };
  const QuadrupedDef small{0.1, 1000};  // the same weight product, 0.1 kg m
  ASSERT_EQ(QuadrupedDef{}.density * std::pow(QuadrupedDef{}.unit, 4), 0.1);
  const double small_dt = travel(small, 1), small_half = travel(small, 2);
  EXPECT_GT(small_half / small_dt, 1.25) << small_dt << " " << small_half;
  const double at_dt = travel(QuadrupedDef{}, 1), half = travel(QuadrupedDef{}, 2), quarter = travel(QuadrupedDef{}, 4);
  EXPECT_NEAR(half / at_dt, 1, 0.1) << at_dt << " " << half;
  EXPECT_NEAR(quarter / at_dt, 1, 0.1) << at_dt << " " << quarter;
}

// A replay's scene: the task lays its grid under the torso at the start with
// the counters, the controller adds its landscape each time it changes and
// only then; recording it changes nothing of the evaluation.
TEST(RiverEval, AReplayRecordsTheGridTheCountersAndTheLandscapeOnlyWhenItChanges) {
  const SimConfig cfg = river_config(10);
  auto c = develop_creature(random_genes(cfg, 3), cfg);
  ASSERT_TRUE(c.ok()) << c.error();
  Replay replay;
  const EvalResult r = evaluate(*c, cfg, 42, &replay);
  ASSERT_FALSE(r.failed) << r.failure;
  const SceneRecord& scene = replay.scene;
  ASSERT_EQ(scene.cell_kinds.size(), 7u);
  ASSERT_FALSE(scene.events.empty());
  // at t = 0: the grid, its start cell under the torso's centre, and the counters
  ASSERT_TRUE(std::holds_alternative<SceneGrid>(scene.events[0].what));
  EXPECT_EQ(scene.events[0].t, 0);
  const SceneGrid& grid = std::get<SceneGrid>(scene.events[0].what);
  EXPECT_EQ(grid.cell, cfg.river.body.unit);
  const double torso_x = replay.frames[0].poses[0], torso_y = replay.frames[0].poses[1];
  const int sx = static_cast<int>(std::floor((torso_x - grid.origin.x) / grid.cell));
  const int sy = static_cast<int>(std::floor((torso_y - grid.origin.y) / grid.cell));
  EXPECT_EQ(sx, 0);  // a level's start is on column 0
  EXPECT_EQ(grid.cells[static_cast<std::size_t>(sy * 20 + sx)], static_cast<int>(Cell::Grass));
  std::set<std::string> counted;
  for (const SceneEvent& e : scene.events)
    if (const auto* n = std::get_if<SceneCounter>(&e.what); n && e.t == 0) counted.insert(n->name);
  EXPECT_EQ(counted, (std::set<std::string>{"level", "score", "deaths"}));
  // the landscape: first at t = 0, then only when it changed, at most once a step
  std::vector<const SceneEvent*> fields;
  for (const SceneEvent& e : scene.events)
    if (std::holds_alternative<SceneField>(e.what)) fields.push_back(&e);
  ASSERT_GE(fields.size(), 2u);  // the controller's first step sets its iotas
  EXPECT_EQ(fields[0]->t, 0);
  for (std::size_t k = 1; k < fields.size(); ++k) {
    EXPECT_NE(std::get<SceneField>(fields[k]->what).values, std::get<SceneField>(fields[k - 1]->what).values) << k;
    EXPECT_GT(fields[k]->t, fields[k - 1]->t) << k;
  }
  EXPECT_LT(fields.size(), static_cast<std::size_t>(r.steps / 10));
  for (std::size_t k = 1; k < scene.events.size(); ++k) EXPECT_GE(scene.events[k].t, scene.events[k - 1].t);
  // recording it changes nothing
  const EvalResult plain = evaluate(*c, cfg, 42);
  EXPECT_EQ(plain.fitness, r.fitness);
  EXPECT_EQ(plain.steps, r.steps);
  EXPECT_EQ(plain.metrics, r.metrics);
}

// Issue 32: the river crossing comes in through the interfaces, so its words
// appear in src/ (comments aside) only in its own folders and the tables';
// its motif, a controller's part evolved alone by a kind of its own, only in
// the brain's river folder and the tables'.
TEST(RiverEval, ItsWordsLiveInItsOwnFoldersAndTheTablesOnly) {
  namespace fs = std::filesystem;
  const fs::path src = fs::path(BESTIARY_SOURCE_DIR) / "src";
  // the folders whose code (comments aside) holds any of `words`
  const auto folders_with = [&](std::initializer_list<const char*> words) {
    std::set<std::string> folders;
    for (const auto& e : fs::recursive_directory_iterator(src)) {
      if (!e.is_regular_file()) continue;
      std::ifstream in(e.path());
      std::string line;
      while (std::getline(in, line)) {
        std::string code = line.substr(0, line.find("//"));  // comments aside
        for (char& c : code) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        for (const char* w : words)
          if (code.find(w) != std::string::npos) folders.insert(fs::relative(e.path().parent_path(), src).string());
      }
    }
    return folders;
  };
  EXPECT_EQ(folders_with({"river", "shunting"}), (std::set<std::string>{"brain/river", "eval", "task/river"}));
  EXPECT_EQ(folders_with({"motif"}), (std::set<std::string>{"brain/river", "eval"}));
}

}  // namespace
}  // namespace bx
