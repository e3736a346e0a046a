// Reconciling a skill to a changed body (lessin2015 VI, Algorithm 2): after a
// General ESP stage let the body change for a new skill, each older skill
// gets generations of its own in which the body is fixed and only "control
// for skill s" evolves, scored on s's own task.
//
// A skill's control here is what encapsulation left of it that the body
// meets: its wires into the muscles and into the switches of the skills it
// drives (the inputs gated by its switch, InputGene::gate), its muscles'
// resting activations among them (the gated wires from the constant 1).
// Their weights evolve; nothing else does (no part, neuron, source or other
// skill's wire), so every other skill stays exactly as it was, and the
// skill's internals (its oscillators, their frequencies) as they were. Our
// choice: the paper does not say which of a skill's genes its reconciliation
// may change, and ours neither tags a locked neuron with its skill nor may
// unlock a neuron another skill reads.
#pragma once

#include <string_view>

#include "core/rng.h"
#include "genome/genome.h"
#include "genome/operators.h"

namespace bx {

/// The index of `skill`'s switch among g's global neurons, or -1.
int skill_switch(const Genome& g, std::string_view skill);

/// How many wires `skill`'s switch gates in `g`.
int skill_wire_count(const Genome& g, std::string_view skill);

/// Each wire `skill` gates, with probability `rate`, gets its weight moved by
/// N(0, param_sigma x the weight range), clamped to it. Nothing else changes.
void mutate_skill_wires(Genome& g, std::string_view skill, const OperatorDef& def, double rate, Rng& rng);

/// `a` with each of `skill`'s wires' weights from `a` or `b` at random (the
/// two must have the same wires: reconciled from one creature, they do).
/// `a` as it is when the wires differ.
Genome cross_skill_wires(const Genome& a, const Genome& b, std::string_view skill, Rng& rng);

}  // namespace bx
