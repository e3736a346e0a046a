// The motif run (preset rivercrossing-motif): a creature kind without a body
// evolved, replayed by `simulate` and `best`, refused by the commands that
// need a body; and the river runs' motif file, recorded with its hash.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sqlite3.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "core/hash.h"
#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using bxtest::bestiary;
using bxtest::Outcome;
using bxtest::slurp;
using nlohmann::json;

// every individual as (id, genome, the exact bits of its fitness), and the generation rows
std::string exact_individuals(const fs::path& run) {
  sqlite3* db = nullptr;
  sqlite3_stmt* s = nullptr;
  std::string out;
  if (sqlite3_open_v2((run / "run.sqlite").c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK &&
      sqlite3_prepare_v2(db, "SELECT id, genome, fitness, parent1, parent2, operator FROM individual ORDER BY id", -1,
                         &s, nullptr) == SQLITE_OK)
    while (sqlite3_step(s) == SQLITE_ROW) {
      char bits[64];
      std::snprintf(bits, sizeof bits, "%a", sqlite3_column_double(s, 2));
      out += std::to_string(sqlite3_column_int64(s, 0)) + "|" +
             reinterpret_cast<const char*>(sqlite3_column_text(s, 1)) + "|" + bits + "|" +
             std::to_string(sqlite3_column_int64(s, 3)) + "|" + std::to_string(sqlite3_column_int64(s, 4)) + "|" +
             reinterpret_cast<const char*>(sqlite3_column_text(s, 5)) + "\n";
    }
  sqlite3_finalize(s);
  sqlite3_close(db);
  return out;
}

// the fitness the run stored for its best
double stored_best(const fs::path& run) {
  const std::string rows =
      bxtest::query(run / "run.sqlite", "SELECT best_id FROM generation ORDER BY gen DESC LIMIT 1");
  sqlite3* db = nullptr;
  sqlite3_stmt* s = nullptr;
  double v = -1;
  const std::string sql = "SELECT fitness FROM individual WHERE id = " + rows.substr(0, rows.find('|'));
  if (sqlite3_open_v2((run / "run.sqlite").c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK &&
      sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK && sqlite3_step(s) == SQLITE_ROW)
    v = sqlite3_column_double(s, 0);
  sqlite3_finalize(s);
  sqlite3_close(db);
  return v;
}

// a short motif run: the preset scaled down, 30 individuals and 90 tournaments
const std::string kShort =
    " --set evolution.population=30 --set evolution.evaluations=90 --set evolution.report_every=30 --seed 4 --quiet";

// one run for the suite (and the same with two workers)
class MotifRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir = fs::temp_directory_path() / ("bx_motif_run_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (int w = 1; w <= 2; ++w)
      outcome[w - 1] = new Outcome(bestiary("run rivercrossing-motif" + kShort + " --workers " + std::to_string(w) +
                                            " --out " + run(w).string()));
  }
  static void TearDownTestSuite() {
    fs::remove_all(dir);
    for (Outcome*& o : outcome) delete o;
  }
  void SetUp() override {
    for (Outcome* o : outcome) ASSERT_EQ(o->code, 0) << o->out << o->err;
  }
  static fs::path run(int workers = 1) { return dir / ("run" + std::to_string(workers)); }
  // a path under a folder that does not exist: a command that writes nothing leaves it so
  static fs::path unmade(const std::string& name) { return dir / "unmade" / name; }

  static fs::path dir;
  static Outcome* outcome[2];
};

fs::path MotifRun::dir;
Outcome* MotifRun::outcome[2] = {nullptr, nullptr};

TEST_F(MotifRun, ItIsTheSameRunWithOneOrTwoWorkers) {
  const std::string one = exact_individuals(run(1));
  EXPECT_EQ(bxtest::count_lines(one), 120);  // 30 + 90 tournaments, each child evaluated once
  EXPECT_EQ(exact_individuals(run(2)), one);
  EXPECT_EQ(stored_best(run(2)), stored_best(run(1)));
  EXPECT_GT(stored_best(run(1)), 0);
  // what it evolves, and where its curves are (no creature to show)
  EXPECT_NE(outcome[0]->out.find("its curves: "), std::string::npos) << outcome[0]->out;
  EXPECT_EQ(outcome[0]->out.find("watch the run"), std::string::npos) << outcome[0]->out;
  // its children are mutated single-point crossovers, as the search's
  EXPECT_EQ(bxtest::query(run(1) / "run.sqlite", "SELECT DISTINCT operator FROM individual WHERE id >= 30"),
            "crossover|\n");
}

TEST_F(MotifRun, SimulateReproducesTheStoredBestAndSaysItsMeasures) {
  Outcome j = bestiary("simulate " + run().string() + " --json");
  ASSERT_EQ(j.code, 0) << j.err;
  const json r = json::parse(j.out);
  EXPECT_EQ(r["creature"], "motif");
  EXPECT_EQ(r["body"], false);
  EXPECT_TRUE(r["viable"].get<bool>());
  EXPECT_TRUE(r["as_scored"].get<bool>());
  EXPECT_EQ(r["fitness"].get<double>(), stored_best(run()));  // bit for bit
  EXPECT_EQ(r["steps"], 0);                                    // no physics
  for (const char* m : {"oscillation", "quiescence", "dominant hz", "quiet power"})
    EXPECT_TRUE(r["metrics"].contains(m)) << m;
  EXPECT_EQ(r["replay"], nullptr);
  Outcome t = bestiary("simulate " + run().string());
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_NE(t.out.find("motif creature, no body\n"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("\noscillation "), std::string::npos) << t.out;
  EXPECT_NE(t.out.find(", dominant hz "), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("(the stored fitness, bit for bit)"), std::string::npos) << t.out;
  // and any individual of it
  Outcome first = bestiary("simulate " + run().string() + ":0 --json");
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_TRUE(json::parse(first.out)["as_scored"].get<bool>());
}

TEST_F(MotifRun, BestWritesItsGenotypeFileWhichSimulatesAsScored) {
  const fs::path file = dir / "best.json";
  Outcome b = bestiary("best " + run().string() + " --out " + file.string());
  ASSERT_EQ(b.code, 0) << b.err;
  const json j = json::parse(slurp(file));
  EXPECT_EQ(j["kind"], "floats");
  EXPECT_EQ(j["genes"].size(), 15u);
  EXPECT_TRUE(j["provenance"].contains("config"));
  Outcome s = bestiary("simulate " + file.string() + " --json");
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_TRUE(json::parse(s.out)["as_scored"].get<bool>());
  EXPECT_EQ(json::parse(s.out)["fitness"].get<double>(), stored_best(run()));
}

TEST_F(MotifRun, PlotDrawsItsMeasuresAsMeans) {
  const fs::path svg = dir / "oscillation.svg";
  Outcome p = bestiary("plot " + run().string() + " --metric oscillation --out " + svg.string());
  ASSERT_EQ(p.code, 0) << p.err;
  const std::string text = slurp(svg);
  EXPECT_NE(text.find("oscillation"), std::string::npos);
  EXPECT_NE(text.find("mean over the evaluations"), std::string::npos);
  // 4 report rows (generation 0 and 3 intervals of 30 tournaments), each with its measures
  EXPECT_EQ(bxtest::query(run() / "run.sqlite", "SELECT count(*) FROM generation_metric WHERE name = 'oscillation'"),
            "4|\n");
}

TEST_F(MotifRun, CommandsThatNeedABodyRefuseInOneLineAndWriteNothing) {
  const std::string best = run().string();
  const fs::path file = dir / "refused.json";
  ASSERT_EQ(bestiary("best " + best + " --out " + file.string()).code, 0);
  struct Case {
    std::string args, error;
  };
  const std::string no_body = "bestiary: genotype.kind \"motif\" has no body: ";
  const Case cases[] = {
      {"render " + best + " --out " + unmade("best.mp4").string(), no_body + "nothing to render\n"},
      {"render " + file.string() + " --out " + unmade("file.gif").string(), no_body + "nothing to render\n"},
      {"show " + best + ":5 --out " + unmade("five.html").string(), no_body + "nothing to show\n"},
      {"show " + file.string() + " --out " + unmade("file.html").string(), no_body + "nothing to show\n"},
      {"check " + best, no_body + "nothing to check\n"},
      {"check " + file.string() + " --json", no_body + "nothing to check\n"},
      {"simulate " + best + " --replay " + unmade("replay.json").string(),
       "bestiary: --replay: genotype.kind \"motif\" has no body: nothing to replay\n"},
      {"simulate " + best + " --seconds 5", "bestiary: --seconds: genotype.kind \"motif\" has no body: no task to lengthen\n"},
      {"show " + best, no_body + "no creature to show (its curves: `" + std::string(BESTIARY_BINARY) + " plot " + best +
                           " --out fitness.svg`, and --metric NAME)\n"},
  };
  for (const Case& c : cases) {
    Outcome o = bestiary(c.args);
    EXPECT_EQ(o.code, 2) << c.args;
    EXPECT_EQ(o.err, c.error) << c.args;
    EXPECT_EQ(o.out, "") << c.args;
  }
  EXPECT_FALSE(fs::exists(dir / "unmade"));
  EXPECT_FALSE(fs::exists(run() / "view.html"));
}

TEST_F(MotifRun, ARiverRunRecordsTheMotifFileItReadAndItsHash) {
  // the preset names the shipped file; the run's resolved config records it and its hash
  const fs::path river = dir / "river";
  const std::string tiny =
      " --set evolution.population=3 --set evolution.evaluations=0 --set river.seconds=0.05 --workers 0 --quiet";
  Outcome r = bestiary("run rivercrossing-small" + tiny + " --out " + river.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string shipped = slurp(std::string(BESTIARY_SOURCE_DIR) + "/motifs/stanton2015-found.json");
  const std::string cfg = slurp(river / "config.toml");
  EXPECT_NE(cfg.find("\nfile = \"stanton2015-found\"\nhash = \"" + bx::fnv1a64_hex(shipped) + "\"\n"),
            std::string::npos)
      << cfg;
  // a motif run's best, named by its path: its genes are the motif, its hash recorded
  const fs::path file = dir / "evolved.json";
  ASSERT_EQ(bestiary("best " + run().string() + " --out " + file.string()).code, 0);
  const fs::path mine = dir / "river-mine";
  r = bestiary("run rivercrossing-small" + tiny + " --set motif.file=" + file.string() + " --out " + mine.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string own = slurp(mine / "config.toml");
  EXPECT_NE(own.find("\nfile = \"" + file.string() + "\"\nhash = \"" + bx::fnv1a64_hex(slurp(file)) + "\"\n"),
            std::string::npos)
      << own;
  EXPECT_EQ(own.find("w0 = [-0.7863092507538241,"), std::string::npos) << "still the shipped motif";
  // and its best simulates as scored, whatever becomes of the file
  fs::remove(file);
  Outcome s = bestiary("simulate " + mine.string() + " --json");
  ASSERT_EQ(s.code, 0) << s.err;
  EXPECT_TRUE(json::parse(s.out)["as_scored"].get<bool>());
}

TEST_F(MotifRun, ABadMotifFileStopsARunBeforeItStartsNamingTheFile) {
  const fs::path missing = dir / "missing.json";
  const fs::path out = dir / "never";
  Outcome r = bestiary("run rivercrossing-small --set motif.file=" + missing.string() + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "bestiary: --set motif.file=" + missing.string() + ": motif.file: \"" + missing.string() +
                       "\": no shipped motif of that name (shipped: stanton2015-found) and no such file\n");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
