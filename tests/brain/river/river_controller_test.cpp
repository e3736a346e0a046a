// The river crossing's controller as the loop sees it: the task inputs in
// their documented order reach the brain, effectors are 2 m - 1 of its motor
// neurons and task output 0 is the decision network's action.
#include "brain/river/river_controller.h"

#include <gtest/gtest.h>

#include <variant>
#include <vector>

#include "brain/river/found_motif.h"
#include "core/rng.h"

namespace bx {
namespace {

// Genes whose DN, on a stone, asks to put down (action -1) and sets the
// resource's iota to 1; every other weight random.
RiverBrainModel stone_model() {
  Rng rng(7);
  std::vector<double> g(181);
  for (double& x : g) x = rng.uniform(-2, 2);
  std::fill(g.begin(), g.begin() + 44, 0.0);
  g[0 * 6 + river_cell::kStone] = 2;          // stone -> hidden 0
  g[24 + river_cell::kResource * 4 + 0] = 3;  // hidden 0 -> resource's iota
  g[24 + 0 * 4 + 0] = -3;                     // hidden 0 -> action
  auto m = make_river_brain_model(RiverBrainDef{}, found_motif(), g);
  EXPECT_TRUE(m.ok()) << m.error();
  return *m;
}

TEST(RiverController, TakesTheGridTheCellCarryingAndFourSensorPoints) {
  RiverController c(stone_model());
  EXPECT_EQ(c.n_sensors(), 0);
  EXPECT_EQ(c.n_effectors(), 12);
  EXPECT_EQ(c.n_task_inputs(), 400 + 1 + 1 + 8);
  EXPECT_EQ(c.n_task_outputs(), 1);
  const RiverInputs& in = c.inputs();
  EXPECT_EQ(in.here(), 400);
  EXPECT_EQ(in.carrying(), 401);
  EXPECT_EQ(in.sensors(), 402);
}

TEST(RiverController, DrivesItsBrainWithTheInputsInTheirOrder) {
  const RiverBrainModel m = stone_model();
  RiverController c(m);
  auto s = c.make_state();
  // before the first step: signals and action 0
  for (double e : s->effectors()) EXPECT_EQ(e, 0);
  EXPECT_EQ(s->task_outputs()[0], 0);

  // a resource at (5, 7), the agent on a stone, carrying, sensors around (4.5, 6.5)
  std::vector<double> in(static_cast<std::size_t>(c.n_task_inputs()), river_cell::kGrass);
  std::vector<int> grid(400, river_cell::kGrass);
  grid[7 * 20 + 5] = river_cell::kResource;
  in[7 * 20 + 5] = river_cell::kResource;
  in[400] = river_cell::kStone;
  in[401] = 1;
  const GridPoint points[4] = {{5.0, 6.5}, {4.5, 7.0}, {4.0, 6.5}, {4.5, 6.0}};
  for (int k = 0; k < 4; ++k) {
    in[static_cast<std::size_t>(402 + 2 * k)] = points[k].x;
    in[static_cast<std::size_t>(403 + 2 * k)] = points[k].y;
  }
  // the same brain driven by hand
  RiverBrain hand(m);
  for (int step = 0; step < 3; ++step) {
    s->step({}, in, 0.01);
    hand.set_grid(grid);
    hand.decide(river_cell::kStone, true);
    hand.step(points, 0.01);
    for (int j = 0; j < 12; ++j) ASSERT_DOUBLE_EQ(s->effectors()[j], 2 * hand.motors()[j] - 1) << j;
  }
  EXPECT_EQ(s->task_outputs()[0], -1);  // put down, as the genes say on a stone
  EXPECT_EQ(hand.decision().iota[river_cell::kResource], 1);
  // the landscape saw the resource: the sensor nearest it reads the most
  EXPECT_GT(hand.pn().inputs()[0], 0);
}

// for a replay, the landscape is recorded as a field over the grid each
// time its values change, and only then
TEST(RiverController, RecordsItsLandscapeOnlyWhenItChanges) {
  const RiverBrainModel m = stone_model();
  RiverController c(m);
  auto s = c.make_state();
  SceneRecord r;
  // before the first step: the all-zero landscape, once
  s->record(0, r);
  s->record(0.01, r);
  ASSERT_EQ(r.events.size(), 1u);
  const SceneField zero = std::get<SceneField>(r.events[0].what);  // a copy: events grow
  EXPECT_EQ(zero.name, "landscape");
  EXPECT_EQ(zero.width, 20);
  EXPECT_EQ(zero.height, 20);
  EXPECT_EQ(zero.lo, -15);
  EXPECT_EQ(zero.hi, 15);
  EXPECT_EQ(zero.values, std::vector<double>(400, 0.0));
  // on a stone the resource's iota turns 1: a new landscape
  std::vector<double> in(static_cast<std::size_t>(c.n_task_inputs()), river_cell::kGrass);
  in[7 * 20 + 5] = river_cell::kResource;
  in[400] = river_cell::kStone;
  for (int k = 0; k < 4; ++k) in[static_cast<std::size_t>(402 + 2 * k)] = in[static_cast<std::size_t>(403 + 2 * k)] = 5;
  s->step({}, in, 0.01);
  s->record(0.02, r);
  ASSERT_EQ(r.events.size(), 2u);
  EXPECT_EQ(r.events[1].t, 0.02);
  const SceneField& source = std::get<SceneField>(r.events[1].what);
  EXPECT_EQ(source.values[7 * 20 + 5], 15);  // the source, at maxI
  // the same inputs again: the same landscape, nothing recorded
  for (int k = 0; k < 5; ++k) {
    s->step({}, in, 0.01);
    s->record(0.03 + 0.01 * k, r);
  }
  EXPECT_EQ(r.events.size(), 2u);
  // the resource gone: a flat landscape again
  in[7 * 20 + 5] = river_cell::kGrass;
  s->step({}, in, 0.01);
  s->record(0.1, r);
  ASSERT_EQ(r.events.size(), 3u);
  EXPECT_EQ(std::get<SceneField>(r.events[2].what).values, zero.values);
}

}  // namespace
}  // namespace bx
