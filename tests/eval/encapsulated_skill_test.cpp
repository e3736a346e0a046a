// An encapsulated skill's behaviour (lessin2015 IV-B, genome/encapsulate.h;
// development's brain.skill) on the muscle crawler of creatures: run
// alone it drives its muscles exactly as before, step for step; with its
// switch off they are silent; a second skill leaves the first as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "brain/controller.h"
#include "develop/develop.h"
#include "eval/step.h"
#include "eval/task_table.h"
#include "genome/dialect.h"
#include "genome/encapsulate.h"
#include "io/config.h"
#include "support/creatures.h"

namespace bx {
namespace {

SimConfig crawl_config() {
  SimConfig c = default_run_config(Dialect::Lessin2015).sim;
  c.motor.response_time = 0.01;  // lessin2015-locomotion-small's lag and drop
  c.task.drop_height = 0.01;
  c.task.seconds = 4;
  return c;
}

// every physics step's effector signals of one evaluation, in turn
std::vector<double> signals(const Genome& g, SimConfig c, const std::string& skill) {
  c.develop.skill = skill;
  Development d = develop(g, c.develop);
  EXPECT_TRUE(d.viable()) << d.reason;
  if (!d.viable()) return {};
  const CreatureModel& m = *d.model;
  auto task = make_task(m, c, 1, 0);
  EXPECT_TRUE(task.ok());
  GraphBrain brain(m.brain);
  EvalState s(m, brain, c, std::move(*task));
  std::vector<double> out;
  while (!s.task->done() && step(m, c, s)) out.insert(out.end(), s.signals.begin(), s.signals.end());
  EXPECT_FALSE(s.failed) << s.failure;
  return out;
}

Genome crawler() { return bxtest::load_creature("lessin_crawler.json"); }

Genome encapsulated(const Genome& g, const std::string& name) {
  auto e = encapsulate(g, {name});
  EXPECT_TRUE(e.ok()) << e.error();
  return e.ok() ? *e : g;
}

TEST(EncapsulatedSkill, WithItsSwitchOnItDrivesTheMusclesExactlyAsBeforeStepForStep) {
  const Genome g = crawler();
  const SimConfig c = crawl_config();
  const std::vector<double> before = signals(g, c, "");
  ASSERT_FALSE(before.empty());
  // the crawler pulses: not a constant signal
  EXPECT_GT(*std::max_element(before.begin(), before.end()) - *std::min_element(before.begin(), before.end()), 0.2);
  const Genome e = encapsulated(g, "crawl");
  EXPECT_EQ(signals(e, c, "crawl"), before);  // bit for bit, every step
}

TEST(EncapsulatedSkill, WithItsSwitchOffTheSkillIsSilent) {
  const Genome e = encapsulated(crawler(), "crawl");
  // nothing drives the switch (free brain): every muscle at 0, all along
  const std::vector<double> off = signals(e, crawl_config(), "");
  ASSERT_FALSE(off.empty());
  EXPECT_TRUE(std::all_of(off.begin(), off.end(), [](double x) { return x == 0; }));
}

// a second skill on the first: a wire and a bias of its own on a muscle the
// first drives, and a wire into the first's switch
Genome second_skill(const Genome& e) {
  Genome g = e;
  EffectorGene* ef = nullptr;
  for (NodeGene& n : g.nodes)
    if (!n.effectors.empty() && !ef) ef = &n.effectors[0];
  EXPECT_NE(ef, nullptr);
  InputGene in;
  in.place = SourcePlace::Self;
  in.kind = SourceKind::Muscle;
  in.index = 0;
  in.weight = 0.7;
  ef->inputs.push_back(in);
  ef->bias = 0.25;
  NeuronGene& sw = g.global_neurons.back();
  sw.locked = false;  // open to the second skill
  InputGene drive;
  drive.place = SourcePlace::Global;
  drive.index = 0;  // a locked neuron of the first skill
  drive.weight = 0.5;
  sw.inputs.push_back(drive);
  return g;
}

TEST(EncapsulatedSkill, ASecondSkillGatesItsOwnWiresAndLeavesTheFirstAsItWas) {
  const Genome g = crawler();
  ASSERT_FALSE(g.global_neurons.empty());
  const Genome e = encapsulated(g, "crawl");
  const Genome two = second_skill(e);
  ASSERT_TRUE(validate(two).ok()) << validate(two).error();
  const SimConfig c = crawl_config();
  const std::vector<double> learned = signals(two, c, "");  // the second skill as it was learned
  const Genome e2 = encapsulated(two, "twitch");
  ASSERT_TRUE(validate(e2).ok()) << validate(e2).error();
  const int sw1 = static_cast<int>(e.global_neurons.size()) - 1, sw2 = static_cast<int>(e2.global_neurons.size()) - 1;
  // its wire into the first's switch, gated by its own
  ASSERT_EQ(e2.global_neurons[sw1].inputs.size(), 1u);
  EXPECT_EQ(e2.global_neurons[sw1].inputs[0].gate, sw2);
  // either skill alone: the first as the crawler, the second as learned
  EXPECT_EQ(signals(e2, c, "crawl"), signals(g, c, ""));
  EXPECT_EQ(signals(e2, c, "twitch"), learned);
  // an unknown skill does not develop, and says which it has
  SimConfig bad = c;
  bad.develop.skill = "fly";
  Development d = develop(e2, bad.develop);
  ASSERT_FALSE(d.viable());
  EXPECT_NE(d.reason.find("\"crawl\", \"twitch\""), std::string::npos) << d.reason;
}

}  // namespace
}  // namespace bx
