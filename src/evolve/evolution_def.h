// Definition of an evolutionary run's algorithm, with defaults in one place.
// Presets set each paper's constants (presets/*.toml).
#pragma once

#include <cstdint>

#include "genome/genome.h"

namespace bx {

/// Which loop drives evolution.
enum class Algorithm {
  Generational,  ///< chaumont2007 5.2, 5.7: elite survive, the rest replaced by children
  SteadyState,   ///< miconi2006 5.2: triple tournaments, the worst replaced by a child
};

/// Which members of a steady-state tournament it evaluates.
enum class TournamentEvaluates {
  Child,  ///< miconi2006 5.2: the child once, when born; the three compete on the fitness they keep
  All,    ///< stanton2015: the three, each in a fresh world, compete on these evaluations; a child
          ///< is first evaluated in its first tournament
};

/// How parents are drawn from the survivors of a generational GA.
enum class Selection { Rank, Proportionate, Uniform };

/// The evolutionary algorithm's settings.
struct EvolutionDef {
  Algorithm algorithm = Algorithm::Generational;
  int population = 300;           ///< chaumont2007 5.2: 300; miconi2006 6.1: 500
  // generational (chaumont2007)
  int generations = 100;          ///< chaumont2007 5.2: 100
  double elite_fraction = 0.2;    ///< the best 20% survive (5.2); steady state: the elite elite_evaluations re-evaluates
  Selection selection = Selection::Rank;
  double p_asexual = 0.4;         ///< children from mutation alone (5.7)
  double p_crossover = 0.3;       ///< children from crossover (5.7)
  double p_graft = 0.3;           ///< children from grafting (5.7)
  double asexual_rate = 0.10;     ///< per-parameter mutation probability of asexual children
  double sexual_mutation_chance = 0.10;  ///< chance that a crossover/graft child is mutated
  double sexual_rate = 0.05;      ///< its per-site probability
  // steady state (miconi2006)
  long evaluations = 500000;      ///< cycles after the initial population (6.1: 500,000)
  double mutation_rate = 0.04;    ///< P_mut (5.1)
  int asexual_mutations = 4;      ///< the asexual option applies the mutation operator 4 times (5.2)
  /// Tournaments evaluated together: each batch draws disjoint triples from
  /// the same population, so workers can evaluate them at once; 1 is the
  /// paper's strictly sequential loop. Results never depend on the workers.
  int batch = 8;
  /// Child: a creature's fitness is measured once, at birth (miconi2006).
  /// All: each tournament evaluates its three members afresh (a new layout,
  /// a new physics seed) and ranks them by these evaluations; a creature's
  /// fitness is the mean of every evaluation it had (Stanton & Channon 2015,
  /// whose population of 150 "are evaluated in groups of three").
  TournamentEvaluates tournament_evaluates = TournamentEvaluates::Child;
  /// Steady state: islands the population is split into (pagmo's
  /// archipelago), each population / islands members that hold their own
  /// tournaments. A batch holds `batch` tournaments on every island, so
  /// islands x batch evaluations go to the workers at once. 1: one population
  /// (the papers).
  int islands = 1;
  /// Creatures born on each island (its migrant among them) between
  /// migrations: then every island's best, copied under a new id (operator
  /// "migrant", its record as it stands), replaces the worst evaluated member
  /// of the next island in the ring. A migrant is born, so it counts toward
  /// evolution.evaluations.
  long migration_every = 100;
  // both
  /// Evaluations an elite's fitness is the mean (task.trial_score = min: the
  /// least) of: after each generation
  /// (steady state: report interval) the best elite_fraction are evaluated
  /// again, each under a fresh seed, until every one has this many, so a
  /// lucky evaluation does not keep a creature alive nor make the run's best
  /// (issue 11). 1: each creature is evaluated once (the papers).
  int elite_evaluations = 1;
  /// Evaluations the elite's best is the mean (least) of: once it has
  /// elite_evaluations, the best is evaluated again until it has this many,
  /// and again whenever another takes its place, so the best of a
  /// generation (and of the run) is not the luckiest of many near-equal
  /// creatures, such as clones that differ only in unexpressed genes
  /// (issue 11). 0 or at most elite_evaluations: the best is evaluated as
  /// the rest of the elite.
  int best_evaluations = 0;
  /// The best's further evaluations come in rounds that double its count (to
  /// 2, 4, 8, ... up to best_evaluations), each followed by a new ranking, so
  /// a creature whose first few evaluations were lucky drops out after a few
  /// more instead of all of them: best_evaluations can be large where one
  /// evaluation is noisy (a river level reached in a third of the layouts).
  /// false: all at once.
  bool best_evaluations_doubling = false;
  /// Evaluations of the run's best, once its last stage ends, under seeds
  /// that no evaluation of the run used (held_out_seed): an estimate of its
  /// fitness that selection never saw. Selection keeps what scored well, so
  /// the best's stored fitness (the most of many means) overstates what it
  /// scores in a fresh world where one evaluation is noisy (a river level
  /// reached in some layouts); `check` compares its other seeds with this.
  /// Stored in the run (RunStore::held_out); 0: none.
  int held_out_evaluations = 0;
  /// The elite's 2nd, 4th, ... evaluations step at half physics.dt
  /// (divided_step_config), so that with the least of them (task.trial_score =
  /// min) a gait that only the step makes does not keep its score (issue 11).
  /// So do the best's (best_evaluations) and, with tournament_evaluates = all,
  /// every creature's 2nd, 4th, ... tournament evaluation: selection then
  /// ranks behaviour at two steps, and a score that only one step gives (a
  /// river walker's step-made turn, docs/physics.md cause 32) is half lost.
  /// (The held-out evaluations stay at dt: `check` varies the step itself.)
  bool elite_half_step = false;
  /// With it, the elite's evaluations cycle through physics.dt, dt/2 (when
  /// elite_half_step) and dt/4 (repeat_step_divisor): a score the step makes
  /// at dt/4 only, such as a topple the step decides, is lost too (issue 11).
  bool elite_quarter_step = false;
  int max_regenerations = 1000;   ///< non-viable children redrawn at most this often, then a random genome
  /// Random genotypes drawn in a row, none of them viable, before the run
  /// stops and says why (the reason most of them gave): under a config that no
  /// creature survives (develop.max_body_length below any body) the draws
  /// would never end. The presets' longest streak in 20,000 draws is 84
  /// (chaumont2007's catapults, 92% of whose random genomes overlap
  /// themselves: 10,000 in a row has odds of e^-800), the others' 6 or
  /// fewer. (A reconciliation stage's random genomes are never viable, as
  /// they lack its skill: it breeds from its founders, and reaches random
  /// genomes only after max_regenerations children in a row not viable.)
  int max_random_redraws = 10000;
  /// A child whose genotype equals a parent's is made again (new parents,
  /// new operator), up to max_regenerations times, then kept. A stage whose
  /// genomes are mostly locked (lessin2015's Fast ESP: the body and every
  /// learned skill frozen) otherwise spends half its evaluations on copies:
  /// crossover of two frozen genomes that differ in a few free genes gives
  /// one of them, and most mutations find nothing they may change. Off in
  /// every dialect's defaults (our choice where on: the ESP presets).
  bool distinct_children = false;
  double evaluation_timeout = 120;  ///< seconds before a worker's evaluation is abandoned
  /// Fitness of an evaluation that blew up, crashed or timed out: "an
  /// arbitrary low value" (chaumont2007 5.4). 0 suits tasks whose scores are
  /// never negative; the aim task's can be, so its presets set it lower.
  double failed_fitness = 0;
  /// Steady state: evaluations between statistics rows and checkpoints (0: the population size).
  long report_every = 0;
  friend bool operator==(const EvolutionDef&, const EvolutionDef&) = default;
};

/// The algorithm of a dialect's paper, with its constants.
EvolutionDef default_evolution(Dialect d);

}  // namespace bx
