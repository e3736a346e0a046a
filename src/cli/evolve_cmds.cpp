// `bestiary run`, `resume`, `best` and `presets`.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <functional>
#include <optional>
#include <thread>
#include <unistd.h>

#include "cli/commands.h"
#include "cli/creature.h"
#include "cluster/mpi_evaluator.h"
#include "core/text.h"
#include "core/files.h"
#include "eval/creature.h"
#include "run/run.h"
#include "genome/genotype_file.h"
#include "io/config.h"
#include "io/presets.h"
#include "io/mjcf.h"
#include "io/urdf.h"
#include "io/run_csv.h"
#include "io/run_store.h"
#include "io/syllabus.h"

namespace bx {

namespace {

namespace fs = std::filesystem;

// SIGINT/SIGTERM: the database is always at a generation boundary, so stop now
char g_resume_hint[8192];  // made before the signal: a handler may only write
void on_interrupt(int) {
  (void)!::write(STDERR_FILENO, g_resume_hint, std::strlen(g_resume_hint));
  ::_exit(130);
}

void catch_interrupts(const std::string& dir) {
  std::snprintf(g_resume_hint, sizeof g_resume_hint, "\ninterrupted; continue with: %s resume %s\n",
                program().c_str(), dir.c_str());
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

int default_workers() { return std::max(1u, std::thread::hardware_concurrency()); }

std::string timestamp() {
  std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y%m%d-%H%M%S", std::localtime(&t));
  return buf;
}

int finish(const std::string& dir, const Status& s) {
  if (!s) return fail(s.error());
  std::printf("run in %s (config.toml, run.sqlite, run.log)\n", dir.c_str());
  bool body = true;  // a kind without a body has no creature to watch
  if (auto store = RunStore::open(run_db_path(dir)); store) {
    auto gens = (*store)->generations();
    auto stages = (*store)->stages();
    if (stages.size() > 1 || (stages.size() == 1 && !stages.front().name.empty())) {
      // each stage's curve from its own generation 0: their fitnesses measure different tasks
      for (std::size_t k = 0; k < stages.size(); ++k) {
        const int from = stages[k].first_gen, to = k + 1 < stages.size() ? stages[k + 1].first_gen : 1 << 30;
        const GenerationStats *first = nullptr, *last = nullptr;
        for (const auto& g : gens) {
          if (g.generation < from || g.generation >= to) continue;
          if (!first) first = &g;
          last = &g;
        }
        if (!first) continue;
        std::printf("stage %zu %s: best fitness %.6g (its generation 0: %.6g)", k + 1, stages[k].name.c_str(),
                    last->best, first->best);
        // a General ESP stage: how many of its children fell below a retest (scored 0)
        bool retested = false;
        for (const MetricStat& m : first->metrics) retested |= m.name.rfind(kRetestFailure, 0) == 0;
        if (retested) {
          const std::int64_t end = k + 1 < stages.size() ? stages[k + 1].first_id : INT64_MAX;
          const long fell = (*store)->count_failures(kRetestFailure, stages[k].first_id, end);
          const long born = (*store)->count_failures("", stages[k].first_id, end);
          std::printf("; %ld of its %ld children fell below a retest", fell, born);
        }
        std::printf("\n");
      }
    } else if (!gens.empty()) {
      std::printf("best fitness %.6g (generation 0: %.6g)\n", gens.back().best, gens.front().best);
    }
    if (auto h = (*store)->held_out(); h && *h)
      std::printf("its best (individual %lld) held out: %.6g over %zu evaluations under seeds the run never used\n",
                  static_cast<long long>((**h).id), (**h).fitness, (**h).by_seed.size());
    if (auto text = (*store)->config_text(); text)
      if (auto syl = read_syllabus(*text, run_db_path(dir)); syl) body = has_body(syl->stages.front().cfg.sim.creature);
  }
  std::printf("its genome: %s best %s --out best.json\n", program().c_str(), dir.c_str());
  if (body)
    std::printf("watch the run: %s show %s  (writes %s/view.html)\n", program().c_str(), dir.c_str(), dir.c_str());
  else
    std::printf("its curves: %s plot %s --out %s/fitness.svg  (--metric NAME: its measures)\n", program().c_str(),
                dir.c_str(), dir.c_str());
  return 0;
}

// The evaluator a run or resume asked for: the process pool (`--workers`),
// or, under mpirun, the other MPI ranks (`--evaluator mpi`; docs/cluster.md).
struct EvaluatorArgs {
  std::string kind = "pool";
  bool workers_given = false;
};

Status check_evaluator(const EvaluatorArgs& e) {
  if (e.kind != "mpi") return Ok{};
  if (e.workers_given)
    return Error{"--workers and --evaluator mpi: under MPI the ranks other than 0 are the workers "
                 "(mpirun -np N gives N - 1); drop --workers"};
  return Ok{};
}

RunOptions run_options(const EvaluatorArgs& e, int workers, bool quiet, int stop_after) {
  RunOptions o;
  o.workers = workers;
  o.quiet = quiet;
  o.stop_after = stop_after;
  if (e.kind == "mpi") o.evaluator = make_mpi_evaluator;
  return o;
}

struct RunArgs {
  std::string config, out;
  std::uint64_t seed = 1;
  bool seed_given = false;
  std::string seeds;  ///< --seeds: several runs, one per seed (under MPI side by side)
  EvaluatorArgs evaluator;
  int workers = default_workers();
  std::vector<std::string> set;
  bool quiet = false;
  int stop_after = 0;
};

int cmd_run(const RunArgs& a);

// runs/NAME-TIME, or with -2, -3, ... when that exists
std::string default_run_dir(const std::string& name) {
  std::string dir = "runs/" + name + "-" + timestamp();
  for (int k = 2; fs::exists(dir); ++k) dir = "runs/" + name + "-" + timestamp() + "-" + std::to_string(k);
  return dir;
}

// `run --seeds`: one run per seed, each in OUT/seed-S; under MPI each group of
// ranks runs its own seed side by side (mpi_group), otherwise one after another
int cmd_run_seeds(const RunArgs& a) {
  auto seeds = parse_seed_list(a.seeds);
  if (!seeds) return fail(seeds.error());
  if (a.seed_given) return fail("--seed and --seeds: give one of them");
  RunArgs one = a;
  one.seeds.clear();
  auto out_of = [&](std::uint64_t s) { return (fs::path(one.out) / ("seed-" + std::to_string(s))).string(); };
  if (a.evaluator.kind == "mpi") {
    if (a.out.empty())
      return fail("--seeds under --evaluator mpi needs --out DIR (each seed's run goes to DIR/seed-S)");
    const int ranks = mpi_world_size();
    if (static_cast<int>(seeds->size()) != mpi_groups())
      return fail("--seeds: " + std::to_string(seeds->size()) + " seeds side by side need at least " +
                  std::to_string(2 * seeds->size()) + " MPI ranks (each seed a rank 0 and at least one evaluating); "
                  "this job has " + std::to_string(ranks) + " (mpirun -np N)");
    one.seed = (*seeds)[static_cast<std::size_t>(mpi_group())];
    one.out = out_of(one.seed);
    return cmd_run(one);
  }
  if (one.out.empty()) {
    auto src = config_source(a.config);
    if (!src) return fail(src.error());
    one.out = default_run_dir(src->first);
  }
  const std::string base = one.out;
  for (std::uint64_t s : *seeds) {
    one.seed = s;
    one.out = (fs::path(base) / ("seed-" + std::to_string(s))).string();
    if (int code = cmd_run(one); code != 0) return code;
  }
  return 0;
}

int cmd_run(const RunArgs& a) {
  if (!a.seeds.empty()) return cmd_run_seeds(a);
  auto src = config_source(a.config);
  if (!src) return fail(src.error());
  auto syl = read_syllabus(src->second, a.config, a.set);
  if (!syl) return fail(syl.error());
  const RunConfig* cfg = &syl->stages.front().cfg;
  if (Status s = check_run(*syl); !s) return fail(s.error());
  if (a.workers < 0) return fail("--workers: expected 0 or more, got " + std::to_string(a.workers));
  if (Status s = check_evaluator(a.evaluator); !s) return fail(s.error());
  const int workers = a.evaluator.kind == "mpi" ? mpi_evaluating_ranks() : a.workers;
  if (a.evaluator.kind == "mpi")
    if (Status s = mpi_ready(); !s) return fail(s.error());  // before a folder exists
  std::string dir = a.out;
  if (dir.empty()) {
    dir = default_run_dir(src->first);
  }
  if (Status s = create_run(dir, *syl, src->second, a.config, a.seed); !s) return fail(s.error());
  // what it evolves: a graph genome's dialect, or another creature kind's name
  const std::string what = cfg->sim.creature == CreatureKind::Graph
                               ? std::string(to_string(cfg->dialect))
                               : std::string(creature_kind_row(cfg->sim.creature).name) + " creatures";
  const std::string stages = syl->staged() ? ", " + std::to_string(syl->stages.size()) + " stages" : "";
  if (!a.quiet)
    std::printf("run %s: %s%s, seed %llu, %d %s -> %s\n", src->first.c_str(), what.c_str(), stages.c_str(),
                static_cast<unsigned long long>(a.seed), workers,
                a.evaluator.kind == "mpi" ? "MPI ranks evaluating" : "workers", dir.c_str());
  catch_interrupts(dir);
  const Status s = drive_run(dir, run_options(a.evaluator, a.workers, a.quiet, a.stop_after));
  // refused before a generation was stored: it leaves nothing, as a run refused before it began
  if (!s) discard_unstarted_run(dir);
  return finish(dir, s);
}

int cmd_resume(const std::string& dir, const EvaluatorArgs& evaluator, int workers, bool quiet,
               const std::vector<std::string>& set) {
  if (!fs::is_directory(dir)) return fail(dir + ": no such run directory");
  if (Status s = check_evaluator(evaluator); !s) return fail(s.error());
  if (evaluator.kind == "mpi")
    if (Status s = mpi_ready(); !s) return fail(s.error());
  if (!set.empty())
    if (Status s = extend_run(dir, set); !s) return fail(s.error());
  auto p = run_progress(dir);
  if (!p) return fail(p.error());
  if (p->complete) {
    std::printf("%s: already complete (%d of %d generations, %ld evaluations); lengthen it with --set %s=N\n",
                dir.c_str(), p->generations_done, p->generations_total, p->evaluations,
                "evolution.generations (or evaluations)");
    return finish(dir, Ok{});
  }
  if (!quiet)
    std::printf("resuming %s at generation %d of %d (%ld evaluations done)\n", dir.c_str(), p->generations_done,
                p->generations_total, p->evaluations);
  catch_interrupts(dir);
  return finish(dir, drive_run(dir, run_options(evaluator, workers, quiet, 0)));
}

struct ExportArgs {
  std::string target, csv, mjcf, urdf;
  CreatureFlags flags;
};

// A creature's body written to `out` (flag `flag`, extension `ext`) in a
// format `write` gives (the text, and its notes and what it counted), with
// a line of what it wrote and a note a line.
int export_body(const ExportArgs& a, const char* flag, const std::string& out, const char* ext,
                const std::function<std::string(const CreatureModel&, const Subject&, std::vector<std::string>&)>& write,
                const std::function<std::string(const CreatureModel&)>& counted) {
  if (fs::path(out).extension().string() != ext)
    return fail(std::string(flag) + ": expected a file name ending in " + ext + ", got \"" + out + "\"");
  auto subject = resolve_creature(a.target, a.flags);
  if (!subject) return fail(subject.error());
  auto creature = subject->develop();
  if (!creature) return fail(a.target + ": not viable: " + creature.error());
  if (!creature->body) return fail(a.target + ": a " + subject->kind_name() + " has no body to export");
  std::vector<std::string> notes;
  const std::string text = write(*creature->body, *subject, notes);
  if (Status s = make_parent_dir(flag, out); !s) return fail(s.error());
  if (Status s = write_file_atomic(out, text); !s) return fail(s.error());
  std::printf("%s -> %s: %s\n", subject->label.c_str(), out.c_str(), counted(*creature->body).c_str());
  for (const std::string& line : notes) std::printf("note: %s\n", line.c_str());
  return 0;
}

std::string mass_text(const CreatureModel& m) {
  char kg[32];
  std::snprintf(kg, sizeof kg, "%.6g kg", m.total_mass());
  return kg;
}

// a creature as MJCF: its body, joints, actuators and the physics that matter
int export_mjcf(const ExportArgs& a) {
  return export_body(
      a, "--mjcf", a.mjcf, ".xml",
      [](const CreatureModel& m, const Subject& s, std::vector<std::string>& notes) {
        MjcfNotes n;
        std::string xml = creature_mjcf(m, s.cfg.sim, s.label, &n);
        notes = n.lines;
        return xml;
      },
      [](const CreatureModel& m) {
        return std::to_string(m.n_parts()) + " bodies, " + std::to_string(m.joints.size()) + " joints, " +
               std::to_string(m.effectors.size()) + " effectors, " + mass_text(m);
      });
}

// a creature as URDF: its links, inertias, shapes and joints
int export_urdf(const ExportArgs& a) {
  return export_body(
      a, "--urdf", a.urdf, ".urdf",
      [](const CreatureModel& m, const Subject& s, std::vector<std::string>& notes) {
        return creature_urdf(m, s.cfg.sim, s.label, &notes);
      },
      [](const CreatureModel& m) {
        return std::to_string(m.n_parts()) + " links, " + std::to_string(m.joints.size()) + " joints, " + mass_text(m);
      });
}

int cmd_export(const ExportArgs& a) {
  if (!a.csv.empty() + !a.mjcf.empty() + !a.urdf.empty() != 1)
    return fail("export: say what to write, one of: --csv DIR (a run), --mjcf OUT.xml or --urdf OUT.urdf (a creature)");
  if (!a.mjcf.empty()) return export_mjcf(a);
  if (!a.urdf.empty()) return export_urdf(a);
  const std::string& dir = a.target;
  if (!fs::is_directory(dir)) return fail(dir + ": no such run directory");
  const std::string& csv = a.csv;
  auto e = export_run_csv(run_db_path(dir), csv);
  if (!e) return fail(e.error());
  std::printf("%s -> %s: generations.csv (%ld rows), individuals.csv (%ld), metrics.csv (%ld), run.csv (%ld)\n",
              dir.c_str(), csv.c_str(), e->generations, e->individuals, e->metrics, e->run);
  return 0;
}

int cmd_verify(const std::string& dir) {
  if (!fs::is_directory(dir)) return fail(dir + ": no such run directory");
  auto v = verify_run(dir);
  if (!v) return fail(v.error());
  std::printf("%s: sound: %ld generations, %ld individuals, %ld stage%s, the checkpoint and the config; "
              "%ld rows match their checksums",
              dir.c_str(), v->generations, v->individuals, v->stages, v->stages == 1 ? "" : "s", v->sealed);
  if (v->unsealed > 0)
    std::printf(", %ld stored before runs kept checksums were read but cannot be checked", v->unsealed);
  std::printf("\n");
  return 0;
}

int cmd_best(const std::string& target, const CreatureFlags& flags, const std::string& out) {
  if (!names_run(target)) return fail(target + ": expected a run directory (RUN_DIR, RUN_DIR:ID or RUN_DIR:gen=G)");
  auto c = resolve_creature(target, flags);
  if (!c) return fail(c.error());
  const Individual& ind = *c->individual;
  bool overall = fs::is_directory(target) && !flags.id && !flags.gen;
  std::fprintf(stderr, "%sindividual %lld of generation %d, fitness %.6g (%s)\n", overall ? "best so far: " : "",
               static_cast<long long>(ind.id), ind.generation, ind.fitness, ind.op.c_str());
  if (c->held_out)
    std::fprintf(stderr, "held out: %.6g, the %s of %zu evaluations under seeds its run never used "
                 "(evolution.held_out_evaluations)\n",
                 c->held_out->fitness, score_name(c->cfg.sim.trial_score), c->held_out->by_seed.size());
  // the genotype (a graph genome's file, or another kind's genotype file)
  // with where it came from: the run's config and the seed that scored it
  // travel with it, so `simulate/show/render/check FILE` replay that evaluation
  std::string text = genotype_file_string(*c->genotype, provenance_json(*c, c->run_config_text));
  if (out.empty()) {
    std::printf("%s", text.c_str());
    return 0;
  }
  if (Status s = make_parent_dir("--out", out); !s) return fail(s.error());
  if (Status s = write_file_atomic(out, text); !s) return fail(s.error());
  std::fprintf(stderr, "written to %s, with its run's config and evaluation seed; its evaluation, exactly: %s simulate %s\n",
               out.c_str(), program().c_str(), out.c_str());
  return 0;
}

// the paper a config reproduces: its creature kind's, else its dialect's
std::string paper_of(const RunConfig& cfg) {
  if (std::string_view p = creature_kind_row(cfg.sim.creature).paper; !p.empty()) return std::string(p);
  switch (cfg.dialect) {
    case Dialect::Sims1994: return "Sims 1994";
    case Dialect::Miconi2006: return "Miconi & Channon 2006";
    case Dialect::Chaumont2007: return "Chaumont et al. 2007";
    case Dialect::Lessin2015: return "Lessin et al. 2015";
  }
  return "";
}

// with thousands separators: 12,000
std::string grouped(long v) {
  const std::string digits = std::to_string(v);
  std::string out;
  for (std::size_t k = 0; k < digits.size(); ++k) {
    if (k > 0 && digits[k - 1] != '-' && (digits.size() - k) % 3 == 0) out += ',';
    out += digits[k];
  }
  return out;
}

// one line per preset: name, paper, budget, time on 2 cores, what it runs
int cmd_presets() {
  struct Row {
    std::string name, paper, budget, time, summary;
  };
  std::vector<Row> rows{{"NAME", "PAPER", "BUDGET", "TIME (2 CORES)", "WHAT IT RUNS"}};
  for (const auto& p : presets()) {
    // a config, or a run of stages (an ESP syllabus)
    auto syl = read_syllabus(p.text, p.name);
    if (!syl) return fail(syl.error());  // a broken built-in preset: the build's tests catch it
    const RunConfig& cfg = syl->stages.front().cfg;
    const EvolutionDef& e = cfg.evolution;
    // a steady state counts tournaments when each evaluates its three, else evaluations
    const std::string births = e.tournament_evaluates == TournamentEvaluates::All ? " tournaments" : " evaluations";
    std::string budget = e.algorithm == Algorithm::Generational
                             ? grouped(e.population) + " x " + grouped(e.generations) + " generations"
                             : grouped(e.population) + ", " + grouped(e.evaluations) + births;
    if (syl->staged()) {
      // the stages' populations (their range, when they differ) over every stage's generations,
      // or a steady state's tournaments (evaluations) over every stage
      long generations = 0, evaluations = 0;
      int least = e.population, most = e.population;
      bool generational = true;
      for (const StageDef& st : syl->stages) {
        generations += total_generations(st.cfg.evolution);
        evaluations += st.cfg.evolution.evaluations;
        generational = generational && st.cfg.evolution.algorithm == Algorithm::Generational;
        least = std::min(least, st.cfg.evolution.population);
        most = std::max(most, st.cfg.evolution.population);
      }
      const std::string pops = grouped(least) + (most > least ? "-" + grouped(most) : "");
      const std::string stages = " in " + std::to_string(syl->stages.size()) + " stages";
      budget = generational ? pops + " x " + grouped(generations) + " generations" + stages
                            : pops + ", " + grouped(evaluations) + births + stages;
    }
    rows.push_back({p.name, paper_of(cfg), budget, preset_time(p), preset_summary(p)});
  }
  std::size_t w[4] = {};
  for (const auto& r : rows)
    for (auto [k, f] : {std::pair{0, &r.name}, {1, &r.paper}, {2, &r.budget}, {3, &r.time}})
      w[k] = std::max(w[k], f->size());
  for (const auto& r : rows)
    std::printf("%-*s  %-*s  %-*s  %-*s  %s\n", static_cast<int>(w[0]), r.name.c_str(), static_cast<int>(w[1]),
                r.paper.c_str(), static_cast<int>(w[2]), r.budget.c_str(), static_cast<int>(w[3]), r.time.c_str(),
                r.summary.c_str());
  return 0;
}

}  // namespace

void add_evolve_commands(CLI::App& app) {
  static RunArgs run;
  auto* r = app.add_subcommand("run", "Start an evolutionary run from a preset or a TOML config");
  r->add_option("config", run.config, "Preset name (see `bestiary presets`) or config file")->required();
  r->add_option("--out", run.out, "Run directory to create (default runs/NAME-TIME)");
  auto* rs = r->add_option("--seed", run.seed, "Master seed of the run")->default_val(1)->check(whole_number(0, UINT64_MAX));
  r->add_option("--seeds", run.seeds,
                "Several runs, one per seed (A-B, A,B,C), each in OUT/seed-S: one after another, or under "
                "--evaluator mpi side by side, the ranks split between them (docs/cluster.md)");
  auto* rw = r->add_option("--workers", run.workers, "Worker processes (default: the number of cores; 0: in-process)")
                 ->check(whole_number(0, 256));
  r->add_option("--evaluator", run.evaluator.kind,
                "pool (worker processes on this machine; default) or mpi (under mpirun: the other ranks evaluate; "
                "docs/cluster.md)")
      ->check(CLI::IsMember({"pool", "mpi"}));
  r->add_option("--set", run.set, "Override a config key: section.key=value (repeatable)");
  r->add_flag("--quiet", run.quiet, "No progress output");
  r->add_option("--stop-after", run.stop_after, "Stop after N generations (the run stays resumable)")
      ->check(whole_number(1, INT32_MAX));
  r->callback([rw, rs] {
    run.evaluator.workers_given = rw->count() > 0;
    run.seed_given = rs->count() > 0;
    std::exit(cmd_run(run));
  });

  static std::string resume_dir;
  static int resume_workers = default_workers();
  static EvaluatorArgs resume_evaluator;
  static bool resume_quiet = false;
  static std::vector<std::string> resume_set;
  auto* s = app.add_subcommand("resume", "Continue a run from its last checkpoint");
  s->add_option("dir", resume_dir, "Run directory")->required();
  auto* sw = s->add_option("--workers", resume_workers, "Worker processes (results do not depend on it)")
                 ->check(whole_number(0, 256));
  s->add_option("--evaluator", resume_evaluator.kind, "pool (default) or mpi (under mpirun; results do not depend on it)")
      ->check(CLI::IsMember({"pool", "mpi"}));
  s->add_flag("--quiet", resume_quiet, "No progress output");
  s->add_option("--set", resume_set,
                "Lengthen the run: evolution.generations=N (generational) or evolution.evaluations=N (steady state); "
                "or measure its best held out: evolution.held_out_evaluations=N");
  s->callback([sw] {
    resume_evaluator.workers_given = sw->count() > 0;
    std::exit(cmd_resume(resume_dir, resume_evaluator, resume_workers, resume_quiet, resume_set));
  });

  static ExportArgs exp;
  auto* x = app.add_subcommand("export", "Write a run's database as CSV files, or a creature as MuJoCo's MJCF or as URDF");
  add_creature_options(x, exp.target, exp.flags);
  x->add_option("--csv", exp.csv, "A run: the directory to write its CSV files into (created if need be)");
  x->add_option("--mjcf", exp.mjcf, "A creature: the MJCF file (.xml) to write (docs/export.md)");
  x->add_option("--urdf", exp.urdf, "A creature: the URDF file (.urdf) to write (docs/export.md)");
  x->callback([] { std::exit(cmd_export(exp)); });

  static std::string verify_dir;
  auto* v = app.add_subcommand("verify", "Check a run's database whole: every stored row against its checksum, none missing");
  v->add_option("dir", verify_dir, "Run directory")->required();
  v->callback([] { std::exit(cmd_verify(verify_dir)); });

  static std::string best_target, best_out;
  static CreatureFlags best_flags;
  auto* b = app.add_subcommand("best", "Write the genome of a run's best (or of any of its creatures), with its provenance");
  b->add_option("run", best_target, "RUN_DIR (its best so far), RUN_DIR:ID or RUN_DIR:gen=G")->required();
  b->add_option("--id", best_flags.id, "A run's individual (as RUN_DIR:ID)");
  b->add_option("--gen", best_flags.gen, "The best of a run's generation (as RUN_DIR:gen=G)");
  b->add_option("--out", best_out, "Genome file to write (default: standard output)");
  b->callback([] { std::exit(cmd_best(best_target, best_flags, best_out)); });

  auto* p = app.add_subcommand("presets", "List the presets");
  p->callback([] { std::exit(cmd_presets()); });
}

Result<std::pair<std::string, std::string>> config_source(const std::string& arg) {
  // a path (a folder in it, or a .toml name) is a file, and its error says why it cannot be read
  if (fs::exists(arg) || arg.find('/') != std::string::npos || fs::path(arg).extension() == ".toml") {
    auto text = read_file(arg);
    if (!text) return Error{text.error()};
    return std::pair{fs::path(arg).stem().string(), *text};
  }
  if (const Preset* p = find_preset(arg)) return std::pair{p->name, p->text};
  std::vector<std::string> names;
  for (const auto& p : presets()) names.push_back(p.name);
  return Error{arg + ": no such config file, and no preset of that name" + did_you_mean(arg, names) + " (`" +
               program() + " presets` lists them)"};
}

}  // namespace bx
