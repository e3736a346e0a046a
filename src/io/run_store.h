// The run database (SQLite, Revolve2's convention): the run with its seed and
// build version; per generation its statistics; per individual its genome,
// fitness, parents, operator and failure; and the checkpoint, written in the
// same transaction as the generation it closes, so the database is always at
// a generation boundary, whenever the process is killed.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "evolve/evolution.h"

struct sqlite3;

namespace bx {

/// What a checkpoint holds besides the individuals (which the database has).
struct Checkpoint {
  int generation = -1;
  long evaluations = 0;
  std::int64_t next_id = 0;
  std::vector<std::int64_t> population;  ///< ids, in population order
};

/// An open run database.
class RunStore {
 public:
  /// Creates `path` (which must not exist) with the run's metadata.
  static Result<std::unique_ptr<RunStore>> create(const std::string& path,
                                                  const std::vector<std::pair<std::string, std::string>>& meta);
  /// Opens an existing database.
  static Result<std::unique_ptr<RunStore>> open(const std::string& path);
  ~RunStore();

  /// Stores one generation: its statistics, the individuals born in it and
  /// the checkpoint after it, all or nothing.
  Status write_generation(const GenerationStats& stats, const std::vector<Individual>& born,
                          const Checkpoint& cp);
  /// The last checkpoint, if any generation was stored.
  std::optional<Checkpoint> checkpoint() const;
  /// Statistics of every stored generation, in order.
  std::vector<GenerationStats> generations() const;
  /// One individual by id.
  std::optional<Individual> individual(std::int64_t id) const;
  /// The fittest of the generations' bests so far (nullopt before any generation).
  std::optional<Individual> best_individual() const;
  /// A metadata value ("" if absent).
  std::string meta(const std::string& key) const;
  /// Sets a metadata value.
  Status set_meta(const std::string& key, const std::string& value);

 private:
  explicit RunStore(sqlite3* db) : db_(db) {}
  sqlite3* db_;
  bool seed_column_ = true;  ///< false: an older database opened read-only, without individual.seed
};

}  // namespace bx
