// Every command that takes a creature works for any creature kind: a tiny
// run of the river crossing (a float vector developing into a fixed
// quadruped and its controller) through best, simulate, check, show and
// plot, from the run and from the genotype file `best --out` writes, each
// evaluated exactly as it was scored; and a genotype file that says nothing
// of its creature asks for a config in one line.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sqlite3.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using bxtest::bestiary;
using bxtest::Outcome;
using bxtest::slurp;
using nlohmann::json;

// the tiny run: 6 individuals, 2 s each
constexpr const char* kRiverConfig = R"([genotype]
kind = "river"  # brings the river task, the quadruped's physics and its PD motors
[river]
seconds = 2
[evolution]
algorithm = "steady_state"
population = 6
evaluations = 6
p_asexual = 0
p_crossover = 1
p_graft = 0
)";

// a column of the individual table for one id, as its exact double
double stored(const fs::path& run, std::int64_t id, const char* column = "fitness") {
  sqlite3* db = nullptr;
  sqlite3_stmt* s = nullptr;
  double v = -1e300;
  const std::string sql = std::string("SELECT ") + column + " FROM individual WHERE id = " + std::to_string(id);
  if (sqlite3_open_v2((run / "run.sqlite").c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK &&
      sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK && sqlite3_step(s) == SQLITE_ROW)
    v = sqlite3_column_double(s, 0);
  sqlite3_finalize(s);
  sqlite3_close(db);
  return v;
}

// one run for the whole suite: it is what every test reads
class Kinds : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir = fs::temp_directory_path() / ("bx_kinds_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "river.toml") << kRiverConfig;
    run_outcome = new Outcome(
        bestiary("run " + (dir / "river.toml").string() + " --out " + (dir / "run").string() + " --workers 0 --quiet"));
  }
  static void TearDownTestSuite() {
    fs::remove_all(dir);
    delete run_outcome;
  }
  void SetUp() override { ASSERT_EQ(run_outcome->code, 0) << run_outcome->out << run_outcome->err; }

  static fs::path run() { return dir / "run"; }
  // `best --out FILE` of the run's best, and the best's id
  static std::int64_t best_file(const fs::path& file) {
    Outcome b = bestiary("best " + run().string() + " --out " + file.string());
    EXPECT_EQ(b.code, 0) << b.err;
    return json::parse(slurp(file))["provenance"]["individual"].get<std::int64_t>();
  }

  static fs::path dir;
  static Outcome* run_outcome;
};

fs::path Kinds::dir;
Outcome* Kinds::run_outcome = nullptr;

TEST_F(Kinds, BestWritesAFloatGenotypeFileWithItsProvenance) {
  const fs::path file = dir / "best.json";
  Outcome b = bestiary("best " + run().string() + " --out " + file.string());
  ASSERT_EQ(b.code, 0) << b.err;
  const json j = json::parse(slurp(file));
  EXPECT_EQ(j["format"], "bestiary-genotype");
  EXPECT_EQ(j["version"], 1);
  EXPECT_EQ(j["kind"], "floats");
  EXPECT_EQ(j["genes"].size(), 181u);  // the river crossing's weights
  // the provenance a graph genome file gets
  const json& p = j["provenance"];
  for (const char* k : {"run", "individual", "generation", "fitness", "evaluations", "seed", "genome_hash",
                        "config_hash", "config"})
    EXPECT_TRUE(p.contains(k)) << k;
  EXPECT_EQ(p["run"], run().string());
  EXPECT_NE(p["config"].get<std::string>().find("kind = \"river\""), std::string::npos);
  EXPECT_EQ(p["fitness"].get<double>(), stored(run(), p["individual"].get<std::int64_t>()));
  // to standard output without --out: the same text
  Outcome out = bestiary("best " + run().string());
  ASSERT_EQ(out.code, 0) << out.err;
  EXPECT_EQ(out.out, slurp(file));
}

TEST_F(Kinds, SimulateReproducesTheStoredFitnessFromTheRunAndFromTheFile) {
  const fs::path file = dir / "sim.json";
  const std::int64_t id = best_file(file);
  for (const std::string& target : {run().string(), file.string()}) {
    Outcome s = bestiary("simulate " + target + " --json");
    ASSERT_EQ(s.code, 0) << target << s.err;
    const json j = json::parse(s.out);
    EXPECT_TRUE(j["viable"].get<bool>());
    EXPECT_TRUE(j["as_scored"].get<bool>()) << target;
    EXPECT_EQ(j["fitness"].get<double>(), stored(run(), id)) << target;  // bit for bit
    EXPECT_EQ(j["creature"], "river");
    EXPECT_EQ(j["parts"], 9);
    EXPECT_NEAR(j["seconds"].get<double>(), 2.0, 1e-9);
    // the task's named measures
    EXPECT_TRUE(j["metrics"].contains("level"));
    EXPECT_TRUE(j["metrics"].contains("food eaten"));
    // the text says the measures on one line, and the fitness as stored
    Outcome t = bestiary("simulate " + target);
    ASSERT_EQ(t.code, 0) << target << t.err;
    EXPECT_NE(t.out.find("river creature, 9 parts, 8 joints, 12 effectors"), std::string::npos) << t.out;
    EXPECT_NE(t.out.find("\nlevel 1, levels completed "), std::string::npos) << t.out;
    EXPECT_NE(t.out.find(", food eaten "), std::string::npos) << t.out;
    EXPECT_NE(t.out.find("(the stored fitness, bit for bit)"), std::string::npos) << t.out;
    EXPECT_EQ(t.out.find("distance"), std::string::npos) << t.out;  // the measures say it
  }
}

TEST_F(Kinds, SimulateWritesAReplayOfTheBodyAndItsControllersSignals) {
  const fs::path replay = dir / "replay.json";
  Outcome s = bestiary("simulate " + run().string() + " --replay " + replay.string());
  ASSERT_EQ(s.code, 0) << s.err;
  const json r = json::parse(slurp(replay));
  EXPECT_EQ(r["creature"], "river");
  EXPECT_FALSE(r.contains("dialect"));
  EXPECT_EQ(r["parts"].size(), 9u);
  EXPECT_EQ(r["effectors"].size(), 12u);
  ASSERT_GT(r["frames"].size(), 50u);
  // every frame complete, as the viewer checks it: one pose per part, one
  // value per listed neuron (the controller's signals; frame 0's are zeros)
  EXPECT_GT(r["neurons"].size(), 0u);
  for (const auto& n : r["neurons"]) EXPECT_EQ(n, (json{{"part", -1}, {"fn", "controller"}}));
  for (const auto& f : r["frames"]) {
    EXPECT_EQ(f["poses"].size(), 9u);
    EXPECT_EQ(f["neurons"].size(), r["neurons"].size());
    EXPECT_EQ(f["effectors"].size(), 12u);
  }
  EXPECT_TRUE(r["result"]["metrics"].contains("levels completed"));
  // the same creature, config and seed give the same bytes
  const fs::path again = dir / "again.json";
  const fs::path file = dir / "replayed.json";
  best_file(file);
  ASSERT_EQ(bestiary("simulate " + file.string() + " --replay " + again.string()).code, 0);
  json a = json::parse(slurp(again)), b = r;
  a.erase("genome");
  b.erase("genome");
  EXPECT_EQ(a, b);
}

TEST_F(Kinds, CheckReEvaluatesTheCreatureAsScored) {
  const fs::path file = dir / "check.json";
  const std::int64_t id = best_file(file);
  const std::string quick = " --set check.other_seeds=1 --set check.converge_seeds=1";
  for (const std::string& target : {run().string(), file.string()}) {
    Outcome c = bestiary("check " + target + quick + " --json");
    // 0 passed, 1 failed the gates (a tiny run's creature may well), never bad input
    ASSERT_TRUE(c.code == 0 || c.code == 1) << target << c.out << c.err;
    const json j = json::parse(c.out);
    EXPECT_EQ(j["passed"].get<bool>(), c.code == 0);
    EXPECT_EQ(j["fitness"].get<double>(), stored(run(), id)) << target;
    std::vector<std::string> names;
    for (const auto& v : j["variants"]) names.push_back(v["name"]);
    // one other seed, the steps, the lag, the half rate, clamped and held
    EXPECT_EQ(names, (std::vector<std::string>{"seed 2", "dt/2", "dt/4", "motor lag +10 ms", "brain at 50 Hz",
                                               "clamped", "held"}))
        << c.out;
    EXPECT_EQ(j["effector_sd"].size(), 12u);
    // and in text: the verdict
    Outcome t = bestiary("check " + target + quick);
    EXPECT_EQ(t.code, c.code) << t.out << t.err;
    EXPECT_NE(t.out.find("verdict: "), std::string::npos) << t.out;
  }
}

// A controller whose decision network is silent sets every iota to 0: its
// landscape is flat whatever the layout, so its signals are the same under
// every seed, and check names it open loop; one whose DN raises the
// resource's iota reads each layout's landscape, and is not.
TEST_F(Kinds, CheckNamesAControllerThatSensesNothingOfItsLayoutOpenLoop) {
  const fs::path file = dir / "open_loop.json";
  best_file(file);
  json genome = json::parse(slurp(file));
  constexpr int kDecisionGenes = 4 * 6 + 5 * 4;  // the DN's weights lead the genome
  for (double dn : {0.0, 1.0}) {
    for (int g = 0; g < kDecisionGenes; ++g) genome["genes"][g] = dn;
    std::ofstream(file) << genome.dump();
    Outcome c = bestiary("check " + file.string() + " --set check.other_seeds=3 --json");
    ASSERT_TRUE(c.code == 0 || c.code == 1) << c.out << c.err;
    const json j = json::parse(c.out);
    const std::string notes = j["notes"].dump();
    if (dn == 0) {
      EXPECT_TRUE(j["open_loop"].get<bool>()) << c.out;
      EXPECT_NE(notes.find("open loop: under all 3 other seeds"), std::string::npos) << notes;
    } else {
      EXPECT_FALSE(j["open_loop"].get<bool>()) << c.out;
      EXPECT_EQ(notes.find("open loop"), std::string::npos) << notes;
    }
  }
}

TEST_F(Kinds, ShowWritesTheRunsPageAndPlotItsCurves) {
  const fs::path page = dir / "view.html";
  Outcome s = bestiary("show " + run().string() + " --out " + page.string());
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_NE(s.out.find("viewer written to " + page.string()), std::string::npos) << s.out;
  const json data = json::parse(bxtest::embedded_data(slurp(page)));
  EXPECT_EQ(data["run"]["dialect"], "river");  // what the run evolves
  ASSERT_GE(data["replays"].size(), 1u);
  const json& replay = data["replays"][0]["replay"];
  EXPECT_EQ(replay["creature"], "river");
  // the page's download is the genotype file's text
  EXPECT_EQ(json::parse(data["replays"][0]["genome"].get<std::string>())["kind"], "floats");
  // one creature's page, from the file
  const fs::path file = dir / "show.json";
  best_file(file);
  Outcome one = bestiary("show " + file.string() + " --out " + (dir / "one.html").string());
  ASSERT_EQ(one.code, 0) << one.err;
  EXPECT_NE(one.out.find("(the stored fitness, bit for bit)"), std::string::npos) << one.out;
  EXPECT_NE(one.out.find("\nlevel 1, levels completed "), std::string::npos) << one.out;
  // the fitness plot
  Outcome p = bestiary("plot " + run().string() + " --out " + (dir / "plot.svg").string());
  ASSERT_EQ(p.code, 0) << p.err;
  EXPECT_NE(slurp(dir / "plot.svg").find("<svg"), std::string::npos);
  // its task's metrics instead: one curve per level, over tournaments
  Outcome m = bestiary("plot " + run().string() + " --metric \"level 2 completed\" --metric \"level 5\" --out " +
                       (dir / "levels.svg").string());
  ASSERT_EQ(m.code, 0) << m.err;
  const std::string levels = slurp(dir / "levels.svg");
  EXPECT_NE(levels.find(">level 2 completed</text>"), std::string::npos);
  EXPECT_NE(levels.find(">level 5 completed</text>"), std::string::npos);
  EXPECT_EQ(levels.find(">level 1 completed</text>"), std::string::npos);
  EXPECT_NE(levels.find(">tournaments</text>"), std::string::npos);
  EXPECT_NE(levels.find(">share of evaluations (%)</text>"), std::string::npos);
  Outcome none = bestiary("plot " + run().string() + " --metric speed --out " + (dir / "none.svg").string());
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("--metric: no metric of "), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("matches \"speed\" (it has: level, levels completed, food eaten"), std::string::npos)
      << none.err;
  EXPECT_FALSE(fs::exists(dir / "none.svg"));
}

TEST_F(Kinds, AFloatGenotypeFileWithoutProvenanceNeedsAConfig) {
  // the genes of the run's best, without where they came from
  const fs::path best = dir / "plain_best.json";
  const std::int64_t id = best_file(best);
  json j = json::parse(slurp(best));
  const fs::path plain = dir / "plain.json";
  std::ofstream(plain) << json{{"kind", "floats"}, {"genes", j["genes"]}}.dump();
  Outcome r = bestiary("simulate " + plain.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "bestiary: " + plain.string() +
                       ": a floats genotype without provenance: give --config, a config whose genotype.kind "
                       "develops it\n");
  for (const char* cmd : {"check", "show", "render"}) {
    Outcome c = bestiary(std::string(cmd) + " " + plain.string() + (std::string(cmd) == "render" ? " --out x.mp4" : ""));
    EXPECT_EQ(c.code, 2) << cmd;
    EXPECT_EQ(c.err, r.err) << cmd;
  }
  // with the run's config and the best's seed it is the best's evaluation again
  const std::string seed = j["provenance"]["seed"];
  Outcome s = bestiary("simulate " + plain.string() + " --config " + (run() / "config.toml").string() + " --seed " +
                       seed + " --json");
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_EQ(json::parse(s.out)["fitness"].get<double>(), stored(run(), id));
  // a config of stages (a staged preset's file, rivercrossing-small's): its
  // last stage's, whose best such a run reports
  const fs::path staged = dir / "staged.toml";
  std::ofstream(staged) << "[genotype]\nkind = \"river\"\n[river]\nseconds = 2\n[[stage]]\nname = 'short'\n"
                           "[stage.river]\nseconds = 1\n[[stage]]\nname = 'long'\nstart = \"population\"\n";
  Outcome st = bestiary("simulate " + plain.string() + " --config " + staged.string());
  ASSERT_EQ(st.code, 0) << st.err;
  EXPECT_NE(st.out.find("simulated 2.00 s"), std::string::npos) << st.out;
  // `config` of it prints each stage as a run stores it
  Outcome sc = bestiary("config --config " + staged.string());
  ASSERT_EQ(sc.code, 0) << sc.err;
  EXPECT_NE(sc.out.find("[[stage]]\nname = 'short'"), std::string::npos) << sc.out;
  EXPECT_NE(sc.out.find("[[stage]]\nname = 'long'"), std::string::npos) << sc.out;
  // a preset's name is a config wherever a config is taken, as `run` takes it
  Outcome pc = bestiary("config --config rivercrossing-small");
  ASSERT_EQ(pc.code, 0) << pc.err;
  EXPECT_NE(pc.out.find("name = 'levels'"), std::string::npos) << pc.out;
  Outcome ps = bestiary("simulate " + plain.string() + " --config rivercrossing-small --set river.seconds=1");
  ASSERT_EQ(ps.code, 0) << ps.err;
  EXPECT_NE(ps.out.find("simulated 1.00 s"), std::string::npos) << ps.out;
  Outcome none = bestiary("config --config rivercrossing-smal");
  EXPECT_EQ(none.code, 2);
  EXPECT_EQ(none.err, "bestiary: rivercrossing-smal: no such config file, and no preset of that name "
                      "(did you mean \"rivercrossing-small\"?) (`" BESTIARY_BINARY " presets` lists them)\n");
  // a config of another creature kind, or genes its kind does not take: one line each
  const fs::path graph = dir / "graph.toml";
  std::ofstream(graph) << "[task]\nseconds = 2\n";
  Outcome g = bestiary("simulate " + plain.string() + " --config " + graph.string());
  EXPECT_EQ(g.code, 2);
  EXPECT_EQ(g.err, "bestiary: " + graph.string() + ": genotype.kind \"graph\" develops graph genotypes, but " +
                       plain.string() + " holds a floats genotype\n");
  const fs::path shorter = dir / "short.json";
  std::ofstream(shorter) << R"({"kind": "floats", "genes": [0.5, 0.25]})";
  Outcome s2 = bestiary("simulate " + shorter.string() + " --config " + (run() / "config.toml").string());
  EXPECT_EQ(s2.code, 2);
  EXPECT_EQ(s2.err, "bestiary: " + shorter.string() +
                        ": floats: genes: need 181 values, got 2 (genotype.kind \"river\")\n");
  // a graph genome with the river's config: the same check the other way round
  Outcome w = bestiary("simulate " + bxtest::creature("walker.json") + " --config " +
                       (run() / "config.toml").string());
  EXPECT_EQ(w.code, 2);
  EXPECT_EQ(w.err, "bestiary: " + (run() / "config.toml").string() +
                       ": genotype.kind \"river\" develops floats genotypes, but " + bxtest::creature("walker.json") +
                       " holds a graph genotype\n");
}

}  // namespace
