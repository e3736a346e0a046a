// `bestiary show` and `bestiary render`: watch a creature in a self-contained
// browser page, or as a video made from that page by headless Chromium and
// ffmpeg (docs/viewer.md). Both simulate the genome exactly as `simulate`
// does: same loading, config overlay, development and evaluation.
#include <CLI/CLI.hpp>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <sqlite3.h>

#include <algorithm>
#include <cerrno>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/creature.h"
#include "core/files.h"
#include "core/text.h"
#include "io/http_serve.h"
#include "eval/evaluate.h"
#include "eval/task_table.h"
#include "genome/encapsulate.h"
#include "genome/genotype_file.h"
#include "io/config.h"
#include "io/fitness_plot.h"
#include "io/html_view.h"
#include "io/replay_file.h"
#include "io/run_page.h"
#include "io/run_store.h"
#include "io/syllabus.h"
#include "run/run.h"

extern char** environ;

namespace bx {

namespace {

namespace fs = std::filesystem;

/// Arguments of `show` and `render`.
struct WatchArgs {
  std::string genome;  ///< a genome file, a run's creature, or (show) a run
  CreatureFlags flags;
  std::string out;
  int width = 1280, height = 720;
  std::optional<int> fps;  ///< render: default 30 for mp4, 15 for gif
  bool quiet = false;      ///< render: no progress output
  std::vector<std::string> metrics;  ///< plot: the task's metrics whose names contain these, not fitness
  std::vector<std::string> more_runs;  ///< plot, show: runs compared with the first (genome)
  std::string group_by;                ///< plot: "preset" or a config key: runs of one value are one condition
  bool watch = false;                  ///< show RUN: serve the page and keep it current while the run goes on
  int port = 0;                        ///< ... on this port of 127.0.0.1 (0: any free one)
};

// how often a watched page asks whether the run stored more, and the server looks (s)
constexpr double kWatchEvery = 2;

/// What simulating gave: the page's entry and the result.
struct Watched {
  LabelledReplay entry;  ///< labelled with the creature alone (its trial: trial_text)
  EvalResult result;
};

// show puts at most this many of an evaluation's trials on its page, each a
// replay: a fight-or-flight of eight directions is sixteen
constexpr int kMaxTrialsShown = 16;

// develop and simulate with a replay of each of the trials `trials` names, as
// `simulate --replay` does, in one evaluation: the trial --trial chose (else
// the first) when `trials` is 0, else each of the first `trials`
Result<std::vector<Watched>> simulate(const Subject& c, int trials = 0) {
  auto dev = c.develop();
  if (!dev) return Error{c.label + ": not viable: " + dev.error()};
  const CreatureModel& m = *dev->body;
  std::vector<Replay> replays(static_cast<std::size_t>(std::max(1, trials)));
  std::vector<EvalResult> results;
  if (trials > 0)
    results = evaluate_trials(m, *dev->controller, c.cfg.sim, c.seed, replays);
  else
    results.push_back(evaluate_trial(*dev, c.cfg.sim, c.seed, c.trial.value_or(0), &replays.front()));
  ReplayInfo info{c.label, c.seed, c.cfg.sim.physics.dt, c.cfg.sim.physics.friction, replay_creature(c.cfg.sim)};
  std::string label = c.individual ? "individual " + std::to_string(c.individual->id) + " (generation " +
                                         std::to_string(c.individual->generation) + ")"
                                   : fs::path(c.label).stem().string();
  std::vector<Watched> out;
  for (std::size_t k = 0; k < results.size(); ++k)
    out.push_back({{label, replay_to_string(m, replays[k], results[k], info), genotype_text(*c.genotype)}, results[k]});
  return out;
}

// which of several trials a replay is, and what it set up (Task::describe):
// ", trial 2 of 4: light at 135 degrees"; "" for a single trial
std::string trial_text(const EvalResult& res) {
  if (res.trial_fitness.empty()) return "";
  return ", trial " + std::to_string(res.trial + 1) + " of " + std::to_string(res.trial_fitness.size()) +
         (res.setup.empty() ? "" : ": " + res.setup);
}

void print_result(const Subject& c, const EvalResult& res) {
  if (!c.settings.empty()) std::printf("%s\n", c.settings.c_str());
  std::printf("%s: simulated %.2f s, seed %llu, distance %.4f m, %s\n", c.label.c_str(), res.seconds,
              static_cast<unsigned long long>(c.seed), res.distance, fitness_line(res.fitness, c.scored_fitness()).c_str());
  if (std::string note = c.evaluations_note(); !note.empty()) std::printf("%s\n", note.c_str());
  if (!res.metrics.empty()) std::printf("%s\n", metrics_line(res.metrics).c_str());
  if (res.failed) std::printf("failed: %s\n", res.failure.c_str());
  if (!res.trial_fitness.empty())
    // the measures are one trial's, the fitness the fold of all
    std::printf("trial %d of %zu%s: the lines above are its own, but the fitness, the %s of the %zu trials'\n",
                res.trial + 1, res.trial_fitness.size(), res.setup.empty() ? "" : (" (" + res.setup + ")").c_str(),
                trial_fold_name(c.cfg.sim).c_str(), res.trial_fitness.size());
}

// A run directory: its context and fitness curves, the overall best, the
// generations' bests and their lineages, re-simulated exactly (the run's
// config and evaluation seeds).
// A run's page: its html, and the line that says what it holds. `stamp`
// (non-empty: watched) goes into the page for it to follow the run.
struct RunPageText {
  std::string html, summary;
};
Result<RunPageText> run_page(const WatchArgs& a, const std::string& stamp = {}, double every = 0) {
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
int watch_run(const WatchArgs& a) {
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

int cmd_show_run(WatchArgs a) {
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
int cmd_show_runs(const WatchArgs& a) {
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
    auto w = simulate(*c);
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

int cmd_show(WatchArgs a) {
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
  auto w = simulate(*c, shown);
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
    auto ws = simulate(alone);
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

// ---- render: the tools it runs ----

// an executable file named `name` on PATH (or `name` itself if it has a '/')
std::optional<std::string> find_program(const std::string& name) {
  auto ok = [](const fs::path& p) { return ::access(p.c_str(), X_OK) == 0 && !fs::is_directory(p); };
  if (name.find('/') != std::string::npos) return ok(name) ? std::optional(name) : std::nullopt;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string d; std::getline(dirs, d, ':');)
    if (!d.empty() && ok(fs::path(d) / name)) return (fs::path(d) / name).string();
  return std::nullopt;
}

/// Where render finds node, its script and the browser and encoder.
struct Tools {
  std::string node, script, chromium, ffmpeg;
};

// The viewer folder holds render.mjs and node_modules (npm ci); the build
// records the source tree's (BESTIARY_VIEWER_DIR), the environment variable
// of the same name overrides it. Chromium: $BESTIARY_CHROMIUM, else Debian's.
Result<Tools> find_tools() {
  Tools t;
  const char* env_dir = std::getenv("BESTIARY_VIEWER_DIR");
  fs::path dir = env_dir && *env_dir ? env_dir : BESTIARY_VIEWER_DIR;
  t.script = (dir / "render.mjs").string();
  if (!fs::exists(t.script) || !fs::exists(dir / "node_modules/playwright-core/package.json"))
    return Error{"render: the viewer's render.mjs and node_modules are not in " + dir.string() +
                 " (run ./scripts/setup, or set BESTIARY_VIEWER_DIR to a viewer/ folder after `npm ci`)"};
  auto node = find_program("node");
  if (!node) return Error{"render: node is not on PATH (Debian package nodejs; ./scripts/setup installs it)"};
  const char* env_chromium = std::getenv("BESTIARY_CHROMIUM");
  std::optional<std::string> chromium;
  if (env_chromium && *env_chromium) {
    chromium = find_program(env_chromium);
    if (!chromium) return Error{std::string("BESTIARY_CHROMIUM: no such program: ") + env_chromium};
  } else {
    chromium = find_program("/usr/bin/chromium");
    if (!chromium) chromium = find_program("chromium");
    if (!chromium)
      return Error{"render: chromium not found (Debian package chromium, or set BESTIARY_CHROMIUM)"};
  }
  auto ffmpeg = find_program("ffmpeg");
  if (!ffmpeg) return Error{"render: ffmpeg is not on PATH (Debian package ffmpeg)"};
  t.node = *node;
  t.chromium = *chromium;
  t.ffmpeg = *ffmpeg;
  return t;
}

/// How a child program ended: its exit code (-1 if it could not start or died
/// of a signal) and the last non-empty line it wrote on stderr, its own
/// explanation of a failure.
struct Ended {
  int code = -1;
  std::string last_err;
};

// Runs argv with stdin from /dev/null, reading its stdout and stderr through
// pipes while it runs: each stdout line goes to `on_line`. One poll loop, no
// threads; it stops once the child has exited and its pipes are drained, even
// if a grandchild still holds them open.
Ended run(const std::vector<std::string>& argv, const std::function<void(const std::string&)>& on_line) {
  std::vector<char*> args;
  for (const auto& s : argv) args.push_back(const_cast<char*>(s.c_str()));
  args.push_back(nullptr);
  int out[2], err[2];
  if (::pipe2(out, O_CLOEXEC) != 0) return {};
  if (::pipe2(err, O_CLOEXEC) != 0) {
    ::close(out[0]);
    ::close(out[1]);
    return {};
  }
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&fa, out[1], 1);
  posix_spawn_file_actions_adddup2(&fa, err[1], 2);
  pid_t pid;
  int rc = posix_spawn(&pid, args[0], &fa, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  ::close(out[1]);
  ::close(err[1]);
  Ended end;
  if (rc != 0) {
    ::close(out[0]);
    ::close(err[0]);
    return end;
  }

  // whole lines: stdout's to on_line, stderr's non-empty ones kept as the last
  std::string pending[2];
  auto take = [&](int i, const std::string& line) {
    if (i == 0) on_line(line);
    else if (line.find_first_not_of(" \t\r") != std::string::npos) end.last_err = line;
  };
  pollfd fds[2] = {{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
  bool exited = false;
  int status = 0;
  while (fds[0].fd >= 0 || fds[1].fd >= 0) {
    int n = ::poll(fds, 2, exited ? 0 : 500);
    if (n < 0 && errno != EINTR) break;
    if (n == 0 && exited) break;  // drained
    for (int i = 0; i < 2 && n > 0; ++i) {
      if (fds[i].fd < 0 || !fds[i].revents) continue;
      char buf[4096];
      ssize_t got = ::read(fds[i].fd, buf, sizeof buf);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) {
        ::close(fds[i].fd);
        fds[i].fd = -1;
        continue;
      }
      pending[i].append(buf, static_cast<std::size_t>(got));
      for (std::size_t nl; (nl = pending[i].find('\n')) != std::string::npos; pending[i].erase(0, nl + 1))
        take(i, pending[i].substr(0, nl));
    }
    if (!exited && ::waitpid(pid, &status, WNOHANG) == pid) exited = true;
  }
  for (int i = 0; i < 2; ++i) {
    if (fds[i].fd >= 0) ::close(fds[i].fd);
    if (!pending[i].empty()) take(i, pending[i]);
  }
  if (!exited)
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
  end.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return end;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// ---- render ----

int cmd_render(const WatchArgs& a) {
  // inputs: the creature, its config and flags, the output's kind and folder, the tools
  auto c = resolve_creature(a.genome, a.flags);
  if (!c) return fail(c.error());
  if (!has_body(c->cfg.sim.creature)) return fail(no_body(c->cfg.sim.creature, "nothing to render"));
  std::string ext = lower(fs::path(a.out).extension().string());
  if (ext != ".mp4" && ext != ".gif")
    return fail("--out: expected a file name ending in .mp4 or .gif, got \"" + a.out + "\"");
  std::string format = ext.substr(1);
  for (auto [flag, v] : {std::pair{"--width", a.width}, std::pair{"--height", a.height}}) {
    if (v < 16 || v > 3840)
      return fail(std::string(flag) + ": expected a number of pixels in [16, 3840], got " + std::to_string(v));
    if (format == "mp4" && v % 2 != 0)
      return fail(std::string(flag) + ": an mp4 needs an even number of pixels, got " + std::to_string(v));
  }
  // a GIF compresses far less than H.264: half an mp4's frames keep it small and are smooth enough
  const int fps = a.fps.value_or(format == "gif" ? 15 : 30);
  if (fps < 1 || fps > 60) return fail("--fps: expected frames per second in [1, 60], got " + std::to_string(fps));
  if (Status s = make_parent_dir("--out", a.out); !s) return fail(s.error());
  auto tools = find_tools();
  if (!tools) return fail(tools.error());

  // simulate, and write the page into a fresh temporary folder
  if (!a.quiet) std::printf("simulating %s ...\n", c->label.c_str());
  std::fflush(stdout);
  auto watched = simulate(*c);
  if (!watched) return fail(watched.error());
  Watched* w = &watched->front();
  w->entry.label += trial_text(w->result);
  std::string tmpl = (fs::temp_directory_path() / "bestiary-render-XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) return fail("render: cannot make a temporary folder in " + fs::temp_directory_path().string());
  fs::path work = tmpl;
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } cleanup{work};
  std::string page = (work / "page.html").string();
  if (Status s = save_view_html(page, {w->entry}); !s) return fail(s.error());

  // the page, frame by frame, through ffmpeg into OUT.tmp; renamed when whole
  double seconds = w->result.seconds;
  long frames = std::max(1L, std::lround(seconds * fps));
  std::string tmp = a.out + ".tmp";
  if (!a.quiet) std::printf("rendering %ld frames (%d x %d, %d fps)...\n", frames, a.width, a.height, fps);
  std::fflush(stdout);

  // render.mjs's progress lines: one updating line on a terminal, else one
  // every PROGRESS_SECONDS and the last
  constexpr auto PROGRESS_SECONDS = std::chrono::seconds(10);
  const bool tty = !a.quiet && ::isatty(STDOUT_FILENO);
  const std::string last_frame = "frame " + std::to_string(frames) + "/";
  auto shown = std::chrono::steady_clock::now();
  bool open_line = false;
  auto progress = [&](const std::string& line) {
    if (a.quiet) return;
    auto now = std::chrono::steady_clock::now();
    if (tty) {
      std::printf("\r\033[K%s", line.c_str());
      open_line = true;
    } else if (now - shown >= PROGRESS_SECONDS || line.rfind(last_frame, 0) == 0) {
      std::printf("%s\n", line.c_str());
      shown = now;
    }
    std::fflush(stdout);
  };
  Ended end = run({tools->node, tools->script, "--html", page, "--out", tmp, "--format", format,
                   "--frames", std::to_string(frames), "--fps", std::to_string(fps),
                   "--width", std::to_string(a.width), "--height", std::to_string(a.height),
                   "--chromium", tools->chromium, "--ffmpeg", tools->ffmpeg},
                  progress);
  if (open_line) std::printf("\n");
  std::fflush(stdout);
  if (end.code != 0) {
    std::remove(tmp.c_str());
    return fail("render: " + (end.last_err.empty()
                                  ? "node " + tools->script + " failed (exit " + std::to_string(end.code) + ")"
                                  : end.last_err));
  }
  std::error_code ec;
  fs::rename(tmp, a.out, ec);
  if (ec) {
    std::remove(tmp.c_str());
    return fail(a.out + ": cannot replace file (" + ec.message() + ")");
  }
  print_result(*c, w->result);
  std::printf("video written to %s (%ld frames, %.2f s)\n", a.out.c_str(), frames,
              static_cast<double>(frames) / fps);
  return 0;
}


}  // namespace

// ---- plot ----

// fitness over generations: SVG written directly, PNG rendered from it by Chromium
// The value of `key` ("section.key") in a run's resolved config text (every
// key, as config_to_toml writes it: "[section]" lines, then "key = value").
Result<std::string> config_value(const std::string& text, const std::string& key) {
  const std::size_t dot = key.find('.');
  if (dot == std::string::npos) return Error{"--group-by: expected preset or section.key, got \"" + key + "\""};
  const std::string section = "[" + key.substr(0, dot) + "]", name = key.substr(dot + 1);
  bool in = false;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line[0] == '[') {
      in = line == section;
      continue;
    }
    if (in && line.rfind(name + " = ", 0) == 0) return line.substr(name.size() + 3);
  }
  return Error{"--group-by: no config key \"" + key + "\" (see `bestiary config --reference`)"};
}

int write_plot(const WatchArgs& a, const std::string& ext, const std::string& svg, const std::string& what);

// Every recorded metric of `runs` whose name contains one of `wants`, in the
// task's order; an error names what they have when none does.
Result<std::vector<std::string>> matched_metrics(const std::vector<const std::vector<GenerationStats>*>& runs,
                                                 const std::vector<std::string>& wants, const std::string& where) {
  std::vector<std::string> names, known;
  for (const auto* gens : runs)
    for (const auto& g : *gens)
      for (const MetricStat& m : g.metrics)
        if (std::find(known.begin(), known.end(), m.name) == known.end()) known.push_back(m.name);
  for (const std::string& k : known)
    for (const std::string& want : wants)
      if (k.find(want) != std::string::npos) {
        names.push_back(k);
        break;
      }
  if (names.empty()) {
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    return Error{"--metric: no metric of " + where + " matches \"" + wants.front() + "\" (it has: " +
                 (list.empty() ? std::string("none") : list) + ")"};
  }
  return names;
}

// A run's x per report: a steady state's tournaments per report interval
// (its first stage's), else 1 generation.
double per_report(const EvolutionDef& e) {
  if (e.algorithm != Algorithm::SteadyState) return 1.0;
  return static_cast<double>(e.report_every > 0 ? e.report_every : e.population);
}

// several runs on one chart, each condition its median and interquartile
// band: their fitness, or with --metric their task's metrics
int cmd_plot_runs(const WatchArgs& a, std::string& svg, std::string& what) {
  std::vector<std::string> dirs{a.genome};
  std::optional<double> per;
  dirs.insert(dirs.end(), a.more_runs.begin(), a.more_runs.end());
  std::vector<PlottedRun> runs;
  bool steady = false, generational = false;
  for (const std::string& dir : dirs) {
    auto store = RunStore::open(run_db_path(dir));
    if (!store) return fail(store.error());
    PlottedRun r;
    r.gens = (*store)->generations();
    if (r.gens.empty()) return fail(dir + ": no generation finished yet");
    auto text = (*store)->config_text();
    if (!text) return fail(text.error());
    auto syl = read_syllabus(*text, run_db_path(dir) + " (its config)");
    if (!syl) return fail(syl.error());
    (syl->stages.front().cfg.evolution.algorithm == Algorithm::SteadyState ? steady : generational) = true;
    const double p = per_report(syl->stages.front().cfg.evolution);
    if (!a.metrics.empty() && per && *per != p)
      return fail("plot --metric: " + dir + " reports every " + std::to_string(static_cast<long>(p)) +
                  " tournaments, the first run every " + std::to_string(static_cast<long>(*per)) +
                  ": no common x axis");
    per = p;
    if (a.group_by.empty()) {
      r.condition = dir;
    } else if (a.group_by == "preset") {
      r.condition = (*store)->meta("name");
    } else {
      auto v = config_value(*text, a.group_by);
      if (!v) return fail(dir + ": " + v.error());
      r.condition = a.group_by + " = " + *v;
    }
    runs.push_back(std::move(r));
  }
  if (steady && generational)
    return fail("plot: generational and steady-state runs have no common x axis (generations against evaluations)");
  const std::string title = a.group_by.empty() ? std::to_string(runs.size()) + " runs"
                                               : std::to_string(runs.size()) + " runs by " + a.group_by;
  if (!a.metrics.empty()) {
    std::vector<const std::vector<GenerationStats>*> all;
    for (const PlottedRun& r : runs) all.push_back(&r.gens);
    auto names = matched_metrics(all, a.metrics, "these runs");
    if (!names) return fail(names.error());
    svg = compare_metric_svg(runs, *names, *per, steady ? "tournaments" : "generation", title, a.width, a.height);
  } else {
    svg = compare_svg(runs, steady, title, a.width, a.height);
  }
  what = std::to_string(runs.size()) + " runs";
  return 0;
}

int cmd_plot(const WatchArgs& a) {
  const std::string& dir = a.genome;
  std::string ext = lower(fs::path(a.out).extension().string());
  if (ext != ".svg" && ext != ".png")
    return fail("--out: expected a .svg or .png file, got \"" + a.out + "\"");
  if (a.width < 100 || a.height < 100 || a.width > 8000 || a.height > 8000)
    return fail("--width/--height: expected 100 to 8000 pixels, got " + std::to_string(a.width) + "x" +
                std::to_string(a.height));
  std::string svg, what;
  if (!a.more_runs.empty() || !a.group_by.empty()) {
    if (int code = cmd_plot_runs(a, svg, what); code != 0) return code;
    return write_plot(a, ext, svg, what);
  }
  auto store = RunStore::open(run_db_path(dir));
  if (!store) return fail(store.error());
  auto gens = (*store)->generations();
  if (gens.empty()) return fail(dir + ": no generation finished yet");
  std::string title = (*store)->meta("name") + " (seed " + (*store)->meta("seed") + ")";
  if (a.metrics.empty()) {
    svg = fitness_svg(gens, title, a.width, a.height);
  } else {
    auto names = matched_metrics({&gens}, a.metrics, dir);
    if (!names) return fail(names.error());
    // a steady state's report intervals count tournaments
    auto text = (*store)->config_text();
    if (!text) return fail(text.error());
    auto syl = read_syllabus(*text, run_db_path(dir) + " (its config)");
    if (!syl) return fail(syl.error());
    const EvolutionDef& e = syl->stages.front().cfg.evolution;
    const bool steady = e.algorithm == Algorithm::SteadyState;
    svg = metric_svg(gens, *names, per_report(e), steady ? "tournaments" : "generation", title, a.width, a.height);
  }
  char best[64];
  std::snprintf(best, sizeof best, "%.6g", gens.back().best);
  return write_plot(a, ext, svg, dir + ": " + std::to_string(gens.size()) + " generations, best " + best);
}

// the chart to --out: SVG as it is, PNG through headless Chromium
int write_plot(const WatchArgs& a, const std::string& ext, const std::string& svg, const std::string& what) {
  if (Status s = make_parent_dir("--out", a.out); !s) return fail(s.error());
  if (ext == ".svg") {
    if (Status s = write_file_atomic(a.out, svg); !s) return fail(s.error());
  } else {
    auto chromium = find_program("/usr/bin/chromium");
    if (!chromium) chromium = find_program("chromium");
    if (!chromium) return fail("plot: chromium not found for PNG output (Debian package chromium; or use .svg)");
    fs::path tmp = fs::temp_directory_path() / ("bestiary-plot-" + std::to_string(::getpid()));
    fs::create_directories(tmp);
    if (Status s = write_file_atomic((tmp / "plot.svg").string(), svg); !s) return fail(s.error());
    std::string png = a.out + ".tmp.png";
    Ended end = run({*chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                     "--disable-background-networking", "--disable-component-update", "--disable-sync",
                     "--hide-scrollbars", "--user-data-dir=" + (tmp / "profile").string(),
                     "--window-size=" + std::to_string(a.width) + "," + std::to_string(a.height),
                     "--screenshot=" + png, "file://" + (tmp / "plot.svg").string()},
                    [](const std::string&) {});
    fs::remove_all(tmp);
    if (end.code != 0 || !fs::exists(png)) {
      fs::remove(png);
      return fail("plot: chromium failed to render the PNG: " + end.last_err);
    }
    fs::rename(png, a.out);
  }
  std::printf("%s -> %s\n", what.c_str(), a.out.c_str());
  return 0;
}

void add_watch_commands(CLI::App& app) {
  // arguments live as long as the app: parsing fills them, the callback reads them
  static WatchArgs show, render;
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

  auto* r = app.add_subcommand("render", "Simulate a genome and make a video of it (mp4 or gif)");
  add_creature_options(r, render.genome, render.flags);
  add_trial_option(r, render.flags);
  r->add_option("--out", render.out, "Video file to write: .mp4 or .gif")->required();
  r->add_option("--width", render.width, "Width in pixels")->default_val(1280);
  r->add_option("--height", render.height, "Height in pixels")->default_val(720);
  r->add_option("--fps", render.fps, "Frames per second (default 30 for mp4, 15 for gif)");
  r->add_flag("--quiet", render.quiet, "No progress output");
  r->callback([] { std::exit(cmd_render(render)); });

  static WatchArgs plot;
  auto* p = app.add_subcommand("plot", "Plot a run's best, mean and median fitness (or its task's metrics) per "
                                       "generation, or compare several runs");
  p->add_option("run_dir", plot.genome, "Run directory")->required();
  p->add_option("more_runs", plot.more_runs,
                "More run directories: each run's (or each condition's median) best and mean on one chart");
  p->add_option("--group-by", plot.group_by,
                "Compare conditions: runs with the same preset (\"preset\") or the same value of a config key "
                "(section.key) are one, drawn as the median over its runs with the interquartile band of the best");
  p->add_option("--out", plot.out, "Image to write: .svg or .png")->required();
  p->add_option("--width", plot.width, "Width in pixels")->default_val(800);
  p->add_option("--height", plot.height, "Height in pixels")->default_val(500);
  p->add_option("--metric", plot.metrics,
                "Instead of fitness, the share of each generation's evaluations in which each task metric whose name "
                "contains this was not 0 (repeatable; e.g. \"completed\": each level a task counts as completed); "
                "a metric not always 0 or 1 is drawn as its mean over those evaluations; several runs: each condition's "
                "median with its interquartile band");
  p->callback([] { std::exit(cmd_plot(plot)); });
}

}  // namespace bx
