// A run database as CSV files, for R, spreadsheets and anything without
// SQLite (`bestiary export RUN --csv DIR`; docs/run-database.md says what
// each column is). RFC 4180: a header row, fields quoted when they hold a
// comma, a quote or a line break; reals as the shortest text that reads back
// to the same double.
#pragma once

#include <string>

#include "core/result.h"

namespace bx {

/// What export_run_csv wrote: the files' rows (headers aside).
struct CsvExport {
  long generations = 0, individuals = 0, metrics = 0, run = 0;
};

/// Writes DIR/generations.csv (one row a generation or report interval, with
/// its stage's name), DIR/individuals.csv (every creature born but its genome:
/// `bestiary best RUN:ID` writes that), DIR/metrics.csv (the task's named
/// measures per generation) and DIR/run.csv (the run's facts: its name, seed,
/// build; its config is the run folder's config.toml). The database is opened
/// read-only; an error names the file.
Result<CsvExport> export_run_csv(const std::string& db_path, const std::string& dir);

}  // namespace bx
