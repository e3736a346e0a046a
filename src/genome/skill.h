// A skill to encapsulate (lessin2015 IV-B): what a run of several stages
// hands a genotype kind when a stage's skill is done (genome/genotype.h's
// with_skill_encapsulated; the graph genome's is genome/encapsulate.h).
#pragma once

#include <string>

namespace bx {

/// The skill to encapsulate.
struct SkillDef {
  std::string name;  ///< unique among the genotype's skills, not empty
  int group = -1;    ///< its switch's pandemonium group (lessin2015 IV-C), or -1: none
};

}  // namespace bx
