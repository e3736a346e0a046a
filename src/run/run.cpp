#include "run/run.h"

#include <fcntl.h>
#include <sys/file.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>

#include "core/files.h"
#include "core/hash.h"
#include "core/text.h"
#include "core/version.h"
#include "develop/graph_ops.h"
#include "eval/evaluator.h"
#include "evolve/evolution.h"
#include "genome/genotype_file.h"
#include "genome/shipped_creatures.h"
#include "io/run_store.h"
#include "io/syllabus.h"

namespace bx {

namespace fs = std::filesystem;

std::string run_db_path(const std::string& dir) { return (fs::path(dir) / "run.sqlite").string(); }
std::string run_config_path(const std::string& dir) { return (fs::path(dir) / "config.toml").string(); }
std::string run_log_path(const std::string& dir) { return (fs::path(dir) / "run.log").string(); }

namespace {

// the name a run directory has while it is being created, beside where it will be
// (built by appending: GCC 12 warns falsely, -Wrestrict, on "." + string)
std::string creating_prefix(const fs::path& dir) {
  std::string p = ".";
  p += dir.filename().string();
  p += ".creating-";
  return p;
}

// where a run folder named `dir` is: its path in normal form, without a
// trailing separator ("runs/x/" is "runs/x", not a folder inside it)
fs::path run_folder(const std::string& dir) {
  fs::path p = fs::path(dir).lexically_normal();
  if (p.filename().empty() && p.has_parent_path()) p = p.parent_path();
  return p;
}

fs::path creating_path(const fs::path& dir, long pid) {
  return dir.parent_path() / (creating_prefix(dir) + std::to_string(pid));
}

// removes what earlier creations of `dir`, killed before they finished, left
void remove_stale_creations(const fs::path& dir) {
  std::error_code ec;
  const std::string prefix = creating_prefix(dir);
  fs::path parent = dir.parent_path().empty() ? fs::path(".") : dir.parent_path();
  for (const auto& e : fs::directory_iterator(parent, ec)) {
    std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
    if (pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM)) continue;  // still at work
    fs::remove_all(e.path(), ec);
  }
}

void sync_dir(const fs::path& dir) {
  int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

Status create_run(const std::string& dir, const Syllabus& stages, const std::string& config_text,
                  const std::string& name, std::uint64_t seed) {
  if (fs::exists(dir))
    return Error{dir + ": already exists (resume it with `bestiary resume " + dir +
                 "`, or choose another --out)"};
  // built under another name and renamed into place, so that `dir` appears
  // complete (config.toml, and the database with the config and seed) or not at
  // all, whenever the process is killed or the disk fills
  const fs::path target = run_folder(dir);
  std::error_code ec;
  if (!target.parent_path().empty()) fs::create_directories(target.parent_path(), ec);
  if (ec) return Error{target.parent_path().string() + ": cannot create directory (" + ec.message() + ")"};
  remove_stale_creations(target);
  const fs::path tmp = creating_path(target, static_cast<long>(::getpid()));
  fs::create_directory(tmp, ec);
  if (ec) return Error{dir + ": cannot create directory (" + ec.message() + ")"};
  auto fail = [&](const std::string& why) {
    std::error_code ignored;
    fs::remove_all(tmp, ignored);
    return Status(Error{why});
  };
  // the resolved config: every key, as this run will use it (its source's
  // name as TOML's UTF-8 text on one line, whatever bytes the path holds)
  std::string resolved =
      "# Resolved config of this run (from " + one_line(utf8_text(name)) + ")\n" + syllabus_to_toml(stages);
  if (Status s = write_file_atomic(run_config_path(tmp.string()), resolved); !s)
    return fail(dir + ": " + s.error());
  {
    auto store = RunStore::create(run_db_path(tmp.string()), {{"name", name},
                                                              {"seed", std::to_string(seed)},
                                                              {"config", resolved},
                                                              {"source_config", config_text},
                                                              {"bestiary_version", bestiary_version()},
                                                              {"bestiary_git", bestiary_git()}});
    if (!store) return fail(dir + ": " + store.error());
  }  // closed: its journal is folded into the file before the rename
  sync_dir(tmp);
  if (::rename(tmp.c_str(), target.c_str()) != 0) {
    int err = errno;
    return fail(dir + ": cannot create directory (" + std::strerror(err) + ")");
  }
  sync_dir(target.parent_path());
  return Ok{};
}

void discard_unstarted_run(const std::string& dir) {
  const fs::path target = run_folder(dir);  // where create_run put it
  {
    auto store = RunStore::open(run_db_path(target.string()));
    if (!store) return;
    auto cp = (*store)->checkpoint();
    if (!cp || *cp) return;  // a generation stored (or no telling): the run is kept
  }  // closed before its folder goes
  // out of place first, as create_run put it in place: `dir` is gone at
  // once, and what a kill leaves is a stale creation the next run removes
  const fs::path gone = creating_path(target, static_cast<long>(::getpid()));
  std::error_code ec;
  fs::rename(target, gone, ec);
  if (!ec) fs::remove_all(gone, ec);
}

namespace {

// a run's database, config and seed, each checked: a database that lacks what a
// run needs is refused with what it lacks, never run with defaults
struct OpenRun {
  std::unique_ptr<RunStore> store;
  Syllabus syllabus;  ///< its stages (a plain config's run: one)
  std::uint64_t seed = 0;
};

// One process drives or lengthens a run at a time: it holds an flock on the
// run's database file while it does (SQLite's own locks are fcntl locks, which
// this does not touch; workers close every descriptor but their pipes, and
// the lock goes with the process however it ends).
class RunLock {
 public:
  static Result<std::unique_ptr<RunLock>> take(const std::string& dir) {
    const int fd = ::open(run_db_path(dir).c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return Error{run_db_path(dir) + ": " + std::strerror(errno)};
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      ::close(fd);
      if (err == EWOULDBLOCK)
        return Error{dir + ": the run is going on in another process (which holds its lock): wait for it to end, "
                           "or stop it first (Ctrl-C there); nothing was changed"};
      return Error{run_db_path(dir) + ": cannot lock the run (" + std::strerror(err) + ")"};
    }
    return std::unique_ptr<RunLock>(new RunLock(fd));
  }
  ~RunLock() { ::close(fd_); }
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;

 private:
  explicit RunLock(int fd) : fd_(fd) {}
  int fd_;
};

Result<OpenRun> open_run(const std::string& dir, const std::vector<std::string>& overrides = {}) {
  auto store = RunStore::open(run_db_path(dir));
  if (!store) return Error{store.error()};
  auto text = (*store)->config_text();
  if (!text) return Error{text.error()};
  auto syl = read_syllabus(*text, run_db_path(dir) + " (the run's config)", overrides);
  if (!syl) return Error{syl.error()};
  auto seed = (*store)->master_seed();
  if (!seed) return Error{seed.error()};
  return OpenRun{std::move(*store), std::move(*syl), *seed};
}

// the seed of stage k's evolution: the run's own for the first, so a run of
// one stage is as it was before runs had stages
std::uint64_t stage_seed(std::uint64_t seed, int k) {
  constexpr std::uint64_t kStage = 0x5747;  // a stream purpose of its own
  return k == 0 ? seed : stream_seed({seed, kStage, static_cast<std::uint64_t>(k)});
}

// where a run stands: its stage and that stage's evolution state, read from
// the checkpoint (generations numbered within the stage), or the start
struct Standing {
  StageRow stage;
  EvolutionState state;
};

Result<Standing> standing(const std::string& dir, RunStore& store, bool load_population) {
  Standing s;
  auto cp = store.checkpoint();
  if (!cp) return Error{cp.error()};
  if (!*cp) return s;
  const Checkpoint& c = **cp;
  s.stage = c.stage;
  s.state.generation = c.generation - c.stage.first_gen;
  s.state.evaluations = c.evaluations;
  s.state.next_id = c.next_id;
  s.state.first_id = c.stage.first_id;
  if (!load_population) return s;
  for (std::int64_t id : c.population) {
    auto ind = store.individual(id);
    if (!ind) return Error{run_db_path(dir) + ": the checkpoint's " + ind.error()};
    s.state.population.push_back(std::move(*ind));
  }
  return s;
}

// what the run breeds: the genotypes its creature kind develops, with their operators
std::shared_ptr<const GenotypeOps> genotype_ops(const RunConfig& cfg) {
  const CreatureKindRow& kind = creature_kind_row(cfg.sim.creature);
  if (kind.float_genes) return std::make_shared<FloatVectorOps>(kind.float_genes(cfg.sim));
  return std::make_shared<GraphOps>(cfg.dialect, cfg.operators, cfg.sim.develop);
}

// the founder of a stage that starts from a file (the first stage's start =
// "file"): its creature as the file gives it, refused if the file changed
// since the run began; its body locked if the stage locks bodies
Result<Individual> file_founder(const StageDef& st) {
  const std::string where = "stage \"" + st.name + "\": file: ";
  auto text = read_creature_text(st.file);
  if (!text) return Error{where + text.error()};
  if (const std::string h = fnv1a64_hex(text->text); h != st.file_hash)
    return Error{where + text->source + " has changed since the run began (its text's hash is " + h + ", the run's " +
                 st.file_hash + "): put back the file it started from, or begin a new run"};
  auto g = genotype_from_file_text(text->text, text->source);
  if (!g) return Error{where + g.error()};
  auto ops = genotype_ops(st.cfg);
  auto fits = ops->from_json((*g)->to_json());
  if (!fits) return Error{where + text->source + ": " + fits.error()};
  Individual f;
  f.genotype = std::move(*fits);
  if (st.lock_body) f.genotype = ops->with_body_locked(*f.genotype);
  return f;
}

}  // namespace

std::uint64_t retest_seed(std::uint64_t run_seed, int stage, int retest) {
  constexpr std::uint64_t kRetest = 0x5245;  // a stream purpose of its own
  return stream_seed({run_seed, kRetest, static_cast<std::uint64_t>(stage), static_cast<std::uint64_t>(retest)});
}

std::uint64_t held_out_seed(std::uint64_t run_seed, int k) {
  constexpr std::uint64_t kHeldOut = 0x484f;  // a stream purpose of its own
  return stream_seed({run_seed, kHeldOut, static_cast<std::uint64_t>(k)});
}

namespace {

// stage k's General ESP retests (StageDef::retest_tolerance): each leaf
// skill before it must keep (1 - tolerance) x what the creature that ended
// the skill's last stage (its own, or its last reconciliation) scores on
// that stage's task in the retest's world; every child is retested in that
// world, so one whose body and skill did not change keeps exactly its
// parent's score (a retest in a world of its own would fail a third of
// unchanged lessin_crawlers, whose gait varies so between seeds)
Result<std::vector<Retest>> stage_retests(const Syllabus& syl, const StageRow& stage, const RunStore& store,
                                          Evaluator& eval, std::uint64_t run_seed) {
  const int k = stage.index;
  std::vector<Retest> out;
  const std::vector<RetestRow> rows = retest_rows(syl, k);
  if (rows.empty()) return out;
  const std::vector<StageRow> begun = store.stages();
  const std::vector<GenerationStats> gens = store.generations();
  for (const RetestRow& r : rows) {
    const StageDef& leaf = syl.stages[r.stage];
    const int last = syl.learned_in(r.stage, k);  // its stage, or its last reconciliation
    // the generation before the next stage's first (this stage's row is
    // written with its first generation: it may not be stored yet)
    std::optional<int> next_first;
    if (last + 1 == k) next_first = stage.first_gen;
    else if (last + 1 < static_cast<int>(begun.size())) next_first = begun[last + 1].first_gen;
    std::optional<std::int64_t> best;
    if (next_first)
      for (const GenerationStats& g : gens)
        if (g.generation == *next_first - 1) best = g.best_id;
    const std::string where = "stage \"" + syl.stages[k].name + "\": retest of \"" + leaf.name + "\": ";
    if (!best) return Error{where + "the run has no record of the creature stage \"" + syl.stages[last].name + "\" ended with"};
    auto ind = store.individual(*best);
    if (!ind) return Error{where + ind.error()};
    const std::uint64_t seed = retest_seed(run_seed, k, static_cast<int>(out.size()));
    const std::vector<EvalOutcome> ref = eval.evaluate({{ind->genotype.get(), seed, 1, last}});
    if (!ref[0].viable || ref[0].result.failed)
      return Error{where + "individual " + std::to_string(*best) + " (stage \"" + syl.stages[last].name +
                   "\"'s last best) fails its own task in the retest's world: " +
                   (ref[0].viable ? ref[0].result.failure : ref[0].reason)};
    out.push_back({leaf.name, r.task, seed, (1 - *syl.stages[k].retest_tolerance) * ref[0].result.fitness});
  }
  return out;
}

}  // namespace

Status check_run(const Syllabus& syl) {
  for (const StageDef& st : syl.stages) {
    const std::string where = syl.staged() ? "stage \"" + st.name + "\": " : "";
    auto ops = genotype_ops(st.cfg);
    if (Status s = check_breeding(st.cfg.evolution, *ops); !s) return Error{where + s.error()};
    if (st.lock_body && !ops->can_lock_body())
      return Error{where + "body: \"locked\": genotypes of kind " + std::string(ops->kind()) + " have no body to lock"};
    if (st.start == StageStart::File)
      if (auto f = file_founder(st); !f) return Error{f.error()};
    if (st.retest_tolerance && st.cfg.evolution.algorithm == Algorithm::SteadyState &&
        st.cfg.evolution.tournament_evaluates == TournamentEvaluates::All)
      return Error{where + "retest_tolerance: a stage whose tournaments evaluate all three afresh "
                   "(evolution.tournament_evaluates = \"all\") cannot retest its children (each is retested once, at birth)"};
    if (st.encapsulate && !ops->can_encapsulate())
      return Error{where + "encapsulate: true: genotypes of kind " + std::string(ops->kind()) + " (dialect " +
                   std::string(to_string(st.cfg.dialect)) + ") have no skill switches (lessin2015's have)"};
  }
  return Ok{};
}

namespace {

// Whether a finished run still owes its best's held-out measure: its last
// stage asks for one (evolution.held_out_evaluations) and none is stored
// for its best as it now stands (a lengthened run may have another), or
// one of another count.
Result<bool> held_out_due(const RunStore& store, const EvolutionDef& last) {
  if (last.held_out_evaluations <= 0) return false;
  auto h = store.held_out();
  if (!h) return Error{h.error()};
  auto best = store.best_individual();
  if (!best) return Error{best.error()};
  return !*h || (*h)->id != best->id || static_cast<int>((*h)->by_seed.size()) != last.held_out_evaluations;
}

// The run's best evaluated under evolution.held_out_evaluations held-out
// seeds on the last stage's task (row `task` of the evaluator's table), in
// one batch, and stored; a line of what came of it to the log (and to the
// user unless quiet).
Status measure_held_out(const std::string& dir, RunStore& store, const StageDef& last, int task,
                        std::uint64_t run_seed, Evaluator& evaluator, std::ostream& log, bool quiet) {
  auto best = store.best_individual();
  if (!best) return Error{run_db_path(dir) + ": " + best.error()};
  const int n = last.cfg.evolution.held_out_evaluations;
  if (!quiet) {
    std::printf("held out: evaluating the best (individual %lld) under %d seeds no evaluation of the run used ...\n",
                static_cast<long long>(best->id), n);
    std::fflush(stdout);
  }
  std::vector<EvalJob> jobs;
  for (int k = 0; k < n; ++k) jobs.push_back({best->genotype.get(), held_out_seed(run_seed, k), 1, task});
  const std::vector<EvalOutcome> out = evaluator.evaluate(jobs);
  HeldOut h;
  h.id = best->id;
  int failed = 0;
  for (const EvalOutcome& o : out) {
    const bool lost = !o.viable || o.result.failed;
    failed += lost;
    h.by_seed.push_back(lost ? last.cfg.evolution.failed_fitness : o.result.fitness);
  }
  h.fitness = fold_scores(last.cfg.sim.trial_score, h.by_seed);
  if (Status s = store.set_held_out(h); !s) return Error{run_db_path(dir) + ": " + s.error()};
  char line[320];
  std::snprintf(line, sizeof line,
                "held out: individual %lld, the %s of %d evaluations under seeds the run never used: %.6g "
                "(its stored fitness, what selection saw: %.6g)%s",
                static_cast<long long>(h.id), score_name(last.cfg.sim.trial_score), n, h.fitness, best->fitness,
                failed ? (", " + std::to_string(failed) + " failed").c_str() : "");
  log << line << std::endl;
  if (!quiet) std::printf("%s\n", line);
  return Ok{};
}

}  // namespace

Result<RunProgress> run_progress(const std::string& dir) {
  auto run = open_run(dir);
  if (!run) return Error{run.error()};
  if (auto s = run->store->check_integrity(); !s) return Error{s.error()};
  auto at = standing(dir, *run->store, false);
  if (!at) return Error{at.error()};
  const auto& stages = run->syllabus.stages;
  RunProgress p;
  p.generations_done = at->stage.first_gen + at->state.generation + 1;
  for (const StageDef& st : stages) p.generations_total += total_generations(st.cfg.evolution);
  p.evaluations = at->state.evaluations;
  p.complete = at->stage.index + 1 == static_cast<int>(stages.size()) &&
               Evolution::finished(stages.back().cfg.evolution, at->state);
  if (p.complete) {
    auto due = held_out_due(*run->store, stages.back().cfg.evolution);
    if (!due) return Error{due.error()};
    p.complete = !*due;
  }
  return p;
}

Result<Integrity> verify_run(const std::string& dir) {
  auto run = open_run(dir);  // its config and seed read
  if (!run) return Error{run.error()};
  auto sound = run->store->check_integrity();
  if (!sound) return Error{sound.error()};
  // and every genome read as its kind (a run begun before checksums has
  // only this for its older rows)
  for (std::int64_t id = 0; id < sound->individuals; ++id)
    if (auto ind = run->store->individual(id); !ind) return Error{run_db_path(dir) + ": " + ind.error()};
  return sound;
}

Status extend_run(const std::string& dir, const std::vector<std::string>& overrides) {
  auto run = open_run(dir);
  if (!run) return Error{run.error()};
  // nothing is written to a damaged run
  if (auto sound = run->store->check_integrity(); !sound) return Error{sound.error()};
  if (run->store->read_only()) return Error{dir + ": read-only here (permission denied): cannot lengthen the run"};
  auto lock = RunLock::take(dir);
  if (!lock) return Error{lock.error()};
  RunStore* store = run->store.get();
  std::string extended;
  for (const auto& o : overrides) extended += " --set " + o;
  const std::string text = *store->config_text();
  const std::string head = text.substr(0, text.find('\n'));
  // a held-out measure of its best, asked for after the run (evolution.held_out_evaluations):
  // changes no evaluation, so any run may take it, one of stages too
  const std::string held_out_key = "evolution.held_out_evaluations=";
  if (!overrides.empty() &&
      std::all_of(overrides.begin(), overrides.end(), [&](const std::string& o) { return o.rfind(held_out_key, 0) == 0; })) {
    auto syl = read_syllabus(text, run_db_path(dir) + " (the run's config)", overrides);
    if (!syl) return Error{syl.error()};
    const std::string resolved = head + " (held out by resume" + extended + ")\n" +
                                 (syl->staged() ? syllabus_to_toml(*syl) : config_to_toml(syl->stages.front().cfg));
    if (Status s = store->set_meta("config", resolved); !s) return Error{run_db_path(dir) + ": " + s.error()};
    return write_file_atomic(run_config_path(dir), resolved);
  }
  if (run->syllabus.staged())
    return Error{dir + ": a run of several stages cannot be lengthened (yet): its stages' budgets are its syllabus'"};
  const RunConfig* old = &run->syllabus.stages.front().cfg;
  const bool generational = old->evolution.algorithm == Algorithm::Generational;
  const std::string allowed = generational ? "evolution.generations" : "evolution.evaluations";
  for (const auto& o : overrides)
    if (o.rfind(allowed + "=", 0) != 0 && o.rfind(held_out_key, 0) != 0)
      return Error{"--set " + o + ": resume can only lengthen a run (" + allowed + "=N) or measure its best held " +
                   "out (" + held_out_key + "N); the rest of its config stays"};
  auto cfg = read_run_config(*store->config_text(), run_db_path(dir) + " (the run's config)", overrides);
  if (!cfg) return Error{cfg.error()};
  auto cp_r = store->checkpoint();
  if (!cp_r) return Error{cp_r.error()};
  const auto& cp = *cp_r;
  const int done = cp ? cp->generation + 1 : 0;
  const long born = cp ? static_cast<long>(cp->next_id) : 0;  // creatures born: the budget's count
  const EvolutionDef &was = old->evolution, &now = cfg->evolution;
  if (generational && now.generations < done)
    return Error{"--set evolution.generations=" + std::to_string(now.generations) + ": the run has done " +
                 std::to_string(done) + " generations already"};
  if (!generational) {
    if (now.population + now.evaluations < born)
      return Error{"--set evolution.evaluations=" + std::to_string(now.evaluations) + ": the run has done " +
                   std::to_string(born - now.population) + " already"};
    // a longer run's intervals match this one's only if its budget ended on one
    const long every = was.report_every > 0 ? was.report_every : was.population;
    if (now.evaluations > was.evaluations && was.evaluations % every != 0)
      return Error{"--set evolution.evaluations: this run's budget (" + std::to_string(was.evaluations) +
                   ") does not end on a report interval (" + std::to_string(every) +
                   "), so a longer run would not continue it exactly"};
  }
  std::string resolved = head + " (lengthened by resume" + extended + ")\n" + config_to_toml(*cfg);
  if (Status s = store->set_meta("config", resolved); !s) return Error{run_db_path(dir) + ": " + s.error()};
  return write_file_atomic(run_config_path(dir), resolved);
}

namespace {

std::string duration(double s) {
  char buf[32];
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 60) std::snprintf(buf, sizeof buf, "%.0fs", s);
  else if (s < 3600) std::snprintf(buf, sizeof buf, "%dm%02ds", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  else std::snprintf(buf, sizeof buf, "%dh%02dm", static_cast<int>(s) / 3600, static_cast<int>(s) % 3600 / 60);
  return buf;
}

}  // namespace

Result<std::vector<std::uint64_t>> parse_seed_list(const std::string& text) {
  const std::string what = "--seeds \"" + text + "\": expected seeds as A-B, A,B,C or one seed (whole numbers)";
  auto number = [](std::string_view t) -> std::optional<std::uint64_t> {
    std::uint64_t v = 0;
    auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size()) return std::nullopt;
    return v;
  };
  std::vector<std::uint64_t> seeds;
  const std::size_t dash = text.find('-');
  if (dash != std::string::npos) {
    auto a = number(std::string_view(text).substr(0, dash)), b = number(std::string_view(text).substr(dash + 1));
    if (!a || !b || *b < *a) return Error{what};
    if (*b - *a >= 10000) return Error{"--seeds \"" + text + "\": more than 10,000 seeds"};
    for (std::uint64_t s = *a;; ++s) {
      seeds.push_back(s);
      if (s == *b) break;
    }
    return seeds;
  }
  for (std::size_t at = 0;;) {
    const std::size_t comma = text.find(',', at);
    auto v = number(std::string_view(text).substr(at, comma == std::string::npos ? std::string::npos : comma - at));
    if (!v) return Error{what};
    if (std::find(seeds.begin(), seeds.end(), *v) != seeds.end())
      return Error{"--seeds \"" + text + "\": seed " + std::to_string(*v) + " twice"};
    seeds.push_back(*v);
    if (seeds.size() > 10000) return Error{"--seeds \"" + text + "\": more than 10,000 seeds"};
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return seeds;
}

Status drive_run(const std::string& dir, const RunOptions& opt) {
  // the run's own config and seed, as stored when it was created
  auto run = open_run(dir);
  if (!run) return Error{run.error()};
  RunStore& store = *run->store;
  if (store.read_only()) return Error{dir + ": read-only here (permission denied): cannot continue the run"};
  auto lock = RunLock::take(dir);
  if (!lock) return Error{lock.error()};
  if (auto s = store.check_integrity(); !s) return Error{s.error()};
  const std::vector<StageDef>& stages = run->syllabus.stages;
  const int n_stages = static_cast<int>(stages.size());
  if (Status s = check_run(run->syllabus); !s) return s;
  // config.toml is the run's config for people to read: the stored one rules
  std::string note;
  const std::string stored = *store.config_text();
  if (!fs::exists(run_config_path(dir))) {
    if (Status s = write_file_atomic(run_config_path(dir), stored); !s) return s;
    note = run_config_path(dir) + " was missing: written again from the run's database";
  } else if (auto text = read_file(run_config_path(dir)); !text || *text != stored) {
    note = run_config_path(dir) + " differs from the config stored in the run's database, which the run uses "
           "(edits to it change nothing; lengthen a run with `resume DIR --set evolution.generations=N`)";
  }
  if (!note.empty()) std::fprintf(stderr, "note: %s\n", note.c_str());

  // where it stands: the last checkpoint, or the start
  auto at = standing(dir, store, true);
  if (!at) return Error{at.error()};
  StageRow stage = at->stage;
  EvolutionState state = std::move(at->state);
  if (stage.index >= n_stages)
    return Error{run_db_path(dir) + ": the checkpoint is in stage " + std::to_string(stage.index + 1) +
                 ", but the run's config has " + std::to_string(n_stages)};
  stage.name = stages[stage.index].name;
  if (stage.index == 0 && state.generation < 0 && state.population.empty() && stages[0].start == StageStart::File) {
    auto f = file_founder(stages[0]);
    if (!f) return Error{f.error()};
    state.population.push_back(std::move(*f));  // the founder, until the first generation replaces it
  }
  auto finished_stage = [&] { return Evolution::finished(stages[stage.index].cfg.evolution, state); };
  auto finished_run = [&] { return stage.index + 1 == n_stages && finished_stage(); };
  if (finished_run()) {
    auto due = held_out_due(store, stages.back().cfg.evolution);
    if (!due) return Error{due.error()};
    if (!*due) return Ok{};
  }

  // one evaluator for every stage: its task table holds each stage's config
  // and each General ESP retest's (task_table)
  double timeout = 0;
  for (const StageDef& st : stages) timeout = std::max(timeout, st.cfg.evolution.evaluation_timeout);
  std::unique_ptr<Evaluator> evaluator;
  if (opt.evaluator) {
    auto e = opt.evaluator(task_table(run->syllabus), timeout);
    if (!e) return Error{e.error()};
    evaluator = std::move(*e);
  } else {
    evaluator = make_evaluator(task_table(run->syllabus), opt.workers, timeout);
  }
  std::ofstream log(run_log_path(dir), std::ios::app);
  const bool tty = !opt.quiet && ::isatty(STDOUT_FILENO);
  auto t0 = std::chrono::steady_clock::now();
  long evals_this_session = 0;
  if (!note.empty()) log << "note: " << note << std::endl;
  log << "session: resuming at generation " << stage.first_gen + state.generation + 1;
  if (run->syllabus.staged()) log << " (stage " << stage.index + 1 << " of " << n_stages << ", " << stages[stage.index].name << ")";
  log << " with " << evaluator->workers() << " workers" << std::endl;

  for (int done = 0;;) {
    if (finished_stage()) {
      if (stage.index + 1 == n_stages) break;
      // the next stage starts from this one's final population, best first
      std::vector<Individual> last = std::move(state.population);
      std::stable_sort(last.begin(), last.end(), ranks_before);
      const StageDef& next = stages[stage.index + 1];
      if (next.start == StageStart::Best) last.resize(1);
      if (next.start == StageStart::Random) last.clear();
      auto ops = genotype_ops(next.cfg);
      if (ops->can_encapsulate()) {
        // the skill just learned encapsulated (lessin2015 IV-B), and the
        // switches of the skills the next stage uses opened to it
        const StageDef& done_stage = stages[stage.index];
        const SkillDef skill{done_stage.encapsulate ? done_stage.name : "", run->syllabus.group_id(done_stage.group)};
        for (Individual& f : last) {
          auto e = ops->with_skill_encapsulated(*f.genotype, skill, next.uses);
          if (!e) return Error{"stage \"" + done_stage.name + "\": individual " + std::to_string(f.id) + ": " + e.error()};
          f.genotype = std::move(*e);
        }
      }
      if (next.lock_body)
        for (Individual& f : last) f.genotype = ops->with_body_locked(*f.genotype);
      stage = {stage.index + 1, next.name, stage.first_gen + state.generation + 1, state.next_id};
      EvolutionState fresh;
      fresh.evaluations = state.evaluations;
      fresh.next_id = fresh.first_id = state.next_id;
      state = std::move(fresh);
      state.population = std::move(last);  // the founders, until the stage's first generation replaces them
    }
    if (opt.stop_after > 0 && done >= opt.stop_after) break;
    const StageDef& st = stages[stage.index];
    const std::vector<Individual> founders = state.generation < 0 ? state.population : std::vector<Individual>{};
    auto retests = stage_retests(run->syllabus, stage, store, *evaluator, run->seed);
    if (!retests) return Error{retests.error()};
    Evolution evo(genotype_ops(st.cfg), st.cfg.evolution, stage_seed(run->seed, stage.index), st.cfg.sim.trial_score,
                  stage.index, founders, std::move(*retests));
    const int total = evo.total_generations();
    if (!opt.quiet) {
      // while few children are viable, a generation may take long before it is evaluated
      auto last = std::chrono::steady_clock::now();
      evo.on_redraws([&, last](long rejected) mutable {
        const auto now = std::chrono::steady_clock::now();
        if (now - last < std::chrono::seconds(2)) return;
        last = now;
        std::printf("%sgen %d/%d: %ld non-viable children redrawn so far (the limits of [develop]; at most "
                    "evolution.max_random_redraws random ones in a row)%s",
                    tty ? "\r\033[K" : "", state.generation + 1, total - 1, rejected, tty ? "" : "\n");
        std::fflush(stdout);
      });
    }
    double first_step = 0;  // seconds
    int done_in_stage = 0;
    for (; !evo.finished(state); ++done, ++done_in_stage) {
      if (opt.stop_after > 0 && done >= opt.stop_after) break;
      const long evaluations_before = state.evaluations;
      auto step = evo.step(state, *evaluator);
      if (!step) {
        // no creature to breed (none viable): nothing of the step is stored,
        // the run stands at its last checkpoint
        const std::string why = (run->syllabus.staged() ? "stage \"" + st.name + "\": " : "") + step.error();
        log << "stopped: " << why << std::endl;
        if (tty && done > 0) std::printf("\n");  // after the progress line
        return Error{why};
      }
      GenerationResult& res = *step;
      // the database numbers generations through the stages
      res.stats.generation += stage.first_gen;
      for (Individual& ind : res.born) ind.generation += stage.first_gen;
      Checkpoint cp{stage.first_gen + state.generation, state.evaluations, state.next_id, {}, stage};
      for (const auto& ind : state.population) cp.population.push_back(ind.id);
      if (Status s = store.write_generation(res.stats, res.born, res.reevaluated, cp); !s)
        return Error{run_db_path(dir) + ": " + s.error()};

      // progress: one updating line on a terminal, else a line per generation
      evals_this_session += state.evaluations - evaluations_before;  // elites evaluated again too
      double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      double rate = elapsed > 0 ? evals_this_session / elapsed : 0;
      int gens_left = total - 1 - state.generation;
      for (int k = stage.index + 1; k < n_stages; ++k) gens_left += total_generations(stages[k].cfg.evolution);
      // time per report interval from the intervals after this session's
      // first, which may be a cheaper one (the steady state's first is its
      // initial population: 150 river evaluations against 600 after it)
      if (done_in_stage == 0) first_step = elapsed;
      double per_gen = done_in_stage == 0 ? elapsed : (elapsed - first_step) / done_in_stage;
      char line[320];
      const auto& gs = res.stats;
      std::string where = run->syllabus.staged()
                              ? "stage " + std::to_string(stage.index + 1) + "/" + std::to_string(n_stages) + " " +
                                    st.name + "  "
                              : "";
      std::snprintf(line, sizeof line,
                    "%sgen %d/%d  evals %ld  best %.5g  mean %.5g  median %.5g  rejected %ld  failed %ld  %.1f evals/s  left %s",
                    where.c_str(), state.generation, total - 1, gs.evaluations, gs.best, gs.mean, gs.median,
                    gs.rejected, gs.failed, rate, duration(gens_left * per_gen).c_str());
      log << line << std::endl;
      if (tty) {
        std::printf("\r\033[K%s", line);
        std::fflush(stdout);
      } else if (!opt.quiet) {
        std::printf("%s\n", line);
        std::fflush(stdout);
      }
    }
    if (opt.stop_after > 0 && done >= opt.stop_after) break;
  }
  if (tty) std::printf("\n");
  if (finished_run()) {
    auto due = held_out_due(store, stages.back().cfg.evolution);
    if (!due) return Error{due.error()};
    if (*due) return measure_held_out(dir, store, stages.back(), n_stages - 1, run->seed, *evaluator, log, opt.quiet);
  }
  return Ok{};
}

}  // namespace bx
