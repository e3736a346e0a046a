// The river crossing's genome layout (Stanton & Channon 2015, "Genetic
// Representation"): one float array holding, in this order, the DN's
// input->hidden and hidden->output weights, the PN's input->hidden and
// hidden->output weights, the PG interconnection weights (PN outputs into
// the motifs' input neurons) and the PG->motor weights. Within each matrix
// the weights into one receiving neuron are contiguous (WeightMatrix's
// row-major order). The motif's own parameters are not in it: the motif is
// evolved beforehand and shared by every individual.
#pragma once

#include <span>
#include <string>

#include "brain/river/dense_layer.h"
#include "core/result.h"

namespace bx {

/// The sizes of the controller's layers that are not fixed by the world.
/// Defaults are the paper's where it gives them.
struct RiverShape {
  int dn_hidden = 4;  ///< the DN's hidden neurons (the paper: four)
  /// The PN's hidden neurons. The paper is silent; 4, the only hidden layer
  /// size it gives (the DN's), keeps the genome short for a run of 10^6
  /// tournaments (docs/rivercrossing.md ("The controller")).
  int pn_hidden = 4;
  int motifs = 5;   ///< PG motifs, and PN outputs (one per motif)
  int motors = 12;  ///< motor neurons, one per degree of freedom
  friend bool operator==(const RiverShape&, const RiverShape&) = default;
};

/// An error naming the field and value if a size is below 1.
Status check_river_shape(const RiverShape& s);

/// The weights a genome holds, in genome order.
struct RiverWeights {
  WeightMatrix dn_input_hidden;   ///< dn_hidden x kDecisionInputs
  WeightMatrix dn_hidden_output;  ///< kDecisionOutputs x dn_hidden
  WeightMatrix pn_input_hidden;   ///< pn_hidden x kPhysicalInputs
  WeightMatrix pn_hidden_output;  ///< motifs x pn_hidden
  WeightMatrix pg_input;          ///< motifs x motifs: PN output k into motif m's input neuron at (m, k)
  WeightMatrix pg_motor;          ///< motors x motifs: motif m's output into motor j at (j, m)
};

/// How many genes a genome of this (valid) shape holds: 181 for the
/// defaults.
int river_gene_count(const RiverShape& s);

/// The shape as one line, for messages: "DN 6-4-5, PN 8-4-5, 5 motifs, 12 motors".
std::string river_shape_name(const RiverShape& s);

/// The genes laid into the weights in genome order; an error naming the
/// expected and the given count when they differ, or the field of an
/// invalid shape.
Result<RiverWeights> unpack_river_genes(const RiverShape& s, std::span<const double> genes);

}  // namespace bx
