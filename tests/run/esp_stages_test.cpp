// ESP's skills in a run of several stages (lessin2015 IV-B, IV-D): a stage
// with encapsulate = true hands the next stage founders with its skill
// encapsulated (locked, switched, its wires gated), the switches of the
// skills the next stage uses open; every later individual keeps them frozen;
// stopped at the transition and resumed, the run ends as one never stopped.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "genome/dialect.h"
#include "genome/encapsulate.h"
#include "genome/graph_genotype.h"
#include "genome/locks.h"
#include "io/run_store.h"
#include "io/syllabus.h"
#include "run/run.h"
#include "support/run_command.h"

namespace bx {
namespace {

// three short skills of lessin2015 creatures: forward, then a turn that
// builds on nothing (its own pandemonium group), then one that uses the turn
const char* kEsp = R"(
[genome]
dialect = "lessin2015"
[evolution]
algorithm = "generational"
population = 6
generations = 2
[operators]
add_input = 0.5
[task]
seconds = 0.5
settle_timeout = 1

[[stage]]
name = "forward"
encapsulate = true

[[stage]]
name = "left"
group = "turn"
body = "locked"
encapsulate = true

[[stage]]
name = "towards"
uses = ["left"]
)";

class EspStages : public bxtest::InTempDir {
 protected:
  std::string make(const std::string& name) {
    auto s = read_syllabus(kEsp, "esp.toml");
    EXPECT_TRUE(s.ok()) << s.error();
    std::string run = (dir / name).string();
    Status st = create_run(run, *s, kEsp, "esp.toml", 3);
    EXPECT_TRUE(st.ok()) << st.error();
    return run;
  }
  static std::string dump(const std::string& run) {
    std::string out;
    for (const char* q : {"SELECT * FROM generation ORDER BY gen", "SELECT * FROM individual ORDER BY id",
                          "SELECT * FROM stage ORDER BY idx"})
      out += bxtest::query(run_db_path(run), q);
    return out;
  }
};

const NeuronGene* switch_of(const Genome& g, const std::string& skill) {
  for (const NeuronGene& nr : g.global_neurons)
    if (nr.skill == skill) return &nr;
  return nullptr;
}

TEST_F(EspStages, EachSkillIsEncapsulatedForTheNextAndStaysFrozen) {
  auto syl = read_syllabus(kEsp, "esp.toml");
  ASSERT_TRUE(syl.ok()) << syl.error();
  EXPECT_TRUE(syl->stages[0].encapsulate);
  EXPECT_FALSE(syl->stages[2].encapsulate);
  EXPECT_EQ(*read_syllabus(syllabus_to_toml(*syl), "resolved"), *syl);
  ASSERT_TRUE(check_run(*syl).ok());
  const std::string run = make("run");
  ASSERT_TRUE(drive_run(run, {0, true, 0}).ok());
  auto store = RunStore::open(run_db_path(run));
  ASSERT_TRUE(store.ok()) << store.error();
  auto stages = (*store)->stages();
  ASSERT_EQ(stages.size(), 3u);

  // the turn's founder: forward encapsulated, its switch closed (the turn uses nothing)
  auto f1 = (*store)->individual(stages[1].first_id);
  ASSERT_TRUE(f1.ok()) << f1.error();
  const Genome& g1 = *graph_genome(*f1->genotype);
  ASSERT_TRUE(validate(g1).ok()) << validate(g1).error();
  EXPECT_EQ(skills_of(g1), std::vector<std::string>{"forward"});
  ASSERT_NE(switch_of(g1, "forward"), nullptr);
  EXPECT_TRUE(switch_of(g1, "forward")->locked);
  for (const NodeGene& n : g1.nodes)
    for (const NeuronGene& nr : n.neurons) EXPECT_TRUE(nr.locked);

  // the last stage's founder: both skills; the turn's switch open to it, in group 0 ("turn")
  auto f2 = (*store)->individual(stages[2].first_id);
  ASSERT_TRUE(f2.ok()) << f2.error();
  const Genome& g2 = *graph_genome(*f2->genotype);
  ASSERT_TRUE(validate(g2).ok()) << validate(g2).error();
  EXPECT_EQ(skills_of(g2), (std::vector<std::string>{"forward", "left"}));
  EXPECT_TRUE(switch_of(g2, "forward")->locked);
  EXPECT_FALSE(switch_of(g2, "left")->locked);
  EXPECT_EQ(switch_of(g2, "left")->group, 0);

  // every later individual keeps its founder's frozen genes; add_input wires some anew
  int wired = 0;
  for (std::int64_t id = stages[2].first_id + 1;; ++id) {
    auto ind = (*store)->individual(id);
    if (!ind) break;
    const Genome& g = *graph_genome(*ind->genotype);
    Status kept = locks_kept(g2, g);
    EXPECT_TRUE(kept.ok()) << "individual " << id << ": " << kept.error();
    const NeuronGene* left = switch_of(g, "left");
    ASSERT_NE(left, nullptr);
    bool own = gated_prefix(left->inputs) < static_cast<int>(left->inputs.size());
    for (const NodeGene& n : g.nodes)
      for (const EffectorGene& ef : n.effectors) own |= gated_prefix(ef.inputs) < static_cast<int>(ef.inputs.size());
    wired += own;
  }
  EXPECT_GT(wired, 0);
}

TEST_F(EspStages, StoppedAtATransitionAndResumedEndsTheSame) {
  const std::string whole = make("whole");
  ASSERT_TRUE(drive_run(whole, {0, true, 0}).ok());
  const std::string expected = dump(whole);
  for (int stop : {2, 3}) {  // at the first stage's end, inside the second
    const std::string run = make("stop" + std::to_string(stop));
    ASSERT_TRUE(drive_run(run, {0, true, stop}).ok());
    ASSERT_TRUE(drive_run(run, {1, true, 0}).ok());
    EXPECT_EQ(dump(run), expected) << "stopped after " << stop << " generations";
  }
}

TEST(EspSyllabus, EncapsulationNeedsSkillSwitches) {
  auto bad = read_syllabus("[genome]\ndialect = \"lessin2015\"\n[[stage]]\nname = \"a\"\nencapsulate = \"yes\"\n", "s.toml");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error(), "s.toml: stage 1.encapsulate: expected true or false (whether its skill is encapsulated when it ends)");
  auto sims = read_syllabus("[genome]\ndialect = \"sims1994\"\n[[stage]]\nname = \"a\"\nencapsulate = true\n[[stage]]\nname = \"b\"\n",
                            "s.toml");
  ASSERT_TRUE(sims.ok()) << sims.error();
  Status s = check_run(*sims);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(),
            "stage \"a\": encapsulate: true: genotypes of kind graph (dialect sims1994) have no skill switches (lessin2015's have)");
}

}  // namespace
}  // namespace bx
