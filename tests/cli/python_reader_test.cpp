// scripts/bestiary_runs.py, the Python reader of run folders
// (docs/run-database.md, "From Python"): its tables match the database, an
// individual re-simulated through the command gives its stored fitness, and
// as a command it prints one line a run or refuses in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>

#include "support/run_command.h"

namespace {

namespace fs = std::filesystem;
using bxtest::Outcome;

class PythonReader : public bxtest::InTempDir {};

TEST_F(PythonReader, ReadsTheTablesAndReSimulatesAnIndividualExactly) {
  const fs::path run = dir / "r";
  ASSERT_EQ(bxtest::small_run(run).code, 0);
  const std::string script = BESTIARY_SOURCE_DIR "/scripts/bestiary_runs.py";
  const std::string py =
      "import sys; sys.path.insert(0, '" BESTIARY_SOURCE_DIR "/scripts'); from bestiary_runs import Run; "
      "r = Run('" + run.string() + "'); g = r.generations(); i = r.individuals(); "
      "print(len(g), len(i), g[-1]['evaluations'], r.facts['seed']); print(repr(g[-1]['best'])); "
      "one = [x for x in i if x['evaluations'] == 1 and x['generation'] > 0][0]; "
      "s = r.resimulate(one['id'], bestiary='" BESTIARY_BINARY "'); "
      "print(s['fitness'] == one['fitness'], 'nodes' in r.genome(one['id']))";
  Outcome o = bxtest::run_command("python3 -c \"" + py + "\"");
  ASSERT_EQ(o.code, 0) << o.err;
  const std::string gens = bxtest::query(run / "run.sqlite", "SELECT count(*) FROM generation");
  const std::string inds = bxtest::query(run / "run.sqlite", "SELECT count(*) FROM individual");
  const std::string evals = bxtest::query(run / "run.sqlite", "SELECT max(evaluations) FROM generation");
  auto cell = [](std::string s) { return s.substr(0, s.find('|')); };
  std::istringstream lines(o.out);
  std::string counts, best, checks;
  std::getline(lines, counts);
  std::getline(lines, best);
  EXPECT_EQ(counts, cell(gens) + " " + cell(inds) + " " + cell(evals) + " 1") << o.out;  // ... and the seed
  // the last best as Python read it is the stored double, exactly
  EXPECT_EQ(bxtest::query(run / "run.sqlite", "SELECT best = " + best + " FROM generation ORDER BY gen DESC LIMIT 1"),
            "1|\n")
      << best;
  EXPECT_NE(o.out.find("\nTrue True\n"), std::string::npos) << o.out;
  // as a command: one line a run; a folder without a run: one line, exit 2
  Outcome c = bxtest::run_command("python3 " + script + " " + run.string());
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.out.find(" generations, " + cell(evals) + " evaluations, best "), std::string::npos) << c.out;
  c = bxtest::run_command("python3 " + script + " " + (dir / "none").string());
  EXPECT_EQ(c.code, 2);
  EXPECT_EQ(std::count(c.err.begin(), c.err.end(), '\n'), 1) << c.err;
}

}  // namespace
