// A run database checked whole (issue 37): every row carries a checksum of its
// values, written with it, and RunStore::check_integrity names the first row
// that no longer matches, the first row missing, and SQLite's own damage.
// The proof: every byte of a small run's database flipped in turn is either
// named or changes no stored value.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "io/run_store.h"
#include "run/run.h"

namespace bx {
namespace {

namespace fs = std::filesystem;

// the smallest run that has everything: several generations, parents, a
// checkpoint, a stage, the run's config
const char* kTiny = R"(
[genome]
dialect = "sims1994"
[evolution]
algorithm = "generational"
population = 3
generations = 2
[task]
seconds = 0.3
)";

// every value of every table, exactly: each value's type and its bytes (a
// real's 8 bytes, not a rounded text); "" if the database cannot be read
std::string exact_dump(const fs::path& path) {
  sqlite3* db = nullptr;
  std::string out;
  const std::string uri = "file:" + path.string() + "?immutable=1";
  if (sqlite3_open_v2(uri.c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr) != SQLITE_OK) {
    sqlite3_close(db);
    return "";
  }
  for (const char* table : {"run", "stage", "checkpoint", "generation", "generation_metric", "individual"}) {
    const std::string sql = std::string("SELECT * FROM ") + table + " ORDER BY rowid";
    sqlite3_stmt* s = nullptr;
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) != SQLITE_OK) {
      out = "";
      break;
    }
    out += table;
    out += '\n';
    int rc;
    while ((rc = sqlite3_step(s)) == SQLITE_ROW) {
      for (int c = 0; c < sqlite3_column_count(s); ++c) {
        const int type = sqlite3_column_type(s, c);
        out += static_cast<char>('0' + type);
        if (type == SQLITE_FLOAT) {
          const double d = sqlite3_column_double(s, c);
          char bytes[sizeof d];
          std::memcpy(bytes, &d, sizeof d);
          out.append(bytes, sizeof bytes);
        } else if (type != SQLITE_NULL) {
          const auto* p = static_cast<const char*>(sqlite3_column_blob(s, c));
          out += std::to_string(sqlite3_column_bytes(s, c)) + ':';
          if (p) out.append(p, static_cast<std::size_t>(sqlite3_column_bytes(s, c)));
        }
        out += '|';
      }
      out += '\n';
    }
    sqlite3_finalize(s);
    if (rc != SQLITE_DONE) {
      out = "";
      break;
    }
  }
  sqlite3_close(db);
  return out;
}

class RunStoreIntegrity : public ::testing::Test {
 protected:
  void SetUp() override {
    root = fs::temp_directory_path() /
           ("bx_integrity_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root);
    fs::create_directories(root);
    auto cfg = read_run_config(kTiny, "tiny.toml");
    ASSERT_TRUE(cfg.ok()) << cfg.error();
    run = (root / "run").string();
    ASSERT_TRUE(create_run(run, *cfg, kTiny, "tiny.toml", 5).ok());
    Status s = drive_run(run, {0, true, 0});
    ASSERT_TRUE(s.ok()) << s.error();
    ASSERT_FALSE(fs::exists(run_db_path(run) + "-wal")) << "the run closed its database";
  }
  void TearDown() override { fs::remove_all(root); }

  // check_integrity of the database at `path`: "" when sound, else its error
  static std::string verdict(const std::string& path) {
    auto store = RunStore::open(path);
    if (!store) return store.error();
    auto sound = (*store)->check_integrity();
    return sound ? "" : sound.error();
  }
  // runs `sql` on a copy of the run's database and returns the copy's path
  std::string damaged(const std::string& sql) {
    const std::string copy = (root / "damaged.sqlite").string();
    fs::remove(copy);
    fs::copy_file(run_db_path(run), copy);
    sqlite3* db = nullptr;
    EXPECT_EQ(sqlite3_open_v2(copy.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
    char* err = nullptr;
    EXPECT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err), SQLITE_OK) << (err ? err : "");
    sqlite3_free(err);
    sqlite3_close(db);
    return copy;
  }

  fs::path root;
  std::string run;
};

TEST_F(RunStoreIntegrity, ASoundRunIsSoundAndEveryRowIsSealed) {
  auto store = RunStore::open(run_db_path(run));
  ASSERT_TRUE(store.ok()) << store.error();
  auto sound = (*store)->check_integrity();
  ASSERT_TRUE(sound.ok()) << sound.error();
  EXPECT_EQ(sound->generations, 2);
  EXPECT_EQ(sound->individuals, 5);  // 3, then 2 children beside the elite
  EXPECT_EQ(sound->stages, 1);
  EXPECT_EQ(sound->unsealed, 0);
  // the run's 6 keys, a stage, the checkpoint, 2 generations, 5 individuals
  EXPECT_EQ(sound->sealed, 15);
  auto v = verify_run(run);
  ASSERT_TRUE(v.ok()) << v.error();
}

// a value changed behind the run's back (the audit's cases: a genome's key
// renamed, a comment of the stored source config), a row lost, a table
// dropped: each named in the user's terms, not SQLite's
TEST_F(RunStoreIntegrity, EachDamageIsNamedInTheUsersTerms) {
  struct Case {
    const char* what;
    std::string sql;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"a genome's key renamed", "UPDATE individual SET genome = replace(genome, '\"weight\"', '\"weighd\"') WHERE id = 4",
       "individual 4 does not match its checksum"},
      {"a fitness changed", "UPDATE individual SET fitness = fitness + 1e-12 WHERE id = 2",
       "individual 2 does not match its checksum"},
      {"the source config edited", "UPDATE run SET value = value || '# x' WHERE key = 'source_config'",
       "the run's 'source_config' does not match its checksum"},
      {"a generation's best changed", "UPDATE generation SET best = 9 WHERE gen = 1",
       "generation 1 does not match its checksum"},
      {"a checksum removed", "UPDATE individual SET digest = NULL WHERE id = 3", "individual 3 has no checksum"},
      {"the checkpoint row deleted", "DELETE FROM checkpoint",
       "the checkpoint is missing, though 2 generations and 5 individuals are stored"},
      {"an individual deleted", "DELETE FROM individual WHERE id = 1",
       "individual 1 is missing (damaged: the checkpoint counts 5 born)"},
      {"a generation deleted", "DELETE FROM generation WHERE gen = 0",
       "generation 0 is missing (damaged: the checkpoint follows generation 1)"},
      {"the individual table dropped", "DROP TABLE individual", "the run database lacks its individual table"},
      {"the generation table dropped", "DROP TABLE generation", "the run database lacks its generation table"},
      {"the stage table dropped", "DROP TABLE stage", "the run database lacks its stage table"},
      {"the checkpoint table dropped", "DROP TABLE checkpoint", "the run database lacks its checkpoint table"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    const std::string v = verdict(damaged(c.sql));
    EXPECT_NE(v.find(c.expected), std::string::npos) << v;
    EXPECT_EQ(v.find('\n'), std::string::npos) << v;
    EXPECT_EQ(v.find("SQLITE"), std::string::npos) << v;
    EXPECT_EQ(v.find("constraint"), std::string::npos) << v;
  }
}

// every byte of the file flipped in turn (all its bits): named by
// check_integrity, or without effect on any stored value
TEST_F(RunStoreIntegrity, EveryByteFlippedIsNamedOrChangesNoStoredValue) {
  std::ifstream in(run_db_path(run), std::ios::binary);
  const std::string original((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(original.size(), 8 * 1024u);
  // in memory where the machine has it (/dev/shm): the same checks, fewer disk writes
  const fs::path scratch = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") / root.filename() : root;
  fs::create_directories(scratch);
  const std::string copy = (scratch / "flipped.sqlite").string();
  {
    std::ofstream(copy, std::ios::binary) << original;
  }
  const std::string expected = exact_dump(copy);
  ASSERT_FALSE(expected.empty());
  long named = 0, harmless = 0;
  // flipped and restored in place, one byte at a time (the file is checked
  // whole after each, and written again if a check changed it)
  const int fd = ::open(copy.c_str(), O_RDWR);
  ASSERT_GE(fd, 0);
  std::string now_bytes(original.size(), '\0');
  for (std::size_t at = 0; at < original.size(); ++at) {
    const char flipped = static_cast<char>(~static_cast<unsigned char>(original[at]));
    ASSERT_EQ(::pwrite(fd, &flipped, 1, static_cast<off_t>(at)), 1);
    const std::string v = verdict(copy);
    bool harmless_flip = v.empty();
    if (!harmless_flip) {
      ++named;
      EXPECT_EQ(v.find('\n'), std::string::npos) << "byte " << at << ": " << v;
    } else {
      ++harmless;
      // sound by its verdict: then every stored value is as it was
      const std::string now = exact_dump(copy);
      if (now != expected) {
        std::size_t d = 0;
        while (d < now.size() && d < expected.size() && now[d] == expected[d]) ++d;
        const std::size_t from = d < 60 ? 0 : d - 60;
        ADD_FAILURE() << "byte " << at << " (page " << at / 4096 << ", offset " << at % 4096
                      << ") changed a stored value unnoticed: at " << d << " of the dump, was \""
                      << expected.substr(from, 100) << "\", now \"" << now.substr(from, 100) << "\"";
        break;
      }
    }
    ASSERT_EQ(::pwrite(fd, &original[at], 1, static_cast<off_t>(at)), 1);
    const auto size = static_cast<std::size_t>(::lseek(fd, 0, SEEK_END));
    if (size != original.size() || ::pread(fd, now_bytes.data(), now_bytes.size(), 0) != static_cast<ssize_t>(original.size()) ||
        now_bytes != original) {
      ASSERT_EQ(::ftruncate(fd, 0), 0);
      ASSERT_EQ(::pwrite(fd, original.data(), original.size(), 0), static_cast<ssize_t>(original.size()));
    }
    if (fs::exists(copy + "-wal") && fs::file_size(copy + "-wal") > 0) fs::remove(copy + "-wal");
  }
  ::close(fd);
  if (scratch != root) fs::remove_all(scratch);
  EXPECT_GT(named, 0);
  std::printf("%ld flips named, %ld without effect on a stored value\n", named, harmless);
  RecordProperty("named", std::to_string(named));
  RecordProperty("harmless", std::to_string(harmless));
}

}  // namespace
}  // namespace bx
