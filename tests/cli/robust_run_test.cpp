// Runs that survive anything (issue 13): a run killed at any moment leaves
// nothing or a resumable run; a worker lost from outside costs nothing; a
// damaged run database is named, never run with defaults or crashed on;
// signals stop a run once.
#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using bxtest::bestiary;
using bxtest::Outcome;
using bxtest::slurp;
using Clock = std::chrono::steady_clock;

using bxtest::query;

void execute(const fs::path& db_path, const std::string& sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
  char* err = nullptr;
  EXPECT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err), SQLITE_OK) << (err ? err : "");
  sqlite3_free(err);
  sqlite3_close(db);
}

// everything a run stores that its outcome depends on
std::string dump(const fs::path& dir) {
  fs::path db = dir / "run.sqlite";
  return query(db, "SELECT * FROM generation ORDER BY gen") + query(db, "SELECT * FROM individual ORDER BY id") +
         query(db, "SELECT gen, state FROM checkpoint");
}

// `bestiary ARGS...` started in the background, its stderr to `err` (if given)
pid_t start(const std::vector<std::string>& args, const fs::path& err = {}, bool own_group = false) {
  pid_t pid = ::fork();
  if (pid == 0) {
    if (own_group) ::setpgid(0, 0);
    if (!err.empty()) std::freopen(err.c_str(), "w", stderr);
    std::freopen("/dev/null", "w", stdout);
    std::vector<char*> argv{const_cast<char*>(BESTIARY_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(BESTIARY_BINARY, argv.data());
    ::_exit(127);
  }
  return pid;
}

// the pids of a process's children
std::vector<pid_t> children(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children");
  std::vector<pid_t> out;
  for (long p; in >> p;) out.push_back(static_cast<pid_t>(p));
  return out;
}

// a process that still runs (not gone, not a zombie)
bool alive(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(in, line)) return false;
  auto paren = line.rfind(')');
  return paren != std::string::npos && paren + 2 < line.size() && line[paren + 2] != 'Z';
}

class RobustRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("bx_robust_" + std::to_string(::getpid()) + "_" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    cfg = (dir / "small.toml").string();
    // about a second on 2 cores
    std::ofstream(cfg) << "# a small test run\n[genome]\ndialect = \"sims1994\"\n"
                          "[evolution]\npopulation = 12\ngenerations = 5\n[task]\nseconds = 2\n";
  }
  void TearDown() override { fs::remove_all(dir); }

  // an undisturbed run of the small config
  fs::path whole() {
    fs::path w = dir / "whole";
    if (!fs::exists(w)) {
      EXPECT_EQ(bestiary("run " + cfg + " --out " + w.string() + " --workers 2 --quiet").code, 0);
    }
    return w;
  }

  fs::path dir;
  std::string cfg;
};

TEST_F(RobustRun, KilledAtAnyMomentLeavesNothingOrARunThatResumesExactly) {
  // longer than the small run: about 1.6 seconds on 2 cores
  const std::string longer = (dir / "longer.toml").string();
  std::ofstream(longer) << "[genome]\ndialect = \"sims1994\"\n[evolution]\npopulation = 12\ngenerations = 7\n"
                           "[task]\nseconds = 2\n";
  fs::path undisturbed = dir / "undisturbed";
  ASSERT_EQ(bestiary("run " + longer + " --out " + undisturbed.string() + " --quiet").code, 0);
  const std::string expected = dump(undisturbed);
  ASSERT_NE(expected, "");
  int nothing = 0, resumed = 0, complete = 0;
  // 20 moments over the first second (creation, generation 0, later
  // generations), then two later ones
  std::vector<int> moments_ms;
  for (int k = 0; k < 20; ++k) moments_ms.push_back(k * 50);
  moments_ms.push_back(1300);
  moments_ms.push_back(1800);
  for (int ms : moments_ms) {
    SCOPED_TRACE("killed after " + std::to_string(ms) + " ms");
    fs::path run = dir / ("killed" + std::to_string(ms));
    pid_t pid = start({"run", longer, "--out", run.string(), "--workers", "2", "--quiet"});
    std::this_thread::sleep_for(std::chrono::milliseconds(ms));
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (!fs::exists(run)) {
      // nothing: the same command starts it afresh
      ++nothing;
      Outcome r = bestiary("run " + longer + " --out " + run.string() + " --workers 2 --quiet");
      ASSERT_EQ(r.code, 0) << r.err;
    } else {
      // a run: complete, or resumable to exactly the undisturbed run's end
      Outcome r = bestiary("resume " + run.string() + " --workers 1 --quiet");
      ASSERT_EQ(r.code, 0) << r.err;
      ++(r.out.find("already complete") != std::string::npos ? complete : resumed);
    }
    EXPECT_EQ(dump(run), expected);
    EXPECT_TRUE(fs::exists(run / "config.toml"));
    // no half-made directory left beside it
    for (const auto& e : fs::directory_iterator(dir))
      EXPECT_EQ(e.path().filename().string().find(".creating-"), std::string::npos) << e.path();
  }
  std::printf("after a kill: %d left nothing, %d resumed, %d complete\n", nothing, resumed, complete);
  // the moments reach past creation: most kills leave a run to resume
  EXPECT_GT(resumed, 0);
}

TEST_F(RobustRun, AWorkerKilledFromOutsideCostsNothing) {
  const std::string expected = dump(whole());
  fs::path run = dir / "lost_worker";
  pid_t pid = start({"run", cfg, "--out", run.string(), "--workers", "2", "--quiet"});
  // once generation 0 is stored, kill one worker as a user or the OOM killer would
  auto t0 = Clock::now();
  while (query(run / "run.sqlite", "SELECT count(*) FROM generation") < "1" && Clock::now() - t0 < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  auto workers = children(pid);
  ASSERT_FALSE(workers.empty());
  ASSERT_EQ(::kill(workers.front(), SIGKILL), 0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_EQ(query(run / "run.sqlite", "SELECT count(*) FROM individual WHERE failure LIKE 'worker%'"), "0|\n");
  EXPECT_EQ(dump(run), expected);
}

TEST_F(RobustRun, SigtermToTheProcessGroupStopsOnceAndTakesTheWorkersAlong) {
  fs::path run = dir / "terminated", err = dir / "stderr.txt";
  pid_t pid = start({"run", cfg, "--out", run.string(), "--workers", "2", "--quiet"}, err, true);
  auto t0 = Clock::now();
  std::vector<pid_t> workers;
  while ((workers = children(pid)).size() < 2 && Clock::now() - t0 < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_EQ(workers.size(), 2u);
  ::kill(-pid, SIGTERM);  // as a terminal or a service manager would
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  std::string text = slurp(err);
  auto first = text.find("interrupted");
  ASSERT_NE(first, std::string::npos) << text;
  EXPECT_EQ(text.find("interrupted", first + 1), std::string::npos) << text;
  // the workers end with it, without finishing their evaluations
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  for (pid_t w : workers) EXPECT_FALSE(alive(w)) << "worker " << w;
  EXPECT_EQ(bestiary("resume " + run.string() + " --quiet").code, 0);
  EXPECT_EQ(dump(run), dump(whole()));
}

// a damaged copy of a run stopped after 3 generations, and what `resume` says of it
struct Damage {
  const char* what;
  std::string sql;        // run on the copy's database
  std::string expected;   // in the one error line
  std::string unsealed;   // what a run stored before rows carried checksums says ("": the same)
};

TEST_F(RobustRun, ADamagedRunDatabaseIsNamedNeverRunWithDefaultsOrCrashedOn) {
  fs::path good = dir / "stopped";
  ASSERT_EQ(bestiary("run " + cfg + " --out " + good.string() + " --stop-after 3 --quiet").code, 0);
  const std::string changed = "does not match its checksum (damaged: a stored value changed since it was written)";
  const std::vector<Damage> damages = {
      {"checkpoint not JSON", "UPDATE checkpoint SET state = '{bad'", "the checkpoint " + changed,
       "the checkpoint is not a JSON object"},
      {"checkpoint without next_id", "UPDATE checkpoint SET state = json_remove(state, '$.next_id')",
       "the checkpoint " + changed, "the checkpoint lacks \"next_id\""},
      {"checkpoint naming a missing individual",
       "UPDATE checkpoint SET state = json_set(state, '$.population[0]', 99999)", "the checkpoint " + changed,
       "no individual 99999"},
      {"seed not a number", "UPDATE run SET value = 'abc' WHERE key = 'seed'",
       "the run's seed is not a whole number (\"abc\")", ""},
      {"no config", "DELETE FROM run WHERE key = 'config'", "the run's config is missing", ""},
      {"text fitness", "UPDATE individual SET fitness = 'abc' WHERE id = 3", "individual 3 " + changed,
       "individual 3's fitness is not a number (\"abc\")"},
  };
  for (const bool sealed : {true, false}) {
    for (const auto& d : damages) {
      SCOPED_TRACE(std::string(d.what) + (sealed ? "" : ", stored before checksums"));
      fs::path copy = dir / "damaged";
      fs::remove_all(copy);
      fs::copy(good, copy);
      if (!sealed) execute(copy / "run.sqlite", bxtest::kBeforeChecksums);
      execute(copy / "run.sqlite", d.sql);
      Outcome r = bestiary("resume " + copy.string() + " --quiet");
      EXPECT_EQ(r.code, 2) << r.out << r.err;
      const std::string& expected = sealed || d.unsealed.empty() ? d.expected : d.unsealed;
      EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
      EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
      // and `verify` says the same
      Outcome v = bestiary("verify " + copy.string());
      EXPECT_EQ(v.code, 2) << v.out << v.err;
      EXPECT_NE(v.err.find(expected), std::string::npos) << v.err;
    }
  }
  // garbage over the middle of the file: SQLite's check names it
  fs::path copy = dir / "overwritten";
  fs::copy(good, copy);
  auto size = fs::file_size(copy / "run.sqlite");
  ASSERT_GT(size, 8 * 4096u);
  {
    std::fstream f(copy / "run.sqlite", std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(size / 2 / 4096 * 4096));
    std::string junk(4096, '\x5a');
    f.write(junk.data(), static_cast<std::streamsize>(junk.size()));
  }
  Outcome r = bestiary("resume " + copy.string() + " --quiet");
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("damaged"), std::string::npos) << r.err;
}

// A second resume (or a lengthening) of a run that is going on is refused in
// one line and changes nothing: the run ends as an undisturbed one, and its
// log has no word of the refusal (issue 36: it died on "UNIQUE constraint
// failed" and wrote into the live run's log)
TEST_F(RobustRun, AResumeOfARunGoingOnIsRefusedAndChangesNothing) {
  const std::string longer = (dir / "longer.toml").string();
  std::ofstream(longer) << "[genome]\ndialect = \"sims1994\"\n[evolution]\npopulation = 12\ngenerations = 7\n"
                           "[task]\nseconds = 2\n";
  fs::path undisturbed = dir / "undisturbed";
  ASSERT_EQ(bestiary("run " + longer + " --out " + undisturbed.string() + " --quiet").code, 0);
  fs::path run = dir / "live";
  pid_t pid = start({"run", longer, "--out", run.string(), "--workers", "1", "--quiet"});
  // once its first generation is stored
  for (int k = 0; k < 2000 && query(run / "run.sqlite", "SELECT count(*) FROM generation") == ""; ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  for (const std::string& args : {"resume " + run.string() + " --quiet",
                                  "resume " + run.string() + " --set evolution.generations=9 --quiet"}) {
    SCOPED_TRACE(args);
    Outcome r = bestiary(args);
    ASSERT_TRUE(alive(pid)) << "the run ended before it could be tried";
    EXPECT_EQ(r.code, 2) << r.out << r.err;
    EXPECT_EQ(r.err, "bestiary: " + run.string() +
                         ": the run is going on in another process (which holds its lock): wait for it to end, or "
                         "stop it first (Ctrl-C there); nothing was changed\n");
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  EXPECT_EQ(dump(run), dump(undisturbed));
  const std::string log = slurp(run / "run.log");
  EXPECT_EQ(log.find("session:"), log.rfind("session:")) << log;  // its own session only
  EXPECT_EQ(slurp(run / "config.toml"), slurp(undisturbed / "config.toml"));
  // and once it ended, resume says it is complete
  EXPECT_EQ(bestiary("resume " + run.string() + " --quiet").code, 0);
}

TEST_F(RobustRun, ResumeRunsTheStoredConfigAndSaysWhenConfigTomlDiffers) {
  fs::path run = dir / "edited";
  ASSERT_EQ(bestiary("run " + cfg + " --out " + run.string() + " --stop-after 2 --quiet").code, 0);
  const std::string stored = slurp(run / "config.toml");
  // an edit of config.toml changes nothing, and resume says so
  std::ofstream(run / "config.toml", std::ios::app) << "\n[task]\nseconds = 7\n";
  Outcome r = bestiary("resume " + run.string() + " --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("config.toml differs from the config stored in the run's database, which the run uses"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(dump(run), dump(whole()));
  // a deleted one is written again
  fs::path again = dir / "deleted";
  ASSERT_EQ(bestiary("run " + cfg + " --out " + again.string() + " --stop-after 2 --quiet").code, 0);
  fs::remove(again / "config.toml");
  r = bestiary("resume " + again.string() + " --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("config.toml was missing: written again"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(again / "config.toml"), stored);
}

TEST_F(RobustRun, ARunThatCannotBeCreatedLeavesNothing) {
  // the parent is a file: nothing can be created under it
  std::ofstream(dir / "file") << "x";
  Outcome r = bestiary("run " + cfg + " --out " + (dir / "file" / "run").string() + " --quiet");
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  // a folder this user may not write (root may write anywhere: tested as nobody)
  if (::getuid() != 0 || ::system("command -v setpriv >/dev/null") != 0) return;
  fs::path locked = dir / "locked";
  fs::create_directories(locked);
  fs::permissions(dir, fs::perms::all, fs::perm_options::add);
  fs::permissions(locked, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                              fs::perms::others_read | fs::perms::others_exec);
  fs::copy(whole(), locked / "run");
  fs::permissions(locked / "run", fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                      fs::perms::others_read | fs::perms::others_exec);
  const std::string nobody = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
  Outcome made = bxtest::run_command(nobody + BESTIARY_BINARY + " run " + cfg + " --out " +
                                     (locked / "new").string() + " --quiet");
  EXPECT_EQ(made.code, 2) << made.err;
  EXPECT_FALSE(fs::exists(locked / "new"));
  // and a run this user may only read is read, not called "not a run database"
  Outcome best = bxtest::run_command(nobody + BESTIARY_BINARY + " best " + (locked / "run").string());
  EXPECT_EQ(best.code, 0) << best.err;
  Outcome resume = bxtest::run_command(nobody + BESTIARY_BINARY + " resume " + (locked / "run").string());
  EXPECT_EQ(resume.code, 0) << resume.err;  // complete: nothing to write
  EXPECT_NE(resume.out.find("already complete"), std::string::npos) << resume.out;
}

}  // namespace
