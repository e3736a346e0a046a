#include "io/run_page.h"

#include <algorithm>
#include <cstddef>
#include <deque>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "eval/creature.h"
#include "eval/evaluate.h"
#include "genome/genotype_file.h"
#include "io/replay_file.h"

namespace bx {

namespace {

// indices 0..n-1, both ends first, then the middles of the gaps breadth
// first: every prefix is spread evenly
std::vector<std::size_t> spread_order(std::size_t n) {
  std::vector<std::size_t> out;
  if (n == 0) return out;
  out.push_back(0);
  if (n == 1) return out;
  out.push_back(n - 1);
  std::deque<std::pair<std::size_t, std::size_t>> gaps{{0, n - 1}};
  while (!gaps.empty()) {
    auto [lo, hi] = gaps.front();
    gaps.pop_front();
    if (hi - lo < 2) continue;
    std::size_t mid = lo + (hi - lo) / 2;
    out.push_back(mid);
    gaps.push_back({lo, mid});
    gaps.push_back({mid, hi});
  }
  return out;
}

// The stages as the page lists them: the syllabus's, each begun one with
// its generations among the stored ones (from its first_gen to the next
// begun stage's) and the fittest of their bests. An older database, without
// stages, is all stage 0.
Result<std::vector<RunStage>> stage_views(const std::vector<PageStage>& stages, const std::vector<StageRow>& begun,
                                          const std::vector<GenerationStats>& gens) {
  if (begun.size() > stages.size())
    return Error{"the run has begun " + std::to_string(begun.size()) + " stages, but its config has " +
                 std::to_string(stages.size())};
  std::vector<RunStage> out;
  for (std::size_t k = 0; k < stages.size(); ++k) {
    const PageStage& st = stages[k];
    if (k < begun.size() && begun[k].name != st.name)
      return Error{"the run's stage " + std::to_string(k + 1) + " is \"" + begun[k].name + "\", but its config's is \"" +
                   st.name + "\""};
    RunStage v{st.name, st.uses, st.group};
    if (k < begun.size() || (k == 0 && begun.empty())) {
      v.first_gen = k < begun.size() ? begun[k].first_gen : 0;
      const int end = k + 1 < begun.size() ? begun[k + 1].first_gen : std::numeric_limits<int>::max();
      for (const auto& g : gens) {
        if (g.generation < v.first_gen || g.generation >= end) continue;
        v.best = v.generations == 0 ? g.best : std::max(v.best, g.best);
        ++v.generations;
      }
    }
    out.push_back(std::move(v));
  }
  return out;
}

}  // namespace

std::vector<std::int64_t> replay_choice(std::int64_t best, const std::vector<std::int64_t>& lineage,
                                        const std::vector<std::int64_t>& bests,
                                        const std::vector<std::int64_t>& others, int cap) {
  std::vector<std::int64_t> out;
  std::set<std::int64_t> taken;
  auto take = [&](std::int64_t id) {
    if (static_cast<int>(out.size()) < cap && taken.insert(id).second) out.push_back(id);
  };
  take(best);
  for (const auto* list : {&lineage, &bests, &others})
    for (std::size_t i : spread_order(list->size())) take((*list)[i]);
  return out;
}

Result<RunPage> gather_run_page(const RunStore& store, const std::string& source, const RunConfig& cfg,
                                const SimConfig& sim, std::uint64_t master, int cap) {
  return gather_run_page(store, source, cfg, std::vector<PageStage>{{"", {}, "", sim}}, master, cap);
}

Result<RunPage> gather_run_page(const RunStore& store, const std::string& source, const RunConfig& cfg,
                                const std::vector<PageStage>& stages, std::uint64_t master, int cap) {
  auto gens = store.generations();
  const std::vector<StageRow> begun = store.stages();
  const bool staged = stages.size() > 1;
  const int last_stage_gen = begun.empty() ? 0 : begun.back().first_gen;
  if (gens.empty()) return Error{"no generation finished yet"};
  RunPage page;
  RunView& run = page.run;
  run.name = store.meta("name");
  run.seed = std::to_string(master);
  run.dialect = evolved_name(cfg);
  run.algorithm = cfg.evolution.algorithm == Algorithm::Generational ? "generational" : "steady state";
  run.evaluation_score = score_name(cfg.sim.trial_score);
  run.evaluation_half_step = cfg.evolution.elite_half_step;
  run.evaluation_quarter_step = cfg.evolution.elite_quarter_step;
  run.population = cfg.evolution.population;
  run.planned_generations = total_generations(cfg.evolution);
  run.replay_cap = cap;
  if (staged) {
    auto views = stage_views(stages, begun, gens);
    if (!views) return Error{views.error()};
    run.stages = std::move(*views);
  }
  // the overall best: the fittest generation best, the earliest on a tie
  // (of the last stage's generations: a stage's fitness is its own task's)
  const GenerationStats* top = nullptr;
  for (const auto& g : gens) {
    run.generations.push_back({g.generation, g.best, g.mean, g.median, g.best_id, g.evaluations, g.rejected,
                               g.failed});
    if (g.generation >= last_stage_gen && (!top || g.best > top->best)) top = &g;
  }
  if (!top) top = &gens.back();
  run.best_id = top->best_id;

  // the members: each generation's best and its first parents back to
  // generation 0. The first parent, because the child is its copy (mutated,
  // or with the second parent's nodes spliced in: crossover's from the cut
  // on, a graft's branch); following it gives one line of descent, where
  // both parents would give a tree that doubles each generation back.
  std::map<std::int64_t, Individual> members;
  auto lineage = [&](std::int64_t id) -> Result<std::vector<std::int64_t>> {
    std::vector<std::int64_t> chain;
    for (std::int64_t at = id; at >= 0;) {
      auto it = members.find(at);
      if (it == members.end()) {
        auto ind = store.individual(at);
        if (!ind) return Error{ind.error()};
        it = members.emplace(at, std::move(*ind)).first;
      }
      if (at != id) chain.push_back(at);
      at = it->second.parent1;
    }
    return chain;
  };
  auto best_line = lineage(run.best_id);
  if (!best_line) return Error{best_line.error()};
  std::vector<std::int64_t> bests, others;
  std::set<std::int64_t> named(best_line->begin(), best_line->end());
  named.insert(run.best_id);
  for (const auto& g : gens)
    if (bests.empty() || bests.back() != g.best_id) bests.push_back(g.best_id);
  for (auto b = bests.rbegin(); b != bests.rend(); ++b) {
    auto line = lineage(*b);
    if (!line) return Error{line.error()};
    for (std::int64_t id : *line)
      if (named.insert(id).second) others.push_back(id);
  }

  // the replays, each simulated as the run scored it: its config and seed
  std::map<std::int64_t, int> replay_of;
  for (std::int64_t id : replay_choice(run.best_id, *best_line, bests, others, cap)) {
    const Individual& ind = members.at(id);
    const StageRow stage = stage_of(begun, id);
    if (stage.index >= static_cast<int>(stages.size()))
      return Error{"individual " + std::to_string(id) + " is of stage " + std::to_string(stage.index + 1) +
                   ", but the run's config has " + std::to_string(stages.size())};
    const SimConfig& sim = stages[stage.index].sim;
    auto creature = develop_creature(*ind.genotype, sim);
    if (!creature) continue;  // not viable
    Replay replay;
    std::uint64_t seed = ind.seed;  // the seed stored with it
    EvalResult res = evaluate(*creature, sim, seed, &replay);
    ReplayInfo info{source + " individual " + std::to_string(id), seed, sim.physics.dt, sim.physics.friction,
                    replay_creature(sim)};
    replay_of[id] = static_cast<int>(page.replays.size());
    page.replays.push_back({"individual " + std::to_string(id) + ", generation " + std::to_string(ind.generation) +
                                (staged ? ", stage " + stage.name : ""),
                            replay_to_string(*creature->body, replay, res, info), genotype_text(*ind.genotype)});
  }
  if (!replay_of.count(run.best_id))
    return Error{"the best, individual " + std::to_string(run.best_id) + ", cannot be developed"};
  // the best's held-out measure, where the run made one
  auto held = store.held_out();
  if (!held) return Error{held.error()};
  for (const auto& [id, ind] : members) {
    auto r = replay_of.find(id);
    run.members.push_back({id, ind.generation, ind.fitness, ind.parent1, ind.parent2, ind.op,
                           r == replay_of.end() ? -1 : r->second, ind.evaluations});
    if (*held && (*held)->id == id) {
      run.members.back().held_out = (*held)->fitness;
      run.members.back().held_out_evaluations = static_cast<int>((*held)->by_seed.size());
    }
  }
  return page;
}

}  // namespace bx
