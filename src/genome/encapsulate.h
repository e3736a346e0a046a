// Encapsulation (lessin2015 IV-B, Fig. 7): when a creature has learned a
// skill, the skill is frozen and made switchable as a unit, so later skills
// keep it and may use it.
//
// The paper inserts a multiply node on every wire leaving the skill and lets
// one sigma node drive all of them; the muscles sit behind sigma nodes that
// later skills share. Here the multiply sits on the wire itself: a gated
// input (InputGene::gate) is scaled by its skill's switch, a global sigma
// neuron (NeuronGene::skill), read in the same brain step as its source. So
// with the switch at 1 the skill drives its muscles exactly as before (w * v
// * 1 is w * v, bit for bit: no step of delay, which a node would add), at 0
// it is silent. An effector is the muscle's sigma: a weighted sum whose
// gated inputs are the encapsulated skills' and whose other inputs and bias
// belong to the skill being learned.
//
// encapsulate() locks every neuron and sensor the genome has (they all
// belong to skills learned so far) and the edges they read through (a node
// whose units read a child keeps its out-edges, one whose units read its
// parent its in-edges: the rest of the body may still change), adds the
// skill's switch, and gates with
// it every wire that does not yet have a gate: the inputs of effectors and
// of earlier skills' switches (a composed skill drives the skills it uses
// through their switches). An effector's bias becomes a gated wire from a
// locked constant-1 neuron, so the switch silences it too; an effector that
// no wire drives is locked whole. The locks
// (genome/locks.h) keep all of it through mutation and crossover.
//
// A switch is "open" (unlocked: the skill being learned may wire into it) or
// "closed" (locked): open_switches() opens those of the skills a stage uses.
//
// Running one skill alone (General ESP's retests, a viewer's switches) is
// development's brain.skill (DevelopDef::skill).
#pragma once

#include <string>
#include <vector>

#include "core/result.h"
#include "genome/genome.h"
#include "genome/skill.h"

namespace bx {

/// `g` with the skill it has learned encapsulated as `skill` (above): every
/// neuron and sensor locked, a new switch (closed) named skill.name, and
/// every ungated input of an effector or of an earlier switch gated by it,
/// each effector's bias a gated wire (first in its inputs, so the sum adds
/// it first, as it did as a bias). An error when the dialect has no skill
/// switch, or the name is empty or taken.
Result<Genome> encapsulate(const Genome& g, const SkillDef& skill);

/// Opens the switches of the skills named in `uses` (their `locked` cleared:
/// the skill being learned may add inputs to them) and closes every other,
/// but for one that still has inputs of a skill not encapsulated (a stage
/// that did not encapsulate), which stays open. A name in `uses` that is no
/// switch of `g` is ignored: that skill was not encapsulated.
void open_switches(Genome& g, const std::vector<std::string>& uses);

/// The names of `g`'s skills, in the order they were encapsulated.
std::vector<std::string> skills_of(const Genome& g);

}  // namespace bx
