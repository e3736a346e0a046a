// Helpers of the end-to-end tests (tests/cli, tests/viewer): run a command and capture what it
// prints, a fresh folder per test, and reading files back.
#pragma once

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace bxtest {

namespace fs = std::filesystem;

/// What a command did: exit code, stdout, stderr.
struct Outcome {
  int code;
  std::string out, err;
};

/// Runs a shell command line, capturing stdout and stderr.
inline Outcome run_command(const std::string& line) {
  fs::path err_file = fs::temp_directory_path() / ("bx_cmd_err_" + std::to_string(::getpid()));
  Outcome r;
  FILE* p = ::popen((line + " 2>" + err_file.string()).c_str(), "r");
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  int status = ::pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(err_file);
  std::stringstream ss;
  ss << e.rdbuf();
  r.err = ss.str();
  fs::remove(err_file);
  return r;
}

/// Rows of an SQL query on a database opened read-only, each cell followed by
/// '|' and each row by a newline ("" if it cannot be opened or prepared).
inline std::string query(const fs::path& db_path, const std::string& sql) {
  sqlite3* db = nullptr;
  std::string out;
  if (sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
    sqlite3_stmt* s = nullptr;
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) == SQLITE_OK) {
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

/// SQL that turns a run database into one as Bestiary stored runs before
/// rows carried checksums (format 0, no `digest` columns).
inline const char* kBeforeChecksums =
    "PRAGMA user_version = 0; ALTER TABLE run DROP COLUMN digest; ALTER TABLE generation DROP COLUMN digest; "
    "ALTER TABLE individual DROP COLUMN digest; ALTER TABLE generation_metric DROP COLUMN digest; "
    "ALTER TABLE checkpoint DROP COLUMN digest; ALTER TABLE stage DROP COLUMN digest;";

/// Runs the bestiary binary with arguments.
inline Outcome bestiary(const std::string& args) {
  return run_command(std::string(BESTIARY_BINARY) + " " + args);
}

/// A canonical creature's genome file.
inline std::string creature(const std::string& name) {
  return std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name;
}

/// The whole content of a file ("" if missing).
inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Lines in a text.
inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

/// A test with its own empty folder, removed afterwards.
class InTempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("bx_viewer_" + std::to_string(::getpid()) + "_" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
  fs::path dir;
};

/// Makes a small real run in `dir` (which must not exist), in a few seconds:
/// the quick preset with 12 individuals for 6 generations of 2 s, seed 1. Its
/// best is born after generation 0, so it has a lineage.
inline Outcome small_run(const fs::path& dir) {
  return bestiary("run quick --out " + dir.string() +
                  " --set evolution.population=12 --set evolution.generations=6 --set task.seconds=2"
                  " --workers 0 --quiet");
}

/// The JSON data a viewer page embeds (between its data script tags).
inline std::string embedded_data(const std::string& html) {
  const std::string open = "<script id=\"bestiary-data\" type=\"application/json\">";
  auto a = html.find(open);
  if (a == std::string::npos) return "";
  a += open.size();
  auto b = html.find("</script>", a);
  return b == std::string::npos ? "" : html.substr(a, b - a);
}

}  // namespace bxtest
