// Everything the river crossing takes from a config (SimConfig::river): its
// task, its body, its controller's sizes and landscape, and the box and
// mutation of its genes. The pre-evolved CTRNN its pattern generator copies
// is the brain's, beside this in SimConfig. docs/rivercrossing.md says where
// each default comes from.
#pragma once

#include "brain/river/river_brain.h"
#include "task/river/quadruped.h"
#include "task/river/river_task.h"

namespace bx {

struct RiverDef {
  RiverTaskDef task;
  QuadrupedDef body;
  RiverBrainDef brain;
  /// Every gene (a weight) stays in [-gene_range, gene_range]; a mutated
  /// gene moves by N(0, gene_sigma). The paper gives neither: ours.
  double gene_range = 4;
  double gene_sigma = 0.5;
  friend bool operator==(const RiverDef&, const RiverDef&) = default;
};

}  // namespace bx
