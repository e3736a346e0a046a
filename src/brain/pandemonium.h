// Pandemonium (lessin2015 IV-C): skills that should never act together, such
// as turning left and turning right, compete for control. Each skill is
// switched by a sigma node (IV-B); the sigmas of competing skills form a
// group, and at every brain step only the group's most active sigma sends
// its output, "at full strength", while the others are "entirely
// suppressed". A stage of brain_step (brain.cpp), between publishing the
// neuron outputs and computing the effectors.
#pragma once

#include <span>

#include "brain/brain_model.h"

namespace bx {

/// Sets to 0 the output of every member of each of `m`'s pandemonium groups
/// but the largest; `values` are the brain's value slots (sensors, then
/// neurons), just published. Ties go to the first of the tied members in the
/// group's order (BrainModel::group_member), so the result never depends on
/// anything but the values and that order. One pass over the group arrays;
/// with no groups it reads and writes nothing.
void apply_pandemonium(const BrainModel& m, std::span<double> values);

}  // namespace bx
