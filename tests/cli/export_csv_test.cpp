// `bestiary export RUN --csv DIR`: a run database as CSV files, every row and
// value as stored (reals read back to the same double), fields quoted per RFC
// 4180; refusals in one line.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.h"
#include "support/tiny_runs.h"

namespace {

namespace fs = std::filesystem;
using bxtest::bestiary;
using bxtest::Outcome;

// a tiny river crossing run: named metrics per report interval
const char* kRiver = bxtest::kTinyRiverRun;

std::vector<std::string> lines_of(const fs::path& p) {
  std::istringstream in(bxtest::slurp(p));
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

class ExportCsv : public bxtest::InTempDir {};

TEST_F(ExportCsv, EveryTableRowIsWrittenWithItsValuesExactly) {
  // a config whose name holds a comma and a quote: run.csv quotes it
  const fs::path cfg = write("a,b\"c.toml", kRiver), run = dir / "r", csv = dir / "csv";
  ASSERT_EQ(bestiary("run '" + cfg.string() + "' --workers 0 --quiet --out " + run.string()).code, 0);
  Outcome r = bestiary("export " + run.string() + " --csv " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path db = run / "run.sqlite";
  auto count = [&](const char* table) {
    return std::stol(bxtest::query(db, std::string("SELECT count(*) FROM ") + table));
  };
  const auto gens = lines_of(csv / "generations.csv"), inds = lines_of(csv / "individuals.csv"),
             mets = lines_of(csv / "metrics.csv"), facts = lines_of(csv / "run.csv");
  EXPECT_EQ(gens.front(), "generation,stage,evaluations,best,mean,median,best_id,rejected,failed");
  EXPECT_EQ(static_cast<long>(gens.size()) - 1, count("generation"));
  EXPECT_EQ(static_cast<long>(inds.size()) - 1, count("individual"));
  EXPECT_EQ(static_cast<long>(mets.size()) - 1, count("generation_metric"));
  EXPECT_GT(mets.size(), 10u);  // the river's levels, food, deaths per interval
  EXPECT_NE(r.out.find("individuals.csv (" + std::to_string(count("individual")) + ")"), std::string::npos) << r.out;
  // every individual's fitness reads back to the stored double, bit for bit
  for (std::size_t k = 1; k < inds.size(); ++k) {
    std::istringstream row(inds[k]);
    std::string id, gen, fitness;
    std::getline(row, id, ',');
    std::getline(row, gen, ',');
    std::getline(row, fitness, ',');
    const std::string stored = bxtest::query(db, "SELECT fitness = " + fitness + " FROM individual WHERE id = " + id);
    EXPECT_EQ(stored, "1|\n") << inds[k];
  }
  // the config's name, quoted with its quote doubled; the config itself is not a fact
  const std::string all = bxtest::slurp(csv / "run.csv");
  EXPECT_NE(all.find("\nname,\""), std::string::npos) << all;
  EXPECT_NE(all.find("a,b\"\"c.toml\"\n"), std::string::npos) << all;
  EXPECT_EQ(all.find("\nconfig,"), std::string::npos);
}

TEST_F(ExportCsv, ADatabaseStoredBeforeLaterColumnsAndTablesReadsWithTheirDefaults) {
  const fs::path cfg = write("r.toml", kRiver), run = dir / "r", csv = dir / "csv";
  ASSERT_EQ(bestiary("run " + cfg.string() + " --workers 0 --quiet --out " + run.string()).code, 0);
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open((run / "run.sqlite").c_str(), &db), SQLITE_OK);
  EXPECT_EQ(sqlite3_exec(db,
                         "ALTER TABLE individual DROP COLUMN evaluations; ALTER TABLE individual DROP COLUMN kind; "
                         "ALTER TABLE individual DROP COLUMN seed; DROP TABLE generation_metric; DROP TABLE stage;",
                         nullptr, nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  Outcome r = bestiary("export " + run.string() + " --csv " + csv.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto inds = lines_of(csv / "individuals.csv");
  ASSERT_GT(inds.size(), 1u);
  EXPECT_EQ(inds[1].substr(inds[1].size() - std::string(",1,,,random,,,graph").size()), ",1,,,random,,,graph")
      << inds[1];
  EXPECT_EQ(lines_of(csv / "metrics.csv").size(), 1u);  // the header alone
}

TEST_F(ExportCsv, RefusesInOneLine) {
  for (const std::string& bad : {(dir / "none").string() + " --csv " + (dir / "c").string(), dir.string() + " --csv " + (dir / "c").string(),
                                 dir.string()}) {
    Outcome r = bestiary("export " + bad);
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
