// `bestiary run`, `resume`, `best`, `presets` end to end, including a run
// killed with SIGKILL mid-generation and resumed.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/run_command.h"
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace {

namespace fs = std::filesystem;
using bxtest::Outcome;
using bxtest::bestiary;

using bxtest::query;

std::string dump(const fs::path& dir) {
  fs::path db = dir / "run.sqlite";
  return query(db, "SELECT * FROM generation ORDER BY gen") +
         query(db, "SELECT * FROM individual ORDER BY id");
}

class RunCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("bx_runcli_" + std::to_string(::getpid()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "small.toml") << "# a small test run\n[genome]\ndialect = \"sims1994\"\n"
                                         "[evolution]\npopulation = 12\ngenerations = 5\n[task]\nseconds = 2\n";
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

TEST_F(RunCli, KilledMidRunAndResumedEndsExactlyAsUninterrupted) {
  std::string cfg = (dir / "small.toml").string();
  ASSERT_EQ(bestiary("run " + cfg + " --out " + (dir / "whole").string() + " --workers 2 --quiet").code, 0);
  std::string expected = dump(dir / "whole");
  ASSERT_NE(expected.find("\n"), std::string::npos);

  // start the same run, SIGKILL it as soon as its first generations are stored
  fs::path killed = dir / "killed";
  pid_t pid = ::fork();
  if (pid == 0) {
    ::execl(BESTIARY_BINARY, BESTIARY_BINARY, "run", cfg.c_str(), "--out", killed.c_str(), "--workers",
            "2", "--quiet", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  auto t0 = std::chrono::steady_clock::now();
  while (query(killed / "run.sqlite", "SELECT count(*) FROM generation") < "2" &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be killed";
  EXPECT_NE(dump(killed), expected);

  Outcome r = bestiary("resume " + killed.string() + " --workers 1 --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(dump(killed), expected);

  // the best genome so far, as a genome file that simulate accepts
  Outcome b = bestiary("best " + killed.string() + " --out " + (dir / "best.json").string());
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_NE(b.err.find("best so far: individual"), std::string::npos) << b.err;
  // and its stored fitness is reproduced exactly by the command `best` prints
  auto cmd = b.err.find("bestiary simulate ");
  ASSERT_NE(cmd, std::string::npos) << b.err;
  std::string args = b.err.substr(cmd + 9, b.err.find('\n', cmd) - cmd - 9);
  Outcome s = bestiary(args + " --json");
  ASSERT_EQ(s.code, 0) << s.err;
  std::string fit = query(killed / "run.sqlite", "SELECT max(fitness) FROM individual");
  auto j = s.out.find("\"fitness\":");
  ASSERT_NE(j, std::string::npos);

  // the run in the viewer: every generation, opened on the best
  Outcome v = bestiary("show " + killed.string() + " --out " + (dir / "view.html").string());
  ASSERT_EQ(v.code, 0) << v.err;
  auto run = nlohmann::json::parse(bxtest::embedded_data(bxtest::slurp(dir / "view.html")))["run"];
  ASSERT_EQ(run["generations"].size(), 5u);
  double top = 0;
  for (const auto& g : run["generations"]) top = std::max(top, g["best"].get<double>());
  auto best = std::find_if(run["members"].begin(), run["members"].end(),
                           [&](const nlohmann::json& m) { return m["id"] == run["best_id"]; });
  ASSERT_NE(best, run["members"].end());
  EXPECT_EQ((*best)["fitness"].get<double>(), top);
  EXPECT_NE(v.out.find("5 generations"), std::string::npos) << v.out;

  // and its fitness plot, as SVG (three curves) and as PNG (rendered by Chromium)
  ASSERT_EQ(bestiary("plot " + killed.string() + " --out " + (dir / "fit.svg").string()).code, 0);
  std::ifstream svg_in(dir / "fit.svg");
  std::stringstream svg;
  svg << svg_in.rdbuf();
  EXPECT_EQ(svg.str().rfind("<svg", 0), 0u);
  std::size_t polylines = 0;
  for (auto at = svg.str().find("<polyline"); at != std::string::npos; at = svg.str().find("<polyline", at + 1))
    ++polylines;
  EXPECT_EQ(polylines, 3u);
  Outcome png = bestiary("plot " + killed.string() + " --out " + (dir / "fit.png").string() +
                         " --width 640 --height 400");
  ASSERT_EQ(png.code, 0) << png.err;
  std::ifstream png_in(dir / "fit.png", std::ios::binary);
  std::string magic(8, '\0');
  png_in.read(magic.data(), 8);
  EXPECT_EQ(magic, std::string("\x89PNG\r\n\x1a\n", 8));
  Outcome bad = bestiary("plot " + killed.string() + " --out " + (dir / "fit.jpg").string());
  EXPECT_EQ(bad.code, 2);
  EXPECT_EQ(bad.err, "bestiary: --out: expected a .svg or .png file, got \"" + (dir / "fit.jpg").string() + "\"\n");
  // the browser BESTIARY_CHROMIUM names, as for render: one that is not there is named, and no file
  const fs::path none = dir / "no-chromium", unmade = dir / "unmade.png";
  Outcome missing = bxtest::run_command("BESTIARY_CHROMIUM=" + none.string() + " " + BESTIARY_BINARY + " plot " +
                                        killed.string() + " --out " + unmade.string());
  EXPECT_EQ(missing.code, 2);
  EXPECT_EQ(missing.err, "bestiary: BESTIARY_CHROMIUM: no such program: " + none.string() + "\n");
  EXPECT_FALSE(fs::exists(unmade));
  double stored = std::stod(fit.substr(0, fit.find('|')));  // sqlite prints 15 digits
  EXPECT_NEAR(std::stod(s.out.substr(j + 10)), stored, 1e-13 * std::abs(stored));
}

TEST_F(RunCli, InterruptStopsAtAGenerationBoundaryAndSaysHowToResume) {
  std::string cfg = (dir / "small.toml").string();
  fs::path run = dir / "interrupted";
  pid_t pid = ::fork();
  if (pid == 0) {
    std::freopen((dir / "stderr.txt").c_str(), "w", stderr);
    ::execl(BESTIARY_BINARY, BESTIARY_BINARY, "run", cfg.c_str(), "--out", run.c_str(), "--workers", "2",
            "--quiet", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  auto t0 = std::chrono::steady_clock::now();
  while (query(run / "run.sqlite", "SELECT count(*) FROM generation") < "1" &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  std::ifstream e(dir / "stderr.txt");
  std::stringstream ss;
  ss << e.rdbuf();
  EXPECT_NE(ss.str().find("interrupted; continue with: " + std::string(BESTIARY_BINARY) + " resume " + run.string()),
            std::string::npos)
      << ss.str();
  EXPECT_EQ(bestiary("resume " + run.string() + " --quiet").code, 0);
  EXPECT_EQ(query(run / "run.sqlite", "SELECT count(*) FROM generation"), "5|\n");
}

// the stored fitness of individual `id`, exactly (SQLite's own printing keeps 15 digits)
double stored_fitness(const fs::path& run, const std::string& id) {
  sqlite3* db = nullptr;
  double v = -1e300;
  sqlite3_stmt* s = nullptr;
  if (sqlite3_open_v2((run / "run.sqlite").c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK &&
      sqlite3_prepare_v2(db, ("SELECT fitness FROM individual WHERE id = " + id).c_str(), -1, &s, nullptr) ==
          SQLITE_OK &&
      sqlite3_step(s) == SQLITE_ROW)
    v = sqlite3_column_double(s, 0);
  sqlite3_finalize(s);
  sqlite3_close(db);
  return v;
}

// the "fitness" of simulate --json's output
double json_fitness(const std::string& out) {
  auto at = out.find("\"fitness\":");
  return at == std::string::npos ? -1e300 : std::strtod(out.c_str() + at + 10, nullptr);
}

TEST_F(RunCli, ACreatureNamedInARunIsEvaluatedExactlyAsScored) {
  fs::path run = dir / "run";
  ASSERT_EQ(bestiary("run " + (dir / "small.toml").string() + " --out " + run.string() + " --quiet").code, 0);
  // every individual keeps the seed it was evaluated with
  EXPECT_EQ(query(run / "run.sqlite", "SELECT count(*) FROM individual WHERE seed IS NULL OR seed = ''"), "0|\n");
  std::string best = query(run / "run.sqlite", "SELECT best_id FROM generation ORDER BY best DESC LIMIT 1");
  best = best.substr(0, best.find('|'));
  std::string gen2 = query(run / "run.sqlite", "SELECT best_id FROM generation WHERE gen = 2");
  gen2 = gen2.substr(0, gen2.find('|'));
  std::string some = query(run / "run.sqlite", "SELECT id FROM individual WHERE gen = 1 AND failure = '' LIMIT 1");
  some = some.substr(0, some.find('|'));
  struct Named {
    std::string target, id;
  } named[] = {{run.string(), best}, {run.string() + ":" + some, some}, {run.string() + ":gen=2", gen2},
               {run.string() + " --id " + some, some}, {run.string() + " --gen 2", gen2}};
  for (const auto& n : named) {
    Outcome s = bestiary("simulate " + n.target + " --json");
    ASSERT_EQ(s.code, 0) << n.target << s.err;
    EXPECT_EQ(json_fitness(s.out), stored_fitness(run, n.id)) << n.target;  // bit for bit
    EXPECT_NE(s.out.find("\"as_scored\":true"), std::string::npos) << s.out;
    if (n.target == run.string()) continue;  // a run directory alone shows the run's page
    Outcome v = bestiary("show " + n.target + " --out " + (dir / "one.html").string());
    ASSERT_EQ(v.code, 0) << n.target << v.err;
    EXPECT_NE(v.out.find("(the stored fitness, bit for bit)"), std::string::npos) << v.out;
  }
  // `best --out` writes the genome with its provenance: the file alone replays the scored evaluation
  fs::path file = dir / "picked.json";
  Outcome b = bestiary("best " + run.string() + ":" + some + " --out " + file.string());
  ASSERT_EQ(b.code, 0) << b.err;
  Outcome f = bestiary("simulate " + file.string() + " --json");
  ASSERT_EQ(f.code, 0) << f.err;
  EXPECT_EQ(json_fitness(f.out), stored_fitness(run, some));
  EXPECT_NE(f.out.find("\"as_scored\":true"), std::string::npos) << f.out;
  // and says plainly when it is told to use other settings
  Outcome other = bestiary("simulate " + file.string() + " --seed 5");
  ASSERT_EQ(other.code, 0) << other.err;
  EXPECT_NE(other.out.find("not as scored: --seed given"), std::string::npos) << other.out;
  // only the seed changes: the run's config (2 s evaluations; the dialect's are 10 s) stays
  EXPECT_NE(other.out.find("simulated 2.00 s"), std::string::npos) << other.out;
  Outcome longer = bestiary("simulate " + run.string() + ":" + some + " --seconds 3");
  EXPECT_NE(longer.out.find("not as scored"), std::string::npos) << longer.out;
  EXPECT_EQ(longer.out.find("bit for bit"), std::string::npos) << longer.out;

  // a database from before individuals kept their seed: the seed is derived as it was then
  ASSERT_EQ(query(run / "run.sqlite", "SELECT 1"), "1|\n");
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open((run / "run.sqlite").c_str(), &db), SQLITE_OK);
    EXPECT_EQ(sqlite3_exec(db, bxtest::kBeforeChecksums, nullptr, nullptr, nullptr), SQLITE_OK);
    EXPECT_EQ(sqlite3_exec(db, "ALTER TABLE individual DROP COLUMN seed", nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
  }
  Outcome old = bestiary("simulate " + run.string() + ":" + some + " --json");
  ASSERT_EQ(old.code, 0) << old.err;
  EXPECT_EQ(json_fitness(old.out), stored_fitness(run, some));

  // names that do not resolve are one line and exit code 2
  for (const auto& [args, error] : std::vector<std::pair<std::string, std::string>>{
           {"simulate " + run.string() + ":999999", run.string() + ": no individual 999999"},
           {"simulate " + run.string() + ":gen=77", run.string() + ": no generation 77 (generations 0 to 4)"},
           {"simulate " + run.string() + ":x1",
            run.string() + ":x1: expected RUN_DIR:ID (an individual's id) or RUN_DIR:gen=G"},
           {"simulate " + run.string() + ":3 --gen 1",
            "--id/--gen: the creature is already named by \"" + run.string() + ":3\""},
           {"simulate " + run.string() + " --seed 3",
            "--seed: a run's creature is evaluated with its own stored evaluation seed"},
           {"show " + run.string() + " --seed 3",
            "--config/--seed/--set: a run's page shows its creatures as they were scored (name one, RUN_DIR:ID, "
            "to vary its settings)"},
           {"simulate " + file.string() + " --id 3",
            "--id/--gen: name an individual of a run; " + file.string() + " is a genome file"},
       }) {
    Outcome r = bestiary(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(r.err, "bestiary: " + error + "\n") << args;
  }
}

TEST_F(RunCli, ALengthenedRunEndsExactlyAsARunConfiguredThatLong) {
  std::string cfg = (dir / "small.toml").string();  // 5 generations
  ASSERT_EQ(bestiary("run " + cfg + " --out " + (dir / "whole").string() + " --quiet").code, 0);
  fs::path run = dir / "short";
  ASSERT_EQ(bestiary("run " + cfg + " --out " + run.string() + " --set evolution.generations=3 --quiet").code, 0);
  Outcome done = bestiary("resume " + run.string());
  ASSERT_EQ(done.code, 0) << done.err;
  EXPECT_NE(done.out.find(run.string() + ": already complete (3 of 3 generations"), std::string::npos) << done.out;
  Outcome shorter = bestiary("resume " + run.string() + " --set evolution.generations=2");
  EXPECT_EQ(shorter.code, 2);
  EXPECT_EQ(shorter.err, "bestiary: --set evolution.generations=2: the run has done 3 generations already\n");
  Outcome other = bestiary("resume " + run.string() + " --set task.seconds=3");
  EXPECT_EQ(other.code, 2);
  Outcome longer = bestiary("resume " + run.string() + " --set evolution.generations=5");
  ASSERT_EQ(longer.code, 0) << longer.err;
  EXPECT_NE(longer.out.find("resuming " + run.string() + " at generation 3 of 5"), std::string::npos) << longer.out;
  EXPECT_EQ(dump(run), dump(dir / "whole"));
  std::ifstream toml(run / "config.toml");
  std::stringstream text;
  text << toml.rdbuf();
  EXPECT_NE(text.str().find("generations = 5"), std::string::npos);
}

// A run database written before individuals kept their genotype's kind (all
// were graph genomes) resumes and ends as a run that always had it.
TEST_F(RunCli, ARunStoredBeforeGenotypeKindsResumesExactly) {
  std::string cfg = (dir / "small.toml").string();  // 5 generations
  ASSERT_EQ(bestiary("run " + cfg + " --out " + (dir / "whole").string() + " --quiet").code, 0);
  fs::path run = dir / "old";
  ASSERT_EQ(bestiary("run " + cfg + " --out " + run.string() + " --stop-after 2 --quiet").code, 0);
  EXPECT_EQ(query(run / "run.sqlite", "SELECT DISTINCT kind FROM individual"), "graph|\n");
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open((run / "run.sqlite").c_str(), &db), SQLITE_OK);
    EXPECT_EQ(sqlite3_exec(db, bxtest::kBeforeChecksums, nullptr, nullptr, nullptr), SQLITE_OK);
    EXPECT_EQ(sqlite3_exec(db, "ALTER TABLE individual DROP COLUMN kind", nullptr, nullptr, nullptr), SQLITE_OK);
    sqlite3_close(db);
  }
  Outcome r = bestiary("resume " + run.string() + " --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const char* rows = "SELECT id, gen, genome, fitness, distance, parent1, parent2, operator, failure, seed, kind "
                     "FROM individual ORDER BY id";
  EXPECT_EQ(query(run / "run.sqlite", rows), query(dir / "whole" / "run.sqlite", rows));
  const char* gens = "SELECT gen, evaluations, best, mean, median, best_id, rejected, failed FROM generation ORDER BY gen";
  EXPECT_EQ(query(run / "run.sqlite", gens), query(dir / "whole" / "run.sqlite", gens));
  // the generations it stored after (and the one it resumed at) carry checksums, and verify checks them
  EXPECT_EQ(query(run / "run.sqlite", "SELECT count(digest) FROM generation"), "3|\n");
  Outcome v = bestiary("verify " + run.string());
  EXPECT_EQ(v.code, 0) << v.err;
  EXPECT_NE(v.out.find("stored before runs kept checksums were read but cannot be checked"), std::string::npos) << v.out;
}

// `show RUN RUN...`: each run's best as scored, on one page, named by its folder
TEST_F(RunCli, ShowOfSeveralRunsPutsEachBestAsScoredOnOnePage) {
  const std::string cfg = (dir / "small.toml").string();
  for (const char* seed : {"1", "2"})
    ASSERT_EQ(bestiary("run " + cfg + " --seed " + seed + " --set evolution.generations=2 --out " +
                       (dir / (std::string("s") + seed)).string() + " --quiet --workers 1")
                  .code,
              0);
  const fs::path page = dir / "both.html";
  Outcome r = bestiary("show " + (dir / "s1").string() + " " + (dir / "s2").string() + "/ --out " + page.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("2 runs' bests on one page"), std::string::npos) << r.out;
  // each as scored: the stored fitness, bit for bit
  for (const char* run : {"s1", "s2"}) {
    const std::string best = query(dir / run / "run.sqlite", "SELECT best_id FROM generation ORDER BY gen DESC LIMIT 1");
    const std::string id = best.substr(0, best.find('|'));
    const auto line = r.out.find((dir / run).string());
    ASSERT_NE(line, std::string::npos) << r.out;
    EXPECT_EQ(r.out.find(" individual " + id + " (", line), r.out.find(" individual ", line)) << r.out;
    const std::string data = bxtest::embedded_data(bxtest::slurp(page));
    EXPECT_NE(data.find(std::string("\"label\":\"") + run + ": individual " + id + " "), std::string::npos) << run;
  }
  EXPECT_EQ(r.out.find("not as scored"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("the stored fitness, bit for bit"), std::string::npos) << r.out;
  // what it refuses, in one line, writing nothing
  const fs::path none = dir / "none.html";
  for (const auto& [args, says] : std::vector<std::pair<std::string, std::string>>{
           {(dir / "s1").string() + " " + (dir / "s2").string(), "--out: a page of several runs needs a file"},
           {(dir / "s1").string() + " " + cfg + " --out " + none.string(), cfg + ": not a run folder"},
           {(dir / "s1").string() + " " + (dir / "s2").string() + " --id 3 --out " + none.string(),
            "a page of several runs shows each run's best as it was scored"}}) {
    Outcome bad = bestiary("show " + args);
    EXPECT_EQ(bad.code, 2) << args;
    EXPECT_NE(bad.err.find(says), std::string::npos) << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  }
  EXPECT_FALSE(fs::exists(none));
}

TEST_F(RunCli, BadInputGivesOneErrorLineAndWritesNothing) {
  struct Case {
    std::string args, error;
  };
  std::string cfg = (dir / "small.toml").string();
  fs::path out = dir / "out";
  std::vector<Case> cases = {
      {"run nosuchpreset --out " + out.string(),
       "nosuchpreset: no such config file, and no preset of that name (`" BESTIARY_BINARY " presets` lists them)"},
      {"run " + cfg + " --out " + out.string() + " --set evolution.population=two",
       "--set evolution.population=two: evolution.population: expected an integer, got \"two\""},
      {"run " + cfg + " --out " + out.string() + " --set task.seconds=-1",
       "--set task.seconds=-1: task.seconds: out of range [0, 1000000], got -1"},
      {"resume " + (dir / "nothing").string(), (dir / "nothing").string() + ": no such run directory"},
      {"best " + dir.string(), (dir / "run.sqlite").string() + ": no run database here"},
      // usage errors of the argument parser too: one line, exit code 2
      {"run " + cfg + " --out " + out.string() + " --seed -1",
       "--seed: expected a whole number from 0 to 18446744073709551615, got \"-1\" (see " BESTIARY_BINARY " run --help)"},
      {"run " + cfg + " --out " + out.string() + " --stop-after 0",
       "--stop-after: expected a whole number from 1 to 2147483647, got \"0\" (see " BESTIARY_BINARY " run --help)"},
      {"run " + cfg + " --out " + out.string() + " --frob",
       "The following argument was not expected: --frob (see " BESTIARY_BINARY " run --help)"},
      {"runn " + cfg, "runn: no such command (did you mean \"run\"?); the commands: simulate, config, run, resume, export, verify, "
                      "best, presets, show, render, plot, check, crosscheck"},
      {"run quikc --out " + out.string(), "quikc: no such config file, and no preset of that name (did you mean "
                                          "\"quick\"?) (`" BESTIARY_BINARY " presets` lists them)"},
      {"run " + cfg + " --out " + out.string() + " --set evolution.populaton=5",
       "--set evolution.populaton=5: evolution.populaton: unknown key (did you mean \"population\"?)"},
      // a number read as 0 is not rounded to it (issue 37: 0 is "no limit" here)
      {"run " + cfg + " --out " + out.string() + " --set motor.torque_max_linear_speed=1e-400",
       "--set motor.torque_max_linear_speed=1e-400: motor.torque_max_linear_speed: underflows: below 2.2e-308 a "
       "number reads as 0 or loses digits (write 0, or a larger number), got 1e-400"},
  };
  for (const auto& c : cases) {
    Outcome r = bestiary(c.args);
    EXPECT_EQ(r.code, 2) << c.args;
    EXPECT_EQ(r.err, "bestiary: " + c.error + "\n") << c.args;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
  // an existing run directory is never overwritten
  fs::create_directories(out);
  std::ofstream(out / "keep.txt") << "mine";
  Outcome r = bestiary("run " + cfg + " --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("bestiary: " + out.string() + ": already exists", 0), 0u) << r.err;
  EXPECT_TRUE(fs::exists(out / "keep.txt"));
  EXPECT_FALSE(fs::exists(out / "run.sqlite"));
}

// A config under which no creature is viable drew random genomes forever,
// printing and storing nothing (issue 37): the run stops after
// evolution.max_random_redraws in a row, in one line with the reason most of
// them gave, and a run refused before it stored a generation leaves nothing.
TEST_F(RunCli, ARunUnderWhichNoCreatureIsViableStopsInOneLineAndLeavesNothing) {
  const fs::path out = dir / "none";
  // a folder named with a trailing '/' too (it left an empty folder)
  for (const auto& [algorithm, named] : {std::pair{"generational", out.string()}, {"steady_state", out.string() + "/"}}) {
    // `timeout`: without the bound the run never ends
    Outcome r = bxtest::run_command("timeout 120 " BESTIARY_BINARY " run quick --out " + named +
                                    " --set develop.max_body_length=1e-6 --set evolution.algorithm=" + algorithm +
                                    " --workers 0");
    EXPECT_EQ(r.code, 2) << algorithm << r.err;
    EXPECT_EQ(bxtest::count_lines(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("bestiary: no creature is viable: 10000 random genotypes in a row were not "
                          "(evolution.max_random_redraws); ", 0),
              0u)
        << r.err;
    EXPECT_NE(r.err.find("above develop.max_body_length 1e-06\n"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << algorithm;
    for (const auto& e : fs::directory_iterator(dir))  // nor the folder it was created under
      EXPECT_EQ(e.path().filename().string().find(".none.creating"), std::string::npos) << e.path();
  }
}

// A run refused once it has stored a generation keeps it (and says the same
// when resumed): its second stage, from random genotypes, has none viable.
TEST_F(RunCli, ARunRefusedAfterItStoredAGenerationKeepsIt) {
  std::ofstream(dir / "stages.toml") << "[genome]\ndialect = \"sims1994\"\n[evolution]\npopulation = 12\n"
                                        "generations = 2\n[task]\nseconds = 2\n"
                                        "[[stage]]\nname = \"first\"\n"
                                        "[[stage]]\nname = \"none\"\nstart = \"random\"\n"
                                        "[stage.develop]\nmax_body_length = 1e-6\n";
  const fs::path out = dir / "staged";
  const std::string refusal = "bestiary: stage \"none\": no creature is viable: ";
  // `timeout`: without the bound the second stage never ends
  Outcome r = bxtest::run_command("timeout 120 " BESTIARY_BINARY " run " + (dir / "stages.toml").string() + " --out " +
                                  out.string() + " --workers 0 --quiet");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err.rfind(refusal, 0), 0u) << r.err;
  EXPECT_EQ(bxtest::query(out / "run.sqlite", "SELECT count(*) FROM generation"), "2|\n");
  Outcome again = bxtest::run_command("timeout 120 " BESTIARY_BINARY " resume " + out.string() + " --workers 0 --quiet");
  EXPECT_EQ(again.code, 2) << again.err;
  EXPECT_EQ(again.err.rfind(refusal, 0), 0u) << again.err;
  EXPECT_EQ(bxtest::query(out / "run.sqlite", "SELECT count(*) FROM generation"), "2|\n");
}

TEST_F(RunCli, PresetsAreListedOneLineEach) {
  Outcome r = bestiary("presets");
  ASSERT_EQ(r.code, 0);
  std::string out = "\n" + r.out;
  for (const char* name : {"quick", "miconi2006", "miconi2006-small", "chaumont2007-walker",
                           "chaumont2007-walker-small", "sims1994-walker"})
    EXPECT_NE(out.find(std::string("\n") + name + " "), std::string::npos) << name << r.out;
  // each names its paper: a graph genome's by its dialect, a fixed body's by its creature kind
  auto line_of = [&](const std::string& name) {
    const std::size_t at = out.find("\n" + name + " ");
    return at == std::string::npos ? std::string() : out.substr(at + 1, out.find('\n', at + 1) - at - 1);
  };
  EXPECT_NE(line_of("miconi2006").find("Miconi & Channon 2006"), std::string::npos) << r.out;
  EXPECT_NE(line_of("sims1994-walker").find("Sims 1994"), std::string::npos) << r.out;
  for (const char* name : {"rivercrossing", "rivercrossing-small", "rivercrossing-motif"}) {
    EXPECT_NE(line_of(name).find("Stanton & Channon 2015"), std::string::npos) << name << r.out;
    EXPECT_EQ(line_of(name).find("Sims"), std::string::npos) << name << r.out;
  }
  // a steady state that evaluates a tournament's three counts tournaments (evolution.evaluations)
  EXPECT_NE(line_of("rivercrossing-small").find(" tournaments "), std::string::npos) << r.out;
  // over a run of stages too: a steady state's tournaments summed over them
  EXPECT_NE(line_of("rivercrossing-small").find("150, 3,300 tournaments in 2 stages"), std::string::npos) << r.out;
  EXPECT_NE(line_of("miconi2006-small").find(" evaluations "), std::string::npos) << r.out;
  // a run of stages (an ESP syllabus): its stages' generations, with the range of their populations
  EXPECT_NE(line_of("lessin2015-fast-small").find("Lessin et al. 2015"), std::string::npos) << r.out;
  EXPECT_NE(line_of("lessin2015-fast-small").find("30-60 x 120 generations in 10 stages"), std::string::npos) << r.out;
  EXPECT_NE(line_of("lessin2015-high-reach-fast-small").find("30 x 20 generations in 2 stages"), std::string::npos) << r.out;
}

}  // namespace
