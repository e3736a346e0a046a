// creatures/lessin_crawler.json: lessin2015-locomotion-small seed 1's
// best (docs/results.md), a box with four limbs of shrinking spheres whose 24
// muscles pulse at 6 Hz and row it along. Under the preset's muscle lag and
// drop it crawls, scored by lessin2015's fitness (about its speed in m/s);
// with its muscles held at a constant activation it lies still.
// creatures/lessin_crawler_sided.json is the same creature with its two
// right-side limbs grown from a gene of their own (a copy of the limbs'):
// the same body and gait, bit for bit, whose sides a later skill can drive
// apart (the ESP presets start from it).
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "develop/develop.h"
#include "eval/evaluate.h"
#include "io/config.h"
#include "support/creatures.h"

namespace bx {
namespace {

SimConfig preset_like() {
  SimConfig c = default_run_config(Dialect::Lessin2015).sim;
  c.motor.response_time = 0.01;  // lessin2015-locomotion-small's lag and drop
  c.task.drop_height = 0.01;
  return c;
}

TEST(LessinCrawler, ItsMusclesRowItAlongAndHeldStillItLiesStill) {
  const Genome g = bxtest::load_creature("lessin_crawler.json");
  SimConfig c = preset_like();
  Development d = develop(g, c.develop);
  ASSERT_TRUE(d.viable()) << d.reason;
  const CreatureModel& m = *d.model;
  EXPECT_EQ(m.n_parts(), 13);
  EXPECT_EQ(m.muscles.size(), 24u);
  std::vector<double> fitness;
  for (std::uint64_t seed : {1, 2, 3}) {
    EvalResult r = evaluate(m, c, seed);
    ASSERT_FALSE(r.failed) << r.failure;
    fitness.push_back(r.fitness);
  }
  std::sort(fitness.begin(), fitness.end());
  EXPECT_GT(fitness[1], 0.3);  // measured 0.54-0.62 m/s (seeds 1, 3; seed 2 0.25)
  // constant activations: no step of speed (the slower half scores), and
  // no more travel than the pose change of the muscles' first pull (0.09 m
  // at 0.5, under a tenth of its 1.2 m body)
  for (double a : {0.0, 0.5, 1.0}) {
    SimConfig held = c;
    held.effector_clamp = {a};
    EvalResult r = evaluate(m, held, 1);
    ASSERT_FALSE(r.failed) << r.failure;
    EXPECT_LT(r.fitness, 0.01) << "activation " << a;
    EXPECT_LT(r.distance, 0.1 * m.body_length()) << "activation " << a;
  }
}

TEST(LessinCrawler, ItsSidedCopyIsTheSameCreatureWithARightSideGeneOfItsOwn) {
  const Genome one = bxtest::load_creature("lessin_crawler.json");
  const Genome sided = bxtest::load_creature("lessin_crawler_sided.json");
  ASSERT_EQ(sided.nodes.size(), one.nodes.size() + 1);
  SimConfig c = preset_like();
  Development a = develop(one, c.develop), b = develop(sided, c.develop);
  ASSERT_TRUE(a.viable() && b.viable());
  ASSERT_EQ(a.model->n_parts(), b.model->n_parts());
  // which gene grew each part: the root's, the left limb's (one gene in both), and
  // the right limbs' (the limbs' gene in lessin_crawler, their own in the copy)
  int own = 0;
  for (int p = 0; p < b.model->n_parts(); ++p) {
    EXPECT_EQ(a.model->parts[p].size, b.model->parts[p].size) << p;
    own += b.model->parts[p].gene == 2;
  }
  EXPECT_EQ(own, 8);  // two limbs of four parts
  for (std::uint64_t seed : {1, 2}) {
    EvalResult ra = evaluate(*a.model, c, seed), rb = evaluate(*b.model, c, seed);
    EXPECT_EQ(ra.fitness, rb.fitness) << "seed " << seed;
    EXPECT_EQ(ra.distance, rb.distance) << "seed " << seed;
  }
}

}  // namespace
}  // namespace bx
