#include "run/run.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/files.h"
#include "core/version.h"
#include "develop/graph_ops.h"
#include "eval/evaluator.h"
#include "evolve/evolution.h"
#include "io/run_store.h"

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

Status create_run(const std::string& dir, const RunConfig& cfg, const std::string& config_text,
                  const std::string& name, std::uint64_t seed) {
  if (fs::exists(dir))
    return Error{dir + ": already exists (resume it with `bestiary resume " + dir +
                 "`, or choose another --out)"};
  // built under another name and renamed into place, so that `dir` appears
  // complete (config.toml, and the database with the config and seed) or not at
  // all, whenever the process is killed or the disk fills
  const fs::path target = fs::path(dir).lexically_normal();
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
  // the resolved config: every key, as this run will use it
  std::string resolved = "# Resolved config of this run (from " + name + ")\n" + config_to_toml(cfg);
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

namespace {

// a run's database, config and seed, each checked: a database that lacks what a
// run needs is refused with what it lacks, never run with defaults
struct OpenRun {
  std::unique_ptr<RunStore> store;
  RunConfig cfg;
  std::uint64_t seed = 0;
};

Result<OpenRun> open_run(const std::string& dir, const std::vector<std::string>& overrides = {}) {
  auto store = RunStore::open(run_db_path(dir));
  if (!store) return Error{store.error()};
  auto text = (*store)->config_text();
  if (!text) return Error{text.error()};
  auto cfg = read_run_config(*text, run_db_path(dir) + " (the run's config)", overrides);
  if (!cfg) return Error{cfg.error()};
  auto seed = (*store)->master_seed();
  if (!seed) return Error{seed.error()};
  return OpenRun{std::move(*store), std::move(*cfg), *seed};
}

// what the run breeds: the genotypes its creature kind develops, with their operators
std::shared_ptr<const GenotypeOps> genotype_ops(const RunConfig& cfg) {
  const CreatureKindRow& kind = creature_kind_row(cfg.sim.creature);
  if (kind.float_genes) return std::make_shared<FloatVectorOps>(kind.float_genes(cfg.sim));
  return std::make_shared<GraphOps>(cfg.dialect, cfg.operators, cfg.sim.develop);
}

}  // namespace

Result<RunProgress> run_progress(const std::string& dir) {
  auto run = open_run(dir);
  if (!run) return Error{run.error()};
  if (Status s = run->store->check_integrity(); !s) return Error{s.error()};
  RunProgress p;
  EvolutionState state;
  auto cp = run->store->checkpoint();
  if (!cp) return Error{cp.error()};
  if (*cp) {
    state.generation = (*cp)->generation;
    state.evaluations = (*cp)->evaluations;
    state.next_id = (*cp)->next_id;
  }
  p.generations_done = state.generation + 1;
  p.generations_total = total_generations(run->cfg.evolution);
  p.evaluations = state.evaluations;
  p.complete = Evolution::finished(run->cfg.evolution, state);
  return p;
}

Status extend_run(const std::string& dir, const std::vector<std::string>& overrides) {
  auto run = open_run(dir);
  if (!run) return Error{run.error()};
  if (run->store->read_only()) return Error{dir + ": read-only here (permission denied): cannot lengthen the run"};
  RunStore* store = run->store.get();
  const RunConfig* old = &run->cfg;
  const bool generational = old->evolution.algorithm == Algorithm::Generational;
  const std::string allowed = generational ? "evolution.generations" : "evolution.evaluations";
  for (const auto& o : overrides)
    if (o.rfind(allowed + "=", 0) != 0)
      return Error{"--set " + o + ": resume can only lengthen a run (" + allowed + "=N); the rest of its config stays"};
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
  std::string extended;
  for (const auto& o : overrides) extended += " --set " + o;
  std::string text = *store->config_text();
  std::string head = text.substr(0, text.find('\n'));
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

Status drive_run(const std::string& dir, const RunOptions& opt) {
  // the run's own config and seed, as stored when it was created
  auto run = open_run(dir);
  if (!run) return Error{run.error()};
  RunStore& store = *run->store;
  if (store.read_only()) return Error{dir + ": read-only here (permission denied): cannot continue the run"};
  if (Status s = store.check_integrity(); !s) return s;
  const RunConfig& cfg = run->cfg;
  auto ops = genotype_ops(cfg);
  if (Status s = check_breeding(cfg.evolution, *ops); !s) return s;
  Evolution evo(ops, cfg.evolution, run->seed, cfg.sim.trial_score);
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
  EvolutionState state;
  auto cp = store.checkpoint();
  if (!cp) return Error{cp.error()};
  if (*cp) {
    state.generation = (*cp)->generation;
    state.evaluations = (*cp)->evaluations;
    state.next_id = (*cp)->next_id;
    for (std::int64_t id : (*cp)->population) {
      auto ind = store.individual(id);
      if (!ind) return Error{run_db_path(dir) + ": the checkpoint's " + ind.error()};
      state.population.push_back(std::move(*ind));
    }
  }
  if (evo.finished(state)) return Ok{};

  auto evaluator = make_evaluator(cfg.sim, opt.workers, cfg.evolution.evaluation_timeout);
  std::ofstream log(run_log_path(dir), std::ios::app);
  const bool tty = !opt.quiet && ::isatty(STDOUT_FILENO);
  const int total = evo.total_generations();
  auto t0 = std::chrono::steady_clock::now();
  long evals_this_session = 0;
  double first_step = 0;  // seconds
  if (!note.empty()) log << "note: " << note << std::endl;
  log << "session: resuming at generation " << state.generation + 1 << " with " << evaluator->workers()
      << " workers" << std::endl;

  for (int done = 0; !evo.finished(state); ++done) {
    if (opt.stop_after > 0 && done >= opt.stop_after) break;
    const long evaluations_before = state.evaluations;
    GenerationResult res = evo.step(state, *evaluator);
    Checkpoint cp{state.generation, state.evaluations, state.next_id, {}};
    for (const auto& ind : state.population) cp.population.push_back(ind.id);
    if (Status s = store.write_generation(res.stats, res.born, res.reevaluated, cp); !s)
      return Error{run_db_path(dir) + ": " + s.error()};

    // progress: one updating line on a terminal, else a line per generation
    evals_this_session += state.evaluations - evaluations_before;  // elites evaluated again too
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double rate = elapsed > 0 ? evals_this_session / elapsed : 0;
    int gens_left = total - 1 - state.generation;
    // time per report interval from the intervals after this session's
    // first, which may be a cheaper one (the steady state's first is its
    // initial population: 150 river evaluations against 600 after it)
    if (done == 0) first_step = elapsed;
    double per_gen = done == 0 ? elapsed : (elapsed - first_step) / done;
    char line[256];
    const auto& st = res.stats;
    std::snprintf(line, sizeof line,
                  "gen %d/%d  evals %ld  best %.5g  mean %.5g  median %.5g  rejected %ld  failed %ld  %.1f evals/s  left %s",
                  st.generation, total - 1, st.evaluations, st.best, st.mean, st.median, st.rejected,
                  st.failed, rate, duration(gens_left * per_gen).c_str());
    log << line << std::endl;
    if (tty) {
      std::printf("\r\033[K%s", line);
      std::fflush(stdout);
    } else if (!opt.quiet) {
      std::printf("%s\n", line);
      std::fflush(stdout);
    }
  }
  if (tty) std::printf("\n");
  return Ok{};
}

}  // namespace bx
