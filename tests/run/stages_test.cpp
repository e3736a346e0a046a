// Multi-stage runs (io/syllabus.h): a config's [[stage]] tables, read and
// refused with the stage and key named; a run of several stages in one
// folder, each stage starting from the last one's population, numbered on
// through the database, and, stopped at any generation (inside a stage or
// between two) and resumed, ending exactly as a run never stopped.
#include "io/syllabus.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "eval/evaluator.h"
#include "develop/graph_ops.h"
#include "genome/graph_genotype.h"
#include "genome/genotype.h"
#include "genome/reconcile.h"
#include "genome/shipped_creatures.h"
#include "core/files.h"
#include "core/text.h"
#include "support/creatures.h"
#include "support/general_esp.h"
#include "io/run_store.h"
#include "run/run.h"
#include "support/run_command.h"

namespace bx {
namespace {

namespace fs = std::filesystem;

// three stages: the base's task, then a longer one from the first's best,
// then the same from the second's whole population, a smaller one
const char* kStaged = R"(
[genome]
dialect = "sims1994"
[evolution]
algorithm = "generational"
population = 8
generations = 2
[task]
seconds = 1

[[stage]]
name = "short"

[[stage]]
name = "longer"
uses = ["short"]
group = "g"
[stage.task]
seconds = 1.5
[stage.evolution]
generations = 3

[[stage]]
name = "again"
start = "population"
uses = ["short", "longer"]
[stage.evolution]
population = 6
)";

std::string error_of(const std::string& text) {
  auto s = read_syllabus(text, "s.toml");
  return s ? std::string("(read)") : s.error();
}

TEST(Syllabus, APlainConfigIsOneUnnamedStage) {
  auto s = read_syllabus("[task]\nseconds = 2\n", "plain.toml");
  ASSERT_TRUE(s.ok()) << s.error();
  ASSERT_EQ(s->stages.size(), 1u);
  EXPECT_FALSE(s->staged());
  EXPECT_EQ(s->stages[0].cfg, *read_run_config("[task]\nseconds = 2\n", "plain.toml"));
  EXPECT_EQ(syllabus_to_toml(*s), config_to_toml(s->stages[0].cfg));
}

TEST(Syllabus, StagesOverlayTheBaseThenTheOverrides) {
  auto s = read_syllabus(kStaged, "s.toml", {"physics.dt=0.005"});
  ASSERT_TRUE(s.ok()) << s.error();
  ASSERT_EQ(s->stages.size(), 3u);
  EXPECT_TRUE(s->staged());
  const auto& a = s->stages[0], &b = s->stages[1], &c = s->stages[2];
  EXPECT_EQ(a.name, "short");
  EXPECT_EQ(a.start, StageStart::Random);
  EXPECT_EQ(b.start, StageStart::Best);  // the default after the first
  EXPECT_EQ(c.start, StageStart::Population);
  EXPECT_EQ(b.uses, (std::vector<std::string>{"short"}));
  EXPECT_EQ(b.group, "g");
  EXPECT_DOUBLE_EQ(a.cfg.sim.task.seconds, 1);
  EXPECT_DOUBLE_EQ(b.cfg.sim.task.seconds, 1.5);
  EXPECT_DOUBLE_EQ(c.cfg.sim.task.seconds, 1);  // the base's, not the last stage's
  EXPECT_EQ(b.cfg.evolution.generations, 3);
  EXPECT_EQ(c.cfg.evolution.population, 6);
  for (const auto& st : s->stages) EXPECT_DOUBLE_EQ(st.cfg.sim.physics.dt, 0.005);
  EXPECT_EQ(s->find("longer"), 1);
  EXPECT_EQ(s->find("none"), -1);
}

TEST(Syllabus, WrittenOutItReadsBackTheSame) {
  auto s = read_syllabus(kStaged, "s.toml", {"physics.dt=0.005", "evolution.generations=1"});
  ASSERT_TRUE(s.ok()) << s.error();
  const std::string text = syllabus_to_toml(*s);
  auto back = read_syllabus(text, "resolved.toml");
  ASSERT_TRUE(back.ok()) << back.error() << "\n" << text;
  EXPECT_EQ(*back, *s) << text;
  EXPECT_EQ(syllabus_to_toml(*back), text);
}

TEST(Syllabus, ErrorsNameTheStageAndTheKey) {
  const std::string base = "[genome]\ndialect = \"sims1994\"\n";
  auto staged = [&](const std::string& stages) { return error_of(base + stages); };
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\n[[stage]]\nname = \"b\"\nuses = [\"c\"]\n"),
            "s.toml: stage \"b\".uses: \"c\": no earlier stage has this name (did you mean \"a\"?)");
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\nuses = [\"b\"]\n[[stage]]\nname = \"b\"\n"),
            "s.toml: stage \"a\".uses: \"b\" is learned after it (a stage uses only earlier ones)");
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\nuses = [\"a\"]\n"),
            "s.toml: stage \"a\".uses: \"a\" is this stage (a stage cannot use itself)");
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\n[[stage]]\nname = \"a\"\n"), "s.toml: stage \"a\".name: given to two stages");
  EXPECT_EQ(staged("[[stage]]\nuses = []\n"), "s.toml: stage 1.name: every stage needs a name (a non-empty string)");
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\nstart = \"best\"\n"),
            "s.toml: stage 1.start: the first stage has no stage before it to start from; it starts \"random\" or \"file\", "
            "got \"best\"");
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\n[[stage]]\nname = \"b\"\nstart = \"worst\"\n"),
            "s.toml: stage 2.start: expected one of random, best, population, file, got \"worst\"");
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\nskill = 3\n"),
            "s.toml: stage 1.skill: unknown stage key (a stage has name, uses, group, start, file, body, encapsulate, "
            "retest_tolerance, reconcile and config sections)");
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\nretest_tolerance = 0.2\n"),
            "s.toml: stage 1.retest_tolerance: the first stage has no skill learned before it to retest");
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\n[[stage]]\nname = \"b\"\nretest_tolerance = 1\n"),
            "s.toml: stage 2.retest_tolerance: expected a number in [0, 1) (the share of a leaf skill's fitness a child "
            "may lose), got 1");
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\n[[stage]]\nname = \"b\"\nretest_tolerance = 0.2\n"),
            "s.toml: stage \"b\".retest_tolerance: no leaf skill is learned before it (an earlier stage that "
            "encapsulates its skill and uses none)");
  // a stage's config key is checked as the config's own, and named with its stage
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\n[stage.task]\nsecond = 2\n"),
            "s.toml: stage \"a\": task.second: unknown key (did you mean \"seconds\"?)");
  EXPECT_EQ(staged("[[stage]]\nname = \"a\"\n[[stage]]\nname = \"b\"\n[stage.genome]\ndialect = \"miconi2006\"\n"),
            "s.toml: stage \"b\": genome.dialect: every stage evolves the first stage's dialect (sims1994), got miconi2006");
  EXPECT_EQ(error_of("stage = 3\n" + base), "s.toml: stage: expected [[stage]] tables, one per stage");
}

// runs in a fresh folder of their own (bxtest::InTempDir's `dir`)
class Stages : public bxtest::InTempDir {
 protected:
  std::string make(const std::string& name) {
    auto s = read_syllabus(kStaged, "test.toml");
    EXPECT_TRUE(s.ok()) << s.error();
    std::string run = (dir / name).string();
    Status st = create_run(run, *s, kStaged, "test.toml", 5);
    EXPECT_TRUE(st.ok()) << st.error();
    return run;
  }
  static std::string dump(const std::string& run) {
    std::string out;
    for (const char* q : {"SELECT * FROM generation ORDER BY gen", "SELECT * FROM individual ORDER BY id",
                          "SELECT * FROM stage ORDER BY idx", "SELECT gen, state FROM checkpoint"})
      out += bxtest::query(run_db_path(run), q);
    return out;
  }
};

TEST_F(Stages, EachStageStartsFromTheLastAndNumbersOn) {
  std::string run = make("run");
  ASSERT_TRUE(drive_run(run, {0, true, 0}).ok());
  auto store = RunStore::open(run_db_path(run));
  ASSERT_TRUE(store.ok()) << store.error();
  // 2 + 3 + 2 generations, numbered on; 8 + 8 x 3 + 6 x 2 individuals, ids on
  auto stages = (*store)->stages();
  ASSERT_EQ(stages.size(), 3u);
  EXPECT_EQ(stages[0].name, "short");
  EXPECT_EQ(stages[1].first_gen, 2);
  EXPECT_EQ(stages[2].first_gen, 5);
  auto gens = (*store)->generations();
  ASSERT_EQ(gens.size(), 7u);
  for (int g = 0; g < 7; ++g) EXPECT_EQ(gens[g].generation, g);
  // the second stage begins with the first's best as it was, then its mutants
  auto first_best = (*store)->individual(gens[1].best_id);
  ASSERT_TRUE(first_best.ok());
  auto copy = (*store)->individual(stages[1].first_id);
  ASSERT_TRUE(copy.ok()) << copy.error();
  EXPECT_EQ(copy->op, "copy");
  EXPECT_EQ(copy->parent1, first_best->id);
  EXPECT_EQ(copy->genotype->to_json(), first_best->genotype->to_json());
  EXPECT_EQ(copy->generation, 2);
  auto mutant = (*store)->individual(stages[1].first_id + 1);
  ASSERT_TRUE(mutant.ok());
  EXPECT_EQ(mutant->op, "mutation");
  EXPECT_EQ(mutant->parent1, first_best->id);
  // the third begins with the second's final population, best first, each as it was
  for (std::int64_t id = stages[2].first_id; id < stages[2].first_id + 6; ++id) {
    auto ind = (*store)->individual(id);
    ASSERT_TRUE(ind.ok());
    EXPECT_EQ(ind->op, "copy");
    auto parent = (*store)->individual(ind->parent1);
    ASSERT_TRUE(parent.ok());
    EXPECT_GE(parent->generation, 2);
    EXPECT_LT(parent->generation, 5);
  }
  // the run's best is its last stage's
  auto best = (*store)->best_individual();
  ASSERT_TRUE(best.ok());
  EXPECT_GE(best->id, stages[2].first_id);
  auto progress = run_progress(run);
  ASSERT_TRUE(progress.ok());
  EXPECT_TRUE(progress->complete);
  EXPECT_EQ(progress->generations_done, 7);
  EXPECT_EQ(progress->generations_total, 7);
}

TEST_F(Stages, StoppedAnywhereAndResumedEndsTheSame) {
  std::string whole = make("whole");
  ASSERT_TRUE(drive_run(whole, {0, true, 0}).ok());
  const std::string expected = dump(whole);
  // inside the first stage, at its end, inside the second, at its end
  for (int stop : {1, 2, 4, 5}) {
    std::string run = make("stop" + std::to_string(stop));
    ASSERT_TRUE(drive_run(run, {0, true, stop}).ok());
    auto progress = run_progress(run);
    ASSERT_TRUE(progress.ok()) << progress.error();
    EXPECT_EQ(progress->generations_done, stop);
    EXPECT_FALSE(progress->complete);
    EXPECT_NE(dump(run), expected);
    ASSERT_TRUE(drive_run(run, {2, true, 0}).ok());  // with workers, too
    EXPECT_EQ(dump(run), expected) << "stopped after " << stop << " generations";
  }
}

// Fast ESP (lessin2015 IV-D): from a stage with body = "locked" on, no
// operator changes the body its founder had; its units still evolve
TEST_F(Stages, ALockedBodyStaysTheFoundersWhileItsBrainEvolves) {
  const std::string text = std::string(kStaged).replace(std::string(kStaged).find("group = \"g\""), 11,
                                                        "group = \"g\"\nbody = \"locked\"");
  auto syl = read_syllabus(text, "test.toml");
  ASSERT_TRUE(syl.ok()) << syl.error();
  ASSERT_TRUE(syl->stages[1].lock_body);
  EXPECT_EQ(*read_syllabus(syllabus_to_toml(*syl), "resolved"), *syl);
  const std::string run = (dir / "run").string();
  ASSERT_TRUE(create_run(run, *syl, text, "test.toml", 5).ok());
  ASSERT_TRUE(drive_run(run, {0, true, 0}).ok());
  auto store = RunStore::open(run_db_path(run));
  ASSERT_TRUE(store.ok());
  auto stages = (*store)->stages();
  ASSERT_EQ(stages.size(), 3u);
  auto founder = (*store)->individual(stages[1].first_id);
  ASSERT_TRUE(founder.ok());
  const Genome& f = *graph_genome(*founder->genotype);
  for (const NodeGene& n : f.nodes) EXPECT_EQ(n.lock, unsigned{kLockBody | kLockJoint | kLockInEdges | kLockOutEdges});
  int brains_changed = 0;
  for (std::int64_t id = stages[1].first_id + 1;; ++id) {
    auto ind = (*store)->individual(id);
    if (!ind) break;
    const Genome& g = *graph_genome(*ind->genotype);
    ASSERT_GE(g.nodes.size(), f.nodes.size()) << "individual " << id;
    for (std::size_t k = 0; k < f.nodes.size(); ++k) {
      const NodeGene &a = f.nodes[k], &b = g.nodes[k];
      EXPECT_EQ(a.shape, b.shape) << id;
      EXPECT_EQ(a.size, b.size) << id;
      EXPECT_EQ(a.density, b.density) << id;
      EXPECT_EQ(a.joint, b.joint) << id;
      EXPECT_EQ(a.recursive_limit, b.recursive_limit) << id;
      EXPECT_EQ(a.edges, b.edges) << id;
      EXPECT_EQ(a.lock, b.lock) << id;
      brains_changed += a.neurons != b.neurons || a.effectors != b.effectors || a.sensors != b.sensors;
    }
  }
  EXPECT_GT(brains_changed, 0);
}

TEST(Syllabus, OnlyABodyAStageStartsFromCanBeLocked) {
  const std::string base = "[genome]\ndialect = \"sims1994\"\n";
  EXPECT_EQ(error_of(base + "[[stage]]\nname = \"a\"\nbody = \"locked\"\n"),
            "s.toml: stage 1.body: \"locked\" locks the bodies the stage starts from, and start = \"random\" takes none "
            "(random genotypes have no body yet)");
  EXPECT_EQ(error_of(base + "[[stage]]\nname = \"a\"\n[[stage]]\nname = \"b\"\nbody = \"rigid\"\n"),
            "s.toml: stage 2.body: expected \"free\" or \"locked\", got \"rigid\"");
  EXPECT_EQ(error_of(base + "[[stage]]\nname = \"a\"\n[[stage]]\nname = \"b\"\nstart = \"random\"\nbody = \"locked\"\n"),
            "s.toml: stage 2.body: \"locked\" locks the bodies the stage starts from, and start = \"random\" takes none "
            "(random genotypes have no body yet)");
  // a creature kind without a body (the motif) has none to lock
  auto motif = read_syllabus("[genotype]\nkind = \"motif\"\n[evolution]\np_asexual = 0.5\np_crossover = 0.5\np_graft = 0\n"
                             "[[stage]]\nname = \"a\"\n[[stage]]\nname = \"b\"\nbody = \"locked\"\n",
                             "m.toml");
  ASSERT_TRUE(motif.ok()) << motif.error();
  Status s = check_run(*motif);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "stage \"b\": body: \"locked\": genotypes of kind floats have no body to lock");
}

// the first stage may start from a canonical creature or a genome file: the
// file's creature once as it is (operator "file", no parent), the rest of
// the population its mutants; its body locked with body = "locked"
const char* kFromFile = R"(
[genome]
dialect = "sims1994"
[evolution]
algorithm = "generational"
population = 5
generations = 2
[task]
seconds = 1

[[stage]]
name = "walk"
start = "file"
file = "walker"
body = "locked"

[[stage]]
name = "on"
)";

TEST_F(Stages, TheFirstStageStartsFromAFilesCreatureAndResumesTheSame) {
  auto syl = read_syllabus(kFromFile, "test.toml");
  ASSERT_TRUE(syl.ok()) << syl.error();
  const StageDef& first = syl->stages.front();
  EXPECT_EQ(first.start, StageStart::File);
  EXPECT_EQ(first.file_hash.size(), 16u);  // the reader writes it
  EXPECT_EQ(*read_syllabus(syllabus_to_toml(*syl), "resolved"), *syl);
  auto make = [&](const std::string& name) {
    const std::string run = (dir / name).string();
    EXPECT_TRUE(create_run(run, *syl, kFromFile, "test.toml", 4).ok());
    return run;
  };
  const std::string whole = make("whole");
  ASSERT_TRUE(drive_run(whole, {0, true, 0}).ok());
  auto store = RunStore::open(run_db_path(whole));
  ASSERT_TRUE(store.ok());
  auto founder = (*store)->individual(0);
  ASSERT_TRUE(founder.ok());
  EXPECT_EQ(founder->op, "file");
  EXPECT_EQ(founder->parent1, -1);
  Genome walker = bxtest::load_creature("walker.json");
  for (NodeGene& n : walker.nodes) n.lock |= kLockBody | kLockJoint | kLockInEdges | kLockOutEdges;
  EXPECT_EQ(*graph_genome(*founder->genotype), walker);
  auto mutant = (*store)->individual(1);
  ASSERT_TRUE(mutant.ok());
  EXPECT_EQ(mutant->op, "mutation");
  EXPECT_EQ(mutant->parent1, -1);
  const std::string expected = dump(whole);
  for (int stop : {1, 2, 3}) {
    const std::string run = make("stop" + std::to_string(stop));
    ASSERT_TRUE(drive_run(run, {0, true, stop}).ok());
    ASSERT_TRUE(drive_run(run, {1, true, 0}).ok());
    EXPECT_EQ(dump(run), expected) << "stopped after " << stop;
  }
}

TEST_F(Stages, AStartFileThatIsMissingBadOrChangedIsRefused) {
  const std::string base = "[genome]\ndialect = \"sims1994\"\n[[stage]]\nname = \"a\"\n";
  EXPECT_EQ(error_of(base + "start = \"file\"\n"),
            "s.toml: stage 1.file: start = \"file\" needs the genome file to start from (a canonical creature's name, "
            "creatures/, or a path)");
  EXPECT_EQ(error_of(base + "file = \"walker\"\n"),
            "s.toml: stage 1.file: given, but the stage starts \"random\" (start = \"file\" starts from it)");
  EXPECT_EQ(error_of(base + "start = \"file\"\nfile = \"walkr\"\n"),
            "s.toml: stage 1.file: \"walkr\": no canonical creature of that name (did you mean \"walker\"?) (creatures/ "
            "has " + std::to_string(shipped_creatures().size()) + ") and no such file");
  EXPECT_EQ(error_of(base + "[[stage]]\nname = \"b\"\nstart = \"file\"\nfile = \"walker\"\n"),
            "s.toml: stage 2.start: only the first stage starts from a file (a later one starts from what the last left: "
            "best or population), got \"file\"");
  const std::string bad = (dir / "bad.json").string();
  ASSERT_TRUE(write_file_atomic(bad, "{\"nodes\": 3}").ok());
  EXPECT_EQ(error_of(base + "start = \"file\"\nfile = \"" + bad + "\"\n").rfind("s.toml: stage 1.file: " + bad, 0), 0u);
  // a creature of another dialect: refused before the run begins
  auto other = read_syllabus(base + "start = \"file\"\nfile = \"lessin_crawler\"\n", "s.toml");
  ASSERT_TRUE(other.ok()) << other.error();
  Status s = check_run(*other);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error(), "stage \"a\": file: creature lessin_crawler (shipped): genotype: dialect is lessin2015, the run's "
                       "is sims1994");
  // a file changed since the run began: the run will not start from it
  const std::string mine = (dir / "mine.json").string();
  auto walker = read_creature_text("walker");
  ASSERT_TRUE(walker.ok());
  ASSERT_TRUE(write_file_atomic(mine, walker->text).ok());
  const std::string text = base + "start = \"file\"\nfile = \"" + mine + "\"\n";
  auto syl = read_syllabus(text, "s.toml");
  ASSERT_TRUE(syl.ok()) << syl.error();
  const std::string run = (dir / "run").string();
  ASSERT_TRUE(create_run(run, *syl, text, "s.toml", 1).ok());
  ASSERT_TRUE(write_file_atomic(mine, walker->text + "\n").ok());
  s = drive_run(run, {0, true, 0});
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("stage \"a\": file: " + mine + " has changed since the run began"), std::string::npos)
      << s.error();
}

// the steady state's budget counts the creatures born in each stage
TEST_F(Stages, SteadyStateStagesCountTheirOwnBudgetsAndResumeTheSame) {
  const char* text = R"(
[genome]
dialect = "miconi2006"
[evolution]
algorithm = "steady_state"
population = 9
evaluations = 6
batch = 3
report_every = 3
[task]
seconds = 1

[[stage]]
name = "one"

[[stage]]
name = "two"
[stage.evolution]
evaluations = 9
)";
  auto syl = read_syllabus(text, "test.toml");
  ASSERT_TRUE(syl.ok()) << syl.error();
  auto make = [&](const std::string& name) {
    const std::string run = (dir / name).string();
    EXPECT_TRUE(create_run(run, *syl, text, "test.toml", 3).ok());
    return run;
  };
  const std::string whole = make("whole");
  ASSERT_TRUE(drive_run(whole, {0, true, 0}).ok());
  auto store = RunStore::open(run_db_path(whole));
  ASSERT_TRUE(store.ok());
  // 1 + 2 report intervals, then 1 + 3; 9 + 6 creatures, then 9 + 9
  auto stages = (*store)->stages();
  ASSERT_EQ(stages.size(), 2u);
  EXPECT_EQ(stages[1].first_gen, 3);
  EXPECT_EQ(stages[1].first_id, 15);
  EXPECT_EQ((*store)->generations().size(), 7u);
  EXPECT_EQ(bxtest::query(run_db_path(whole), "SELECT count(*) FROM individual"), "33|\n");
  const std::string expected = dump(whole);
  for (int stop : {2, 3, 5}) {
    const std::string run = make("stop" + std::to_string(stop));
    ASSERT_TRUE(drive_run(run, {0, true, stop}).ok());
    ASSERT_TRUE(drive_run(run, {2, true, 0}).ok());
    EXPECT_EQ(dump(run), expected) << "stopped after " << stop;
  }
}

TEST_F(Stages, ARunOfStagesIsNotLengthened) {
  std::string run = make("run");
  Status s = extend_run(run, {"evolution.generations=9"});
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("cannot be lengthened"), std::string::npos) << s.error();
}

// General ESP (lessin2015 VI, Algorithm 1): a strike learned on a body that
// may change, each child retested on the crawler's encapsulated forward
// locomotion, run alone
const std::string kGeneral = bxtest::general_syllabus();

TEST(Syllabus, AGeneralStageRetestsEachLeafSkillAloneOnItsOwnRow) {
  auto syl = read_syllabus(kGeneral, "g.toml");
  ASSERT_TRUE(syl.ok()) << syl.error();
  EXPECT_EQ(*syl->stages[1].retest_tolerance, 0.5);
  EXPECT_FALSE(syl->stages[0].retest_tolerance);
  EXPECT_EQ(*read_syllabus(syllabus_to_toml(*syl), "resolved"), *syl);
  EXPECT_EQ(syl->leaf_skills(1), std::vector<int>{0});
  const std::vector<SimConfig> rows = task_table(*syl);
  ASSERT_EQ(rows.size(), 3u);  // the two stages', then forward run alone
  EXPECT_EQ(rows[2].develop.skill, "forward");
  SimConfig forward = syl->stages[0].cfg.sim;
  forward.develop.skill = "forward";
  EXPECT_EQ(rows[2], forward);
  ASSERT_EQ(retest_rows(*syl, 1).size(), 1u);
  EXPECT_EQ(retest_rows(*syl, 1)[0].stage, 0);
  EXPECT_EQ(retest_rows(*syl, 1)[0].task, 2);
  EXPECT_TRUE(retest_rows(*syl, 0).empty());
}

TEST_F(Stages, AGeneralStageScoresZeroBelowARetestAndResumesTheSame) {
  auto syl = read_syllabus(kGeneral, "g.toml");
  ASSERT_TRUE(syl.ok()) << syl.error();
  auto make = [&](const std::string& name) {
    const std::string run = (dir / name).string();
    EXPECT_TRUE(create_run(run, *syl, kGeneral, "g.toml", 3).ok());
    return run;
  };
  const std::string whole = make("whole");
  ASSERT_TRUE(drive_run(whole, {0, true, 0}).ok());
  auto store = RunStore::open(run_db_path(whole));
  ASSERT_TRUE(store.ok());
  // forward's level: what its stage's last best scores in the retest's
  // world; each strike child keeps half of it run alone in that world, or scores 0
  const std::vector<GenerationStats> gens = (*store)->generations();
  ASSERT_EQ(gens.size(), 4u);
  auto learned = (*store)->individual(gens[1].best_id);
  ASSERT_TRUE(learned.ok());
  const std::uint64_t world = retest_seed(3, 1, 0);
  const double least = 0.5 * evaluate_genotype(*learned->genotype, syl->stages[0].cfg.sim, world).result.fitness;
  SimConfig alone = syl->stages[0].cfg.sim;
  alone.develop.skill = "forward";
  int fell = 0, kept = 0;
  for (std::int64_t id = (*store)->stages()[1].first_id;; ++id) {
    auto ind = (*store)->individual(id);
    if (!ind) break;
    const EvalOutcome again = evaluate_genotype(*ind->genotype, alone, world);
    ASSERT_TRUE(again.viable && !again.result.failed);
    if (again.result.fitness < least) {
      ++fell;
      EXPECT_EQ(ind->fitness, 0);
      EXPECT_EQ(ind->failure, "retest forward: " + g_number(again.result.fitness) + " < " + g_number(least));
    } else {
      ++kept;
      EXPECT_EQ(ind->failure.rfind("retest", 0), std::string::npos) << ind->failure;
    }
  }
  EXPECT_EQ(fell + kept, 7);  // 4, then 3 children of the one elite
  // the stage's copy of forward's best scores exactly what it did: kept
  auto copy = (*store)->individual((*store)->stages()[1].first_id);
  ASSERT_TRUE(copy.ok());
  EXPECT_EQ(copy->op, "copy");
  EXPECT_EQ(copy->failure.rfind("retest", 0), std::string::npos) << copy->failure;
  EXPECT_GT(fell, 0);
  EXPECT_GT(kept, 0);
  bool recorded = false;
  for (const MetricStat& m : gens[2].metrics) recorded |= m.name == "retest forward";
  EXPECT_TRUE(recorded);
  // stopped at every generation (the stages' boundary among them) and resumed
  const std::string expected = dump(whole);
  for (int stop : {1, 2, 3}) {
    const std::string run = make("stop" + std::to_string(stop));
    ASSERT_TRUE(drive_run(run, {0, true, stop}).ok());
    ASSERT_TRUE(drive_run(run, {1, true, 0}).ok());
    EXPECT_EQ(dump(run), expected) << "stopped after " << stop;
  }
}

// Algorithm 2 after Algorithm 1: forward's wires reconciled to the body
// the strike stage left, then a second strike stage that retests forward
// against what its reconciliation ended with
const std::string kReconcile = kGeneral + R"(
[[stage]]
name = "forward again"
reconcile = "forward"
)" + bxtest::general_strike_stage("strike again");

TEST(Syllabus, AReconcilingStageRunsItsSkillAloneOnItsOwnTaskAndIsCheckedByName) {
  auto syl = read_syllabus(kReconcile, "r.toml");
  ASSERT_TRUE(syl.ok()) << syl.error();
  const StageDef& again = syl->stages[2];
  EXPECT_EQ(again.reconcile, "forward");
  SimConfig alone = syl->stages[0].cfg.sim;
  alone.develop.skill = "forward";
  EXPECT_EQ(again.cfg.sim, alone);
  EXPECT_EQ(again.cfg.operators.reconcile_skill, "forward");
  EXPECT_EQ(*read_syllabus(syllabus_to_toml(*syl), "resolved"), *syl);
  EXPECT_EQ(syl->learned_in(0, 3), 2);  // forward's level: its reconciliation's
  EXPECT_EQ(syl->learned_in(0, 2), 0);
  const std::string two = kGeneral + "\n[[stage]]\nname = \"r\"\n";
  EXPECT_EQ(error_of(two + "reconcile = \"walk\"\n"),
            "s.toml: stage \"r\".reconcile: \"walk\": no earlier stage has this name");
  EXPECT_EQ(error_of(two + "reconcile = \"strike\"\n"),
            "s.toml: stage \"r\".reconcile: \"strike\": that stage's skill is not encapsulated");
  EXPECT_EQ(error_of(two + "reconcile = \"forward\"\nencapsulate = true\n"),
            "s.toml: stage \"r\".reconcile: a reconciling stage starts from the last one's best (start = \"best\") "
            "and has no encapsulate, uses or retest_tolerance of its own: it evolves \"forward\"'s wires again");
}

TEST_F(Stages, AReconcilingStageChangesOnlyItsSkillsWiresAndSetsItsNewLevel) {
  auto syl = read_syllabus(kReconcile, "r.toml");
  ASSERT_TRUE(syl.ok()) << syl.error();
  const std::string run = (dir / "run").string();
  ASSERT_TRUE(create_run(run, *syl, kReconcile, "r.toml", 3).ok());
  ASSERT_TRUE(drive_run(run, {0, true, 0}).ok());
  auto store = RunStore::open(run_db_path(run));
  ASSERT_TRUE(store.ok());
  const std::vector<StageRow> stages = (*store)->stages();
  ASSERT_EQ(stages.size(), 4u);
  const std::vector<GenerationStats> gens = (*store)->generations();
  ASSERT_EQ(gens.size(), 8u);
  // the reconciling stage's creatures: its founder's genome but for forward's
  // wires' weights, each scored on forward run alone
  auto founder = (*store)->individual(stages[2].first_id);
  ASSERT_TRUE(founder.ok());
  EXPECT_EQ(founder->op, "copy");
  const Genome& f = *graph_genome(*founder->genotype);
  const int gate = skill_switch(f, "forward");
  ASSERT_GE(gate, 0);
  int moved = 0;
  for (std::int64_t id = stages[2].first_id; id < stages[3].first_id; ++id) {
    auto ind = (*store)->individual(id);
    ASSERT_TRUE(ind.ok());
    Genome g = *graph_genome(*ind->genotype);
    for (std::size_t n = 0; n < g.nodes.size(); ++n)
      for (std::size_t e = 0; e < g.nodes[n].effectors.size(); ++e)
        for (std::size_t i = 0; i < g.nodes[n].effectors[e].inputs.size(); ++i) {
          InputGene& in = g.nodes[n].effectors[e].inputs[i];
          const double was = f.nodes[n].effectors[e].inputs[i].weight;
          if (in.weight != was) {
            EXPECT_EQ(in.gate, gate) << "a wire not forward's changed";
            ++moved;
          }
          in.weight = was;
        }
    EXPECT_EQ(g, f) << "individual " << id << ": more than forward's wires changed";
    if (ind->evaluations == 1) {
      SimConfig alone = syl->stages[0].cfg.sim;
      alone.develop.skill = "forward";
      EXPECT_EQ(ind->fitness, evaluate_genotype(*ind->genotype, alone, ind->seed).result.fitness) << id;
    }
  }
  EXPECT_GT(moved, 0);
  // the second strike stage's least: half of what the reconciliation's last
  // best scores (forward alone, its stage's task) in the retest's world
  bool fell_or_kept = false;
  SimConfig alone = syl->stages[0].cfg.sim;
  alone.develop.skill = "forward";
  auto reconciled = (*store)->individual(gens[5].best_id);
  ASSERT_TRUE(reconciled.ok());
  const std::uint64_t world = retest_seed(3, 3, 0);
  const double least = 0.5 * evaluate_genotype(*reconciled->genotype, alone, world).result.fitness;
  for (std::int64_t id = stages[3].first_id;; ++id) {
    auto ind = (*store)->individual(id);
    if (!ind) break;
    const EvalOutcome again = evaluate_genotype(*ind->genotype, alone, world);
    ASSERT_TRUE(again.viable && !again.result.failed);
    EXPECT_EQ(ind->failure.rfind("retest", 0) == 0, again.result.fitness < least) << ind->failure;
    fell_or_kept = true;
  }
  EXPECT_TRUE(fell_or_kept);
  // stopped where the reconciliation begins and where it ends, and resumed
  const std::string expected = dump(run);
  for (int stop : {4, 6}) {
    const std::string again = (dir / ("stop" + std::to_string(stop))).string();
    ASSERT_TRUE(create_run(again, *syl, kReconcile, "r.toml", 3).ok());
    ASSERT_TRUE(drive_run(again, {0, true, stop}).ok());
    ASSERT_TRUE(drive_run(again, {1, true, 0}).ok());
    EXPECT_EQ(dump(again), expected) << "stopped after " << stop;
  }
}

// an evaluator's task table: a batch that mixes tasks gives each job its own
// task's evaluation, in this process and in workers
TEST(TaskTable, AJobIsEvaluatedOnItsOwnTask) {
  auto s = read_syllabus(kStaged, "s.toml");
  ASSERT_TRUE(s.ok()) << s.error();
  std::vector<SimConfig> tasks;
  for (const auto& st : s->stages) tasks.push_back(st.cfg.sim);
  auto ops = [&] {
    const RunConfig& c = s->stages[0].cfg;
    return GraphOps(c.dialect, c.operators, c.sim.develop);
  }();
  Rng rng(3);
  auto g = ops.random(rng);
  std::vector<EvalJob> jobs = {{g.get(), 7, 1, 0}, {g.get(), 7, 1, 1}};
  SerialEvaluator serial(tasks);
  auto out = serial.evaluate(jobs);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].result.fitness, SerialEvaluator(tasks[0]).evaluate({{g.get(), 7}})[0].result.fitness);
  EXPECT_EQ(out[1].result.fitness, SerialEvaluator(tasks[1]).evaluate({{g.get(), 7}})[0].result.fitness);
  // 1 s against 1.5 s of the same creature
  EXPECT_LT(out[0].result.steps, out[1].result.steps);
  auto pooled = ProcessPoolEvaluator(tasks, 2, 60).evaluate(jobs);
  ASSERT_EQ(pooled.size(), 2u);
  for (int k = 0; k < 2; ++k) EXPECT_EQ(pooled[k].result.fitness, out[k].result.fitness);
}

}  // namespace
}  // namespace bx
