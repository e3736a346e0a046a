// Watching a creature: `show` and `render` simulate it exactly as `simulate`
// does (same loading, config overlay, development and evaluation), with a
// replay of each trial watched, for the viewer's page (docs/viewer.md).
#pragma once

#include <string>
#include <vector>

#include "cli/creature.h"
#include "core/result.h"
#include "eval/evaluate.h"
#include "io/html_view.h"

namespace bx {

/// What simulating gave: the page's entry and the result.
struct Watched {
  LabelledReplay entry;  ///< labelled with the creature alone (its trial: trial_text)
  EvalResult result;
};

/// Develops and simulates `c` with a replay of each of the trials `trials`
/// names, as `simulate --replay` does, in one evaluation: the trial --trial
/// chose (else the first) when `trials` is 0, else each of the first `trials`.
Result<std::vector<Watched>> simulate_watched(const Subject& c, int trials = 0);

/// Which of several trials a replay is, and what it set up (Task::describe):
/// ", trial 2 of 4: light at 135 degrees"; "" for a single trial.
std::string trial_text(const EvalResult& res);

/// The lines `simulate` prints of a result: settings, fitness, metrics, trial.
void print_result(const Subject& c, const EvalResult& res);

}  // namespace bx
