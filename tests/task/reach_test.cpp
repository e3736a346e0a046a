// The high-reach task (lessin2015 VII-B): each shape's highest point at a
// pose against closed forms; the reach is the greatest top over the
// measured span, a jump's peak included, nothing before measuring; end to
// end, a box that lies still reaches its own height.
#include "task/reach.h"

#include <gtest/gtest.h>

#include <cmath>

#include "develop/creature_model.h"
#include "develop/develop.h"
#include "eval/evaluate.h"
#include "io/config.h"
#include "support/creatures.h"
#include "support/parts.h"

namespace bx {
namespace {

PartModel shaped(Shape shape, Vec3 size) {
  PartModel p = bxtest::box_part(size, 1, {0, 0, 0});
  p.shape = shape;
  return p;
}

TEST(Reach, EachShapesTopAtAPose) {
  const Pose up{{0, 0, 1}, Mat3::identity()};
  const Pose tilted{{0, 0, 1}, Mat3::rotation({0, 1, 0}, -kPi / 6)};  // x axis 30 degrees up
  // a box: half its extents along the vertical, each through its axis's rise
  EXPECT_NEAR(part_top(shaped(Shape::Box, {0.4, 0.2, 0.1}), up), 1.05, 1e-12);
  EXPECT_NEAR(part_top(shaped(Shape::Box, {0.4, 0.2, 0.1}), tilted),
              1 + (0.4 * 0.5 + 0.1 * std::cos(kPi / 6)) / 2, 1e-12);
  // a sphere: its radius, however turned
  EXPECT_NEAR(part_top(shaped(Shape::Sphere, {0.3, 0.3, 0.3}), tilted), 1.15, 1e-12);
  // a capsule 0.5 long, 0.1 across: its axis segment (0.4) rising, then the ball's radius
  EXPECT_NEAR(part_top(shaped(Shape::Capsule, {0.5, 0.1, 0.1}), up), 1.05, 1e-12);
  EXPECT_NEAR(part_top(shaped(Shape::Capsule, {0.5, 0.1, 0.1}), tilted), 1 + 0.2 * 0.5 + 0.05, 1e-12);
  // a cylinder 0.5 long, 0.2 across: lying, its rim; upright, its end face
  EXPECT_NEAR(part_top(shaped(Shape::Cylinder, {0.5, 0.2, 0.2}), up), 1.1, 1e-12);
  EXPECT_NEAR(part_top(shaped(Shape::Cylinder, {0.5, 0.2, 0.2}), {{0, 0, 1}, Mat3::rotation({0, 1, 0}, -kPi / 2)}),
              1.25, 1e-12);
  EXPECT_NEAR(part_top(shaped(Shape::Cylinder, {0.5, 0.2, 0.2}), tilted),
              1 + 0.25 * 0.5 + 0.1 * std::cos(kPi / 6), 1e-12);
}

// a one-box creature whose centre the test moves
struct Lift : Observation {
  double t = 0, z = 0.05;
  double time() const override { return t; }
  Vec3 centre_of_mass() const override { return {0, 0, z}; }
  int n_parts() const override { return 1; }
  Pose part_pose(int) const override { return {{0, 0, z}, Mat3::identity()}; }
  bool touches_part(int) const override { return false; }
};

TEST(Reach, TheGreatestTopWhileMeasuredAJumpIncluded) {
  CreatureModel m;
  m.parts.push_back(bxtest::box_part({0.1, 0.1, 0.1}, 1, {0, 0, 0.05}));
  ReachDef def;
  def.seconds = 1;
  def.settle = {0.05, 0.25, 2};
  const double dt = 0.125;
  ReachTask task(def, m, dt);
  Lift o;
  task.begin(o);
  // settling: still for two steps; a lift before measuring would not count
  while (task.phase() != Phase::Measure) {
    o.t += dt;
    task.observe(o);
  }
  EXPECT_NEAR(task.reach(), 0.1, 1e-12);  // it stands 0.1 m tall
  // a jump to 0.4 m at 0.5 s, then back down
  const double t0 = o.t;
  while (!task.done()) {
    o.t += dt;
    const double s = o.t - t0;
    o.z = 0.05 + (std::abs(s - 0.5) < 1e-9 ? 0.3 : 0);
    task.observe(o);
  }
  EXPECT_NEAR(task.reach(), 0.4, 1e-12);
  const TaskScore sc = task.score(m);
  EXPECT_NEAR(sc.fitness, 0.4, 1e-12);
  ASSERT_GE(sc.metrics.size(), 3u);
  EXPECT_EQ(sc.metrics[1].name, "start_top");
  EXPECT_NEAR(sc.metrics[1].value, 0.1, 1e-12);
  EXPECT_EQ(sc.metrics[2].name, "reach_time");
  EXPECT_NEAR(sc.metrics[2].value, 0.5, 1e-12);
}

// end to end: creatures/box.json, one box with no brain, lies still and
// reaches exactly its own height (less the contacts' give)
TEST(Reach, ABoxLyingStillReachesItsHeight) {
  auto cfg = read_run_config("[genome]\ndialect = \"sims1994\"\n[task]\nkind = \"high_reach\"\n[reach]\nseconds = 2\n",
                             "run.toml");
  ASSERT_TRUE(cfg.ok()) << cfg.error();
  const Genome g = bxtest::load_creature("box.json");
  Development d = develop(g, cfg->sim.develop);
  ASSERT_TRUE(d.viable()) << d.reason;
  const EvalResult r = evaluate(*d.model, cfg->sim, 1);
  ASSERT_FALSE(r.failed) << r.failure;
  EXPECT_TRUE(r.note.empty()) << r.note;
  EXPECT_NEAR(r.fitness, g.nodes[0].size.z, 2e-3);
  EXPECT_NEAR(*r.metric("start_top"), r.fitness, 1e-4);
}

}  // namespace
}  // namespace bx
