// The whole controller: model errors, when the landscape is recomputed, and
// one step wired landscape -> PN -> PG -> motors, against the parts run by
// hand.
#include "brain/river/river_brain.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/rng.h"

namespace bx {
namespace {

// A motif that oscillates under input is not needed here: any valid one.
Motif some_motif() {
  Motif m;
  m.w = {{{0.5, -1, 0.2}, {1.5, 0.1, -0.7}, {0, 2, -0.3}}};
  m.tau = {0.2, 0.3, 0.5};
  m.alpha = {0.1, -0.4, 0.6};
  m.input = 0;
  m.output = 2;
  return m;
}

std::vector<double> random_genes(int n, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<double> g(static_cast<std::size_t>(n));
  for (double& x : g) x = rng.uniform(-2, 2);
  return g;
}

// Genes whose DN, on a stone, sets the resource's iota to 1 and the action
// to -1, and on any other cell decides nothing; every other weight random.
std::vector<double> stone_genes() {
  std::vector<double> g = random_genes(181, 7);
  std::fill(g.begin(), g.begin() + 44, 0.0);
  g[0 * 6 + river_cell::kStone] = 2;              // stone -> hidden 0
  g[24 + river_cell::kResource * 4 + 0] = 3;      // hidden 0 -> resource's iota
  g[24 + 0 * 4 + 0] = -3;                         // hidden 0 -> action
  return g;
}

RiverBrainModel model(std::vector<double> genes) {
  Result<RiverBrainModel> m = make_river_brain_model(RiverBrainDef{}, some_motif(), genes);
  EXPECT_TRUE(m.ok()) << m.error();
  return *m;
}

// A 20x20 grass grid with a resource at (i, j).
std::vector<int> resource_at(int i, int j) {
  std::vector<int> g(400, river_cell::kGrass);
  g[static_cast<std::size_t>(j * 20 + i)] = river_cell::kResource;
  return g;
}

TEST(RiverBrain, ModelErrorsNameTheirCause) {
  const std::vector<double> genes = random_genes(181, 1);
  Result<RiverBrainModel> r = make_river_brain_model(RiverBrainDef{}, some_motif(), random_genes(100, 1));
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("100 genes given, 181 expected"), std::string::npos) << r.error();

  Motif bad = some_motif();
  bad.tau[2] = -1;
  r = make_river_brain_model(RiverBrainDef{}, bad, genes);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("tau[2] is -1"), std::string::npos) << r.error();

  RiverBrainDef def;
  def.landscape.width = 0;
  r = make_river_brain_model(def, some_motif(), genes);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("width is 0"), std::string::npos) << r.error();

  def = RiverBrainDef{};
  def.landscape.iota_scale = 0;
  r = make_river_brain_model(def, some_motif(), genes);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("iota_scale is 0"), std::string::npos) << r.error();

  EXPECT_TRUE(make_river_brain_model(RiverBrainDef{}, some_motif(), genes).ok());
}

TEST(RiverBrain, StartsFlatAndAtRest) {
  const RiverBrainModel m = model(random_genes(181, 2));
  RiverBrain b(m);
  EXPECT_EQ(b.action(), 0);
  EXPECT_EQ(b.decision(), Decision{});
  for (double x : b.landscape().values()) EXPECT_EQ(x, 0);
  PatternGenerator rest(m.motif, m.weights.pg_input, m.weights.pg_motor);
  ASSERT_EQ(b.motors().size(), 12u);
  EXPECT_EQ(std::vector<double>(b.motors().begin(), b.motors().end()),
            std::vector<double>(rest.motors().begin(), rest.motors().end()));
}

TEST(RiverBrain, LandscapeFollowsTheLastGridAndDecision) {
  RiverBrain b(model(stone_genes()));

  // a grid while every iota is 0: recomputed, still flat
  EXPECT_TRUE(b.set_grid(resource_at(15, 10)));
  for (double x : b.landscape().values()) EXPECT_EQ(x, 0);
  EXPECT_FALSE(b.set_grid(resource_at(15, 10)));

  // on a stone the resource turns salient: the landscape peaks there at maxI
  EXPECT_TRUE(b.decide(river_cell::kStone, false));
  EXPECT_EQ(b.action(), -1);
  EXPECT_EQ(b.decision().iota[river_cell::kResource], 1);
  EXPECT_EQ(b.landscape().at(15, 10), 15);
  EXPECT_GT(b.landscape().at(14, 10), 0);
  // the same decision again changes nothing
  EXPECT_FALSE(b.decide(river_cell::kStone, true));

  // the resource moves: the peak moves with it
  EXPECT_TRUE(b.set_grid(resource_at(3, 4)));
  EXPECT_EQ(b.landscape().at(3, 4), 15);
  EXPECT_LT(b.landscape().at(15, 10), 15);

  // off the stone the iotas return to 0, and so does the landscape
  EXPECT_TRUE(b.decide(river_cell::kGrass, false));
  EXPECT_EQ(b.action(), 0);
  for (double x : b.landscape().values()) EXPECT_EQ(x, 0);
}

// river.resource_iota = "shown": the resource's iota is 1 whatever the DN
// decides, so a DN that decides nothing still leaves it in the landscape;
// the other iotas stay the DN's.
TEST(RiverBrain, AShownResourceStaysInTheLandscapeWhateverTheDecision) {
  std::vector<double> silent = stone_genes();
  std::fill(silent.begin(), silent.begin() + 44, 0.0);  // every iota and the action 0
  RiverBrainDef def;
  def.resource_iota = ResourceIota::Shown;
  Result<RiverBrainModel> shown = make_river_brain_model(def, some_motif(), silent);
  ASSERT_TRUE(shown.ok()) << shown.error();
  RiverBrain b(*shown), paper(model(silent));
  for (RiverBrain* brain : {&b, &paper}) {
    brain->set_grid(resource_at(15, 10));
    brain->decide(river_cell::kGrass, false);
  }
  EXPECT_EQ(b.decision(), Decision{});  // the DN decided nothing
  EXPECT_EQ(b.landscape().at(15, 10), 15);
  EXPECT_GT(b.landscape().at(5, 10), 0);
  for (double x : paper.landscape().values()) EXPECT_EQ(x, 0);
  // the resource moves: the peak moves with it
  EXPECT_TRUE(b.set_grid(resource_at(3, 4)));
  EXPECT_EQ(b.landscape().at(3, 4), 15);
}

TEST(RiverBrain, SensorOnTheSourceReadsOneAndIsFlagged) {
  RiverBrain b(model(stone_genes()));
  b.set_grid(resource_at(15, 10));
  b.decide(river_cell::kStone, false);
  const std::vector<GridPoint> sensors{{15.5, 10.5}, {12.5, 10.5}, {13.5, 11.5}, {14.0, 9.0}};
  b.step(sensors, 0.01);
  std::span<const double> in = b.pn().inputs();
  EXPECT_EQ(in[0], 1);  // maxI / maxI
  EXPECT_DOUBLE_EQ(in[1], b.landscape().at(12, 10) / 15);
  EXPECT_DOUBLE_EQ(in[2], b.landscape().at(13, 11) / 15);
  EXPECT_DOUBLE_EQ(in[3], (b.landscape().at(13, 8) + b.landscape().at(14, 8) + b.landscape().at(13, 9) +
                           b.landscape().at(14, 9)) / 60);
  EXPECT_EQ(std::vector<double>(in.begin() + 4, in.end()), (std::vector<double>{1, 0, 0, 0}));
}

// The brain's step is the parts' composition: the same weights run by hand
// give the same values, step after step, as the sensors move.
TEST(RiverBrain, StepRunsLandscapeThenPnThenPgThenMotors) {
  const RiverBrainModel m = model(stone_genes());
  RiverBrain b(m);
  const std::vector<int> grid = resource_at(10, 12);
  b.set_grid(grid);
  b.decide(river_cell::kStone, false);

  ShuntingModel sm(m.def.landscape);
  sm.shape(grid, b.decision().iota);
  PhysicalNetwork pn(m.weights.pn_input_hidden, m.weights.pn_hidden_output);
  PatternGenerator pg(m.motif, m.weights.pg_input, m.weights.pg_motor);

  for (int n = 0; n < 200; ++n) {
    const double x = 4 + 0.03 * n, y = 12.5;
    const std::vector<GridPoint> sensors{{x + 0.5, y}, {x, y + 0.5}, {x - 0.5, y}, {x, y - 0.5}};
    b.step(sensors, 0.01);
    std::vector<double> readings;
    for (const GridPoint& p : sensors) readings.push_back(sm.activity_at(p) / 15);
    pg.step(pn.run(readings), 0.01);
    ASSERT_EQ(std::vector<double>(b.pn().outputs().begin(), b.pn().outputs().end()),
              std::vector<double>(pn.outputs().begin(), pn.outputs().end()))
        << "step " << n;
    ASSERT_EQ(std::vector<double>(b.motors().begin(), b.motors().end()),
              std::vector<double>(pg.motors().begin(), pg.motors().end()))
        << "step " << n;
  }
  // moving toward the resource, the front sensor (0) reads the most
  EXPECT_EQ(b.pn().inputs()[4], 1);
  for (double v : b.motors()) {
    EXPECT_GT(v, 0);
    EXPECT_LT(v, 1);
  }
}

}  // namespace
}  // namespace bx
