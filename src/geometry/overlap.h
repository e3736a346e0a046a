// Overlap of solids at rest: development's self-intersection test, a
// geometric query on ODE's colliders with no world and no bodies.
#pragma once

#include <span>
#include <utility>

#include "core/math.h"
#include "genome/genome.h"

namespace bx {

/// A solid: a shape of full extents `size` at `pose`. `joined_to` names the
/// solid it is attached to by a joint (-1: none): joined solids may touch.
struct Solid {
  Shape shape = Shape::Box;
  Vec3 size;
  Pose pose;
  int joined_to = -1;
};

/// The first pair (i < j) of solids, not joined, whose shapes (each shrunk by
/// `margin` metres on every side) overlap; {-1, -1} if none.
/// Sorts the solids along their longest spread axis and tests only pairs whose
/// bounding boxes overlap there, in the order of the all-pairs loop, so the
/// pair found is the all-pairs loop's first; about O(n log n) for solids that
/// are not piled up in one place.
std::pair<int, int> first_overlap(std::span<const Solid> solids, double margin);

}  // namespace bx
