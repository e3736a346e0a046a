// The evolutionary loops: a generational GA (chaumont2007) and a steady-state
// GA with triple tournaments (miconi2006), on one population or on islands
// with ring migration (evolution.islands). Both breed genotypes of any kind
// through its GenotypeOps (genome/genotype.h) in the shares EvolutionDef
// gives, hand batches to an Evaluator and never touch processes; every random
// draw comes from a stream seeded by (run seed, generation or batch, child),
// so a run resumed from a checkpoint continues exactly as if it had never
// stopped.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <memory>

#include "core/result.h"
#include "core/rng.h"
#include "eval/evaluator.h"
#include "evolve/evolution_def.h"
#include "evolve/metric_tally.h"
#include "genome/genotype.h"

namespace bx {

/// One evaluated creature of a run.
struct Individual {
  std::int64_t id = -1;
  std::shared_ptr<const Genotype> genotype;  ///< immutable, so copies of an individual share it
  /// The mean (or least: Evolution's fold) over its evaluations: the first,
  /// when it was born, and those under fresh seeds while it was among the
  /// elite (evolution.elite_evaluations) or, with tournament_evaluates = all,
  /// in each tournament it was drawn into. 0 while it has none.
  double fitness = 0;
  double distance = 0;  ///< the first evaluation's, the one a replay shows
  std::string failure;  ///< why it failed (crash, timeout, explosion) or scored 0 by rule
  std::int64_t parent1 = -1, parent2 = -1;
  std::string op;       ///< random, mutation, crossover, graft; copy, file (a stage's founders); migrant (islands)
  int generation = 0;   ///< the generation (steady state: the report interval) it was born in
  std::uint64_t seed = 0;  ///< the seed of its first evaluation (the k-th's: repeat_seed(seed, k))
  /// How many evaluations `fitness` folds (their mean, or least: Evolution's
  /// fold); 0 for a child of tournament_evaluates = all not yet drawn into a tournament.
  int evaluations = 1;
};

/// Statistics of one generation (steady state: one report interval).
struct GenerationStats {
  int generation = 0;
  long evaluations = 0;   ///< cumulative evaluations at its end
  double best = 0, mean = 0, median = 0;  ///< over the population's evaluated members
  std::int64_t best_id = -1;
  long rejected = 0;      ///< non-viable children redrawn during it
  long failed = 0;        ///< evaluations that crashed, timed out or blew up
  /// The task's metrics over the evaluations that selected in it (those of
  /// the children born; with tournament_evaluates = all, the tournaments'),
  /// not the elite's evaluations again.
  std::vector<MetricStat> metrics;
};

/// Where a run stands; what a checkpoint holds.
struct EvolutionState {
  int generation = -1;    ///< last completed generation
  long evaluations = 0;   ///< cumulative evaluations, elites evaluated again included
  std::int64_t next_id = 0;  ///< the next individual's id
  /// The id of its first individual: a stage of a multi-stage run (io/syllabus.h)
  /// continues the run's ids, and a steady-state budget counts the creatures
  /// born in it, next_id - first_id.
  std::int64_t first_id = 0;
  std::vector<Individual> population;
};

/// The outcome of one step.
struct GenerationResult {
  GenerationStats stats;
  /// individuals created and evaluated, in id order, as they stand after the
  /// step (an elite among them may have been evaluated again)
  std::vector<Individual> born;
  /// Individuals born before this step and evaluated again in it
  /// (evolution.elite_evaluations), as they stand after it, in id order.
  std::vector<Individual> reevaluated;
};

/// Draws a parent index from survivors sorted best first, by rank (weight
/// n - i), fitness-proportionately (shifted so the worst keeps 1% of the
/// range) or uniformly.
std::size_t select_survivor(const std::vector<Individual>& survivors, Selection how, Rng& rng);

/// Whether `a` ranks before `b`: evaluated before not yet evaluated, then
/// the fitter, then the older (so ties break the same way every time).
bool ranks_before(const Individual& a, const Individual& b);

/// The evaluation seed of individual `id` of a run with master seed `seed`.
std::uint64_t evaluation_seed(std::uint64_t seed, std::int64_t id);

/// Generations (steady state: report intervals) a run of `evo` has in all.
int total_generations(const EvolutionDef& evo);

/// Whether `evo`'s breeding scheme suits genotypes bred by `ops`: grafting
/// (p_graft > 0) needs a kind that has it. The error names the field.
Status check_breeding(const EvolutionDef& evo, const GenotypeOps& ops);

/// How a run under `evo` evaluated a creature it evaluated `evaluations`
/// times (repeated_fitness reproduces its score).
Repeats elite_repeats(const EvolutionDef& evo, int evaluations);

/// A skill that every child is evaluated on again beside its own task
/// (lessin2015's General ESP, Algorithm 1: the body may change, so each
/// existing leaf skill is retested): `task` is the evaluator's task it runs
/// on (the skill alone: its stage's config with brain.skill), `seed` the
/// world every child is retested in (one for all: a child whose body and
/// skill did not change scores what its parent did), `least` the fitness it
/// must keep. A child that scores less on any retest (or whose retest
/// fails) has fitness 0 for good (`failure` says which, starting with
/// kRetestFailure), and its metrics record each retest as "retest NAME".
struct Retest {
  std::string skill;
  int task = 0;
  std::uint64_t seed = 0;
  double least = 0;
  friend bool operator==(const Retest&, const Retest&) = default;
};

/// How the `failure` of a child that fell below a retest starts.
inline constexpr std::string_view kRetestFailure = "retest ";

/// Whether `ind` scored 0 for falling below a retest (Retest): the elite
/// is not evaluated again then, so its 0 stands.
bool failed_retest(const Individual& ind);

/// Ring migration between `islands` equal islands of `population` (members
/// [k n, (k + 1) n) are island k's; evolution.islands): each island's best,
/// chosen before any moves, is copied under a new id from `next_id`
/// (operator "migrant", born in `generation`; its record as it stands:
/// fitness, evaluations and seed, so a replay shows the evaluation it was
/// scored on) over the worst evaluated member of the next island (the worst
/// of all if none is evaluated yet). Copies, not moves: the best stays home
/// too, as in pagmo's archipelago. Returns the migrants, island by island.
std::vector<Individual> migrate(std::vector<Individual>& population, int islands, std::int64_t& next_id,
                                int generation);

/// An evolutionary run's algorithm.
class Evolution {
 public:
  /// `ops` breeds the run's genotypes; check_breeding(evo, *ops) must hold.
  /// `fold` is how an elite's evaluations make its fitness: the run's
  /// task.trial_score, so an elite evaluated again is scored as one creature
  /// evaluated over as many trials (fold_score).
  ///
  /// `task` is the evaluator's task its jobs name (EvalJob::task: a stage's
  /// index). Without `founders` the first generation is random genotypes;
  /// with them (a stage that starts from the last one's population, best
  /// first), its k-th child is founder k mod n, as it is for k < n and a
  /// mutant of it (the algorithm's asexual mutation) after that. A founder
  /// without an id (-1: read from a file) is born with operator "file".
  ///
  /// `retests` are the skills each child is evaluated on again (Retest),
  /// in the same batch as its own task; none but in General ESP's stages.
  Evolution(std::shared_ptr<const GenotypeOps> ops, EvolutionDef evo, std::uint64_t seed,
            TrialScore fold = TrialScore::Mean, int task = 0, std::vector<Individual> founders = {},
            std::vector<Retest> retests = {});

  /// True when the run has done all its generations or evaluations.
  bool finished(const EvolutionState& s) const { return finished(evo_, s); }
  static bool finished(const EvolutionDef& evo, const EvolutionState& s);
  /// Generations (steady state: report intervals) the run will have in all.
  int total_generations() const;
  /// Runs the next generation: the initial population first. An error when
  /// it cannot breed one: max_random_redraws random genotypes in a row not
  /// viable (with the reason most of them gave); `s` may then be part way through the
  /// step, to be dropped (a run stores nothing of it).
  Result<GenerationResult> step(EvolutionState& s, Evaluator& eval) const;
  /// The evaluation seed of an individual.
  std::uint64_t eval_seed(std::int64_t id) const;
  /// Called with the generation's count of non-viable children redrawn so
  /// far, at every kRedrawReport-th: progress while breeding is slow
  /// because few children are viable (it changes nothing of the run).
  void on_redraws(std::function<void(long)> report) { on_redraws_ = std::move(report); }
  static constexpr long kRedrawReport = 1000;

 private:
  struct Child {
    std::shared_ptr<const Genotype> genotype;
    std::int64_t parent1 = -1, parent2 = -1;
    std::string op;
  };
  Result<Child> random_child(Rng& rng, long& rejected) const;
  Child mutant(const Individual& a, Rng& rng) const;
  /// Whether `c` must be made again as a copy of parent `a` or `b` (none
  /// for a mutant) (EvolutionDef::distinct_children).
  bool copies_parent(const Child& c, const Genotype& a, const Genotype* b = nullptr) const;
  Result<Child> viable(Child c, Rng& rng, long& rejected, const std::function<Child(Rng&)>& remake) const;
  std::vector<Individual> evaluate(std::vector<Child> children, EvolutionState& s, Evaluator& eval,
                                   long& failed, MetricTally& tally) const;
  Individual unevaluated(Child c, EvolutionState& s) const;
  void tournaments(EvolutionState& s, Evaluator& eval, std::vector<int> members, std::vector<double>& fresh,
                   long& failed, MetricTally& tally, std::vector<Individual>& evaluated) const;
  Result<GenerationResult> initial(EvolutionState& s, Evaluator& eval) const;
  Result<GenerationResult> generational(EvolutionState& s, Evaluator& eval) const;
  Result<GenerationResult> steady_state(EvolutionState& s, Evaluator& eval) const;
  GenerationStats stats(const EvolutionState& s) const;
  int elite_count(int n) const;
  std::vector<Individual> reevaluate_elite(EvolutionState& s, Evaluator& eval, long& failed,
                                           std::vector<Individual>& born) const;

  std::shared_ptr<const GenotypeOps> ops_;
  EvolutionDef evo_;
  std::uint64_t seed_;
  TrialScore fold_;
  int task_;
  std::vector<Individual> founders_;
  std::vector<Retest> retests_;
  std::function<void(long)> on_redraws_;
  void rejected_one(long& rejected) const {
    if (++rejected % kRedrawReport == 0 && on_redraws_) on_redraws_(rejected);
  }
};

}  // namespace bx
