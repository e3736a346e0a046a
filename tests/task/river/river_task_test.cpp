// The river crossing joined to a body: the grid is laid under the torso, the
// agent's cell follows the torso's centre, the task inputs are in
// RiverInputs' order, the action output goes to the rules, and a resource
// reached lays the next level's start under the walker. The body here is a
// scripted pose (an Observation written in the test).
#include "task/river/river_task.h"

#include <gtest/gtest.h>

#include <cmath>
#include <variant>
#include <vector>

#include "develop/creature_model.h"
#include "physics/world.h"

namespace bx {
namespace {

// a torso whose pose the test sets
struct Torso : Observation {
  Pose pose;
  double t = 0;
  double time() const override { return t; }
  Vec3 centre_of_mass() const override { return pose.p; }
  int n_parts() const override { return 1; }
  Pose part_pose(int) const override { return pose; }
  bool touches_part(int) const override { return false; }
};

// sensors at the centres of a 1 x 1 torso's sides: +x, +y, -x, -y
const std::array<Vec3, 4> kSensors = {Vec3{0.5, 0, 0}, Vec3{0, 0.5, 0}, Vec3{-0.5, 0, 0}, Vec3{0, -0.5, 0}};

RiverTaskDef def(double cell = 1, int first_level = 1) {
  RiverTaskDef d;
  d.cell = cell;
  d.first_level = first_level;
  return d;
}

// the controller's action on the task (the world and body are not the task's concern)
void act(RiverTask& task, const Torso& torso, double action) {
  static World world{PhysicsDef{}};
  const double out[1] = {action};
  task.act(CreatureModel{}, out, world, torso);
}

// moves the torso to the middle of cell c and lets the task observe it
void walk_to(RiverTask& task, Torso& torso, CellIndex c, double cell = 1) {
  const GridPoint now = task.to_grid(torso.pose.p);
  torso.pose.p.x += (c.x + 0.5 - now.x) * cell;
  torso.pose.p.y += (c.y + 0.5 - now.y) * cell;
  task.observe(torso);
}

TEST(RiverTask, LaysTheGridWithTheStartCellUnderTheTorso) {
  for (double cell : {1.0, 0.25}) {
    RiverTask task(def(cell), 0.01, 3, 0, kSensors);
    Torso torso;
    torso.pose.p = {0.3, -0.2, 0.4};
    task.begin(torso);
    const CellIndex s = task.world().agent();
    const GridPoint g = task.to_grid(torso.pose.p);
    EXPECT_NEAR(g.x, s.x + 0.5, 1e-12);
    EXPECT_NEAR(g.y, s.y + 0.5, 1e-12);
    EXPECT_EQ(s.x, 0);
    EXPECT_EQ(task.max_steps(), 60000);  // 10 minutes at 0.01 s
  }
}

TEST(RiverTask, GivesTheGridTheCellCarryingAndTheSensorsTurnedWithTheTorso) {
  RiverTask task(def(), 0.01, 3, 0, kSensors);
  Torso torso;
  torso.pose.R = Mat3::rotation({0, 0, 1}, kPi / 2);  // facing +y
  task.begin(torso);
  std::vector<double> in(static_cast<std::size_t>(task.n_inputs()));
  ASSERT_EQ(task.n_inputs(), 410);
  task.inputs(torso, in);
  const Grid& grid = task.world().grid();
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x)
      ASSERT_EQ(in[static_cast<std::size_t>(y * 20 + x)], river_cell_code(grid.at({x, y})));
  EXPECT_EQ(in[400], river_cell::kGrass);  // the start cell
  EXPECT_EQ(in[401], 0);                   // carrying nothing
  // sensor 0 (+x of the torso) now points along +y: half a cell up from the middle
  const CellIndex s = task.world().agent();
  EXPECT_NEAR(in[402], s.x + 0.5, 1e-12);
  EXPECT_NEAR(in[403], s.y + 1.0, 1e-12);
  EXPECT_NEAR(in[404], s.x + 0.0, 1e-12);  // sensor 1 (+y) along -x
  EXPECT_NEAR(in[405], s.y + 0.5, 1e-12);
}

TEST(RiverTask, FoodAndTheResourceScoreAndTheNextLevelStartsUnderTheWalker) {
  RiverTask task(def(), 0.01, 5, 0, kSensors);
  Torso torso;
  task.begin(torso);
  ASSERT_EQ(task.world().level(), 1);
  const Layout& level1 = task.world().layout();
  // walk to the resource along the start row, then its column, over whatever lies there (level 1
  // has only food: nothing kills)
  const CellIndex start = level1.start, goal = level1.resource;
  int food = 0;
  for (int x = start.x + 1; x <= goal.x; ++x) {
    food += task.world().grid().at({x, start.y}) == Cell::Food;
    walk_to(task, torso, {x, start.y});
    act(task, torso, 0);
  }
  const int dy = goal.y > start.y ? 1 : -1;
  for (int y = start.y + dy; y != goal.y + dy; y += dy) {
    if (task.world().level() != 1) break;
    food += task.world().grid().at({goal.x, y}) == Cell::Food;
    walk_to(task, torso, {goal.x, y});
  }
  EXPECT_EQ(task.world().level(), 2);
  EXPECT_TRUE(task.world().alive());
  const TaskScore score = task.score(CreatureModel{});
  EXPECT_EQ(score.fitness, 100 + food);
  // the walker, not moved, stands over the middle of level 2's start cell
  const GridPoint g = task.to_grid(torso.pose.p);
  EXPECT_NEAR(g.x, task.world().layout().start.x + 0.5, 1e-12);
  EXPECT_NEAR(g.y, task.world().layout().start.y + 0.5, 1e-12);
  EXPECT_EQ(score.metrics[0].name, "level");
  EXPECT_EQ(score.metrics[0].value, 2);
  EXPECT_EQ(score.metrics[1].value, 1);  // levels completed
  EXPECT_EQ(score.metrics[2].value, food);
  EXPECT_EQ(score.metrics[5].name, "level 1 completed");
  EXPECT_EQ(score.metrics[5].value, 1);
  // its distance: the torso's travel in the plane, start to end, whatever the levels' grids
  EXPECT_DOUBLE_EQ(score.distance, std::hypot(goal.x - start.x, goal.y - start.y));
}

TEST(RiverTask, TheApproachCreditIsTheShareOfTheWayToTheResourceAtItsClosest) {
  for (double cell : {1.0, 0.1}) {
    RiverTaskDef d = def(cell, 2);  // the dash: nothing on the way
    d.approach = 10;
    RiverTask task(d, 0.01, 5, 0, kSensors);
    Torso torso;
    task.begin(torso);
    const CellIndex start = task.world().layout().start, goal = task.world().layout().resource;
    const double d0 = std::hypot(goal.x - start.x, goal.y - start.y);
    EXPECT_EQ(task.score(CreatureModel{}).fitness, 0);  // not moved: nothing
    // along the start row to the resource's column, then back to the start: the closest counts
    for (int x = start.x + 1; x <= goal.x; ++x) walk_to(task, torso, {x, start.y}, cell);
    const double closest = std::abs(goal.y - start.y);
    for (int x = goal.x - 1; x >= start.x; --x) walk_to(task, torso, {x, start.y}, cell);
    TaskScore s = task.score(CreatureModel{});
    EXPECT_NEAR(s.fitness, 10 * (1 - closest / d0), 1e-9) << cell;
    EXPECT_EQ(s.metrics.back().name, "approach");
    EXPECT_NEAR(s.metrics.back().value, 1 - closest / d0, 1e-9);
    // the resource reached: 100 and the whole credit of level 2; level 3 begins at its start, d_0 again
    for (int x = start.x + 1; x <= goal.x; ++x) walk_to(task, torso, {x, start.y}, cell);
    const int dy = goal.y > start.y ? 1 : -1;
    for (int y = start.y + dy; y != goal.y + dy && task.world().level() == 2; y += dy) walk_to(task, torso, {goal.x, y}, cell);
    ASSERT_EQ(task.world().level(), 3);
    s = task.score(CreatureModel{});
    EXPECT_NEAR(s.fitness, 100 + 10, 1e-9);
    EXPECT_NEAR(s.metrics.back().value, 1, 1e-9);
  }
  // 0, the paper's: the score is the rules' alone
  RiverTask paper(def(1, 2), 0.01, 5, 0, kSensors);
  Torso torso;
  paper.begin(torso);
  walk_to(paper, torso, {5, paper.world().layout().start.y});
  EXPECT_EQ(paper.score(CreatureModel{}).fitness, 0);
  EXPECT_GT(paper.score(CreatureModel{}).metrics.back().value, 0);
}

TEST(RiverTask, WaterKillsAtTheNextActionAndEndsTheTask) {
  RiverTask task(def(1, 4), 0.01, 9, 0, kSensors);  // level 4: a river at column 14
  Torso torso;
  task.begin(torso);
  const CellIndex start = task.world().agent();
  // jump to the bank, then into the river; the put-down output is 0
  walk_to(task, torso, {13, start.y});
  if (task.world().grid().at({13, start.y}) == Cell::Trap) GTEST_SKIP() << "a trap on the bank";
  act(task, torso, 0);
  ASSERT_TRUE(task.world().alive());
  walk_to(task, torso, {14, start.y});
  EXPECT_FALSE(task.done());
  act(task, torso, 0);
  EXPECT_TRUE(task.done());
  const TaskScore score = task.score(CreatureModel{});
  EXPECT_EQ(score.metrics[3].name, "died");
  EXPECT_EQ(score.metrics[3].value, 1);
  EXPECT_EQ(score.metrics[4].value, river_cell::kWater);
}

// the replay's scene: the grid laid where the task placed it (under the
// torso), again on the next level where the walker stands, and the carried
// stone on the torso part
TEST(RiverTask, ItsSceneLaysEachGridWhereTheTaskPlacedIt) {
  RiverTask task(def(0.1, 1), 0.01, 5, 0, kSensors);
  Torso torso;
  torso.pose.p = {0.3, -0.2, 0.05};
  task.begin(torso);
  SceneRecord r;
  task.record(torso, r);
  ASSERT_FALSE(r.events.empty());
  const SceneGrid first = std::get<SceneGrid>(r.events[0].what);  // a copy: events grow
  EXPECT_EQ(first.cell, 0.1);
  // the grid's corner is where to_grid reads 0
  const GridPoint corner = task.to_grid(first.origin);
  EXPECT_NEAR(corner.x, 0, 1e-12);
  EXPECT_NEAR(corner.y, 0, 1e-12);
  EXPECT_EQ(first.origin.z, 0);
  // level 1 to its resource, then the next level's grid under the walker
  const Layout& level1 = task.world().layout();
  const CellIndex start = level1.start, goal = level1.resource;
  for (int x = start.x + 1; x <= goal.x; ++x) walk_to(task, torso, {x, start.y}, 0.1);
  const int dy = goal.y > start.y ? 1 : -1;
  for (int y = start.y + dy; task.world().level() == 1; y += dy) walk_to(task, torso, {goal.x, y}, 0.1);
  torso.t = 4;
  task.record(torso, r);
  const SceneGrid* second = nullptr;
  for (const SceneEvent& e : r.events)
    if (e.t == 4 && std::holds_alternative<SceneGrid>(e.what)) second = &std::get<SceneGrid>(e.what);
  ASSERT_NE(second, nullptr);
  const GridPoint g = task.to_grid(second->origin);
  EXPECT_NEAR(g.x, 0, 1e-12);
  EXPECT_NEAR(g.y, 0, 1e-12);
  EXPECT_NE(second->origin, first.origin);
  EXPECT_EQ(r.events.back(), (SceneEvent{4, SceneCounter{"score", task.score(CreatureModel{}).fitness, {}}}));
}

}  // namespace
}  // namespace bx
