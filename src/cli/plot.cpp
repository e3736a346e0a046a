// `bestiary plot`: a run's fitness (or its task's metrics) over generations,
// or several runs compared as conditions (median and interquartile band): SVG
// written directly, PNG rendered from it by headless Chromium.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/child_process.h"
#include "cli/commands.h"
#include "core/files.h"
#include "core/text.h"
#include "io/fitness_plot.h"
#include "io/run_store.h"
#include "io/syllabus.h"
#include "run/run.h"

namespace bx {

namespace {

namespace fs = std::filesystem;

/// Arguments of `plot`.
struct PlotArgs {
  std::string run_dir;
  std::string out;
  int width = 800, height = 500;
  std::vector<std::string> metrics;    ///< the task's metrics whose names contain these, not fitness
  std::vector<std::string> more_runs;  ///< runs compared with the first
  std::string group_by;                ///< "preset" or a config key: runs of one value are one condition
};

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
int cmd_plot_runs(const PlotArgs& a, std::string& svg, std::string& what) {
  std::vector<std::string> dirs{a.run_dir};
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

// the chart to --out: SVG as it is, PNG through headless Chromium
int write_plot(const PlotArgs& a, const std::string& ext, const std::string& svg, const std::string& what) {
  if (Status s = make_parent_dir("--out", a.out); !s) return fail(s.error());
  if (ext == ".svg") {
    if (Status s = write_file_atomic(a.out, svg); !s) return fail(s.error());
  } else {
    auto chromium = find_chromium("plot", "for PNG output: Debian package chromium, or set BESTIARY_CHROMIUM; or use .svg");
    if (!chromium) return fail(chromium.error());
    fs::path tmp = fs::temp_directory_path() / ("bestiary-plot-" + std::to_string(::getpid()));
    fs::create_directories(tmp);
    if (Status s = write_file_atomic((tmp / "plot.svg").string(), svg); !s) return fail(s.error());
    std::string png = a.out + ".tmp.png";
    Ended end = run_program({*chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
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

int cmd_plot(const PlotArgs& a) {
  const std::string& dir = a.run_dir;
  std::string ext = ascii_lower(fs::path(a.out).extension().string());
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


}  // namespace

void add_plot_command(CLI::App& app) {
  static PlotArgs plot;
  auto* p = app.add_subcommand("plot", "Plot a run's best, mean and median fitness (or its task's metrics) per "
                                       "generation, or compare several runs");
  p->add_option("run_dir", plot.run_dir, "Run directory")->required();
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
