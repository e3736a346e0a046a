// The run page's data (src/io/run_page.h): which replays a bounded page
// keeps, and on a small real run: it opens on the overall best, names every
// generation's best and the first-parent lineages back to generation 0, and
// replays each creature exactly as the run scored it; a run of several
// stages lists its syllabus, each stage with its generations and best.
#include "genome/graph_genotype.h"
#include "io/run_page.h"
#include "eval/evaluate.h"
#include "evolve/evolution.h"
#include "develop/develop.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "run/run.h"
#include "genome/genome_json.h"
#include "support/run_command.h"

namespace {

using namespace bxtest;
using nlohmann::json;

TEST(ReplayChoice, TheBestThenItsLineageThenTheGenerationsBestsThenTheRest) {
  // the best (100), its lineage newest first back to generation 0's 0, the
  // generations' bests (some in the lineage), two others
  std::vector<std::int64_t> lineage = {9, 8, 7, 6, 5, 4, 3, 2, 1, 0};
  std::vector<std::int64_t> bests = {0, 5, 100, 200, 300};
  std::vector<std::int64_t> others = {50, 51};
  auto all = bx::replay_choice(100, lineage, bests, others, 100);
  EXPECT_EQ(all.size(), 15u);  // 1 + 10 + 200 and 300 + 2
  EXPECT_EQ(std::set<std::int64_t>(all.begin(), all.end()).size(), all.size());
  EXPECT_EQ(all.front(), 100);
  EXPECT_EQ(std::vector<std::int64_t>(all.end() - 2, all.end()), others);
  // a cap keeps the best, then the ends of the lineage: the parent and generation 0's ancestor
  EXPECT_EQ(bx::replay_choice(100, lineage, bests, others, 3), (std::vector<std::int64_t>{100, 9, 0}));
  // and its middle (index 4) before the rest of it
  EXPECT_EQ(bx::replay_choice(100, lineage, bests, others, 4), (std::vector<std::int64_t>{100, 9, 0, 5}));
  // once the lineage is in, the last generation's best comes first
  auto twelve = bx::replay_choice(100, lineage, bests, others, 12);
  EXPECT_EQ(twelve.size(), 12u);
  EXPECT_EQ(twelve.back(), 300);
}

class RunPage : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fs::temp_directory_path() / ("bx_run_page_" + std::to_string(::getpid())));
    fs::remove_all(*dir_);
    Outcome r = small_run(*dir_);
    ASSERT_EQ(r.code, 0) << r.err;
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  void SetUp() override {
    auto store = bx::RunStore::open(bx::run_db_path(dir_->string()));
    ASSERT_TRUE(store.ok()) << store.error();
    store_ = std::move(*store);
    auto cfg = bx::read_run_config(store_->meta("config"), "run config");
    ASSERT_TRUE(cfg.ok()) << cfg.error();
    cfg_ = *cfg;
  }
  bx::Result<bx::RunPage> gather(int cap = bx::kRunPageReplays) {
    return bx::gather_run_page(*store_, dir_->string(), cfg_, cfg_.sim, 1, cap);
  }
  static fs::path* dir_;
  std::unique_ptr<bx::RunStore> store_;
  bx::RunConfig cfg_;
};
fs::path* RunPage::dir_ = nullptr;

// the members by id
std::map<std::int64_t, bx::RunMember> by_id(const bx::RunView& run) {
  std::map<std::int64_t, bx::RunMember> out;
  for (const auto& m : run.members) out[m.id] = m;
  return out;
}

TEST_F(RunPage, OpensOnTheBestAndReplaysEachCreatureAsTheRunScoredIt) {
  auto page = gather();
  ASSERT_TRUE(page.ok()) << page.error();
  const bx::RunView& run = page->run;
  // the context
  EXPECT_EQ(run.name, "quick");
  EXPECT_EQ(run.seed, "1");
  EXPECT_EQ(run.dialect, "chaumont2007");
  EXPECT_EQ(run.population, 12);
  EXPECT_EQ(run.planned_generations, 6);
  auto gens = store_->generations();
  ASSERT_EQ(run.generations.size(), gens.size());
  for (std::size_t g = 0; g < gens.size(); ++g) {
    EXPECT_EQ(run.generations[g].rejected, gens[g].rejected);
    EXPECT_EQ(run.generations[g].failed, gens[g].failed);
    EXPECT_EQ(run.generations[g].best_id, gens[g].best_id);
  }
  // the overall best, replayed first
  auto members = by_id(run);
  EXPECT_EQ(run.best_id, store_->best_individual()->id);
  ASSERT_TRUE(members.count(run.best_id));
  EXPECT_EQ(members[run.best_id].replay_index, 0);
  // every generation's best is named, and every first parent back to generation 0
  for (const auto& g : gens) EXPECT_TRUE(members.count(g.best_id)) << g.best_id;
  for (const auto& [id, m] : members) {
    if (m.parent1 >= 0) EXPECT_TRUE(members.count(m.parent1)) << id;
    else EXPECT_EQ(m.gen, 0) << id;
  }
  int depth = 0;
  for (std::int64_t at = run.best_id; members[at].parent1 >= 0; at = members[at].parent1) ++depth;
  EXPECT_GE(depth, 1) << "the small run's best should descend from generation 0";
  // all of them fit under the cap; each replay is its creature's scored evaluation
  ASSERT_EQ(page->replays.size(), run.members.size());
  int elites_evaluated_again = 0;  // (quick evaluates its elite 3 times)
  for (const auto& [id, m] : members) {
    ASSERT_GE(m.replay_index, 0) << id;
    const bx::LabelledReplay& r = page->replays[m.replay_index];
    json replay = json::parse(r.replay_json);
    auto stored = store_->individual(id);
    EXPECT_EQ(m.fitness, stored->fitness) << id;
    EXPECT_EQ(m.evaluations, stored->evaluations) << id;
    // its replay is its first evaluation, which is the stored fitness unless that is a mean
    const double first = replay["result"]["fitness"].get<double>();
    if (stored->evaluations == 1) {
      EXPECT_EQ(first, stored->fitness) << id;
    } else {
      // folded with its re-evaluations, the replayed one gives the stored mean, bit for bit
      bx::Development dev = bx::develop(*bx::graph_genome(*stored->genotype), cfg_.sim.develop);
      ASSERT_TRUE(dev.viable()) << id;
      bx::EvalResult res;
      res.fitness = first;
      EXPECT_EQ(bx::repeated_fitness(*dev.model, cfg_.sim, stored->seed,
                                     bx::elite_repeats(cfg_.evolution, stored->evaluations), res),
                stored->fitness)
          << id;
      ++elites_evaluated_again;
    }
    // (a seed beyond 2^53 is written as text)
    const json& seed = replay["seed"];
    EXPECT_EQ(seed.is_string() ? std::stoull(seed.get<std::string>()) : seed.get<std::uint64_t>(),
              bx::evaluation_seed(1, id))
        << id;
    EXPECT_EQ(r.genome, bx::genome_to_string(*bx::graph_genome(*stored->genotype))) << id;
    EXPECT_EQ(r.label, "individual " + std::to_string(id) + ", generation " + std::to_string(m.gen));
  }
  EXPECT_GT(elites_evaluated_again, 0) << "the small run should show an elite's mean";
}

TEST_F(RunPage, ACapKeepsTheBestAndItsLineageAndSaysWhatItLeftOut) {
  auto page = gather(2);
  ASSERT_TRUE(page.ok()) << page.error();
  const bx::RunView& run = page->run;
  EXPECT_EQ(run.replay_cap, 2);
  ASSERT_EQ(page->replays.size(), 2u);
  auto members = by_id(run);
  ASSERT_GT(members.size(), 2u);
  // the best and its parent have replays; the others are named without one
  const std::int64_t parent = members[run.best_id].parent1;
  int without = 0;
  for (const auto& [id, m] : members) {
    if (id == run.best_id || id == parent) EXPECT_GE(m.replay_index, 0) << id;
    else without += m.replay_index < 0;
  }
  EXPECT_EQ(without, static_cast<int>(members.size()) - 2);
}

TEST_F(RunPage, ShowWritesItAndSaysHowManyCreaturesItReplayed) {
  fs::path page = *dir_ / "page.html";
  Outcome s = bestiary("show " + dir_->string() + " --out " + page.string());
  ASSERT_EQ(s.code, 0) << s.err;
  auto data = json::parse(embedded_data(slurp(page)));
  const json& run = data["run"];
  EXPECT_FALSE(run.contains("stages")) << "a plain run has no syllabus";
  EXPECT_EQ(run["best_id"], store_->best_individual()->id);
  EXPECT_EQ(run["generations"].size(), 6u);
  EXPECT_EQ(data["replays"].size(), run["members"].size());
  EXPECT_NE(s.out.find("(individual " + std::to_string(store_->best_individual()->id) + "); " +
                       std::to_string(data["replays"].size()) + " of " + std::to_string(run["members"].size()) +
                       " creatures replayed"),
            std::string::npos)
      << s.out;
}

// four stages of two generations, stopped in the third: a syllabus graph
// (uses, groups), two stages done, one under way, one not begun
const char* kSyllabus = R"(
[genome]
dialect = "sims1994"
[evolution]
population = 6
generations = 2
[task]
seconds = 1

[[stage]]
name = "forward"

[[stage]]
name = "left"
group = "turn"
[stage.task]
seconds = 2

[[stage]]
name = "face"
uses = ["forward", "left"]
group = "aim"
start = "population"

[[stage]]
name = "fight"
uses = ["face"]
)";

class StagedRunPage : public InTempDir {};

TEST_F(StagedRunPage, ListsTheSyllabusEachStageWithItsGenerationsAndBest) {
  const fs::path cfg = write("syllabus.toml", kSyllabus), run_dir = dir / "r";
  Outcome r = bestiary("run " + cfg.string() + " --workers 0 --quiet --stop-after 5 --out " + run_dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  Outcome s = bestiary("show " + run_dir.string());
  ASSERT_EQ(s.code, 0) << s.err;
  const json run = json::parse(embedded_data(slurp(run_dir / "view.html")))["run"];
  ASSERT_TRUE(run.contains("stages")) << run.dump().substr(0, 400);
  const json& stages = run["stages"];
  ASSERT_EQ(stages.size(), 4u);
  auto store = bx::RunStore::open(bx::run_db_path(run_dir.string()));
  ASSERT_TRUE(store.ok()) << store.error();
  const auto gens = (*store)->generations();
  ASSERT_EQ(gens.size(), 5u);
  // the fittest generation best of generations [from, to)
  auto best_of = [&](int from, int to) {
    double b = gens[from].best;
    for (int g = from; g < to; ++g) b = std::max(b, gens[g].best);
    return b;
  };
  const std::vector<std::string> names = {"forward", "left", "face", "fight"};
  const std::vector<json> uses = {json::array(), json::array(), {"forward", "left"}, {"face"}};
  const std::vector<std::string> groups = {"", "turn", "aim", ""};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(stages[k]["name"], names[k]) << k;
    EXPECT_EQ(stages[k]["uses"], uses[k]) << k;
    EXPECT_EQ(stages[k]["group"], groups[k]) << k;
  }
  // generations numbered through the stages: 0-1, 2-3, then 4 of the third
  EXPECT_EQ(stages[0]["first_gen"], 0);
  EXPECT_EQ(stages[1]["first_gen"], 2);
  EXPECT_EQ(stages[2]["first_gen"], 4);
  EXPECT_EQ(stages[0]["generations"], 2);
  EXPECT_EQ(stages[1]["generations"], 2);
  EXPECT_EQ(stages[2]["generations"], 1);
  EXPECT_EQ(stages[0]["best"].get<double>(), best_of(0, 2));
  EXPECT_EQ(stages[1]["best"].get<double>(), best_of(2, 4));
  EXPECT_EQ(stages[2]["best"].get<double>(), best_of(4, 5));
  // the last is not begun
  EXPECT_TRUE(stages[3]["first_gen"].is_null());
  EXPECT_EQ(stages[3]["generations"], 0);
  EXPECT_TRUE(stages[3]["best"].is_null());
  // the whole run's curve is still there, and the page opens on the stage under way's best
  EXPECT_EQ(run["generations"].size(), 5u);
  EXPECT_EQ(run["best_id"], gens[4].best_id);
}

}  // namespace
