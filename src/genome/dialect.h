// Dialects: the constraints each paper puts on the genome (docs/papers.md S0-S2).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "brain/neuron_set.h"
#include "core/result.h"
#include "genome/genome.h"

namespace bx {

/// How a part's mass is derived from its node.
enum class MassRule {
  Density,     ///< mass = density * volume of the shape
  TanhVolume,  ///< miconi2006 Table 1: mass = mass_scale * tanh(x*y*z)
};

/// How the operators vary a genome (docs/operators.md).
enum class OperatorScheme {
  Graph,     ///< Sims 1994: structural mutations and per-parameter rates; crossover
             ///< and grafting over node lists and edges (sims1994, chaumont2007)
  LimbTree,  ///< miconi2006 5.1: the nine mutation steps in order; crossover of limb
             ///< lists, grafting replaces a random limb's subtree by one of the other's
};

/// The rules of one dialect: what validate() checks and what the operators
/// keep (normalize() repairs an operator's output on the same fields). A new
/// dialect is a new table row. Zero in a count means "no limit".
struct DialectRules {
  Dialect dialect;
  NeuronSetId neuron_set;
  int max_genes;              ///< nodes in the genome
  int max_parts;              ///< parts after development
  bool tree_only;             ///< every non-root node has exactly one incoming edge; no cycles
  std::vector<Shape> shapes;
  std::vector<JointType> joints;
  bool hinge_axis_y_or_z;     ///< miconi2006: hinge axis is the child's y or z axis
  double angle_step;          ///< edge rotations must be multiples of this (0: free)
  int max_neurons_per_part;
  int max_inputs_per_neuron;  ///< 0: the function's own arity
  MassRule mass_rule;
  double mass_scale;          ///< for TanhVolume
  bool edge_roll_free;        ///< false: edge rotation x (roll) must be 0 (miconi2006: two polar angles)
  std::vector<int> reflect_axes;  ///< planes an edge may reflect across (by normal axis 0,1,2)
  /// Limits development gives a hinge whose `limits` are empty (nullopt: unlimited).
  std::optional<Limit> default_hinge_limits;
  bool hinge_limits_fixed;    ///< a hinge's limits must be empty or equal default_hinge_limits
  double max_abs_bias;        ///< bound on neuron and effector bias (0: free)
  double max_abs_weight;      ///< bound on input weights (0: free)
  std::vector<SensorType> sensors;  ///< sensor types a part may carry
  int max_sensors_per_part;
  int max_effectors_per_part;
  bool global_neurons;        ///< global neurons allowed
  /// The neuron function that may belong to a pandemonium group
  /// (NeuronGene::group; lessin2015 IV-C: a skill's switch, sigma); empty: no groups.
  std::string_view group_fn;
  // what only the operators keep (validate() does not require them)
  OperatorScheme operators;
  /// New edges sit on the parent's face lattice (miconi2006 sec. 2: a face and
  /// polar angles), else anywhere on a face with a free orientation.
  bool edge_lattice;
  bool edge_scale_free;       ///< false: every edge's scale is 1
  bool edge_terminal_only;    ///< edges may be terminal-only (Sims 1994)
  /// Every limb carries one joint-angle sensor and one actuator, the root
  /// none (miconi2006 sec. 3.1, Fig. 1).
  bool limb_io;
  /// New neurons and effectors draw their inputs by filling connection slots
  /// (miconi2006 sec. 3), else a count from the operator ranges.
  bool slot_wiring;
  /// Every effector is a muscle (EffectorGene::muscle), the only actuators
  /// (lessin2015 III-E); else effectors drive joint degrees of freedom.
  bool muscle_effectors;
  /// A part and its parent collide, so shapes limit joints (lessin2015 III-B);
  /// else joined parts pass through each other (JointModel::parts_collide).
  bool joined_parts_collide;
};

/// Muscle strength (N/m at full activation) a genome may give (validate()):
/// positive and below a bound far past any useful spring (lessin2015 gives none).
inline constexpr double kMaxMuscleStrength = 1e7;

/// The rules of a dialect.
const DialectRules& dialect_rules(Dialect d);

/// Parses "sims1994", "miconi2006", "chaumont2007", "lessin2015".
std::optional<Dialect> parse_dialect(std::string_view name);

/// Shortest and longest delay of a catapult's release mechanism (brain
/// steps). The mechanism is a constant feeding a chaumont2007 `mem` neuron of
/// n = delay - 1 (the constant itself takes one step), and mem's n is in
/// [1, 1000].
inline constexpr int kMinReleaseDelaySteps = 2;
inline constexpr int kMaxReleaseDelaySteps = 1001;

/// Ranges of a part's physical values, checked by validate() on the genes and
/// by develop() on every grown part (whose size compounds its edges' scales).
/// Physically generous (a 0.1 mm grain to a 10 km block, aerogel to ten times
/// the densest metal) and far inside double precision: they keep masses
/// within about [5e-16, 1e18] kg and moments of inertia within about
/// [5e-25, 1e26] kg m^2, while ODE's mass check and its quaternion
/// normalisation assert on values near the ends of double precision (sizes
/// 1e-308 or 1e308, densities 5e-324 or 1e200 did; docs/fuzzing.md).
inline constexpr double kMinPartSize = 1e-4;     ///< m, each extent
inline constexpr double kMaxPartSize = 1e4;      ///< m, each extent
inline constexpr double kMinDensity = 1e-3;      ///< kg/m^3
inline constexpr double kMaxDensity = 1e6;       ///< kg/m^3
inline constexpr double kMinEdgeScale = 1e-3;    ///< an edge's size factor
inline constexpr double kMaxEdgeScale = 1e3;
/// A grown part's mass (kg) must lie within these, or it is not viable: a
/// guard for every mass rule (the ranges above keep density x volume well
/// inside). With extents in [kMinPartSize, kMaxPartSize] its principal
/// moments of inertia (mass x (a^2 + b^2) / 12 for a box, 2/5 mass r^2 for a
/// sphere) then lie within [1e-29, 2e27] kg m^2: positive and finite, as
/// ODE's mass check needs, so they need no check of their own.
inline constexpr double kMinPartMass = 1e-20, kMaxPartMass = 1e20;

/// Checks a genome against its dialect and against itself (edge targets,
/// source indices, neuron functions and parameter ranges, sensor and
/// effector degrees of freedom, sizes, densities and edge scales within the
/// ranges above). The error names the field as a path such as
/// `nodes[2].joint.limits[0]` and the bad value. A catapult (Genome::catapult,
/// chaumont2007 only) also needs: a projectile node other than the root, a
/// box with a fixed joint (the one exception to the dialect's joint types),
/// no neurons, sensors, effectors or edges and recursive limit 1; exactly one
/// edge to it, from node 0 (the arm), unreflected, not terminal-only, scale 1;
/// no edge to node 0; a delay in [kMinReleaseDelaySteps, kMaxReleaseDelaySteps]; release inputs
/// that are valid sources of node 0 (no "parent"), none through the
/// projectile's edge. The projectile counts towards the dialect's max_genes.
Status validate(const Genome& g);

}  // namespace bx
