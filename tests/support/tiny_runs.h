// Configs of tiny runs that end-to-end tests share: a few seconds each.
#pragma once

namespace bxtest {

/// A tiny river crossing run whose tournaments evaluate all three
/// (evolution.tournament_evaluates = "all", Stanton & Channon 2015), of
/// 1-second evaluations: named metrics per report interval.
inline const char* kTinyRiverRun = R"(
[genotype]
kind = "river"  # brings the river task, the quadruped's physics and its PD motors
[river]
seconds = 1
[evolution]
algorithm = "steady_state"
tournament_evaluates = "all"
population = 9
evaluations = 12
batch = 3
report_every = 3
p_asexual = 0
p_crossover = 1
p_graft = 0
)";

}  // namespace bxtest
