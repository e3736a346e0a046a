// The viewer page (docs/viewer.md): one self-contained HTML file that replays
// creatures in 3D in any browser, offline. Its template (three.js and the
// viewer's script and style, inlined) is built from viewer/src by
// viewer/build.mjs and linked into the binary; this file fills in the data.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"

namespace bx {

/// One creature the page can show.
struct LabelledReplay {
  std::string label;        ///< its name on the page ("walker", "individual 12, generation 3")
  std::string replay_json;  ///< the replay as replay_to_string() writes it
  std::string genome = {};  ///< its genome file's text, for the page's download button ("": none)
};

/// One generation of a run (steady state: one report interval).
struct RunGeneration {
  int gen = 0;
  double best = 0, mean = 0, median = 0;  ///< finite numbers
  std::int64_t best_id = -1;
  long evaluations = 0;  ///< cumulative, at its end
  long rejected = 0;     ///< non-viable children redrawn during it
  long failed = 0;       ///< evaluations that crashed, timed out or blew up
};

/// An individual of a run that the page names: a generation's best or an
/// ancestor of one.
struct RunMember {
  std::int64_t id = -1;
  int gen = 0;           ///< the generation it was born in
  double fitness = 0;    ///< as stored by the run
  std::int64_t parent1 = -1, parent2 = -1;
  std::string op;        ///< the operator that made it
  int replay_index = -1; ///< its replay on the page, or -1 when it was not re-simulated
  int evaluations = 1;   ///< how many evaluations `fitness` folds (RunView::evaluation_score); its replay is the first
  /// The run's held-out measure of it (evolution.held_out_evaluations: the
  /// best, evaluated under seeds the run never used): their fold and how
  /// many; held_out_evaluations 0: none.
  double held_out = 0;
  int held_out_evaluations = 0;
};

/// A stage of a run of several (io/syllabus.h): a node of the page's
/// syllabus graph, and where its own fitness curve lies among the run's
/// generations (each stage's fitness measures its own task).
struct RunStage {
  std::string name;
  std::vector<std::string> uses;  ///< earlier stages whose skills it builds on: the graph's edges
  std::string group;              ///< its pandemonium group ("": none)
  int first_gen = -1;             ///< the run's generation number of its generation 0; -1: not begun
  int generations = 0;            ///< its generations stored so far: first_gen on
  double best = 0;                ///< the fittest of their bests (when generations > 0)
};

/// A run as its page shows it: where it came from, its generations, the
/// individuals it names, and which is the overall best (the page opens on it).
struct RunView {
  std::string name;     ///< the preset or config file it was made from
  std::string seed;     ///< the master seed, as text (64 bits do not fit a JavaScript number)
  std::string dialect, algorithm;
  /// How a member's evaluations make its stored fitness: "mean" or "least"
  /// (task.trial_score; score_name).
  std::string evaluation_score = "mean";
  /// Whether a member's evaluations cycled through physics.dt, half of it
  /// and a quarter of it (evolution.elite_half_step, elite_quarter_step;
  /// repeat_step_divisor).
  bool evaluation_half_step = false;
  bool evaluation_quarter_step = false;
  int population = 0;
  int planned_generations = 0;  ///< generations (report intervals) it has when finished
  std::vector<RunGeneration> generations;
  std::vector<RunMember> members;
  std::int64_t best_id = -1;    ///< must be a member with a replay
  int replay_cap = 0;           ///< most replays the page holds
  std::vector<RunStage> stages; ///< a run of several stages: all of them, in order; else none
  /// `show RUN --watch`: where the run stood when the page was made (its
  /// server answers /stamp with where it stands now: the page reloads when
  /// they differ) and how often the page asks (s); empty: not watched.
  std::string watch_stamp;
  double watch_every = 0;
};

/// The page's data as JSON text:
/// {"replays": [{"label", "replay", "genome"?}...], "run": null | {"name", "seed",
/// "dialect", "algorithm", "evaluation_score", "evaluation_half_step",
/// "evaluation_quarter_step", "population", "planned_generations", "generations":
/// [{"gen", "best", "mean", "median", "best_id", "evaluations", "rejected",
/// "failed"}...], "members": [{"id", "gen", "fitness", "parent1", "parent2"
/// (null when none), "operator", "replay_index" (null when none),
/// "evaluations", "held_out"?: {"fitness", "evaluations"}}...], "best_id", "replay_cap", "stages"?: [{"name", "uses",
/// "group", "first_gen" (null when not begun), "generations", "best" (null
/// when not begun)}...], "watch"?: {"stamp", "every"}}}; "stages" only for a
/// run of several, "watch" only for a watched one. docs/viewer.md
/// describes it.
std::string view_data_json(const std::vector<LabelledReplay>& replays,
                           const std::optional<RunView>& run);

/// The whole page with the data embedded. `replays` must not be empty, and
/// each replay_index must name one of them.
std::string make_view_html(const std::vector<LabelledReplay>& replays,
                           const std::optional<RunView>& run = std::nullopt);

/// Writes the page to `path` atomically.
Status save_view_html(const std::string& path, const std::vector<LabelledReplay>& replays,
                      const std::optional<RunView>& run = std::nullopt);

}  // namespace bx
