#include "io/run_store.h"

#include <sqlite3.h>

#include <unistd.h>

#include <cassert>
#include <cstring>
#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>

#include "eval/records_json.h"
#include "genome/genotype.h"

namespace bx {

namespace {

using nlohmann::json;

// user_version 1: every row carries a checksum of its values (`digest`)
constexpr int kFormat = 1;

const char* kSchema = R"(
PRAGMA journal_mode = WAL;
PRAGMA user_version = 1;
CREATE TABLE run (key TEXT PRIMARY KEY, value TEXT NOT NULL, digest TEXT);
CREATE TABLE generation (
  gen INTEGER PRIMARY KEY, evaluations INTEGER NOT NULL,
  best REAL NOT NULL, mean REAL NOT NULL, median REAL NOT NULL, best_id INTEGER NOT NULL,
  rejected INTEGER NOT NULL, failed INTEGER NOT NULL, digest TEXT);
CREATE TABLE individual (
  id INTEGER PRIMARY KEY, gen INTEGER NOT NULL, genome TEXT NOT NULL,
  fitness REAL NOT NULL, distance REAL NOT NULL, parent1 INTEGER, parent2 INTEGER,
  operator TEXT NOT NULL, failure TEXT NOT NULL, seed TEXT, kind TEXT NOT NULL DEFAULT 'graph',
  evaluations INTEGER NOT NULL DEFAULT 1, digest TEXT);
CREATE INDEX individual_gen ON individual (gen);
CREATE TABLE generation_metric (
  gen INTEGER NOT NULL, name TEXT NOT NULL, mean REAL NOT NULL, nonzero REAL NOT NULL, digest TEXT,
  PRIMARY KEY (gen, name));
CREATE TABLE checkpoint (id INTEGER PRIMARY KEY CHECK (id = 1), gen INTEGER NOT NULL, state TEXT NOT NULL, digest TEXT);
CREATE TABLE stage (idx INTEGER PRIMARY KEY, name TEXT NOT NULL, first_gen INTEGER NOT NULL, first_id INTEGER NOT NULL,
  digest TEXT);
)";

// A table whose rows are sealed: `digest` = bx_digest(table, its values...),
// written with the row and compared by check_integrity. A generation's covers
// how many metric rows it has, so a lost one is named too.
struct Sealed {
  const char* table;
  const char* values;  ///< the expressions hashed, in order
  const char* who;     ///< an expression naming the row in the user's terms
};
constexpr Sealed kSealed[] = {
    {"run", "key, value", "'the run''s ' || quote(key)"},
    {"stage", "idx, name, first_gen, first_id", "'stage ' || idx"},
    {"checkpoint", "id, gen, state", "'the checkpoint'"},
    {"generation",
     "gen, evaluations, best, mean, median, best_id, rejected, failed, "
     "(SELECT count(*) FROM generation_metric m WHERE m.gen = generation.gen)",
     "'generation ' || gen"},
    {"generation_metric", "gen, name, mean, nonzero", "'generation ' || gen || '''s metric ' || quote(name)"},
    {"individual", "id, gen, genome, fitness, distance, parent1, parent2, operator, failure, seed, kind, evaluations",
     "'individual ' || id"},
};

const Sealed& sealed(std::string_view table) {
  for (const Sealed& t : kSealed)
    if (table == t.table) return t;
  assert(false && "not a sealed table");
  return kSealed[0];
}

// bx_digest(values...): FNV-1a (64 bits) of each value's type and content
// (integers and reals as their 8 bytes, little-endian; text and blobs with
// their length), as 16 hex digits. A change of any one byte of any value
// changes it (each step of FNV-1a is a bijection of the state).
void digest_function(sqlite3_context* ctx, int argc, sqlite3_value** argv) {
  std::uint64_t h = 14695981039346656037ull;
  auto byte = [&](unsigned char c) { h = (h ^ c) * 1099511628211ull; };
  auto word = [&](std::uint64_t v) {
    for (int k = 0; k < 8; ++k) byte(static_cast<unsigned char>(v >> (8 * k)));
  };
  for (int i = 0; i < argc; ++i) {
    const int type = sqlite3_value_type(argv[i]);
    byte(static_cast<unsigned char>(type));
    if (type == SQLITE_INTEGER) {
      word(static_cast<std::uint64_t>(sqlite3_value_int64(argv[i])));
    } else if (type == SQLITE_FLOAT) {
      const double d = sqlite3_value_double(argv[i]);
      std::uint64_t bits = 0;
      std::memcpy(&bits, &d, sizeof bits);
      word(bits);
    } else if (type == SQLITE_TEXT || type == SQLITE_BLOB) {
      const auto* p = static_cast<const unsigned char*>(type == SQLITE_TEXT ? sqlite3_value_text(argv[i])
                                                                            : sqlite3_value_blob(argv[i]));
      const int n = sqlite3_value_bytes(argv[i]);
      word(static_cast<std::uint64_t>(n));
      for (int k = 0; k < n; ++k) byte(p[k]);
    }
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  sqlite3_result_text(ctx, buf, 16, SQLITE_TRANSIENT);
}

std::string digest_expr(const Sealed& t) {
  return std::string("bx_digest('") + t.table + "', " + t.values + ")";
}

// a prepared statement, finalized on scope exit
class Stmt {
 public:
  Stmt(sqlite3* db, const char* sql) { sqlite3_prepare_v2(db, sql, -1, &s_, nullptr); }
  ~Stmt() { sqlite3_finalize(s_); }
  Stmt& bind(int i, std::int64_t v) { sqlite3_bind_int64(s_, i, v); return *this; }
  Stmt& bind(int i, double v) { sqlite3_bind_double(s_, i, v); return *this; }
  Stmt& bind(int i, const std::string& v) {
    sqlite3_bind_text(s_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT);
    return *this;
  }
  Stmt& bind_null(int i) { sqlite3_bind_null(s_, i); return *this; }
  int step() { return sqlite3_step(s_); }
  void reset() { sqlite3_reset(s_); sqlite3_clear_bindings(s_); }
  std::int64_t i64(int c) const { return sqlite3_column_int64(s_, c); }
  double real(int c) const { return sqlite3_column_double(s_, c); }
  bool null(int c) const { return sqlite3_column_type(s_, c) == SQLITE_NULL; }
  std::string text(int c) const {
    auto* p = sqlite3_column_text(s_, c);
    return p ? reinterpret_cast<const char*>(p) : "";
  }
  bool ok() const { return s_ != nullptr; }
  sqlite3_stmt* raw() const { return s_; }

 private:
  sqlite3_stmt* s_ = nullptr;
};

Status exec(sqlite3* db, const char* sql) {
  char* err = nullptr;
  if (sqlite3_exec(db, sql, nullptr, nullptr, &err) != SQLITE_OK) {
    std::string msg = err ? err : "unknown error";
    sqlite3_free(err);
    return Error{msg};
  }
  return Ok{};
}

// `text` on one line: line breaks (SQLite's messages have them) as spaces
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

Result<sqlite3*> open_db(const std::string& path, int flags) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, flags, nullptr) != SQLITE_OK) {
    std::string msg = path + ": cannot open run database (" + one_line(sqlite3_errmsg(db)) + ")";
    sqlite3_close(db);
    return Error{msg};
  }
  sqlite3_busy_timeout(db, 5000);
  sqlite3_create_function_v2(db, "bx_digest", -1, SQLITE_UTF8 | SQLITE_DETERMINISTIC, nullptr, digest_function,
                             nullptr, nullptr, nullptr);
  return db;
}

// a whole number, or nothing (no sign, no space, no trailing text)
std::optional<std::uint64_t> whole_number(const std::string& text) {
  if (text.empty() || text.size() > 20) return std::nullopt;
  std::uint64_t v = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    std::uint64_t d = static_cast<std::uint64_t>(c - '0');
    if (v > (UINT64_MAX - d) / 10) return std::nullopt;
    v = v * 10 + d;
  }
  return v;
}

// a column that must hold a number: an error names the field and what it holds
Status number_column(sqlite3_stmt* s, int c, const std::string& what) {
  int t = sqlite3_column_type(s, c);
  if (t == SQLITE_INTEGER || t == SQLITE_FLOAT) return Ok{};
  auto* p = sqlite3_column_text(s, c);
  std::string v = p ? reinterpret_cast<const char*>(p) : "NULL";
  if (v.size() > 40) v = v.substr(0, 40) + "...";
  return Error{what + " is not a number (\"" + v + "\")"};
}

// seals the rows of `t` that `where` picks (with ?1 = key): their digest of their values now
template <class Key>
bool seal(sqlite3* db, const Sealed& t, const char* where, const Key& key) {
  const std::string sql = std::string("UPDATE ") + t.table + " SET digest = " + digest_expr(t) + " WHERE " + where;
  Stmt s(db, sql.c_str());
  s.bind(1, key);
  return s.ok() && s.step() == SQLITE_DONE;
}

bool has_table(sqlite3* db, const char* table) {
  Stmt s(db, "SELECT count(*) FROM sqlite_schema WHERE type = 'table' AND name = ?");
  s.bind(1, std::string(table));
  return s.step() == SQLITE_ROW && s.i64(0) == 1;
}

bool has_column(sqlite3* db, const char* table, const char* column) {
  const std::string sql = std::string("SELECT count(*) FROM pragma_table_info('") + table + "') WHERE name = ?";
  Stmt s(db, sql.c_str());
  s.bind(1, std::string(column));
  return s.step() == SQLITE_ROW && s.i64(0) == 1;
}

// what a database declares: each table's and index's SQL, by name
std::string schema_of(sqlite3* db) {
  std::string out;
  Stmt s(db, "SELECT type, name, tbl_name, sql FROM sqlite_schema ORDER BY name");
  while (s.step() == SQLITE_ROW) out += s.text(0) + "|" + s.text(1) + "|" + s.text(2) + "|" + s.text(3) + "\n";
  return out;
}

// one table's or index's declaration: its type, table and SQL ("" if absent)
std::string declaration(sqlite3* db, const std::string& name) {
  Stmt s(db, "SELECT type, tbl_name, sql FROM sqlite_schema WHERE name = ?");
  s.bind(1, name);
  return s.step() == SQLITE_ROW ? s.text(0) + "|" + s.text(1) + "|" + s.text(2) : "";
}

sqlite3* fresh_schema();

// a format-1 database declares exactly what kSchema does; an error names the
// first table (or the table of the first index) that differs
Status same_declarations(sqlite3* db, const std::string& path) {
  if (schema_of(db) == schema_of(fresh_schema())) return Ok{};
  Stmt s(fresh_schema(), "SELECT type, name, tbl_name FROM sqlite_schema ORDER BY type DESC, name");
  while (s.step() == SQLITE_ROW) {
    const std::string type = s.text(0), name = s.text(1), table = s.text(2);
    const std::string have = declaration(db, name);
    if (have == declaration(fresh_schema(), name)) continue;
    if (type == "table")
      return Error{path + ": the run database " +
                   (have.empty() ? "lacks its " + name + " table"
                                 : "declares its " + name + " table otherwise than it was created") +
                   " (damaged)"};
    return Error{path + ": the run database's index of its " + table + " table is missing or changed (damaged)"};
  }
  return Error{path + ": the run database declares a table or index it was not created with (damaged)"};
}

// a database made from kSchema in memory: what a new run declares
sqlite3* fresh_schema() {
  static sqlite3* db = [] {
    sqlite3* m = nullptr;
    sqlite3_open_v2(":memory:", &m, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
    exec(m, kSchema);
    return m;
  }();
  return db;
}

}  // namespace

Result<std::unique_ptr<RunStore>> RunStore::create(
    const std::string& path, const std::vector<std::pair<std::string, std::string>>& meta) {
  if (std::filesystem::exists(path)) return Error{path + ": run database already exists"};
  auto db = open_db(path, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
  if (!db) return Error{db.error()};
  std::unique_ptr<RunStore> store(new RunStore(*db, path));
  if (Status s = exec(*db, kSchema); !s) return Error{path + ": " + s.error()};
  for (const auto& [k, v] : meta)
    if (Status s = store->set_meta(k, v); !s) return Error{s.error()};
  return store;
}

Result<std::unique_ptr<RunStore>> RunStore::open(const std::string& path) {
  namespace fs = std::filesystem;
  if (!fs::exists(path)) return Error{path + ": no run database here"};
  // a run this user may only read (a shared folder, an archive) opens read-only;
  // a clean copy has no -wal/-shm files and a read-only folder cannot hold
  // them, so it is opened as immutable
  std::string dir = fs::path(path).parent_path().string();
  const bool writable = ::access(path.c_str(), W_OK) == 0 && ::access(dir.empty() ? "." : dir.c_str(), W_OK) == 0;
  const std::string uri = "file:" + path + (writable ? "" : "?immutable=1");
  auto db = open_db(writable ? path : uri, writable ? SQLITE_OPEN_READWRITE
                                                    : SQLITE_OPEN_READONLY | SQLITE_OPEN_URI);
  if (!db) return Error{db.error()};
  std::unique_ptr<RunStore> store(new RunStore(*db, path));
  store->read_only_ = !writable;
  Stmt check(*db, "SELECT count(*) FROM run");
  if (!check.ok() || check.step() != SQLITE_ROW)
    return Error{path + ": not a Bestiary run database (" + one_line(sqlite3_errmsg(*db)) + ")"};
  Stmt version(*db, "PRAGMA user_version");
  store->format_ = version.step() == SQLITE_ROW ? static_cast<int>(version.i64(0)) : -1;
  if (store->format_ < 0 || store->format_ > kFormat)
    return Error{path + ": a run database of format " + std::to_string(store->format_) +
                 ", which this Bestiary does not know (it writes format " + std::to_string(kFormat) +
                 "): made by a newer Bestiary, or damaged"};
  // a run with checksums (format 1) declares its tables as it was created,
  // and needs none of the migrations below; a changed declaration would
  // change what its rows read as
  if (store->format_ >= 1) {
    if (Status d = same_declarations(*db, path); !d) return Error{d.error()};
    return store;
  }
  // every run has had these tables
  for (const char* table : {"generation", "individual", "checkpoint"})
    if (!has_table(*db, table))
      return Error{path + ": the run database lacks its " + table + " table (damaged; a run stores " +
                   (std::string_view(table) == "checkpoint" ? "its checkpoint" : std::string("its ") + table + "s") +
                   " there)"};
  // databases written before individuals kept their evaluation seed get the
  // column (empty: the seed is derived, see individual()); read-only, they stay as they are
  if (!has_column(*db, "individual", "seed"))
    store->seed_column_ = writable && exec(*db, "ALTER TABLE individual ADD COLUMN seed TEXT").ok();
  // and before they kept their genotype's kind: all were graph genomes
  if (!has_column(*db, "individual", "kind"))
    store->kind_column_ =
        writable && exec(*db, "ALTER TABLE individual ADD COLUMN kind TEXT NOT NULL DEFAULT 'graph'").ok();
  // and before an elite's fitness could be the mean of several evaluations
  if (!has_column(*db, "individual", "evaluations"))
    store->evaluations_column_ =
        writable && exec(*db, "ALTER TABLE individual ADD COLUMN evaluations INTEGER NOT NULL DEFAULT 1").ok();
  // and before a generation kept its task's metrics
  if (!has_table(*db, "generation_metric"))
    store->metric_table_ = writable && exec(*db, "CREATE TABLE generation_metric (gen INTEGER NOT NULL, "
                                                 "name TEXT NOT NULL, mean REAL NOT NULL, nonzero REAL NOT NULL, "
                                                 "PRIMARY KEY (gen, name))").ok();
  // and before a run could have stages
  if (!has_table(*db, "stage"))
    store->stage_table_ = writable && exec(*db, "CREATE TABLE stage (idx INTEGER PRIMARY KEY, name TEXT NOT NULL, "
                                                "first_gen INTEGER NOT NULL, first_id INTEGER NOT NULL)").ok();
  // and before rows carried checksums: those written from now on get them
  for (const Sealed& t : kSealed) {
    if (!has_table(*db, t.table) || has_column(*db, t.table, "digest")) continue;
    if (!writable) break;
    exec(*db, (std::string("ALTER TABLE ") + t.table + " ADD COLUMN digest TEXT").c_str());
  }
  store->digest_columns_ = true;
  for (const Sealed& t : kSealed)
    if (!has_column(*db, t.table, "digest")) store->digest_columns_ = false;
  return store;
}

Result<std::uint64_t> RunStore::master_seed() const {
  std::string text = meta("seed");
  if (text.empty()) return Error{path_ + ": the run's seed is missing (no complete run)"};
  auto v = whole_number(text);
  if (!v) return Error{path_ + ": the run's seed is not a whole number (\"" + text.substr(0, 40) + "\")"};
  return *v;
}

Result<std::string> RunStore::config_text() const {
  std::string text = meta("config");
  if (text.empty()) return Error{path_ + ": the run's config is missing (no complete run)"};
  return text;
}

Result<Integrity> RunStore::check_integrity() const {
  // one read transaction: a run going on beside it (show, verify of a live
  // run) is seen at one generation boundary, not half of one
  const bool snapshot = sqlite3_get_autocommit(db_) && exec(db_, "BEGIN").ok();
  struct End {
    sqlite3* db;
    bool on;
    ~End() {
      if (on) exec(db, "COMMIT");
    }
  } end{db_, snapshot};
  // SQLite's own check: pages, records, and every index against its table
  Stmt s(db_, "PRAGMA integrity_check");
  std::string problems;
  int n = 0;
  int rc;
  while ((rc = s.step()) == SQLITE_ROW) {
    std::string line = s.text(0);
    if (line == "ok") continue;
    if (n++ < 3) problems += (problems.empty() ? "" : "; ") + one_line(line);
  }
  if (rc != SQLITE_DONE && problems.empty()) problems = one_line(sqlite3_errmsg(db_));
  if (!problems.empty()) return Error{path_ + ": the database is damaged (" + problems + (n > 3 ? "; ..." : "") + ")"};
  // every number a number: SQLite stores what it is given, and a text reads
  // as 0 (a run with checksums: its checksums say so, below)
  const char* numeric[][2] = {
      {"generation", "evaluations"}, {"generation", "best"}, {"generation", "mean"}, {"generation", "median"},
      {"generation", "best_id"},     {"generation", "rejected"}, {"generation", "failed"},
      {"individual", "gen"},         {"individual", "fitness"}, {"individual", "distance"},
      {"individual", "evaluations"}};
  for (const auto& [table, column] : numeric) {
    if (format_ >= 1) break;
    std::string sql = std::string("SELECT rowid, ") + column + " FROM " + table + " WHERE typeof(" + column +
                      ") NOT IN ('integer', 'real') LIMIT 1";
    Stmt q(db_, sql.c_str());
    if (q.ok() && q.step() == SQLITE_ROW)
      return Error{path_ + ": " + table + " " + std::to_string(q.i64(0)) + "'s " + column + " is not a number (\"" +
                   q.text(1).substr(0, 40) + "\")"};
  }
  // every row as it was written: its values against its checksum (a run
  // begun before checksums has none on the rows it stored then), in one
  // pass over each table
  Integrity out;
  if (digest_columns_) {
    for (const Sealed& t : kSealed) {
      if (format_ < 1 && !has_table(db_, t.table)) continue;
      const std::string bad = std::string("digest IS NOT ") + digest_expr(t) +
                              (format_ >= 1 ? "" : " AND digest IS NOT NULL");
      const std::string sql = std::string("SELECT count(digest), count(*) - count(digest), min(CASE WHEN ") + bad +
                              " THEN rowid END) FROM " + t.table;
      Stmt q(db_, sql.c_str());
      if (!q.ok() || q.step() != SQLITE_ROW)
        return Error{path_ + ": the database is damaged (" + one_line(sqlite3_errmsg(db_)) + ")"};
      if (!q.null(2)) {
        const std::string which = std::string("SELECT ") + t.who + ", digest IS NULL FROM " + t.table + " WHERE rowid = ?";
        Stmt w(db_, which.c_str());
        w.bind(1, q.i64(2));
        const bool row = w.step() == SQLITE_ROW;
        return Error{path_ + ": " + (row ? one_line(w.text(0)).substr(0, 80) : std::string(t.table) + " row") +
                     (row && w.i64(1) ? " has no checksum" : " does not match its checksum") +
                     " (damaged: a stored value changed since it was written)"};
      }
      out.sealed += q.i64(0);
      out.unsealed += q.i64(1);
    }
  }
  // and no row missing: generations 0..the checkpoint's, individuals
  // 0..its next id - 1, stages 0..its stage (each stored with its first generation)
  auto cp = checkpoint();
  if (!cp) return Error{cp.error()};
  auto ids = [&](const char* sql) {
    std::vector<std::int64_t> v;
    Stmt q(db_, sql);
    while (q.step() == SQLITE_ROW) v.push_back(q.i64(0));
    return v;
  };
  const std::vector<std::int64_t> gens = ids("SELECT gen FROM generation ORDER BY gen");
  const std::vector<std::int64_t> born = ids("SELECT id FROM individual ORDER BY id");
  const std::vector<std::int64_t> staged =
      stage_table_ ? ids("SELECT idx FROM stage ORDER BY idx") : std::vector<std::int64_t>{};
  if (!*cp) {
    if (!gens.empty() || !born.empty())
      return Error{path_ + ": the checkpoint is missing, though " + std::to_string(gens.size()) +
                   " generations and " + std::to_string(born.size()) + " individuals are stored (damaged)"};
    return out;
  }
  // the first of 0..n-1 that `v` (sorted) lacks, or n if it holds them all, or -1 if it holds more
  auto first_gap = [](const std::vector<std::int64_t>& v, std::int64_t n) -> std::int64_t {
    for (std::int64_t k = 0; k < n; ++k)
      if (k >= static_cast<std::int64_t>(v.size()) || v[static_cast<std::size_t>(k)] != k) return k;
    return static_cast<std::int64_t>(v.size()) == n ? n : -1;
  };
  const Checkpoint& c = **cp;
  struct Rows {
    const std::vector<std::int64_t>& have;
    std::int64_t expected;  // rows 0..expected-1
    const char* noun;
    std::string context;    // what the checkpoint says of them
  };
  std::vector<Rows> rows = {
      {gens, c.generation + 1, "generation", "the checkpoint follows generation " + std::to_string(c.generation)},
      {born, c.next_id, "individual", "the checkpoint counts " + std::to_string(c.next_id) + " born"}};
  if (format_ >= 1 || !staged.empty())
    rows.push_back({staged, c.stage.index + 1, "stage", "the checkpoint is in stage " + std::to_string(c.stage.index)});
  for (const Rows& r : rows) {
    const std::int64_t gap = first_gap(r.have, r.expected);
    if (gap == r.expected) continue;
    const std::int64_t which = gap >= 0 ? gap : r.have.back();
    return Error{path_ + ": " + r.noun + " " + std::to_string(which) + (gap >= 0 ? " is missing" : " should not be there") +
                 " (damaged: " + r.context + ")"};
  }
  for (std::int64_t id : c.population)
    if (id >= c.next_id)
      return Error{path_ + ": the checkpoint's population names individual " + std::to_string(id) +
                   ", but there is no individual " + std::to_string(id) + " (damaged: " + std::to_string(c.next_id) +
                   " were born)"};
  out.generations = static_cast<long>(gens.size());
  out.individuals = static_cast<long>(born.size());
  out.stages = static_cast<long>(staged.size());
  return out;
}

RunStore::~RunStore() { sqlite3_close(db_); }

Status RunStore::set_meta(const std::string& key, const std::string& value) {
  Stmt s(db_, "INSERT INTO run (key, value) VALUES (?, ?) ON CONFLICT(key) DO UPDATE SET value = excluded.value");
  if (s.bind(1, key).bind(2, value).step() != SQLITE_DONE) return Error{sqlite3_errmsg(db_)};
  if (digest_columns_ && !seal(db_, sealed("run"), "key = ?1", key)) return Error{sqlite3_errmsg(db_)};
  return Ok{};
}

std::string RunStore::meta(const std::string& key) const {
  Stmt s(db_, "SELECT value FROM run WHERE key = ?");
  s.bind(1, key);
  return s.step() == SQLITE_ROW ? s.text(0) : "";
}

Result<std::optional<HeldOut>> RunStore::held_out() const {
  const std::string text = meta("held_out");
  if (text.empty()) return std::optional<HeldOut>{};
  const std::string who = path_ + ": the run's held_out";
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded()) return Error{who + ": not JSON: " + text.substr(0, 60)};
  auto h = held_out_from_json(j, who, true);
  if (!h) return Error{h.error()};
  return std::optional<HeldOut>{std::move(*h)};
}

Status RunStore::set_held_out(const HeldOut& h) {
  return set_meta("held_out", held_out_to_json(h).dump());
}

Status RunStore::write_generation(const GenerationStats& st, const std::vector<Individual>& born,
                                  const std::vector<Individual>& reevaluated, const Checkpoint& cp) {
  if (Status s = exec(db_, "BEGIN IMMEDIATE"); !s) return s;
  auto rollback = [&](const std::string& what) {
    std::string msg = what + ": " + sqlite3_errmsg(db_);
    exec(db_, "ROLLBACK");
    return Status(Error{msg});
  };
  // individuals born in this generation
  {
    Stmt ins(db_, "INSERT INTO individual (id, gen, genome, fitness, distance, parent1, parent2, operator, failure, "
                  "seed, kind, evaluations) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    for (const auto& ind : born) {
      ins.bind(1, ind.id).bind(2, static_cast<std::int64_t>(ind.generation))
          .bind(3, ind.genotype->to_json().dump()).bind(4, ind.fitness).bind(5, ind.distance);
      if (ind.parent1 >= 0) ins.bind(6, ind.parent1); else ins.bind_null(6);
      if (ind.parent2 >= 0) ins.bind(7, ind.parent2); else ins.bind_null(7);
      ins.bind(8, ind.op).bind(9, ind.failure).bind(10, std::to_string(ind.seed))
          .bind(11, std::string(ind.genotype->kind())).bind(12, static_cast<std::int64_t>(ind.evaluations));
      if (ins.step() != SQLITE_DONE || !seal(db_, sealed("individual"), "id = ?1", ind.id))
        return rollback("storing individual " + std::to_string(ind.id));
      ins.reset();
    }
  }
  // earlier individuals evaluated again: their mean and count
  {
    Stmt up(db_, "UPDATE individual SET fitness = ?, evaluations = ? WHERE id = ?");
    for (const auto& ind : reevaluated) {
      up.bind(1, ind.fitness).bind(2, static_cast<std::int64_t>(ind.evaluations)).bind(3, ind.id);
      if (up.step() != SQLITE_DONE || sqlite3_changes(db_) != 1 || !seal(db_, sealed("individual"), "id = ?1", ind.id))
        return rollback("updating individual " + std::to_string(ind.id));
      up.reset();
    }
  }
  // the generation's statistics
  {
    Stmt g(db_, "INSERT INTO generation (gen, evaluations, best, mean, median, best_id, rejected, failed) "
                "VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
    g.bind(1, static_cast<std::int64_t>(st.generation)).bind(2, static_cast<std::int64_t>(st.evaluations))
        .bind(3, st.best).bind(4, st.mean).bind(5, st.median).bind(6, st.best_id)
        .bind(7, static_cast<std::int64_t>(st.rejected)).bind(8, static_cast<std::int64_t>(st.failed));
    if (g.step() != SQLITE_DONE) return rollback("storing generation " + std::to_string(st.generation));
  }
  // and its task's metrics
  {
    Stmt m(db_, "INSERT INTO generation_metric (gen, name, mean, nonzero) VALUES (?, ?, ?, ?)");
    for (const MetricStat& ms : st.metrics) {
      m.bind(1, static_cast<std::int64_t>(st.generation)).bind(2, ms.name).bind(3, ms.mean).bind(4, ms.nonzero);
      if (m.step() != SQLITE_DONE) return rollback("storing generation " + std::to_string(st.generation) + "'s metric " + ms.name);
      m.reset();
    }
  }
  // sealed once its metrics are in (its digest counts them)
  const auto gen = static_cast<std::int64_t>(st.generation);
  if (!seal(db_, sealed("generation_metric"), "gen = ?1", gen) || !seal(db_, sealed("generation"), "gen = ?1", gen))
    return rollback("storing generation " + std::to_string(st.generation));
  // the stage it belongs to, stored with its first generation
  if (cp.generation == cp.stage.first_gen) {
    Stmt g(db_, "INSERT INTO stage (idx, name, first_gen, first_id) VALUES (?, ?, ?, ?)");
    g.bind(1, static_cast<std::int64_t>(cp.stage.index)).bind(2, cp.stage.name)
        .bind(3, static_cast<std::int64_t>(cp.stage.first_gen)).bind(4, cp.stage.first_id);
    if (g.step() != SQLITE_DONE ||
        !seal(db_, sealed("stage"), "idx = ?1", static_cast<std::int64_t>(cp.stage.index)))
      return rollback("storing stage " + std::to_string(cp.stage.index));
  }
  // and the checkpoint that resumes after it
  {
    json state = {{"evaluations", cp.evaluations}, {"next_id", cp.next_id}, {"population", cp.population}};
    if (cp.stage.index != 0 || cp.stage.first_gen != 0 || cp.stage.first_id != 0)
      state["stage"] = {{"index", cp.stage.index}, {"name", cp.stage.name}, {"first_gen", cp.stage.first_gen},
                        {"first_id", cp.stage.first_id}};
    Stmt c(db_, "INSERT INTO checkpoint (id, gen, state) VALUES (1, ?, ?) "
                "ON CONFLICT(id) DO UPDATE SET gen = excluded.gen, state = excluded.state");
    c.bind(1, static_cast<std::int64_t>(cp.generation)).bind(2, state.dump());
    if (c.step() != SQLITE_DONE || !seal(db_, sealed("checkpoint"), "id = ?1", std::int64_t{1}))
      return rollback("storing the checkpoint");
  }
  if (Status s = exec(db_, "COMMIT"); !s) return rollback("commit");
  return Ok{};
}

Result<std::optional<Checkpoint>> RunStore::checkpoint() const {
  Stmt s(db_, "SELECT gen, state FROM checkpoint WHERE id = 1");
  if (s.step() != SQLITE_ROW) return std::optional<Checkpoint>{};
  const std::string where = path_ + ": the checkpoint ";
  if (Status t = number_column(s.raw(), 0, "its generation"); !t) return Error{where + t.error()};
  Checkpoint cp;
  cp.generation = static_cast<int>(s.i64(0));
  json state = json::parse(s.text(1), nullptr, false);
  if (state.is_discarded() || !state.is_object()) return Error{where + "is not a JSON object"};
  auto count = [&](const char* key, auto& out, std::int64_t lo) -> Status {
    auto it = state.find(key);
    if (it == state.end()) return Error{where + "lacks \"" + key + "\""};
    if (!it->is_number_integer() || it->template get<std::int64_t>() < lo)
      return Error{where + "has \"" + key + "\" = " + it->dump().substr(0, 40) + ", not a whole number"};
    out = it->template get<std::int64_t>();
    return Ok{};
  };
  std::int64_t evaluations = 0;
  if (Status t = count("evaluations", evaluations, 0); !t) return Error{t.error()};
  if (Status t = count("next_id", cp.next_id, 0); !t) return Error{t.error()};
  cp.evaluations = static_cast<long>(evaluations);
  auto pop = state.find("population");
  if (pop == state.end() || !pop->is_array()) return Error{where + "lacks its population (an array of ids)"};
  for (const auto& id : *pop) {
    if (!id.is_number_integer() || id.get<std::int64_t>() < 0)
      return Error{where + "names an individual " + id.dump().substr(0, 40) + ", not an id"};
    cp.population.push_back(id.get<std::int64_t>());
  }
  if (cp.generation < 0 || cp.population.empty()) return Error{where + "is empty (generation " + std::to_string(cp.generation) + ")"};
  if (auto st = state.find("stage"); st != state.end()) {
    if (!st->is_object()) return Error{where + "has a \"stage\" that is not an object"};
    std::int64_t index = 0, first_gen = 0;
    auto read = [&](const char* key, std::int64_t& out) -> Status {
      auto it = st->find(key);
      if (it == st->end() || !it->is_number_integer() || it->get<std::int64_t>() < 0)
        return Error{where + "stage lacks \"" + key + "\" (a whole number)"};
      out = it->get<std::int64_t>();
      return Ok{};
    };
    if (Status t = read("index", index); !t) return Error{t.error()};
    if (Status t = read("first_gen", first_gen); !t) return Error{t.error()};
    if (Status t = read("first_id", cp.stage.first_id); !t) return Error{t.error()};
    auto name = st->find("name");
    if (name == st->end() || !name->is_string()) return Error{where + "stage lacks \"name\" (a string)"};
    cp.stage.index = static_cast<int>(index);
    cp.stage.first_gen = static_cast<int>(first_gen);
    cp.stage.name = name->get<std::string>();
    if (cp.stage.first_gen > cp.generation || cp.stage.first_id > cp.next_id)
      return Error{where + "stage begins after the checkpoint (generation " + std::to_string(cp.stage.first_gen) + ")"};
  }
  return std::optional<Checkpoint>(std::move(cp));
}

StageRow stage_of(const std::vector<StageRow>& stages, std::int64_t id) {
  StageRow out;
  for (const StageRow& s : stages)
    if (s.first_id <= id) out = s;
  return out;
}

std::vector<StageRow> RunStore::stages() const {
  std::vector<StageRow> out;
  if (!stage_table_) return out;
  Stmt s(db_, "SELECT idx, name, first_gen, first_id FROM stage ORDER BY idx");
  while (s.step() == SQLITE_ROW)
    out.push_back({static_cast<int>(s.i64(0)), s.text(1), static_cast<int>(s.i64(2)), s.i64(3)});
  return out;
}

std::vector<GenerationStats> RunStore::generations() const {
  std::vector<GenerationStats> out;
  Stmt s(db_, "SELECT gen, evaluations, best, mean, median, best_id, rejected, failed FROM generation ORDER BY gen");
  while (s.step() == SQLITE_ROW) {
    GenerationStats g;
    g.generation = static_cast<int>(s.i64(0));
    g.evaluations = s.i64(1);
    g.best = s.real(2);
    g.mean = s.real(3);
    g.median = s.real(4);
    g.best_id = s.i64(5);
    g.rejected = s.i64(6);
    g.failed = s.i64(7);
    out.push_back(g);
  }
  if (!metric_table_) return out;
  Stmt m(db_, "SELECT gen, name, mean, nonzero FROM generation_metric ORDER BY gen, rowid");
  std::size_t at = 0;
  while (m.step() == SQLITE_ROW) {
    const std::int64_t gen = m.i64(0);
    while (at < out.size() && out[at].generation < gen) ++at;
    if (at == out.size()) break;
    if (out[at].generation == gen) out[at].metrics.push_back({m.text(1), m.real(2), m.real(3)});
  }
  return out;
}

long RunStore::count_failures(std::string_view prefix, std::int64_t from, std::int64_t to) const {
  Stmt s(db_, "SELECT count(*) FROM individual WHERE id >= ? AND id < ? AND substr(failure, 1, ?) = ?");
  s.bind(1, from);
  s.bind(2, to);
  s.bind(3, static_cast<std::int64_t>(prefix.size()));
  s.bind(4, std::string(prefix));
  return s.step() == SQLITE_ROW ? static_cast<long>(s.i64(0)) : 0;
}

Result<Individual> RunStore::individual(std::int64_t id) const {
  const std::string sql = std::string("SELECT id, gen, genome, fitness, distance, parent1, parent2, operator, failure, ") +
                          (seed_column_ ? "seed" : "''") + ", " + (kind_column_ ? "kind" : "'graph'") + ", " +
                          (evaluations_column_ ? "evaluations" : "1") + " FROM individual WHERE id = ?";
  Stmt s(db_, sql.c_str());
  s.bind(1, id);
  const std::string who = "individual " + std::to_string(id);
  if (s.step() != SQLITE_ROW) return Error{"no " + who};
  for (auto [c, field] : {std::pair{1, "generation"}, {3, "fitness"}, {4, "distance"}, {11, "evaluations"}})
    if (Status t = number_column(s.raw(), c, who + "'s " + field); !t) return Error{t.error()};
  // 0: a child not yet drawn into a tournament (evolution.tournament_evaluates = all)
  if (s.i64(11) < 0)
    return Error{who + "'s evaluations is " + std::to_string(s.i64(11)) + ", not a count"};
  for (auto [c, field] : {std::pair{5, "parent1"}, {6, "parent2"}})
    if (!s.null(c))
      if (Status t = number_column(s.raw(), c, who + "'s " + field); !t) return Error{t.error()};
  const std::string kind = s.text(10);
  auto g = parse_genotype(kind, s.text(2), who);
  if (!g) return Error{g.error()};
  Individual ind;
  ind.id = s.i64(0);
  ind.generation = static_cast<int>(s.i64(1));
  ind.genotype = std::move(*g);
  ind.fitness = s.real(3);
  ind.distance = s.real(4);
  ind.parent1 = s.null(5) ? -1 : s.i64(5);
  ind.parent2 = s.null(6) ? -1 : s.i64(6);
  ind.op = s.text(7);
  ind.failure = s.text(8);
  ind.evaluations = static_cast<int>(std::min<std::int64_t>(s.i64(11), 1 << 30));
  // the stored evaluation seed; an older database's individual was evaluated
  // with the seed derived from the run's master seed and its id
  const std::string seed = s.text(9);
  if (seed.empty()) {
    auto master = master_seed();
    if (!master) return Error{master.error()};
    ind.seed = evaluation_seed(*master, ind.id);
  } else {
    auto v = whole_number(seed);
    if (!v) return Error{who + "'s seed is not a whole number (\"" + seed.substr(0, 40) + "\")"};
    ind.seed = *v;
  }
  return ind;
}

Result<Individual> RunStore::best_individual() const {
  std::optional<Individual> best;
  // a run of several stages: its last stage's (their fitnesses measure different tasks)
  const std::vector<StageRow> st = stages();
  const int from = st.empty() ? 0 : st.back().first_gen;
  for (const auto& g : generations()) {
    if (g.generation < from) continue;
    auto ind = individual(g.best_id);
    if (!ind) return Error{path_ + ": generation " + std::to_string(g.generation) + "'s best: " + ind.error()};
    if (!best || ind->fitness > best->fitness) best = std::move(*ind);
  }
  if (!best) return Error{"no generation finished yet"};
  return std::move(*best);
}

}  // namespace bx
