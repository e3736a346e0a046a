#include "evolve/evolution_def.h"

namespace bx {

EvolutionDef default_evolution(Dialect d) {
  EvolutionDef e;  // the member defaults are chaumont2007's (5.2, 5.7)
  switch (d) {
    case Dialect::Chaumont2007: break;
    case Dialect::Miconi2006:
      // 5.1, 5.2, 6.1: steady state, triple tournaments, P_mut 0.04,
      // four mutations for an asexual child, population 500, 500,000 cycles
      e.algorithm = Algorithm::SteadyState;
      e.population = 500;
      e.evaluations = 500000;
      e.mutation_rate = 0.04;
      e.asexual_mutations = 4;
      e.p_asexual = e.p_crossover = e.p_graft = 1.0 / 3;
      break;
    case Dialect::Sims1994:
      // Sims (1994): generational, survival ratio 1/5, 40/30/30 (as chaumont2007
      // follows him); the rates are our choice
      e.generations = 50;
      e.asexual_rate = 0.05;
      e.sexual_mutation_chance = 1.0;
      e.sexual_rate = 0.05;
      break;
    case Dialect::Lessin2015:
      // III-A: "elitism, fitness-proportionate selection, and rank selection";
      // population and generations per skill are not given (ours)
      e.population = 100;
      e.generations = 50;
      e.selection = Selection::Rank;
      break;
  }
  return e;
}

}  // namespace bx
