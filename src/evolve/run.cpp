#include "evolve/run.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/files.h"
#include "eval/evaluator.h"
#include "evolve/evolution.h"
#include "io/run_store.h"

namespace bx {

namespace fs = std::filesystem;

std::string run_db_path(const std::string& dir) { return (fs::path(dir) / "run.sqlite").string(); }
std::string run_config_path(const std::string& dir) { return (fs::path(dir) / "config.toml").string(); }
std::string run_log_path(const std::string& dir) { return (fs::path(dir) / "run.log").string(); }

Status create_run(const std::string& dir, const RunConfig& cfg, const std::string& config_text,
                  const std::string& name, std::uint64_t seed) {
  if (fs::exists(dir))
    return Error{dir + ": already exists (resume it with `bestiary resume " + dir +
                 "`, or choose another --out)"};
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return Error{dir + ": cannot create directory (" + ec.message() + ")"};
  // the resolved config: every key, as this run will use it
  std::string resolved = "# Resolved config of this run (from " + name + ")\n" + config_to_toml(cfg);
  if (Status s = write_file_atomic(run_config_path(dir), resolved); !s) return s;
  auto store = RunStore::create(run_db_path(dir), {{"name", name},
                                                   {"seed", std::to_string(seed)},
                                                   {"config", resolved},
                                                   {"source_config", config_text},
                                                   {"bestiary_version", BESTIARY_VERSION},
                                                   {"bestiary_git", BESTIARY_GIT}});
  if (!store) return Error{store.error()};
  return Ok{};
}

Result<RunProgress> run_progress(const std::string& dir) {
  auto store = RunStore::open(run_db_path(dir));
  if (!store) return Error{store.error()};
  auto cfg = read_run_config((*store)->meta("config"), run_config_path(dir));
  if (!cfg) return Error{cfg.error()};
  Evolution evo(cfg->dialect, cfg->evolution, cfg->operators, cfg->sim.develop, 0);
  RunProgress p;
  EvolutionState state;
  if (auto cp = (*store)->checkpoint()) {
    state.generation = cp->generation;
    state.evaluations = cp->evaluations;
  }
  p.generations_done = state.generation + 1;
  p.generations_total = evo.total_generations();
  p.evaluations = state.evaluations;
  p.complete = evo.finished(state);
  return p;
}

Status extend_run(const std::string& dir, const std::vector<std::string>& overrides) {
  auto store = RunStore::open(run_db_path(dir));
  if (!store) return Error{store.error()};
  auto old = read_run_config((*store)->meta("config"), run_config_path(dir));
  if (!old) return Error{old.error()};
  const bool generational = old->evolution.algorithm == Algorithm::Generational;
  const std::string allowed = generational ? "evolution.generations" : "evolution.evaluations";
  for (const auto& o : overrides)
    if (o.rfind(allowed + "=", 0) != 0)
      return Error{"--set " + o + ": resume can only lengthen a run (" + allowed + "=N); the rest of its config stays"};
  auto cfg = read_run_config((*store)->meta("config"), run_config_path(dir), overrides);
  if (!cfg) return Error{cfg.error()};
  auto cp = (*store)->checkpoint();
  const int done = cp ? cp->generation + 1 : 0;
  const long evaluations = cp ? cp->evaluations : 0;
  const EvolutionDef &was = old->evolution, &now = cfg->evolution;
  if (generational && now.generations < done)
    return Error{"--set evolution.generations=" + std::to_string(now.generations) + ": the run has done " +
                 std::to_string(done) + " generations already"};
  if (!generational) {
    if (now.population + now.evaluations < evaluations)
      return Error{"--set evolution.evaluations=" + std::to_string(now.evaluations) + ": the run has done " +
                   std::to_string(evaluations - now.population) + " already"};
    // a longer run's intervals match this one's only if its budget ended on one
    const long every = was.report_every > 0 ? was.report_every : was.population;
    if (now.evaluations > was.evaluations && was.evaluations % every != 0)
      return Error{"--set evolution.evaluations: this run's budget (" + std::to_string(was.evaluations) +
                   ") does not end on a report interval (" + std::to_string(every) +
                   "), so a longer run would not continue it exactly"};
  }
  std::string extended;
  for (const auto& o : overrides) extended += " --set " + o;
  std::string text = (*store)->meta("config");
  std::string head = text.substr(0, text.find('\n'));
  std::string resolved = head + " (lengthened by resume" + extended + ")\n" + config_to_toml(*cfg);
  if (Status s = (*store)->set_meta("config", resolved); !s) return Error{run_db_path(dir) + ": " + s.error()};
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
  auto store_r = RunStore::open(run_db_path(dir));
  if (!store_r) return Error{store_r.error()};
  RunStore& store = **store_r;
  // the run's own config and seed, as stored when it was created
  auto cfg_r = read_run_config(store.meta("config"), run_config_path(dir));
  if (!cfg_r) return Error{cfg_r.error()};
  const RunConfig& cfg = *cfg_r;
  std::uint64_t seed = std::stoull(store.meta("seed"));
  Evolution evo(cfg.dialect, cfg.evolution, cfg.operators, cfg.sim.develop, seed);

  // where it stands: the last checkpoint, or the start
  EvolutionState state;
  if (auto cp = store.checkpoint()) {
    state.generation = cp->generation;
    state.evaluations = cp->evaluations;
    state.next_id = cp->next_id;
    for (std::int64_t id : cp->population) {
      auto ind = store.individual(id);
      if (!ind) return Error{run_db_path(dir) + ": checkpoint names individual " + std::to_string(id) + ", which is missing"};
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
  log << "session: resuming at generation " << state.generation + 1 << " with " << evaluator->workers()
      << " workers" << std::endl;

  for (int done = 0; !evo.finished(state); ++done) {
    if (opt.stop_after > 0 && done >= opt.stop_after) break;
    GenerationResult res = evo.step(state, *evaluator);
    Checkpoint cp{state.generation, state.evaluations, state.next_id, {}};
    for (const auto& ind : state.population) cp.population.push_back(ind.id);
    if (Status s = store.write_generation(res.stats, res.born, cp); !s)
      return Error{run_db_path(dir) + ": " + s.error()};

    // progress: one updating line on a terminal, else a line per generation
    evals_this_session += static_cast<long>(res.born.size());
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double rate = elapsed > 0 ? evals_this_session / elapsed : 0;
    int gens_left = total - 1 - state.generation;
    double per_gen = elapsed / (done + 1);
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
