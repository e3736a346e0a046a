// Edits of a genome that keep its references consistent: removing a neuron,
// sensor, edge or node renumbers every source and edge target that pointed
// past it, and fixes the ones that pointed at it. The operators
// (operators.h) are built from these; docs/operators.md lists the rules.
// A catapult's release inputs (Genome::catapult) count as inputs of node 0,
// the arm: every edit below keeps them pointing at the same sources too.
#pragma once

#include <vector>

#include "core/math.h"
#include "core/rng.h"
#include "genome/genome.h"

namespace bx {

/// How an input whose source no longer exists is fixed.
enum class SourceFix {
  Remove,    ///< the input is deleted (later inputs move up one place)
  Reassign,  ///< a random existing source of the same owner, weight kept (removed if none or no
             ///< rng)
  Clamp,     ///< same place and kind, an index past the end clamped to the last that exists;
             ///< a removed element's readers, and places with none, as Reassign
};

// ---------------------------------------------------------------- queries

/// Nodes with an edge to `n`, each once, in index order (`n` itself if it
/// has a reflexive edge).
std::vector<int> parents_of(const Genome& g, int n);

/// Nodes reachable from `from` along edges, `from` first, in breadth-first
/// order (edges in their order). For a tree this is `from`'s subtree.
std::vector<int> subtree(const Genome& g, int from);

/// Per node: reachable from the root.
std::vector<bool> reachable_from_root(const Genome& g);

/// Number of nodes reachable from the root when node `skip_node` and edge
/// `skip_edge` of node `skip_edge_node` are left out (-1: none).
int reachable_count(const Genome& g, int skip_node = -1, int skip_edge_node = -1,
                    int skip_edge = -1);

/// Number of parts development grows (honouring recursive limits,
/// terminal-only edges and reflections), counting stops above `cap`: the
/// result is at most cap + 1. Mirrors develop()'s traversal, so that the
/// genome layer can reject creatures with too many parts without developing.
int count_parts(const Genome& g, int cap);

/// Whether input `in` of a neuron or effector of node `owner` (-1: a global
/// neuron) reads something that exists: the rules of validate(), plus
/// a `parent` source must exist in at least one parent of the node and
/// global sources only in dialects with global neurons.
bool source_exists(const Genome& g, int owner, const InputGene& in);

/// Every source an input of node `owner` (-1: a global neuron) may read,
/// with weight 1: neurons and sensors of the node itself, of its parents
/// (indices every parent has), of each edge's child, of the root (unless
/// the node is the root or the root is its only parent), and global
/// neurons. Global neurons read only root and global sources.
std::vector<InputGene> source_candidates(const Genome& g, int owner);

// ---------------------------------------------------------------- source repair

/// Fixes every input whose source does not exist (source_exists) by `fix`,
/// and resets `edge` to 0 on inputs that do not read a child (canonical
/// form). Returns the number of inputs fixed. `rng` may be null only when
/// `fix` is Remove (Reassign and Clamp fall back to Remove without it).
int repair_sources(Genome& g, SourceFix fix, Rng* rng);

// ---------------------------------------------------------------- removals

/// Removes neuron `k` of node `node`. Inputs that read a later neuron of
/// that node (as self, parent, child or root) are renumbered so that they
/// still read the same neuron; inputs that read neuron `k` are fixed by
/// `fix`.
void remove_neuron(Genome& g, int node, int k, SourceFix fix = SourceFix::Remove,
                   Rng* rng = nullptr);

/// Removes global neuron `k`, renumbering and fixing global sources.
void remove_global_neuron(Genome& g, int k, SourceFix fix = SourceFix::Remove, Rng* rng = nullptr);

/// Removes sensor `k` of node `node`, renumbering and fixing sensor sources.
void remove_sensor(Genome& g, int node, int k, SourceFix fix = SourceFix::Remove,
                   Rng* rng = nullptr);

/// Removes effector `k` of node `node`. In muscle dialects an effector is a
/// muscle whose length is a source: its readers are renumbered and fixed
/// as for a sensor.
void remove_effector(Genome& g, int node, int k, SourceFix fix = SourceFix::Remove,
                     Rng* rng = nullptr);

/// Removes edge `k` of node `node`: `child` sources of that node on later
/// edges are renumbered, those on edge `k` are fixed. Nodes left unreachable
/// stay (see remove_unreachable).
void remove_edge(Genome& g, int node, int k, SourceFix fix = SourceFix::Remove, Rng* rng = nullptr);

/// Moves edge `k` of node `from` to the end of node `to`'s edges (the
/// child keeps the edge's data): `from`'s child sources on it are fixed by
/// `fix`, and the child's parent sources now read `to` (fixed by `fix` where
/// the index does not exist there).
void move_edge(Genome& g, int from, int k, int to, SourceFix fix, Rng* rng);

/// Removes the listed nodes (never the root): edges to them are removed (as
/// remove_edge), the other nodes are renumbered and edge targets follow.
void remove_nodes(Genome& g, const std::vector<int>& nodes, SourceFix fix = SourceFix::Remove,
                  Rng* rng = nullptr);

/// Removes one node (never the root), as remove_nodes.
void remove_node(Genome& g, int n, SourceFix fix = SourceFix::Remove, Rng* rng = nullptr);

/// Removes every edge into node `n` (as remove_edge; e.g. a catapult's arm,
/// which exists once).
void remove_edges_to(Genome& g, int n, SourceFix fix = SourceFix::Remove, Rng* rng = nullptr);

/// Removes every node not reachable from the root; returns how many.
int remove_unreachable(Genome& g, SourceFix fix = SourceFix::Remove, Rng* rng = nullptr);

// ---------------------------------------------------------------- subgraphs

/// Appends to `dst` a copy of the nodes of `src` reachable from `src_root`
/// (breadth-first, at most `max_nodes` of them, >= 1); edges to nodes left
/// out are dropped, and `child` sources on them get edge -1. Returns the
/// index of the copy of `src_root`. Low level: the copy is not yet
/// connected and its sources are not checked; connect it, then call
/// repair_sources (or use splice_subgraph, which does both).
int append_subgraph(Genome& dst, const Genome& src, int src_root, int max_nodes);

/// Points edge `edge` of node `parent` of `dst` at a copy of the subgraph of
/// `src` reachable from `src_root` (at most `max_nodes` nodes), removes the
/// nodes of `dst` no longer reachable, and fixes sources by `fix`: inputs
/// that read the old child through that edge now read the new one at the
/// same index, the copy's parent sources read `parent`, its root sources
/// `dst`'s root. Returns the index of the copy of `src_root` (after
/// renumbering).
int splice_subgraph(Genome& dst, int parent, int edge, const Genome& src, int src_root,
                    int max_nodes, SourceFix fix, Rng* rng);

// ---------------------------------------------------------------- geometry

/// Rotation of a face's frame (x = outward normal, as development uses).
Mat3 face_frame(Face f);

/// Direction of the child's x axis in the parent's frame for an edge.
Vec3 edge_direction(const EdgeGene& e);

/// Where an edge goes so that the child extends along unit direction `d`
/// (parent frame) from the point where the ray from the parent's centre
/// along `d` leaves its bounding box (`parent_size`, full extents). Sets the
/// edge's face, at (u, v) and rotation (roll `roll`, then the two polar
/// angles, rounded to multiples of `step` when step > 0; a rounded roll
/// must itself be a multiple of step).
void place_edge(EdgeGene& e, Vec3 parent_size, Vec3 d, double roll, double step);

/// Fits an edge to a parent of size `parent_size` (after the parent was
/// resized, or the edge moved to another parent) keeping the child's
/// direction: the face and angles stay while the child still points out of
/// its face, and (u, v) becomes the point where the ray from the centre along
/// the child's direction meets that face; otherwise as place_edge. Applied to
/// an edge made by place_edge for the same size, it changes nothing.
void reseat_edge(EdgeGene& e, Vec3 parent_size, double step);

}  // namespace bx
