// The run database (SQLite, Revolve2's convention): the run with its seed and
// build version; per generation its statistics; per individual its genotype
// (kind and JSON form), fitness (the mean of its evaluations) and their
// count, parents, operator and failure; and the checkpoint, written in the
// same transaction as the generation it closes, so the database is always at
// a generation boundary, whenever the process is killed.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "evolve/evolution.h"

struct sqlite3;

namespace bx {

/// A stage of a multi-stage run (io/syllabus.h) as the database has it:
/// where its generations and individuals begin (every run has stage 0).
struct StageRow {
  int index = 0;
  std::string name;        ///< "" for a plain config's single stage
  int first_gen = 0;       ///< the run's generation number of its generation 0
  std::int64_t first_id = 0;  ///< the id of its first individual
};

/// The stage that individual `id` was born in, from a run's stages (none: stage 0).
StageRow stage_of(const std::vector<StageRow>& stages, std::int64_t id);

/// What a checkpoint holds besides the individuals (which the database has).
struct Checkpoint {
  int generation = -1;     ///< the run's generation number (stages number on)
  long evaluations = 0;
  std::int64_t next_id = 0;
  std::vector<std::int64_t> population;  ///< ids, in population order
  StageRow stage;          ///< the stage it is in
};

/// What check_integrity found sound.
struct Integrity {
  long generations = 0, individuals = 0, stages = 0;
  long sealed = 0;    ///< rows that matched their checksum
  long unsealed = 0;  ///< rows stored before runs kept checksums (an older run's), unchecked
};

/// An open run database.
class RunStore {
 public:
  /// Creates `path` (which must not exist) with the run's metadata.
  static Result<std::unique_ptr<RunStore>> create(const std::string& path,
                                                  const std::vector<std::pair<std::string, std::string>>& meta);
  /// Opens an existing database: read-write, or read-only where this user
  /// may not write it (the file or its directory).
  static Result<std::unique_ptr<RunStore>> open(const std::string& path);
  ~RunStore();

  /// Stores one generation: its statistics, the individuals born in it,
  /// the new fitness and evaluation count of earlier ones evaluated again,
  /// and the checkpoint after it, all or nothing.
  Status write_generation(const GenerationStats& stats, const std::vector<Individual>& born,
                          const std::vector<Individual>& reevaluated, const Checkpoint& cp);
  /// The last checkpoint, if any generation was stored; an error names a
  /// malformed one.
  Result<std::optional<Checkpoint>> checkpoint() const;
  /// The stages begun so far, in order (an older database: none).
  std::vector<StageRow> stages() const;
  /// Statistics of every stored generation, in order.
  std::vector<GenerationStats> generations() const;
  /// One individual by id; an error says it is missing, or names the field
  /// that does not read as its type.
  Result<Individual> individual(std::int64_t id) const;
  /// How many individuals with ids in [from, to) have a failure that starts
  /// with `prefix` (a General ESP stage's children below a retest), counted
  /// without reading their genomes.
  long count_failures(std::string_view prefix, std::int64_t from, std::int64_t to) const;
  /// The fittest of the generations' bests so far (an error before any
  /// generation finished, or naming a best that does not read).
  Result<Individual> best_individual() const;
  /// A metadata value ("" if absent).
  std::string meta(const std::string& key) const;
  /// Sets a metadata value.
  Status set_meta(const std::string& key, const std::string& value);
  /// The held-out measure of the run's best, if one was stored; an error
  /// names a malformed one.
  Result<std::optional<HeldOut>> held_out() const;
  /// Stores it (replacing an earlier one: the run was lengthened and has
  /// another best).
  Status set_held_out(const HeldOut& h);

  /// The run's master seed, as stored ("seed"); an error if it is missing or
  /// not a whole number.
  Result<std::uint64_t> master_seed() const;
  /// The run's config text, as stored ("config"); an error if it is missing
  /// (a database that lacks it is no complete run).
  Result<std::string> config_text() const;
  /// Everything a run stored as it was written: SQLite's integrity check of
  /// the file, every stored number a number, every row against its checksum
  /// (its `digest`, written with it), and no row missing (generations and
  /// individuals up to the checkpoint's, its stages); an error names the
  /// first damage in the user's terms (a generation, an individual, the
  /// checkpoint, the run's config).
  Result<Integrity> check_integrity() const;
  /// Opened read-only (this user may not write the run).
  bool read_only() const { return read_only_; }

 private:
  explicit RunStore(sqlite3* db, std::string path) : db_(db), path_(std::move(path)) {}
  sqlite3* db_;
  std::string path_;
  bool read_only_ = false;
  bool seed_column_ = true;  ///< false: an older database opened read-only, without individual.seed
  bool kind_column_ = true;  ///< false: one without individual.kind (its genotypes are graph genomes)
  bool metric_table_ = true;  ///< false: an older database opened read-only, without generation_metric
  bool evaluations_column_ = true;  ///< false: one without individual.evaluations (each was evaluated once)
  bool stage_table_ = true;  ///< false: an older database opened read-only, without stage
  int format_ = 1;           ///< PRAGMA user_version: 0 before rows carried checksums
  bool digest_columns_ = true;  ///< false: an older database opened read-only, without digest columns
};

}  // namespace bx
