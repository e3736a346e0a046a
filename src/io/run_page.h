// The run page (docs/viewer.md): what `bestiary show RUN_DIR` puts in the
// viewer page of a run. Its context (preset, master seed, population,
// generations, per generation the failed and rejected counts), every
// generation's best, the first-parent lineage of each back to generation 0,
// and a bounded number of them re-simulated exactly as the run scored them:
// the overall best first (the page opens on it), then its lineage, then the
// generations' bests, then the other lineages.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/result.h"
#include "evolve/evolution.h"
#include "io/config.h"
#include "io/html_view.h"
#include "io/run_store.h"

namespace bx {

/// Most replays a run page holds: the quick preset's 10 s replays are about
/// 300 kB each, so its page stays near 12 MB at most.
inline constexpr int kRunPageReplays = 40;

/// The page's data: its replays and the run.
struct RunPage {
  std::vector<LabelledReplay> replays;
  RunView run;
};

/// Which of `members` to replay, at most `cap`, in order of priority: the
/// best, its lineage (`lineage`, best first), the generations' bests
/// (`bests`, in generation order), then the others. Each list is taken in an
/// order whose every prefix is spread evenly over it (its ends first), so a
/// cap keeps generation 0's ancestor and the last generation's best.
std::vector<std::int64_t> replay_choice(std::int64_t best, const std::vector<std::int64_t>& lineage,
                                        const std::vector<std::int64_t>& bests,
                                        const std::vector<std::int64_t>& others, int cap);

/// The page of the run in `store` (its directory `source`, config `cfg`,
/// master seed `master`), its creatures simulated with `sim` (the run's
/// simulation config, or one with another duration). Fails when no
/// generation is stored or the best cannot be grown.
Result<RunPage> gather_run_page(const RunStore& store, const std::string& source, const RunConfig& cfg,
                                const SimConfig& sim, std::uint64_t master, int cap = kRunPageReplays);

/// A stage of a run as its page takes it (io/syllabus.h's StageDef): its
/// node in the page's syllabus graph, and the config its creatures are
/// simulated on.
struct PageStage {
  std::string name;
  std::vector<std::string> uses;
  std::string group;
  SimConfig sim;  ///< its config's, or one with another duration
};

/// The same for a run of several stages (io/syllabus.h), `stages` all of
/// the syllabus's in order: each creature is simulated with its own stage's
/// sim (the stage its id was born in), the page's best is the last stage's
/// (their fitnesses measure different tasks), each replay's label names its
/// stage, and the run lists the stages (RunView::stages: where each begins
/// among the stored generations, its best so far). `cfg` is the first
/// stage's, for the page's context. Fails when the store's stages are not
/// the first of `stages`.
Result<RunPage> gather_run_page(const RunStore& store, const std::string& source, const RunConfig& cfg,
                                const std::vector<PageStage>& stages, std::uint64_t master,
                                int cap = kRunPageReplays);

}  // namespace bx
