// `bestiary show`: a self-contained browser page of a creature (each of its
// trials, each ESP skill alone), of a run (its curves, the generations' bests
// and their lineages, re-simulated exactly), of several runs' bests side by
// side, or of a run kept current while it goes on (--watch) (docs/viewer.md).
#include <CLI/CLI.hpp>
#include <sqlite3.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/creature.h"
#include "cli/watch.h"
#include "core/files.h"
#include "core/text.h"
#include "genome/encapsulate.h"
#include "io/html_view.h"
#include "io/http_serve.h"
#include "io/run_page.h"
#include "io/run_store.h"
#include "io/syllabus.h"
#include "run/run.h"

namespace bx {

namespace {

namespace fs = std::filesystem;

/// Arguments of `show`.
struct ShowArgs {
  std::string genome;  ///< a genome file, a run's creature, or a run
  CreatureFlags flags;
  std::string out;
  std::vector<std::string> more_runs;  ///< runs whose bests go beside the first's (genome)
  bool watch = false;                  ///< a run: serve the page and keep it current while the run goes on
  int port = 0;                        ///< ... on this port of 127.0.0.1 (0: any free one)
};

// how often a watched page asks whether the run stored more, and the server looks (s)
constexpr double kWatchEvery = 2;

// show puts at most this many of an evaluation's trials on its page, each a
// replay: a fight-or-flight of eight directions is sixteen
constexpr int kMaxTrialsShown = 16;

// A run directory: its context and fitness curves, the overall best, the
// generations' bests and their lineages, re-simulated exactly (the run's
// config and evaluation seeds).
// A run's page: its html, and the line that says what it holds. `stamp`
// (non-empty: watched) goes into the page for it to follow the run.
struct RunPageText {
  std::string html, summary;
};
Result<RunPageText> run_page(const ShowArgs& a, const std::string& stamp = {}, double every = 0) {
  const std::string dir = a.genome;
  auto store = RunStore::open(run_db_path(dir));
  if (!store) return Error{store.error()};
  auto text = (*store)->config_text();
  if (!text) return Error{text.error()};
  auto syl = read_syllabus(*text, run_db_path(dir) + " (the run's config)");
  if (!syl) return Error{syl.error()};
  const RunConfig* cfg = &syl->stages.front().cfg;
  if (!has_body(cfg->sim.creature))
    return Error{no_body(cfg->sim.creature, "no creature to show (its curves: `" + program() + " plot " + dir +
                                                " --out fitness.svg`, and --metric NAME)")};
  auto seed = (*store)->master_seed();
  if (!seed) return Error{seed.error()};
  // each stage's creatures simulated on its own config; a run of several
  // shows its syllabus as a graph, each stage's curve on its own
  std::vector<PageStage> stages;
  for (const StageDef& st : syl->stages) {
    // a reconciliation (General ESP) hangs off the skill it evolves again
    std::vector<std::string> uses = st.uses;
    if (!st.reconcile.empty()) uses.push_back(st.reconcile);
    stages.push_back({st.name, uses, st.group, st.cfg.sim});
    if (Status s = set_seconds(stages.back().sim, a.flags.seconds); !s) return Error{s.error()};
  }
  // the overall best, the lineages and the generations' bests (io/run_page.h)
  auto page = gather_run_page(**store, dir, *cfg, stages, *seed);
  if (!page) return Error{dir + ": " + page.error()};
  for (std::size_t k = 1; k < syl->stages.size(); ++k)
    page->run.planned_generations += total_generations(syl->stages[k].cfg.evolution);
  page->run.watch_stamp = stamp;
  page->run.watch_every = every;
  const RunView& run = page->run;
  auto best = std::find_if(run.members.begin(), run.members.end(), [&](const RunMember& m) { return m.id == run.best_id; });
  char line[512];
  std::snprintf(line, sizeof line, "%s: %zu generations, best fitness %.6g (individual %lld); %zu of %zu creatures replayed",
                utf8_text(dir).c_str(), run.generations.size(), best->fitness, static_cast<long long>(run.best_id),
                page->replays.size(), run.members.size());
  return RunPageText{make_view_html(page->replays, run), line};
}

// Where a run stands, as a watched page compares it: its generations stored
// and evaluations done (read without a lock: the run may be going on)
std::string run_stamp(const std::string& dir) {
  sqlite3* db = nullptr;
  std::string stamp;
  if (sqlite3_open_v2(run_db_path(dir).c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
    sqlite3_busy_timeout(db, 2000);
    sqlite3_stmt* q = nullptr;
    if (sqlite3_prepare_v2(db, "SELECT count(*), coalesce(max(evaluations), 0) FROM generation", -1, &q, nullptr) ==
            SQLITE_OK &&
        sqlite3_step(q) == SQLITE_ROW)
      stamp = std::to_string(sqlite3_column_int64(q, 0)) + " generations, " + std::to_string(sqlite3_column_int64(q, 1)) +
              " evaluations";
    sqlite3_finalize(q);
  }
  sqlite3_close(db);
  return stamp;
}

// `show RUN --watch`: the page served on 127.0.0.1, made again (and written
// to --out) each time the run stores a generation; the page asks for /stamp
// and reloads when it changed
int watch_run(const ShowArgs& a) {
  auto server = HttpServer::listen(a.port);
  if (!server) return fail(server.error());
  std::string stamp = run_stamp(a.genome);
  if (stamp.empty()) return fail(utf8_text(a.genome) + ": no run database to watch");
  auto page = run_page(a, stamp, kWatchEvery);
  if (!page) return fail(page.error());
  if (Status s = write_file_atomic(a.out, page->html); !s) return fail(s.error());
  std::printf("%s\nwatching at http://127.0.0.1:%d/ (the page reloads as the run stores generations; Ctrl-C "
              "stops; %s is kept current too)\n",
              page->summary.c_str(), server->port(), utf8_text(a.out).c_str());
  std::fflush(stdout);
  std::string html = std::move(page->html);
  server->serve(
      [&](const std::string& path) -> HttpReply {
        if (path == "/" || path == "/view.html") return {200, "text/html; charset=utf-8", html};
        if (path == "/stamp") return {200, "text/plain; charset=utf-8", stamp + "\n"};
        return {404, "text/plain; charset=utf-8", "not here: / (the page) and /stamp\n"};
      },
      [&] {
        const std::string now = run_stamp(a.genome);
        if (now.empty() || now == stamp) return true;
        auto next = run_page(a, now, kWatchEvery);
        if (!next) {  // a page that cannot be made now (a run mid-write): try again at the next tick
          std::fprintf(stderr, "not updated: %s\n", next.error().c_str());
          return true;
        }
        stamp = now;
        html = std::move(next->html);
        if (Status s = write_file_atomic(a.out, html); !s) std::fprintf(stderr, "%s\n", s.error().c_str());
        std::printf("%s\n", next->summary.c_str());
        std::fflush(stdout);
        return true;
      },
      kWatchEvery);
  return 0;
}

int cmd_show_run(ShowArgs a) {
  const std::string dir = a.genome;
  if (a.out.empty()) a.out = (fs::path(dir) / "view.html").string();
  if (Status s = make_parent_dir("--out", a.out); !s) return fail(s.error());
  if (a.watch) return watch_run(a);
  auto page = run_page(a);
  if (!page) return fail(page.error());
  if (Status s = write_file_atomic(a.out, page->html); !s) return fail(s.error());
  std::printf("%s\nviewer written to %s\n", page->summary.c_str(), utf8_text(a.out).c_str());
  return 0;
}

// Several runs: each one's best as scored, side by side on one page (its
// picker switches between them), each labelled with its run.
int cmd_show_runs(const ShowArgs& a) {
  std::vector<std::string> dirs{a.genome};
  dirs.insert(dirs.end(), a.more_runs.begin(), a.more_runs.end());
  if (a.flags.id || a.flags.gen || !a.flags.config.empty() || a.flags.seed || !a.flags.set.empty() ||
      a.flags.seconds || a.flags.trial)
    return fail("--id/--gen/--config/--seed/--set/--seconds/--trial: a page of several runs shows each run's best as "
                "it was scored (name one creature, RUN_DIR:ID, to vary its settings)");
  for (const std::string& d : dirs)
    if (!fs::is_directory(d) || !fs::exists(run_db_path(d)))
      return fail(utf8_text(d) + ": not a run folder (a page of several runs shows each run's best: name run folders)");
  if (a.out.empty()) return fail("--out: a page of several runs needs a file to write (--out compare.html)");
  if (Status s = make_parent_dir("--out", a.out); !s) return fail(s.error());
  std::vector<LabelledReplay> entries;
  for (const std::string& d : dirs) {
    auto c = resolve_creature(d, a.flags);
    if (!c) return fail(c.error());
    if (!has_body(c->cfg.sim.creature)) return fail(no_body(c->cfg.sim.creature, utf8_text(d) + ": nothing to show"));
    auto w = simulate_watched(*c);
    if (!w) return fail(w.error());
    print_result(*c, w->front().result);
    // named by its folder, as runs are told apart (the last part of its path)
    fs::path name = fs::path(d).lexically_normal();
    if (name.filename().empty()) name = name.parent_path();  // "runs/a/"
    w->front().entry.label = utf8_text(name.filename().string()) + ": " + w->front().entry.label +
                             trial_text(w->front().result);
    entries.push_back(std::move(w->front().entry));
  }
  if (Status s = save_view_html(a.out, entries); !s) return fail(s.error());
  std::printf("%zu runs' bests on one page (pick them on the page)\nviewer written to %s\n", entries.size(),
              utf8_text(a.out).c_str());
  return 0;
}

int cmd_show(ShowArgs a) {
  if ((a.watch || a.port) && (!a.more_runs.empty() || !fs::is_directory(a.genome) || a.flags.id || a.flags.gen))
    return fail("--watch/--port: follow one run as it goes: name its folder alone (RUN_DIR)");
  if (a.port && !a.watch) return fail("--port: only with --watch");
  if (!a.more_runs.empty()) return cmd_show_runs(a);
  // a run directory alone is the run's page; RUN_DIR:ID, --id or --gen one of its creatures
  if (fs::is_directory(a.genome) && !a.flags.id && !a.flags.gen) {
    if (!a.flags.config.empty() || a.flags.seed || !a.flags.set.empty())
      return fail("--config/--seed/--set: a run's page shows its creatures as they were scored "
                  "(name one, RUN_DIR:ID, to vary its settings)");
    if (a.flags.trial)
      return fail("--trial: a run's page shows each creature's first trial (name one, RUN_DIR:ID, to watch its trials)");
    return cmd_show_run(a);
  }
  // inputs first, then the simulation, then the page
  auto c = resolve_creature(a.genome, a.flags);
  if (!c) return fail(c.error());
  if (!has_body(c->cfg.sim.creature)) return fail(no_body(c->cfg.sim.creature, "nothing to show"));
  if (a.out.empty())
    a.out = c->individual ? (fs::path(c->run_dir) / ("individual-" + std::to_string(c->individual->id) + ".html")).string()
                          : fs::path(a.genome).replace_extension(".html").string();
  if (Status s = make_parent_dir("--out", a.out); !s) return fail(s.error());
  // an evaluation of several trials (task.trials: the light's headings, the
  // fight's targets): each trial's scenario, one replay each, from one
  // evaluation, unless --trial chose one
  const int trials = std::max(1, c->cfg.sim.trials);
  const int shown = c->trial ? 0 : std::min(trials, kMaxTrialsShown);
  auto w = simulate_watched(*c, shown);
  if (!w) return fail(w.error());
  // an ESP creature (lessin2015 IV-B): each encapsulated skill alone, too
  // (brain.skill), unless one is chosen already; the page's picker switches.
  // Each skill alone is of the watched trial only (the first, or --trial's):
  // every skill in every trial would multiply the page
  const std::vector<std::string> skills =
      c->graph_genome() && c->cfg.sim.develop.skill.empty() ? skills_of(*c->graph_genome()) : std::vector<std::string>{};
  std::vector<LabelledReplay> entries;
  for (Watched& t : *w) {
    t.entry.label += (skills.empty() ? "" : ", its brain free") + trial_text(t.result);
    entries.push_back(std::move(t.entry));
  }
  for (const std::string& skill : skills) {
    Subject alone = *c;
    alone.cfg.sim.develop.skill = skill;
    auto ws = simulate_watched(alone);
    if (!ws) return fail(ws.error());
    Watched& one = ws->front();
    one.entry.label += ", skill \"" + skill + "\" alone" + trial_text(one.result);
    entries.push_back(std::move(one.entry));
  }
  if (Status s = save_view_html(a.out, entries); !s) return fail(s.error());
  print_result(*c, w->front().result);
  if (w->size() > 1)
    std::printf("%zu trials, each its own replay (task.trials): pick them on the page\n", w->size());
  if (!c->trial && shown < trials)
    std::printf("the first %d of the %d trials are on the page; the other %d were left out (--trial K watches any one)\n",
                shown, trials, trials - shown);
  if (!skills.empty())
    std::printf("%zu skill(s) each alone beside it (brain.skill): pick them on the page\n", skills.size());
  std::printf("viewer written to %s\n", a.out.c_str());
  return 0;
}

}  // namespace

void add_show_command(CLI::App& app) {
  // arguments live as long as the app: parsing fills them, the callback reads them
  static ShowArgs show;
  auto* s = app.add_subcommand("show", "Write a self-contained HTML viewer of a genome, or of a run directory (curves and the best of each generation)");
  add_creature_options(s, show.genome, show.flags);
  add_trial_option(s, show.flags);
  s->add_flag("--watch", show.watch,
              "A run: serve its page on 127.0.0.1 and keep it current while the run goes on (the page reloads as "
              "generations are stored; Ctrl-C stops)");
  s->add_option("--port", show.port, "--watch: the port (default: any free one, printed)")
      ->check(CLI::Range(0, 65535));
  s->add_option("more_runs", show.more_runs,
                "More run directories: each run's best as scored, side by side on one page (needs --out)");
  s->add_option("--out", show.out,
                "HTML file to write (default: the genome's name with .html, RUN_DIR/view.html for a run, "
                "RUN_DIR/individual-ID.html for one of its creatures)");
  s->callback([] { std::exit(cmd_show(show)); });
}

}  // namespace bx
