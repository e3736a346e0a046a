// A small General ESP syllabus (lessin2015 VI) for tests: lessin_crawler's
// forward locomotion encapsulated, then a strike learned with the body free,
// each child retested on forward locomotion run alone (half of it kept).
// Short spans (1 s, settling within 2 s) so a run takes about a second.
#pragma once

#include <string>

namespace bxtest {

/// A strike stage of the given name, retesting the leaf skills before it.
inline std::string general_strike_stage(const std::string& name) {
  return "\n[[stage]]\nname = \"" + name + R"("
retest_tolerance = 0.5
[stage.task]
kind = "strike"
[stage.strike]
seconds = 1
settle_timeout = 2
drop_height = 0.01
)";
}

/// forward (from lessin_crawler, encapsulated), then "strike" (General ESP):
/// population 4, 2 generations each.
inline std::string general_syllabus() {
  return R"(
[genome]
dialect = "lessin2015"
[evolution]
population = 4
generations = 2
[task]
seconds = 1
settle_timeout = 2
drop_height = 0.01

[[stage]]
name = "forward"
start = "file"
file = "lessin_crawler"
encapsulate = true
)" + general_strike_stage("strike");
}

}  // namespace bxtest
