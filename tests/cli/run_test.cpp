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

std::string query(const fs::path& db_path, const char* sql) {
  sqlite3* db = nullptr;
  std::string out;
  if (sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
    sqlite3_stmt* s = nullptr;
    if (sqlite3_prepare_v2(db, sql, -1, &s, nullptr) == SQLITE_OK) {
      while (sqlite3_step(s) == SQLITE_ROW) {
        for (int c = 0; c < sqlite3_column_count(s); ++c) {
          auto* t = sqlite3_column_text(s, c);
          out += t ? reinterpret_cast<const char*>(t) : "NULL";
          out += '|';
        }
        out += '\n';
      }
    }
    sqlite3_finalize(s);
  }
  sqlite3_close(db);
  return out;
}

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
  EXPECT_NE(ss.str().find("interrupted; continue with: bestiary resume " + run.string()), std::string::npos)
      << ss.str();
  EXPECT_EQ(bestiary("resume " + run.string() + " --quiet").code, 0);
  EXPECT_EQ(query(run / "run.sqlite", "SELECT count(*) FROM generation"), "5|\n");
}

TEST_F(RunCli, BadInputGivesOneErrorLineAndWritesNothing) {
  struct Case {
    std::string args, error;
  };
  std::string cfg = (dir / "small.toml").string();
  fs::path out = dir / "out";
  std::vector<Case> cases = {
      {"run nosuchpreset --out " + out.string(),
       "nosuchpreset: no such config file, and no preset of that name (`bestiary presets` lists them)"},
      {"run " + cfg + " --out " + out.string() + " --set evolution.populaton=5",
       "--set evolution.populaton=5: evolution.populaton: unknown key"},
      {"run " + cfg + " --out " + out.string() + " --set evolution.population=two",
       "--set evolution.population=two: evolution.population: expected an integer, got \"two\""},
      {"run " + cfg + " --out " + out.string() + " --set task.seconds=-1",
       "--set task.seconds=-1: task.seconds: out of range [0, 1000000], got -1"},
      {"resume " + (dir / "nothing").string(), (dir / "nothing").string() + ": no such run directory"},
      {"best " + dir.string(), (dir / "run.sqlite").string() + ": no run database here"},
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

TEST_F(RunCli, PresetsAreListedOneLineEach) {
  Outcome r = bestiary("presets");
  ASSERT_EQ(r.code, 0);
  std::string out = "\n" + r.out;
  for (const char* name : {"quick", "miconi2006", "miconi2006-small", "chaumont2007-walker",
                           "chaumont2007-walker-small", "sims1994-walker"})
    EXPECT_NE(out.find(std::string("\n") + name + " "), std::string::npos) << name << r.out;
}

}  // namespace
