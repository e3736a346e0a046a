// The viewer page (docs/viewer.md): one self-contained HTML file that replays
// creatures in 3D in any browser, offline. Its template (three.js and the
// viewer's script and style, inlined) is built from viewer/src by
// viewer/build.mjs and linked into the binary; this file fills in the data.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/result.h"

namespace bx {

/// One creature the page can show.
struct LabelledReplay {
  std::string label;        ///< its name on the page ("walker", "generation 12 best")
  std::string replay_json;  ///< the replay as replay_to_string() writes it
};

/// Fitness of one generation of a run.
struct FitnessPoint {
  int gen = 0;
  double best = 0, mean = 0, median = 0;  ///< finite numbers
};

/// Which of the page's replays is the best creature of a generation.
struct GenerationBest {
  int gen = 0;
  int replay_index = 0;  ///< index into the page's replays
};

/// A run's fitness curves and the best creature of its generations: with
/// these the page draws the curves and lets the user pick a generation.
struct RunCurves {
  std::vector<FitnessPoint> generations;
  std::vector<GenerationBest> best_of_generation;
};

/// The page's data as JSON text:
/// {"replays": [{"label", "replay"}...], "run": null | {"generations": [{"gen",
/// "best", "mean", "median"}...], "best_of_generation": [{"gen", "replay_index"}...]}}.
std::string view_data_json(const std::vector<LabelledReplay>& replays,
                           const std::optional<RunCurves>& run);

/// The whole page with the data embedded. `replays` must not be empty, and
/// each replay_index must name one of them.
std::string make_view_html(const std::vector<LabelledReplay>& replays,
                           const std::optional<RunCurves>& run = std::nullopt);

/// Writes the page to `path` atomically.
Status save_view_html(const std::string& path, const std::vector<LabelledReplay>& replays,
                      const std::optional<RunCurves>& run = std::nullopt);

}  // namespace bx
