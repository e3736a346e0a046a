#include "cli/watch.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "eval/task_table.h"
#include "genome/genotype_file.h"
#include "io/replay_file.h"

namespace bx {

namespace fs = std::filesystem;

Result<std::vector<Watched>> simulate_watched(const Subject& c, int trials) {
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

}  // namespace bx
