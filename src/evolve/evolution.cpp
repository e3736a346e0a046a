#include "evolve/evolution.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <map>
#include <set>

#include <cassert>

#include "core/rng.h"
#include "core/text.h"

namespace bx {

namespace {

// purposes of the random streams, so no two uses share one
enum Stream : std::uint64_t { kInitial = 1, kBreed = 2, kTournament = 3, kEvaluation = 4 };

bool better(const Individual& a, const Individual& b) { return ranks_before(a, b); }

// the fitness an evaluation gives, failures at `failed_fitness` and counted
double outcome_fitness(const EvalOutcome& o, double failed_fitness, long& failed) {
  if (!o.viable || o.result.failed) {
    ++failed;
    return failed_fitness;
  }
  return o.result.fitness;
}

}  // namespace

// better first; equal fitness: older first (deterministic); one not yet
// evaluated (tournament_evaluates = all) after every evaluated one
bool ranks_before(const Individual& a, const Individual& b) {
  if ((a.evaluations == 0) != (b.evaluations == 0)) return b.evaluations == 0;
  if (a.fitness != b.fitness) return a.fitness > b.fitness;
  return a.id < b.id;
}

std::size_t select_survivor(const std::vector<Individual>& survivors, Selection how, Rng& rng) {
  std::size_t n = survivors.size();
  if (how == Selection::Uniform || n == 1) return rng.below(n);
  std::vector<double> w(n);
  if (how == Selection::Rank) {
    for (std::size_t i = 0; i < n; ++i) w[i] = static_cast<double>(n - i);
  } else {
    // fitness-proportionate, shifted so the worst survivor still has a small chance
    double lo = survivors.back().fitness, hi = survivors.front().fitness;
    double floor = hi > lo ? (hi - lo) * 0.01 : 1.0;
    for (std::size_t i = 0; i < n; ++i) w[i] = survivors[i].fitness - lo + floor;
  }
  double r = rng.uniform() * std::accumulate(w.begin(), w.end(), 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    r -= w[i];
    if (r < 0) return i;
  }
  return n - 1;
}

int total_generations(const EvolutionDef& evo) {
  if (evo.algorithm == Algorithm::Generational) return evo.generations;
  long every = evo.report_every > 0 ? evo.report_every : evo.population;
  return 1 + static_cast<int>((evo.evaluations + every - 1) / every);
}

Status check_breeding(const EvolutionDef& evo, const GenotypeOps& ops) {
  if (evo.p_graft > 0 && !ops.can_graft())
    return Error{"evolution.p_graft = " + nlohmann::json(evo.p_graft).dump() + ": genotypes of kind " +
                 std::string(ops.kind()) + " have no grafting (give its share to p_asexual or p_crossover)"};
  return Ok{};
}

Evolution::Evolution(std::shared_ptr<const GenotypeOps> ops, EvolutionDef evo, std::uint64_t seed,
                     TrialScore fold, int task, std::vector<Individual> founders, std::vector<Retest> retests)
    : ops_(std::move(ops)),
      evo_(evo),
      seed_(seed),
      fold_(fold),
      task_(task),
      founders_(std::move(founders)),
      retests_(std::move(retests)) {
  assert(ops_ && check_breeding(evo_, *ops_).ok());
  // a tournament's fresh evaluations would have to retest each time: not supported
  assert(retests_.empty() || evo_.algorithm == Algorithm::Generational ||
         evo_.tournament_evaluates == TournamentEvaluates::Child);
}

bool failed_retest(const Individual& ind) { return ind.failure.rfind(kRetestFailure, 0) == 0; }

bool Evolution::finished(const EvolutionDef& evo, const EvolutionState& s) {
  if (evo.algorithm == Algorithm::Generational) return s.generation + 1 >= evo.generations;
  // the budget counts creatures born (tournaments); elites evaluated again cost extra
  return s.generation >= 0 && s.next_id - s.first_id >= evo.population + evo.evaluations;
}

int Evolution::total_generations() const { return bx::total_generations(evo_); }

std::uint64_t evaluation_seed(std::uint64_t seed, std::int64_t id) {
  return stream_seed({seed, kEvaluation, static_cast<std::uint64_t>(id)});
}

std::uint64_t Evolution::eval_seed(std::int64_t id) const { return evaluation_seed(seed_, id); }

// redraws a non-viable child until it is viable; past the limit, a random genome
Result<Evolution::Child> Evolution::viable(Child c, Rng& rng, long& rejected,
                                           const std::function<Child(Rng&)>& remake) const {
  for (int tries = 0; !ops_->viable(*c.genotype); ++tries) {
    rejected_one(rejected);
    if (tries < evo_.max_regenerations) {
      c = remake(rng);
      continue;
    }
    auto r = random_child(rng, rejected);
    if (!r) return r;
    c = std::move(*r);
  }
  return c;
}

// the algorithm's asexual child of `a`
Evolution::Child Evolution::mutant(const Individual& a, Rng& r) const {
  for (int tries = 0;; ++tries) {
    Child c{a.genotype, a.id, -1, "mutation"};
    if (evo_.algorithm == Algorithm::Generational) {
      c.genotype = ops_->mutate(*a.genotype, evo_.asexual_rate, r);
    } else {
      for (int m = 0; m < evo_.asexual_mutations; ++m) c.genotype = ops_->mutate(*c.genotype, evo_.mutation_rate, r);
    }
    if (tries >= evo_.max_regenerations || !copies_parent(c, *a.genotype)) return c;
  }
}

bool Evolution::copies_parent(const Child& c, const Genotype& a, const Genotype* b) const {
  return evo_.distinct_children && (c.genotype->equals(a) || (b && b != &a && c.genotype->equals(*b)));
}

Result<Evolution::Child> Evolution::random_child(Rng& rng, long& rejected) const {
  // random genomes are redrawn until viable, up to max_random_redraws in a
  // row: past it, none may ever be (a config that no body meets), and the
  // reason most of them gave says why (reasons alike but for their numbers
  // counted as one)
  std::map<std::string, std::pair<long, std::string>> reasons;
  const int bound = std::max(1, evo_.max_random_redraws);
  for (int draws = 0; draws < bound; ++draws) {
    Child c{ops_->random(rng), -1, -1, "random"};
    const Status v = ops_->viable(*c.genotype);
    if (v) return c;
    rejected_one(rejected);
    std::string words;
    for (char ch : v.error())
      if (ch < '0' || ch > '9') words += ch;
    auto& [n, example] = reasons[words];
    if (n++ == 0) example = v.error();
  }
  const auto most = std::max_element(reasons.begin(), reasons.end(),
                                     [](const auto& x, const auto& y) { return x.second.first < y.second.first; });
  return Error{"no creature is viable: " + std::to_string(bound) +
               " random genotypes in a row were not (evolution.max_random_redraws); " +
               std::to_string(most->second.first) + " of them: " + one_line(most->second.second, 300)};
}

// a child given its id, generation and seed, not yet evaluated
Individual Evolution::unevaluated(Child c, EvolutionState& s) const {
  Individual ind;
  ind.id = s.next_id++;
  ind.genotype = std::move(c.genotype);
  ind.parent1 = c.parent1;
  ind.parent2 = c.parent2;
  ind.op = c.op;
  ind.generation = s.generation + 1;
  ind.seed = eval_seed(ind.id);
  ind.evaluations = 0;
  return ind;
}

std::vector<Individual> Evolution::evaluate(std::vector<Child> children, EvolutionState& s,
                                            Evaluator& eval, long& failed, MetricTally& tally) const {
  std::vector<Individual> born(children.size());
  // each child's own task, then its retests (General ESP), all in one batch
  const std::size_t per = 1 + retests_.size();
  std::vector<EvalJob> jobs(children.size() * per);
  for (std::size_t k = 0; k < children.size(); ++k) {
    born[k] = unevaluated(std::move(children[k]), s);
    born[k].evaluations = 1;
    jobs[k * per] = {born[k].genotype.get(), born[k].seed, 1, task_};
    for (std::size_t t = 0; t < retests_.size(); ++t)
      jobs[k * per + 1 + t] = {born[k].genotype.get(), retests_[t].seed, 1, retests_[t].task};
  }
  std::vector<EvalOutcome> out = eval.evaluate(jobs);
  for (std::size_t k = 0; k < born.size(); ++k) {
    Individual& ind = born[k];
    const EvalOutcome& own = out[k * per];
    const EvalResult& r = own.result;
    std::vector<Metric> metrics = own.viable && !r.failed ? r.metrics : std::vector<Metric>{};
    std::string fell;  // the first retest it fell below
    for (std::size_t t = 0; t < retests_.size(); ++t) {
      const EvalOutcome& o = out[k * per + 1 + t];
      const bool ok = o.viable && !o.result.failed;
      const double f = ok ? o.result.fitness : 0;
      metrics.push_back({std::string(kRetestFailure) + retests_[t].skill, f});
      if (fell.empty() && (!ok || f < retests_[t].least))
        fell = std::string(kRetestFailure) + retests_[t].skill + ": " +
               (ok ? g_number(f) : "failed (" + (o.viable ? o.result.failure : o.reason) + ")") + " < " +
               g_number(retests_[t].least);
    }
    tally.add(own.viable && !r.failed ? metrics : std::vector<Metric>{});
    if (!own.viable) {
      ind.failure = "not viable: " + out[k].reason;
      ind.fitness = evo_.failed_fitness;
      ++failed;
    } else if (r.failed) {
      ind.failure = r.failure;
      ind.fitness = evo_.failed_fitness;
      ++failed;
    } else if (!fell.empty()) {
      // lessin2015 Algorithm 1: "set individual fitness to 0"
      ind.fitness = 0;
      ind.distance = r.distance;
      ind.failure = fell;
    } else {
      ind.fitness = r.fitness;
      ind.distance = r.distance;
      ind.failure = r.note;
    }
  }
  s.evaluations += static_cast<long>(jobs.size());
  return born;
}

Repeats elite_repeats(const EvolutionDef& evo, int evaluations) {
  return {evaluations, evo.failed_fitness, evo.elite_half_step, evo.elite_quarter_step};
}

int Evolution::elite_count(int n) const {
  return std::clamp(static_cast<int>(std::lround(evo_.elite_fraction * n)), 1, n);
}

// The elite that will survive into the next generation (steady state: the
// best elite_fraction at the end of a report interval), each evaluated again
// under a fresh seed until it has elite_evaluations, its fitness their mean or
// least (fold_: task.trial_score); one whose score falls out of the elite
// makes room for the next, evaluated in turn. Then the best, once it has
// elite_evaluations, is evaluated until it has best_evaluations (all at
// once, or with best_evaluations_doubling in rounds that double its count);
// if it falls, the next best is, until the best has them.
// Returns the individuals born in earlier steps that were evaluated again;
// those born in this step are updated in `born`.
std::vector<Individual> Evolution::reevaluate_elite(EvolutionState& s, Evaluator& eval, long& failed,
                                                    std::vector<Individual>& born) const {
  const int best_target = std::max(evo_.elite_evaluations, evo_.best_evaluations);
  if (best_target <= 1) return {};
  const int n = static_cast<int>(s.population.size());
  const int elite = elite_count(n);
  const Repeats repeats = elite_repeats(evo_, best_target);  // which evaluations step finer
  std::set<int> touched;
  // Evaluations made ahead, by (member, evaluation index): workers a round
  // leaves idle evaluate what later rounds may need (the elite's remaining
  // evaluations, then those of the members ranked next, which enter the
  // elite when one falls). An evaluation is a pure function of its job, so
  // whether it was made ahead changes nothing but the rounds' count: only
  // those a round uses count, and the run is the same for any width.
  std::map<std::pair<int, int>, EvalOutcome> ahead;
  auto job = [&](int i, int e) {
    const Individual& ind = s.population[i];
    return EvalJob{ind.genotype.get(), repeat_seed(ind.seed, e), repeat_step_divisor(repeats, e), task_};
  };
  for (;;) {
    // the members in rank order, sorted only as deep as a loop below reads
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    int ranked = 0;
    auto rank_to = [&](int depth) {
      depth = std::min(depth, n);
      if (depth <= ranked) return;
      std::partial_sort(order.begin() + ranked, order.begin() + depth, order.end(),
                        [&](int x, int y) { return better(s.population[x], s.population[y]); });
      ranked = depth;
    };
    rank_to(std::max(elite, 1));
    // each due individual with how many evaluations it gets in this round
    std::vector<std::pair<int, int>> due;
    // (not one that fell below a retest: its 0 stands)
    for (int k = 0; k < elite; ++k)
      if (s.population[order[k]].evaluations < evo_.elite_evaluations && !failed_retest(s.population[order[k]]))
        due.push_back({order[k], 1});
    if (due.empty() && s.population[order[0]].evaluations < best_target && !failed_retest(s.population[order[0]])) {
      const int has = s.population[order[0]].evaluations, left = best_target - has;
      due.push_back({order[0], evo_.best_evaluations_doubling ? std::min(left, std::max(1, has)) : left});
    }
    if (due.empty()) break;
    std::vector<EvalJob> jobs;
    std::vector<std::pair<int, int>> keys;  // (member, evaluation) of each job
    std::set<std::pair<int, int>> asked;    // the same, to look up
    auto ask = [&](int i, int e) {
      jobs.push_back(job(i, e));
      keys.push_back({i, e});
      asked.insert({i, e});
    };
    for (auto [i, count] : due)
      for (int e = s.population[i].evaluations; e < s.population[i].evaluations + count; ++e)
        if (!ahead.count({i, e})) ask(i, e);
    // idle workers (in a round that needs a call at all): in rank order,
    // each member's evaluations up to the elite's (the best: up to
    // best_target) not yet made or asked for
    const std::size_t width = jobs.empty() ? 0 : static_cast<std::size_t>(std::max(1, eval.workers()));
    for (int k = 0; k < n && jobs.size() < width; ++k) {
      if (k >= ranked) rank_to(k + static_cast<int>(width - jobs.size()));
      const int i = order[k];
      if (failed_retest(s.population[i])) continue;
      const int target = k == 0 ? best_target : evo_.elite_evaluations;
      for (int e = s.population[i].evaluations; e < target && jobs.size() < width; ++e)
        if (!ahead.count({i, e}) && !asked.count({i, e})) ask(i, e);
    }
    std::vector<EvalOutcome> out = jobs.empty() ? std::vector<EvalOutcome>{} : eval.evaluate(jobs);
    for (std::size_t k = 0; k < out.size(); ++k) ahead[keys[k]] = std::move(out[k]);
    for (auto [i, count] : due) {
      Individual& ind = s.population[i];
      for (int c = 0; c < count; ++c) {
        auto made = ahead.find({i, ind.evaluations});
        const double f = outcome_fitness(made->second, evo_.failed_fitness, failed);
        ahead.erase(made);
        ind.fitness = fold_score(fold_, ind.fitness, ind.evaluations, f);
        ++ind.evaluations;
        ++s.evaluations;
      }
      touched.insert(i);
    }
  }
  std::vector<Individual> earlier;
  for (int i : touched) {
    const Individual& ind = s.population[i];
    auto b = std::find_if(born.begin(), born.end(), [&](const Individual& x) { return x.id == ind.id; });
    if (b != born.end()) *b = ind;
    else earlier.push_back(ind);
  }
  std::sort(earlier.begin(), earlier.end(), [](const Individual& a, const Individual& b) { return a.id < b.id; });
  return earlier;
}

GenerationStats Evolution::stats(const EvolutionState& s) const {
  GenerationStats st;
  st.generation = s.generation;
  st.evaluations = s.evaluations;
  std::vector<double> f;
  for (const auto& ind : s.population)
    if (ind.evaluations > 0) f.push_back(ind.fitness);
  if (f.empty()) return st;
  auto best = std::min_element(s.population.begin(), s.population.end(), better);
  st.best = best->fitness;
  st.best_id = best->id;
  st.mean = std::accumulate(f.begin(), f.end(), 0.0) / static_cast<double>(f.size());
  std::sort(f.begin(), f.end());
  std::size_t n = f.size();
  st.median = n % 2 ? f[n / 2] : 0.5 * (f[n / 2 - 1] + f[n / 2]);
  return st;
}

Result<GenerationResult> Evolution::step(EvolutionState& s, Evaluator& eval) const {
  if (s.generation < 0) return initial(s, eval);
  return evo_.algorithm == Algorithm::Generational ? generational(s, eval) : steady_state(s, eval);
}

Result<GenerationResult> Evolution::initial(EvolutionState& s, Evaluator& eval) const {
  long rejected = 0, failed = 0;
  std::vector<Child> children;
  const int n = static_cast<int>(founders_.size());
  for (int k = 0; k < evo_.population; ++k) {
    Rng rng(stream_seed({seed_, kInitial, static_cast<std::uint64_t>(k)}));
    if (n == 0) {
      auto c = random_child(rng, rejected);
      if (!c) return Error{c.error()};
      children.push_back(std::move(*c));
      continue;
    }
    const Individual& f = founders_[k % n];
    auto make = [&](Rng& r) { return mutant(f, r); };
    // a founder as it is (a stage's tasks may refuse a body the last took:
    // then its mutants); one without an id was read from a file
    auto c = k < n ? viable(Child{f.genotype, f.id, -1, f.id >= 0 ? "copy" : "file"}, rng, rejected, make)
                   : viable(make(rng), rng, rejected, make);
    if (!c) return Error{c.error()};
    children.push_back(std::move(*c));
  }
  GenerationResult res;
  MetricTally tally;
  res.born = evaluate(std::move(children), s, eval, failed, tally);
  s.population = res.born;
  res.reevaluated = reevaluate_elite(s, eval, failed, res.born);
  s.generation = 0;
  res.stats = stats(s);
  res.stats.metrics = tally.stats();
  res.stats.rejected = rejected;
  res.stats.failed = failed;
  return res;
}

Result<GenerationResult> Evolution::generational(EvolutionState& s, Evaluator& eval) const {
  const int g = s.generation + 1;
  // the best survive
  std::vector<Individual> sorted = s.population;
  std::sort(sorted.begin(), sorted.end(), better);
  int n = static_cast<int>(sorted.size());
  int elite = elite_count(n);
  std::vector<Individual> survivors(sorted.begin(), sorted.begin() + elite);

  // the rest are children of survivors: asexual, crossover or grafting
  long rejected = 0, failed = 0;
  std::vector<Child> children;
  for (int k = 0; k < evo_.population - elite; ++k) {
    Rng rng(stream_seed({seed_, kBreed, static_cast<std::uint64_t>(g), static_cast<std::uint64_t>(k)}));
    auto make = [&](Rng& r) {
      for (int tries = 0;; ++tries) {
        const Individual& a = survivors[select_survivor(survivors, evo_.selection, r)];
        double u = r.uniform();
        if (u < evo_.p_asexual) return mutant(a, r);
        const Individual& b = survivors[select_survivor(survivors, evo_.selection, r)];
        bool cross = u < evo_.p_asexual + evo_.p_crossover;
        Child c{cross ? ops_->crossover(*a.genotype, *b.genotype, r) : ops_->graft(*a.genotype, *b.genotype, r),
                a.id, b.id, cross ? "crossover" : "graft"};
        if (r.chance(evo_.sexual_mutation_chance)) c.genotype = ops_->mutate(*c.genotype, evo_.sexual_rate, r);
        // a copy of a parent is made again, parents and operator drawn anew (distinct_children)
        if (tries >= evo_.max_regenerations || !copies_parent(c, *a.genotype, b.genotype.get())) return c;
      }
    };
    auto c = viable(make(rng), rng, rejected, make);
    if (!c) return Error{c.error()};
    children.push_back(std::move(*c));
  }

  GenerationResult res;
  MetricTally tally;
  res.born = evaluate(std::move(children), s, eval, failed, tally);
  s.population = std::move(survivors);
  s.population.insert(s.population.end(), res.born.begin(), res.born.end());
  res.reevaluated = reevaluate_elite(s, eval, failed, res.born);
  s.generation = g;
  res.stats = stats(s);
  res.stats.metrics = tally.stats();
  res.stats.rejected = rejected;
  res.stats.failed = failed;
  return res;
}

std::vector<Individual> migrate(std::vector<Individual>& population, int islands, std::int64_t& next_id,
                                int generation) {
  const int isle = static_cast<int>(population.size()) / islands;
  auto begin = [&](int k) { return population.begin() + k * isle; };
  std::vector<Individual> migrants;
  for (int k = 0; k < islands; ++k) {
    Individual m = *std::min_element(begin(k), begin(k + 1), ranks_before);
    m.parent1 = m.id;
    m.parent2 = -1;
    m.id = next_id++;
    m.op = "migrant";
    m.generation = generation;
    migrants.push_back(std::move(m));
  }
  for (int k = 0; k < islands; ++k) {
    const int to = (k + 1) % islands;
    // the last in rank among the evaluated (ranks_before puts the unevaluated last)
    auto worst = std::max_element(begin(to), begin(to + 1), [](const Individual& a, const Individual& b) {
      if ((a.evaluations == 0) != (b.evaluations == 0)) return a.evaluations == 0;
      return ranks_before(a, b);
    });
    *worst = migrants[k];
  }
  return migrants;
}

// Evaluates the population members `members` (tournament_evaluates = all),
// each afresh under the seed of its next evaluation and at the step that
// evaluation takes (repeat_step_divisor: with elite_half_step its 2nd, 4th,
// ... at dt/2, as the elite's and the best's repeats, so `simulate` and
// `check` reproduce a fitness of any count): `fresh` gets each one's fitness
// in this evaluation, its own fitness folds it in, and `evaluated` gets it as
// it then stands.
void Evolution::tournaments(EvolutionState& s, Evaluator& eval, std::vector<int> members, std::vector<double>& fresh,
                            long& failed, MetricTally& tally, std::vector<Individual>& evaluated) const {
  const Repeats repeats = elite_repeats(evo_, 0);  // which evaluations step finer
  std::vector<EvalJob> jobs;
  for (int i : members) {
    const Individual& ind = s.population[i];
    jobs.push_back({ind.genotype.get(), repeat_seed(ind.seed, ind.evaluations),
                    repeat_step_divisor(repeats, ind.evaluations), task_});
  }
  std::vector<EvalOutcome> out = eval.evaluate(jobs);
  fresh.assign(s.population.size(), 0.0);
  for (std::size_t k = 0; k < members.size(); ++k) {
    Individual& ind = s.population[members[k]];
    const double f = outcome_fitness(out[k], evo_.failed_fitness, failed);
    tally.add(out[k].viable && !out[k].result.failed ? out[k].result.metrics : std::vector<Metric>{});
    if (ind.evaluations == 0) {  // its first: the one a replay shows
      ind.distance = out[k].viable ? out[k].result.distance : 0;
      ind.failure = !out[k].viable ? "not viable: " + out[k].reason
                    : out[k].result.failed ? out[k].result.failure : out[k].result.note;
    }
    ind.fitness = fold_score(fold_, ind.fitness, ind.evaluations, f);
    ++ind.evaluations;
    fresh[members[k]] = f;
    evaluated.push_back(ind);
  }
  s.evaluations += static_cast<long>(jobs.size());
}

Result<GenerationResult> Evolution::steady_state(EvolutionState& s, Evaluator& eval) const {
  const long every = evo_.report_every > 0 ? evo_.report_every : evo_.population;
  const long total = s.first_id + evo_.population + evo_.evaluations;
  // creatures born so far: the budget and the intervals count tournaments, so
  // that elites evaluated again (elite_evaluations) do not shift them
  const long until = std::min(total, static_cast<long>(s.next_id) + every);
  const int pop = static_cast<int>(s.population.size());
  const bool all = evo_.tournament_evaluates == TournamentEvaluates::All;
  long rejected = 0, failed = 0;
  MetricTally tally;
  GenerationResult res;
  std::vector<Individual> evaluated;  // members the tournaments evaluated, as they stood after each

  // islands: members [k * isle, (k + 1) * isle) are island k's
  const int islands = std::max(1, evo_.islands);
  const int isle = pop / islands;

  while (s.next_id < until) {
    // one batch of tournaments over disjoint triples of each island's members
    // (one island: of the population), `batch` an island, fewer at the
    // interval's end (spread over the islands, the first ones one more)
    const long before = s.next_id;
    long total_n = std::min<long>({static_cast<long>(evo_.batch) * islands, until - before,
                                   static_cast<long>(isle / 3) * islands});
    total_n = std::max(total_n, 1L);
    Rng rng(stream_seed({seed_, kTournament, static_cast<std::uint64_t>(before)}));
    std::vector<int> idx;  // the triples, island after island
    for (int k = 0; k < islands; ++k) {
      const int nk = static_cast<int>(total_n / islands + (k < total_n % islands ? 1 : 0));
      std::vector<int> own(isle);
      std::iota(own.begin(), own.end(), k * isle);
      for (int i = 0; i < 3 * nk; ++i) std::swap(own[i], own[i + rng.below(isle - i)]);
      idx.insert(idx.end(), own.begin(), own.begin() + 3 * nk);
    }
    const int n = static_cast<int>(total_n);

    // tournament_evaluates = all: the three compete on evaluations in fresh worlds
    std::vector<double> fresh;
    if (all) tournaments(s, eval, std::vector<int>(idx.begin(), idx.begin() + 3 * n), fresh, failed, tally, evaluated);

    std::vector<Child> children;
    std::vector<int> replaced;
    for (int t = 0; t < n; ++t) {
      std::array<int, 3> tri = {idx[3 * t], idx[3 * t + 1], idx[3 * t + 2]};
      if (!all) {
        std::sort(tri.begin(), tri.end(),
                  [&](int x, int y) { return better(s.population[x], s.population[y]); });
      } else {
        // equal evaluations (a sparse task's zeros) tie at random, not by
        // age, so a child that scores as its elders survives as often (drift)
        for (int k = 2; k > 0; --k) std::swap(tri[k], tri[rng.below(k + 1)]);
        std::stable_sort(tri.begin(), tri.end(), [&](int x, int y) { return fresh[x] > fresh[y]; });
      }
      const Individual &a = s.population[tri[0]], &b = s.population[tri[1]];
      // four mutations of the best, crossover + mutation or grafting +
      // mutation (5.2: a third each), in the shares p_asexual, p_crossover, p_graft
      auto make = [&](Rng& r) {
        for (int tries = 0;; ++tries) {
          const double u = r.uniform();
          if (u < evo_.p_asexual) return mutant(a, r);
          const bool cross = u < evo_.p_asexual + evo_.p_crossover;
          Child c{cross ? ops_->crossover(*a.genotype, *b.genotype, r) : ops_->graft(*a.genotype, *b.genotype, r),
                  a.id, b.id, cross ? "crossover" : "graft"};
          c.genotype = ops_->mutate(*c.genotype, evo_.mutation_rate, r);
          if (tries >= evo_.max_regenerations || !copies_parent(c, *a.genotype, b.genotype.get())) return c;
        }
      };
      auto c = viable(make(rng), rng, rejected, make);
      if (!c) return Error{c.error()};
      children.push_back(std::move(*c));
      replaced.push_back(tri[2]);
    }
    std::vector<Individual> born;
    if (all) {
      for (Child& c : children) born.push_back(unevaluated(std::move(c), s));
    } else {
      born = evaluate(std::move(children), s, eval, failed, tally);
    }
    for (std::size_t k = 0; k < born.size(); ++k) s.population[replaced[k]] = born[k];
    res.born.insert(res.born.end(), born.begin(), born.end());
    // a migration each time the births on each island pass a multiple of
    // migration_every, while the budget lasts
    const long every = evo_.migration_every * islands, after_initial = s.first_id + pop;
    if (islands > 1 && (s.next_id - after_initial) / every > (before - after_initial) / every && s.next_id < total)
      for (Individual& m : migrate(s.population, islands, s.next_id, s.generation + 1)) res.born.push_back(std::move(m));
  }
  // members the tournaments evaluated: those born in this interval as they
  // now stand, the earlier ones evaluated again (the last state of each)
  std::map<std::int64_t, Individual> again;
  for (Individual& ind : evaluated) {
    auto b = std::find_if(res.born.begin(), res.born.end(), [&](const Individual& x) { return x.id == ind.id; });
    if (b != res.born.end()) *b = ind;
    else again[ind.id] = std::move(ind);
  }
  for (Individual& ind : reevaluate_elite(s, eval, failed, res.born)) again[ind.id] = std::move(ind);
  for (auto& [id, ind] : again) res.reevaluated.push_back(std::move(ind));
  s.generation += 1;
  res.stats = stats(s);
  res.stats.metrics = tally.stats();
  res.stats.rejected = rejected;
  res.stats.failed = failed;
  return res;
}

}  // namespace bx
