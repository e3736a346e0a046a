// Locks on the graph genome (issue 14 item 5): what of a genome no operator
// may change. A node's lock (NodeGene::lock, NodeLock bits) fixes its body,
// its joint, the edges into or out of it, or its units wholesale; a neuron,
// sensor or effector can be locked alone (its `locked` flag). The operators
// honour locks (mutation skips locked genes and undoes a structural change
// that broke one; crossover and grafting keep the first parent's), and
// locks_kept() is the check they are held to.
//
// Rules a genome's locks follow (lock_problem, part of validate()):
// - locked units come first in their list (new ones are appended after them,
//   so removing an unlocked one never renumbers a locked one); fixed units
//   (is_fixed: locked ones, skills' switches, effectors carrying gated
//   inputs) count as locked here, and gated inputs come first in theirs;
// - a locked unit, and every gated input, reads only locked units: neurons
//   and sensors that are locked themselves or sit in a units-locked node (or
//   a skill's switch), through a parent only when its node's in-edges are
//   locked, through a child only when its node's out-edges are;
// - miconi2006's limb-tree operators do not honour locks: its genomes have none.
//
// Nodes with any lock, or holding a locked unit, are "kept": never removed,
// matched between a parent and its child in order.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "genome/genome.h"

namespace bx {

/// How many of `inputs` lead with a gate (InputGene::gate): the wires of
/// encapsulated skills, frozen.
int gated_prefix(const std::vector<InputGene>& inputs);
/// Whether a unit is fixed: never removed or renumbered, its frozen part
/// unchanged. A locked unit is frozen whole; a skill's switch
/// (NeuronGene::skill) in its function, bias and gated inputs; an effector
/// carrying gated inputs (an encapsulated skill's wires) in its muscle or
/// degree of freedom and those inputs, while its bias and further inputs
/// belong to the skill being learned.
bool is_fixed(const NeuronGene& n);
bool is_fixed(const SensorGene& s);
bool is_fixed(const EffectorGene& e);

/// Whether any node or unit of `g` is locked.
bool has_locks(const Genome& g);
/// Whether a node is kept: locked, or holding a locked unit.
bool is_kept(const NodeGene& n);
/// Whether a node has a unit (neuron, sensor, effector) that is locked alone
/// or by the node's units lock.
bool has_locked_unit(const NodeGene& n);
/// The index of the last kept node, or -1.
int last_kept_node(const Genome& g);
/// Clears a node's lock and its units' (a node copied into a genome whose
/// locks it is not part of).
void unlock(NodeGene& n);

/// Whether `child` keeps every lock of `parent`: the same kept nodes in the
/// same order, each with the same lock, and every locked gene unchanged. The
/// error says which and what changed.
Status locks_kept(const Genome& parent, const Genome& child);

/// What is wrong with `g`'s locks (the rules above), as "path: what", or
/// nothing. validate() calls it.
std::optional<std::string> lock_problem(const Genome& g);

/// The JSON names of the lock bits, in bit order: body, joint, in_edges,
/// out_edges, units.
std::string_view lock_name(NodeLock bit);
/// The names of the bits set in `bits`, in bit order (a node's JSON "lock").
std::vector<std::string> lock_names(unsigned bits);
std::optional<NodeLock> parse_lock(std::string_view name);
inline constexpr NodeLock kLockBits[] = {kLockBody, kLockJoint, kLockInEdges, kLockOutEdges, kLockUnits};

}  // namespace bx
