// The MPI evaluator end to end (docs/cluster.md): `mpirun -np N bestiary run
// ... --evaluator mpi` stores the same database, bit for bit, as the process
// pool with 1 and 2 workers, for 2, 3 and 4 ranks (oversubscribed on this
// machine's cores, on loopback), for a generational, a steady-state, a river
// crossing and a multi-stage General ESP run; a run stopped and resumed under
// MPI ends the same; an evaluation child killed from outside costs nothing;
// misuse is refused in one line, leaving no folder.
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/general_esp.h"
#include "support/run_command.h"
#include "support/tiny_runs.h"

namespace {

namespace fs = std::filesystem;
using bxtest::bestiary;
using bxtest::Outcome;

// mpirun as the tests run it: root allowed (CI runs as root), more ranks than
// cores, every rank on this machine
std::string mpirun(int ranks) {
  return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 300 mpirun --oversubscribe -np " +
         std::to_string(ranks) + " " BESTIARY_BINARY " ";
}

const char* kGenerational = R"(
[genome]
dialect = "sims1994"
[evolution]
algorithm = "generational"
population = 10
generations = 3
[task]
seconds = 1
)";

const char* kSteadyState = R"(
[genome]
dialect = "miconi2006"
[evolution]
population = 10
evaluations = 24
batch = 4
report_every = 8
[task]
seconds = 1
)";

// three islands of six, two tournaments each a batch (width 6), a migration
// every 12 births
const char* kIslands = R"(
[genome]
dialect = "miconi2006"
[evolution]
population = 18
evaluations = 36
batch = 2
islands = 3
migration_every = 4
report_every = 12
[task]
seconds = 1
)";

const char* kRiver = bxtest::kTinyRiverRun;

// every stored row that evolution writes, as text
std::string dump(const fs::path& dir) {
  std::string out;
  for (const char* q : {"SELECT * FROM generation ORDER BY gen", "SELECT * FROM individual ORDER BY id",
                        "SELECT * FROM generation_metric ORDER BY gen, name", "SELECT * FROM stage ORDER BY idx",
                        "SELECT * FROM checkpoint"})
    out += bxtest::query(dir / "run.sqlite", q);
  return out;
}

class MpiRun : public bxtest::InTempDir {
 protected:
  // the run of `config` with the pool's 1 and 2 workers, then under mpirun with 2, 3 and 4 ranks: all the same
  void expect_the_same_for_any_width(const std::string& name, const std::string& config) {
    const fs::path cfg = write(name + ".toml", config);
    std::string expected;
    for (int w : {1, 2}) {
      const fs::path out = dir / (name + "-w" + std::to_string(w));
      Outcome r = bestiary("run " + cfg.string() + " --quiet --workers " + std::to_string(w) + " --out " + out.string());
      ASSERT_EQ(r.code, 0) << r.err;
      const std::string d = dump(out);
      if (expected.empty()) expected = d;
      EXPECT_EQ(d, expected) << name << ", " << w << " workers";
    }
    EXPECT_GT(expected.size(), 500u);
    for (int ranks : {2, 3, 4}) {
      const fs::path out = dir / (name + "-mpi" + std::to_string(ranks));
      Outcome r = bxtest::run_command(mpirun(ranks) + "run " + cfg.string() + " --quiet --evaluator mpi --out " +
                                      out.string());
      ASSERT_EQ(r.code, 0) << name << ", " << ranks << " ranks: " << r.err;
      EXPECT_EQ(dump(out), expected) << name << ", " << ranks << " ranks";
    }
  }
};

TEST_F(MpiRun, AGenerationalRunIsTheSameForAnyNumberOfRanksOrWorkers) {
  expect_the_same_for_any_width("generational", kGenerational);
}

TEST_F(MpiRun, ASteadyStateRunIsTheSameForAnyNumberOfRanksOrWorkers) {
  expect_the_same_for_any_width("steady", kSteadyState);
}

TEST_F(MpiRun, ASteadyStateRunOnIslandsIsTheSameForAnyWidthAndWhenStoppedAndResumed) {
  expect_the_same_for_any_width("islands", kIslands);
  const std::string whole = dump(dir / "islands-w1");
  EXPECT_NE(whole.find("|migrant|"), std::string::npos);
  const fs::path cfg = dir / "islands.toml", cut = dir / "islands-cut";
  ASSERT_EQ(bestiary("run " + cfg.string() + " --quiet --workers 2 --stop-after 2 --out " + cut.string()).code, 0);
  EXPECT_NE(dump(cut).find("|migrant|"), std::string::npos);  // stopped after a migration
  Outcome r = bestiary("resume " + cut.string() + " --quiet --workers 1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(dump(cut), whole);
}

TEST_F(MpiRun, ARiverCrossingRunIsTheSameForAnyNumberOfRanksOrWorkers) {
  expect_the_same_for_any_width("river", kRiver);
}

TEST_F(MpiRun, AGeneralEspSyllabusWithRetestsIsTheSameForAnyNumberOfRanksOrWorkers) {
  expect_the_same_for_any_width("general", bxtest::general_syllabus());
}

TEST_F(MpiRun, StoppedAndResumedUnderMpiItEndsAsAnUninterruptedRun) {
  const fs::path cfg = write("g.toml", kGenerational), whole = dir / "whole", cut = dir / "cut";
  ASSERT_EQ(bestiary("run " + cfg.string() + " --quiet --workers 2 --out " + whole.string()).code, 0);
  Outcome r = bxtest::run_command(mpirun(3) + "run " + cfg.string() + " --quiet --evaluator mpi --stop-after 1 --out " +
                                  cut.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(dump(cut), dump(whole));
  r = bxtest::run_command(mpirun(2) + "resume " + cut.string() + " --quiet --evaluator mpi");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(dump(cut), dump(whole));
}

// the command line of process `pid` with its NULs as spaces ("" once it has gone)
std::string cmdline(const std::string& pid) {
  std::ifstream f("/proc/" + pid + "/cmdline");
  std::string s((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  for (char& c : s)
    if (c == '\0') c = ' ';
  return s;
}

std::string parent_of(const std::string& pid) {
  std::ifstream f("/proc/" + pid + "/stat");
  std::string line;
  std::getline(f, line);
  // pid (comm) state ppid ...: comm may hold spaces, so read after its ')'
  std::istringstream rest(line.substr(line.rfind(')') + 1));
  std::string state, ppid;
  rest >> state >> ppid;
  return ppid;
}

// An evaluation child of the MPI run writing to `out` (a process of the run
// whose parent is one of its ranks: a rank's parent is mpirun), or "".
std::string evaluation_child(const fs::path& out) {
  auto of_run = [&](const std::string& p) {
    const std::string c = cmdline(p);
    return c.find(out.string()) != std::string::npos && c.find("mpirun") == std::string::npos;
  };
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string pid = e.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    if (of_run(pid) && of_run(parent_of(pid))) return pid;
  }
  return "";
}

// A thread that, within 60 s, kills the process `target` names once it names
// one (an empty pid: not yet), or adds a failure saying `what` was never seen.
std::thread kill_when_seen(std::function<std::string()> target, std::string what) {
  return std::thread([target = std::move(target), what = std::move(what)] {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < until) {
      const std::string pid = target();
      if (!pid.empty() && ::kill(std::stoi(pid), SIGKILL) == 0) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ADD_FAILURE() << "no " << what << " was seen";
  });
}

// A generational config of 8 individuals of 4-second evaluations for `generations`
std::string slow_config(int generations) {
  return "[genome]\ndialect = \"sims1994\"\n[evolution]\nalgorithm = \"generational\"\npopulation = 8\n"
         "generations = " + std::to_string(generations) + "\n[task]\nseconds = 4\n";
}

TEST_F(MpiRun, AnEvaluationChildKilledFromOutsideCostsNothing) {
  // the child lives as long as its rank: killed inside an evaluation or
  // between two, its job (or its next) is given again to a fresh child
  const fs::path cfg = write("k.toml", slow_config(4));
  const fs::path whole = dir / "whole", hit = dir / "hit";
  ASSERT_EQ(bestiary("run " + cfg.string() + " --quiet --workers 2 --out " + whole.string()).code, 0);
  std::thread killer = kill_when_seen([&] { return evaluation_child(hit); }, "evaluation child of the run's ranks");
  Outcome r = bxtest::run_command(mpirun(3) + "run " + cfg.string() + " --quiet --evaluator mpi --out " + hit.string());
  killer.join();
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(dump(hit), dump(whole));
}

TEST_F(MpiRun, TheSlurmScriptStartsARunAndTheSameLineResumesIt) {
  // outside Slurm, mpirun starts one rank per core: on this machine 2, so one evaluates
  const fs::path cfg = write("g.toml", kGenerational), out = dir / "slurm-run";
  const std::string line = "cd " + dir.string() + " && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 PRESET=" +
                           cfg.string() + " SEED=3 OUT=" + out.string() + " BESTIARY=" BESTIARY_BINARY
                           " timeout 300 bash " BESTIARY_SOURCE_DIR "/scripts/slurm/bestiary.sbatch";
  Outcome r = bxtest::run_command(line + " --stop-after 1");
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("starting"), std::string::npos) << r.out;
  ASSERT_TRUE(fs::exists(out / "run.sqlite"));
  r = bxtest::run_command(line);
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("resuming"), std::string::npos) << r.out;
  // the same as the run made in one go with the pool
  const fs::path whole = dir / "whole";
  ASSERT_EQ(bestiary("run " + cfg.string() + " --seed 3 --quiet --workers 2 --out " + whole.string()).code, 0);
  EXPECT_EQ(dump(out), dump(whole));
}

TEST_F(MpiRun, ALostRankEndsTheJobAndResumeContinuesItToTheSameEnd) {
  const fs::path cfg = write("k.toml", slow_config(6));
  const fs::path whole = dir / "whole", hit = dir / "hit";
  ASSERT_EQ(bestiary("run " + cfg.string() + " --quiet --workers 2 --out " + whole.string()).code, 0);
  // an evaluating rank (the parent of an evaluation child: rank 0 has none),
  // once the run has stored a generation
  std::thread killer = kill_when_seen(
      [&] {
        const std::string gens = bxtest::query(hit / "run.sqlite", "SELECT count(*) FROM generation");
        const std::string child = gens.empty() || gens == "0|\n" ? "" : evaluation_child(hit);
        return child.empty() ? child : parent_of(child);
      },
      "evaluating rank of the run after its first generation");
  Outcome r = bxtest::run_command(mpirun(3) + "run " + cfg.string() + " --quiet --evaluator mpi --out " + hit.string());
  killer.join();
  EXPECT_NE(r.code, 0) << "the job went on without a rank";
  const std::string cut = dump(hit);
  EXPECT_NE(cut, dump(whole));
  r = bxtest::run_command(mpirun(2) + "resume " + hit.string() + " --quiet --evaluator mpi");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(dump(hit), dump(whole));
}

TEST_F(MpiRun, SeveralSeedsSideBySideAreEachTheSameAsTheirOwnRun) {
  // 5 ranks for 2 seeds: groups of 2 and 3 ranks, each its own rank 0
  const fs::path cfg = write("g.toml", kGenerational), side = dir / "side", alone = dir / "alone";
  Outcome r = bxtest::run_command(mpirun(5) + "run " + cfg.string() + " --quiet --evaluator mpi --seeds 4-5 --out " +
                                  side.string());
  ASSERT_EQ(r.code, 0) << r.err;
  // the pool runs them one after another, into the same folders
  r = bestiary("run " + cfg.string() + " --quiet --workers 2 --seeds 4,5 --out " + alone.string());
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* s : {"seed-4", "seed-5"}) {
    EXPECT_GT(dump(side / s).size(), 500u) << s;
    EXPECT_EQ(dump(side / s), dump(alone / s)) << s;
  }
  EXPECT_NE(dump(side / "seed-4"), dump(side / "seed-5"));
  // too few ranks for the seeds: refused before any folder
  const fs::path few = dir / "few";
  r = bxtest::run_command(mpirun(3) + "run " + cfg.string() + " --quiet --evaluator mpi --seeds 1-2 --out " + few.string());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("2 seeds side by side need at least 4 MPI ranks"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(few));
}

TEST_F(MpiRun, MisuseIsRefusedInOneLineAndLeavesNoFolder) {
  const fs::path cfg = write("g.toml", kGenerational), out = dir / "r";
  // not under mpirun: only one process
  Outcome r = bestiary("run " + cfg.string() + " --evaluator mpi --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--evaluator mpi: this is the only MPI process"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // --workers beside it
  r = bxtest::run_command(mpirun(2) + "run " + cfg.string() + " --evaluator mpi --workers 2 --out " + out.string());
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("--workers and --evaluator mpi"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // an evaluator that is not one
  r = bestiary("run " + cfg.string() + " --evaluator threads --out " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--evaluator"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
