#include "io/run_csv.h"

#include <sqlite3.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string_view>
#include <vector>

#include "core/files.h"
#include "core/text.h"

namespace bx {

namespace {

// one CSV field: quoted when it holds a comma, a quote or a line break
std::string field(std::string_view v) {
  if (v.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(v);
  std::string out = "\"";
  for (char c : v) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

// a column's value as CSV text: reals as the shortest text that reads back
// the same (non-finite: nan, inf, -inf), NULL as an empty field
std::string cell(sqlite3_stmt* s, int c) {
  switch (sqlite3_column_type(s, c)) {
    case SQLITE_NULL: return "";
    case SQLITE_INTEGER: return std::to_string(sqlite3_column_int64(s, c));
    case SQLITE_FLOAT: {
      const double v = sqlite3_column_double(s, c);
      if (std::isnan(v)) return "nan";
      if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
      return shortest_number(v);
    }
    default: {
      const auto* t = reinterpret_cast<const char*>(sqlite3_column_text(s, c));
      return field(t ? std::string_view(t, static_cast<std::size_t>(sqlite3_column_bytes(s, c))) : "");
    }
  }
}

// the rows of `sql` as CSV with `header`, into `path`; the count of rows
Result<long> write_query(sqlite3* db, const std::string& db_path, const std::string& sql, const std::string& header,
                         const std::string& path) {
  sqlite3_stmt* s = nullptr;
  if (sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) != SQLITE_OK) {
    std::string e = sqlite3_errmsg(db);
    sqlite3_finalize(s);
    return Error{db_path + ": not a run database Bestiary can read (" + e + ")"};
  }
  std::string text = header + "\n";
  long rows = 0;
  int rc = SQLITE_ROW;
  while ((rc = sqlite3_step(s)) == SQLITE_ROW) {
    for (int c = 0; c < sqlite3_column_count(s); ++c) {
      if (c) text += ',';
      text += cell(s, c);
    }
    text += "\n";
    ++rows;
  }
  sqlite3_finalize(s);
  if (rc != SQLITE_DONE) return Error{db_path + ": " + sqlite3_errmsg(db)};
  if (Status w = write_file_atomic(path, text); !w) return Error{w.error()};
  return rows;
}

// whether `sql` (one ? bound to `name`) finds a row: a question about the schema
bool finds(sqlite3* db, const char* sql, const char* name) {
  sqlite3_stmt* q = nullptr;
  bool found = false;
  if (sqlite3_prepare_v2(db, sql, -1, &q, nullptr) == SQLITE_OK) {
    sqlite3_bind_text(q, 1, name, -1, SQLITE_STATIC);
    found = sqlite3_step(q) == SQLITE_ROW;
  }
  sqlite3_finalize(q);
  return found;
}

bool has_table(sqlite3* db, const char* name) {
  return finds(db, "SELECT 1 FROM sqlite_schema WHERE type = 'table' AND name = ?", name);
}

}  // namespace

Result<CsvExport> export_run_csv(const std::string& db_path, const std::string& dir) {
  namespace fs = std::filesystem;
  if (!fs::is_regular_file(db_path)) return Error{db_path + ": no run database there"};
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    std::string e = db ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close(db);
    return Error{db_path + ": cannot open (" + e + ")"};
  }
  std::unique_ptr<sqlite3, int (*)(sqlite3*)> hold(db, sqlite3_close);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) return Error{"--csv: cannot create directory \"" + dir + "\"" + (ec ? " (" + ec.message() + ")" : "")};
  const fs::path d(dir);
  // a generation's stage: the last whose first generation is not after it
  // (a run of one stage has none: its stage is "")
  const std::string stage_of =
      "COALESCE((SELECT name FROM stage WHERE first_gen <= g.gen ORDER BY first_gen DESC LIMIT 1), '')";
  const bool staged = has_table(db, "stage");  // (a database stored before runs had stages: none)
  CsvExport out;
  auto gens = write_query(db, db_path,
                          "SELECT g.gen, " + (staged ? stage_of : std::string("''")) +
                              ", g.evaluations, g.best, g.mean, g.median, g.best_id, g.rejected, g.failed "
                              "FROM generation g ORDER BY g.gen",
                          "generation,stage,evaluations,best,mean,median,best_id,rejected,failed",
                          (d / "generations.csv").string());
  if (!gens) return Error{gens.error()};
  out.generations = *gens;
  // a database stored before a column was added reads as its default then
  // (resume and verify add it; this reads without writing)
  auto column = [&](const char* name, const char* otherwise) {
    return finds(db, "SELECT 1 FROM pragma_table_info('individual') WHERE name = ?", name)
               ? std::string(name)
               : std::string(otherwise) + " AS " + name;
  };
  auto inds = write_query(db, db_path,
                          "SELECT id, gen, fitness, distance, " + column("evaluations", "1") +
                              ", parent1, parent2, operator, failure, " + column("seed", "NULL") + ", " +
                              column("kind", "'graph'") + " FROM individual ORDER BY id",
                          "id,generation,fitness,distance,evaluations,parent1,parent2,operator,failure,seed,kind",
                          (d / "individuals.csv").string());
  if (!inds) return Error{inds.error()};
  out.individuals = *inds;
  // (a database stored before runs had metrics: none)
  auto mets = write_query(db, db_path,
                          has_table(db, "generation_metric")
                              ? "SELECT gen, name, mean, nonzero FROM generation_metric ORDER BY gen, name"
                              : "SELECT 1 WHERE 0",
                          "generation,metric,mean,nonzero_share", (d / "metrics.csv").string());
  if (!mets) return Error{mets.error()};
  out.metrics = *mets;
  auto run = write_query(db, db_path, "SELECT key, value FROM run WHERE key <> 'config' ORDER BY key", "key,value",
                         (d / "run.csv").string());
  if (!run) return Error{run.error()};
  out.run = *run;
  return out;
}

}  // namespace bx
