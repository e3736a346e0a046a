// `bestiary run`, `resume`, `best` and `presets`.
#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <optional>
#include <thread>
#include <unistd.h>

#include "cli/commands.h"
#include "core/files.h"
#include "evolve/run.h"
#include "genome/genome_json.h"
#include "io/presets.h"
#include "io/run_store.h"

namespace bx {

namespace {

namespace fs = std::filesystem;

// SIGINT/SIGTERM: the database is always at a generation boundary, so stop now
char g_run_dir[4096];
void on_interrupt(int) {
  const char head[] = "\ninterrupted; continue with: bestiary resume ";
  (void)!::write(STDERR_FILENO, head, sizeof head - 1);
  (void)!::write(STDERR_FILENO, g_run_dir, std::strlen(g_run_dir));
  (void)!::write(STDERR_FILENO, "\n", 1);
  ::_exit(130);
}

void catch_interrupts(const std::string& dir) {
  std::snprintf(g_run_dir, sizeof g_run_dir, "%s", dir.c_str());
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

int default_workers() { return std::max(1u, std::thread::hardware_concurrency()); }

// the text of a config file, or of a preset by that name
Result<std::pair<std::string, std::string>> config_source(const std::string& arg) {
  if (fs::exists(arg)) {
    auto text = read_file(arg);
    if (!text) return Error{text.error()};
    return std::pair{fs::path(arg).stem().string(), *text};
  }
  if (const Preset* p = find_preset(arg)) return std::pair{p->name, p->text};
  return Error{arg + ": no such config file, and no preset of that name (`bestiary presets` lists them)"};
}

std::string timestamp() {
  std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%d-%H%M%S", std::localtime(&t));
  return buf;
}

int finish(const std::string& dir, const Status& s) {
  if (!s) return fail(s.error());
  std::printf("run in %s (config.toml, run.sqlite, run.log)\n", dir.c_str());
  if (auto store = RunStore::open(run_db_path(dir)); store) {
    auto gens = (*store)->generations();
    if (!gens.empty())
      std::printf("best fitness %.6g (generation 0: %.6g)\n", gens.back().best, gens.front().best);
  }
  std::printf("its genome: bestiary best %s --out best.json\n", dir.c_str());
  std::printf("watch the run: bestiary show %s  (writes %s/view.html)\n", dir.c_str(), dir.c_str());
  return 0;
}

struct RunArgs {
  std::string config, out;
  std::uint64_t seed = 1;
  int workers = default_workers();
  std::vector<std::string> set;
  bool quiet = false;
  int stop_after = 0;
};

int cmd_run(const RunArgs& a) {
  auto src = config_source(a.config);
  if (!src) return fail(src.error());
  auto cfg = read_run_config(src->second, a.config, a.set);
  if (!cfg) return fail(cfg.error());
  if (a.workers < 0) return fail("--workers: expected 0 or more, got " + std::to_string(a.workers));
  std::string dir = a.out;
  if (dir.empty()) {
    dir = "runs/" + src->first + "-" + timestamp();
    for (int k = 2; fs::exists(dir); ++k) dir = "runs/" + src->first + "-" + timestamp() + "-" + std::to_string(k);
  }
  if (Status s = create_run(dir, *cfg, src->second, a.config, a.seed); !s) return fail(s.error());
  if (!a.quiet) std::printf("run %s: %s, seed %llu, %d workers -> %s\n", src->first.c_str(),
                            std::string(to_string(cfg->dialect)).c_str(),
                            static_cast<unsigned long long>(a.seed), a.workers, dir.c_str());
  catch_interrupts(dir);
  return finish(dir, drive_run(dir, {a.workers, a.quiet, a.stop_after}));
}

int cmd_resume(const std::string& dir, int workers, bool quiet) {
  if (!fs::is_directory(dir)) return fail(dir + ": no such run directory");
  catch_interrupts(dir);
  return finish(dir, drive_run(dir, {workers, quiet, 0}));
}

int cmd_best(const std::string& dir, const std::string& out) {
  auto store = RunStore::open(run_db_path(dir));
  if (!store) return fail(store.error());
  std::optional<Individual> best = (*store)->best_individual();
  if (!best) return fail(dir + ": no generation finished yet");
  std::fprintf(stderr, "best so far: individual %lld of generation %d, fitness %.6g (%s)\n",
               static_cast<long long>(best->id), best->generation, best->fitness, best->op.c_str());
  if (out.empty()) {
    std::printf("%s", genome_to_string(best->genome).c_str());
    return 0;
  }
  if (Status s = save_genome(out, best->genome); !s) return fail(s.error());
  // the evaluation that scored it, exactly: the run's config and its seed
  std::uint64_t seed = std::stoull((*store)->meta("seed"));
  std::fprintf(stderr, "written to %s; its evaluation, exactly: bestiary simulate %s --config %s --seed %llu\n",
               out.c_str(), out.c_str(), run_config_path(dir).c_str(),
               static_cast<unsigned long long>(evaluation_seed(seed, best->id)));
  return 0;
}

}  // namespace

void add_evolve_commands(CLI::App& app) {
  static RunArgs run;
  auto* r = app.add_subcommand("run", "Start an evolutionary run from a preset or a TOML config");
  r->add_option("config", run.config, "Preset name (see `bestiary presets`) or config file")->required();
  r->add_option("--out", run.out, "Run directory to create (default runs/NAME-TIME)");
  r->add_option("--seed", run.seed, "Master seed of the run")->default_val(1);
  r->add_option("--workers", run.workers, "Worker processes (default: the number of cores; 0: in-process)");
  r->add_option("--set", run.set, "Override a config key: section.key=value (repeatable)");
  r->add_flag("--quiet", run.quiet, "No progress output");
  r->add_option("--stop-after", run.stop_after, "Stop after N generations (the run stays resumable)");
  r->callback([] { std::exit(cmd_run(run)); });

  static std::string resume_dir;
  static int resume_workers = default_workers();
  static bool resume_quiet = false;
  auto* s = app.add_subcommand("resume", "Continue a run from its last checkpoint");
  s->add_option("dir", resume_dir, "Run directory")->required();
  s->add_option("--workers", resume_workers, "Worker processes (results do not depend on it)");
  s->add_flag("--quiet", resume_quiet, "No progress output");
  s->callback([] { std::exit(cmd_resume(resume_dir, resume_workers, resume_quiet)); });

  static std::string best_dir, best_out;
  auto* b = app.add_subcommand("best", "Write the best genome of a run so far");
  b->add_option("dir", best_dir, "Run directory")->required();
  b->add_option("--out", best_out, "Genome file to write (default: standard output)");
  b->callback([] { std::exit(cmd_best(best_dir, best_out)); });

  auto* p = app.add_subcommand("presets", "List the presets");
  p->callback([] {
    for (const auto& pr : presets()) std::printf("%-34s %s\n", pr.name.c_str(), preset_summary(pr).c_str());
    std::exit(0);
  });
}

}  // namespace bx
