// Golden hashes: a short run of each preset family, hashed, against values checked in here.
// A refactor must leave them alone; a change meant to change results (physics, operators,
// evaluation) updates them in a commit of its own that says why. Each run is made with one
// and with two worker processes: the hashes must agree (the same config and seed give the
// same run whatever the parallelism).
//
// What is hashed (FNV-1a, 64 bits):
//   run:    every individual of the run database in id order (generation, genome text, the
//           exact bits of fitness and distance, parents, operator, failure, seed) and every
//           generation row (evaluations, best/mean/median bits, best id, rejected, failed);
//   replay: `bestiary simulate RUN --replay` of the run's best, without the two fields that
//           name where it came from (`bestiary`: the program's version, `genome`: the path).
// On a mismatch the test prints the new values in the form of the table below.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/run_command.h"

namespace {

using bxtest::bestiary;
namespace fs = std::filesystem;

std::uint64_t fnv1a(const std::string& s, std::uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string hex(std::uint64_t h) {
  char b[17];
  std::snprintf(b, sizeof b, "%016" PRIx64, h);
  return b;
}

// Rows of a query as text; REAL cells as their exact bits (%a), so the hash sees every bit.
std::string exact_rows(const fs::path& db_path, const char* sql) {
  sqlite3* db = nullptr;
  std::string out;
  if (sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    sqlite3_close(db);
    return out;
  }
  sqlite3_stmt* s = nullptr;
  if (sqlite3_prepare_v2(db, sql, -1, &s, nullptr) == SQLITE_OK) {
    while (sqlite3_step(s) == SQLITE_ROW) {
      for (int c = 0; c < sqlite3_column_count(s); ++c) {
        if (sqlite3_column_type(s, c) == SQLITE_FLOAT) {
          char b[64];
          std::snprintf(b, sizeof b, "%a", sqlite3_column_double(s, c));
          out += b;
        } else if (sqlite3_column_type(s, c) == SQLITE_NULL) {
          out += "NULL";
        } else {
          out += reinterpret_cast<const char*>(sqlite3_column_text(s, c));
        }
        out += '|';
      }
      out += '\n';
    }
  }
  sqlite3_finalize(s);
  sqlite3_close(db);
  return out;
}

struct Hashes {
  std::string run, replay;
  std::size_t individuals = 0;
};

Hashes hash_run(const fs::path& dir) {
  Hashes h;
  fs::path db = dir / "run.sqlite";
  std::string ind = exact_rows(db,
                               "SELECT id, gen, genome, fitness, distance, parent1, parent2, "
                               "operator, failure, seed FROM individual ORDER BY id");
  std::string gen = exact_rows(db,
                               "SELECT gen, evaluations, best, mean, median, best_id, rejected, "
                               "failed FROM generation ORDER BY gen");
  h.individuals = static_cast<std::size_t>(std::count(ind.begin(), ind.end(), '\n'));
  h.run = hex(fnv1a(gen, fnv1a(ind)));
  fs::path replay = dir / "best-replay.json";
  auto r = bestiary("simulate " + dir.string() + " --replay " + replay.string());
  EXPECT_EQ(r.code, 0) << r.err;
  auto j = nlohmann::json::parse(bxtest::slurp(replay), nullptr, false);
  EXPECT_FALSE(j.is_discarded()) << replay;
  if (j.is_object()) {
    j.erase("bestiary");
    j.erase("genome");
    h.replay = hex(fnv1a(j.dump()));
  }
  return h;
}

struct Golden {
  const char* preset;
  const char* overrides;  // a short run: small population, few evaluations, short tasks
  const char* run;        // the expected hashes
  const char* replay;
};

// Updated only by a commit that changes results on purpose (and says why).
const Golden kGolden[] = {
    {"quick", "--set evolution.population=10 --set evolution.generations=3",
     "4712388f2d71c294", "86465cae2133eed7"},
    {"miconi2006-small",
     "--set evolution.population=10 --set evolution.evaluations=40 --set task.seconds=10",
     "5eef55f87affd293", "7280ee0b58e30015"},
    {"chaumont2007-catapult-small", "--set evolution.population=10 --set evolution.generations=3",
     "4624cb87364d4351", "4b3fe8b250aa4a19"},
    {"sims1994-walker", "--set evolution.population=10 --set evolution.generations=3",
     "92f2a4617151841c", "6e6495f193eaf71a"},
};

// gtest names a failing case by its preset, not by its bytes
void PrintTo(const Golden& g, std::ostream* os) { *os << g.preset; }

class GoldenHashes : public ::testing::TestWithParam<Golden> {
 protected:
  void SetUp() override {
    base = fs::temp_directory_path() /
           ("bx_golden_" + std::to_string(::getpid()) + "_" + GetParam().preset);
    fs::remove_all(base);
    fs::create_directories(base);
  }
  void TearDown() override { fs::remove_all(base); }
  fs::path base;
};

TEST_P(GoldenHashes, AShortRunAndItsBestsReplayAreUnchangedWithOneOrTwoWorkers) {
  const Golden& g = GetParam();
  Hashes by_workers[2];
  for (int w = 1; w <= 2; ++w) {
    const std::string workers = std::to_string(w);
    fs::path dir = base / workers;
    auto r = bestiary(std::string("run ") + g.preset + " " + g.overrides + " --seed 1 --workers " +
                      workers + " --quiet --out " + dir.string());
    ASSERT_EQ(r.code, 0) << r.err;
    by_workers[w - 1] = hash_run(dir);
  }
  const Hashes& h = by_workers[0];
  EXPECT_GT(h.individuals, 20u);
  EXPECT_EQ(by_workers[1].run, h.run) << "two workers gave another run than one";
  EXPECT_EQ(by_workers[1].replay, h.replay) << "two workers gave another best than one";
  EXPECT_TRUE(h.run == g.run && h.replay == g.replay)
      << "results changed. If on purpose, update kGolden in a commit that says why:\n"
      << "     \"" << h.run << "\", \"" << h.replay << "\"},  // " << g.preset;
}

INSTANTIATE_TEST_SUITE_P(Presets, GoldenHashes, ::testing::ValuesIn(kGolden),
                         [](const ::testing::TestParamInfo<Golden>& i) {
                           std::string n = i.param.preset;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

}  // namespace
