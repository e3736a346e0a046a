// Genetic operators per dialect (docs/papers.md S0-S2): random creation,
// mutation, crossover and grafting. Every constant lives in OperatorDef, with
// its defaults in one place (default_operators); docs/operators.md describes
// each operator, every constant's source and the repair rules.
//
// All randomness comes from the Rng passed in: the same inputs and generator
// state give the same output. Every output passes validate(); whether it is
// viable (no self-intersection, not too many parts) is checked by develop(),
// and the caller regenerates non-viable children (miconi2006 5.2,
// chaumont2007 5.5).
#pragma once

#include <utility>
#include <vector>

#include "core/math.h"
#include "core/rng.h"
#include "genome/genome.h"

namespace bx {

/// An inclusive range of integers.
struct IntRange {
  int lo = 0;
  int hi = 0;
  friend bool operator==(const IntRange&, const IntRange&) = default;
};

/// An inclusive range of reals.
struct Range {
  double lo = 0;
  double hi = 0;
  friend bool operator==(const Range&, const Range&) = default;
};

/// The steps of miconi2006's mutation (sec. 5.1), in the paper's order.
/// OperatorDef::miconi_steps switches steps on and off (all on by default;
/// tests run one step at a time).
enum MiconiStep : unsigned {
  kMiconiDeleteLimb = 1u << 0,   ///< (1) delete a random limb and its sub-limbs
  kMiconiAddLimb = 1u << 1,      ///< (2) add a random limb to a random limb
  kMiconiNeuronSlots = 1u << 2,  ///< (3) flip each of the neuron slots of every limb
  kMiconiThresholds = 1u << 3,   ///< (4) threshold +- U(step) on the torus
  kMiconiActivation = 1u << 4,   ///< (5) change the activation function
  kMiconiConnSlots = 1u << 5,    ///< (6) flip each connection slot
  kMiconiWeights = 1u << 6,      ///< (7) weight +- U(step) on the torus
  kMiconiSources = 1u << 7,      ///< (8) reassign the source of a connection
  kMiconiMorphology = 1u << 8,   ///< (9) one of seven morphological mutations per limb
  kMiconiAllSteps = (1u << 9) - 1,
};

/// Probabilities of the structural mutations of graph genomes (sims1994,
/// chaumont2007): each is tried once per mutate() call, independently of the
/// per-parameter rate. All are our choice: Sims (1994) names these
/// mutations but gives no frequencies.
struct StructuralRates {
  double add_node = 0;         ///< a random node, joined by a new edge from an existing node
  double remove_node = 0;      ///< a random non-root node (and what only it reached)
  double add_edge = 0;         ///< a new edge between two random nodes (reflexive allowed)
  double remove_edge = 0;      ///< a random edge (and what only it reached)
  double retarget_edge = 0;    ///< point a random edge at another random node
  double add_neuron = 0;       ///< a random neuron in a random node (or a global one)
  double remove_neuron = 0;    ///< a random neuron (node or global)
  double add_sensor = 0;       ///< a random sensor on a random node
  double remove_sensor = 0;    ///< a random sensor
  double add_effector = 0;     ///< an effector on a random degree of freedom
  double remove_effector = 0;  ///< a random effector
  double change_fn = 0;  ///< a random neuron's function (params reset, inputs fitted to the arity)
  /// A random input for a random weighted-sum neuron or effector that may
  /// take one (lessin2015 IV-B: a skill being learned wires into the muscles
  /// and the switches of the skills it uses). 0 in every dialect's defaults:
  /// config operators.add_input. Tried only when above 0 (no draw otherwise).
  double add_input = 0;
  /// A random ungated input of such a unit removed (config operators.remove_input).
  double remove_input = 0;
  friend bool operator==(const StructuralRates&, const StructuralRates&) = default;
};

/// Catapult genomes (chaumont2007 4.1). With `enabled`, random_genome()
/// makes catapults; mutate(), crossover() and graft() keep a catapult (the
/// first parent) a catapult, one arm and one projectile, the mechanism
/// unchanged but for its input wiring, whatever `enabled` says: its locks.
struct CatapultDef {
  bool enabled = false;
  /// The projectile of a random catapult: a box of this size and density.
  /// Our choice (the paper gives none): a 15 cm cube of water, 3.4 kg.
  Vec3 projectile_size{0.15, 0.15, 0.15};
  double projectile_density = 1000;
  /// Whether mutation changes the projectile's size (chaumont2007 4.2: "in
  /// some experiments"); within size_min..size_max of the body's parts.
  /// Random catapults' projectiles get no body lock then.
  bool mutate_projectile = false;
  /// The mechanism's delay (chaumont2007 4.1: 30 steps = 0.5 s at 60 Hz).
  int release_delay_steps = 30;
  /// Inputs from the body's network to the release of a random catapult.
  /// Our choice.
  IntRange release_inputs_at_creation{0, 2};
  friend bool operator==(const CatapultDef&, const CatapultDef&) = default;
};

/// Every constant of the operators of one dialect. The values live in one
/// place, default_operators() (as Box2D's b2DefaultBodyDef): start from it and
/// override fields; a value-initialized OperatorDef is not meaningful. Each
/// field says where its default comes from ("our choice" where the paper is
/// silent); docs/operators.md tabulates them.
struct OperatorDef {
  Dialect dialect = Dialect::Sims1994;

  // ---- genes
  /// Genes of a random genome, uniform in this range (our choice, 2-5; at
  /// least 2: one limb to move).
  IntRange genes_at_creation{};
  /// No operator makes a genome with fewer genes (miconi2006 5.1: "no
  /// creature may have less than two limbs"; our choice for the others).
  /// Crossover of graph genomes may still drop unreachable nodes below it.
  int min_genes = 0;
  /// No operator makes a genome with more genes: the dialect's limit
  /// (miconi2006 Table 1: 7; chaumont2007 5.5: 20), or our choice (sims1994).
  int max_genes = 0;
  /// A random genome with more parts after development than this is drawn
  /// again (0: the dialect's max_parts). Our choice.
  int max_parts_at_creation = 0;

  // ---- bodies
  /// Range of each dimension (full extents x = length, y, z) of a random
  /// part, and the clamp of size mutations. Our choice (see the docs for
  /// miconi2006: limb mass 0.8 tanh(xyz), motors 4 N).
  Vec3 size_min{};
  Vec3 size_max{};
  /// Density of new parts, kg/m^3 (our choice: water, the genome default).
  double density = 0;
  /// Whether mutation changes density, and within which range (our choice:
  /// fixed; miconi2006 ignores density, its mass is 0.8 tanh(xyz)).
  bool mutate_density = false;
  Range density_range{};
  /// Relative weights of shapes and joint types in random parts (only those
  /// the dialect allows are drawn). Our choice.
  std::vector<std::pair<Shape, double>> shape_weights;
  std::vector<std::pair<JointType, double>> joint_weights;
  /// Angular joint limits of a random joint: lo in [-max, -min], hi in
  /// [min, max] (rad); mutation keeps lo in [-pi, 0] and hi in [0, pi].
  /// Our choice (0.3, pi/2). miconi2006 has fixed limits (empty:
  /// development applies [-3pi/4, 3pi/4], Table 1).
  double angle_limit_min = 0;
  double angle_limit_max = 0;
  /// Linear limits (slider, cylindrical translation): lo in [-max, 0], hi in
  /// [0, max], metres, at creation and in mutation. Our choice (0.2).
  double slide_limit_max = 0;
  /// Highest recursive limit (creation and mutation). Our choice.
  int recursive_limit_max = 0;
  /// Edge scale range (creation draws from scale_at_creation). Our choice.
  Range scale_range{};
  Range scale_at_creation{};
  /// Creation: per node, probability of a reflexive edge (recursion, the
  /// node's recursive limit then drawn in [2, recursive_limit_max]) and of
  /// one extra edge to a random node. Our choice.
  double p_reflexive_edge = 0;
  double p_extra_edge = 0;
  /// Probability that a random limb is reflected. miconi2006 4.1: P_ref =
  /// 0.1 (across the parent's xz plane); graph dialects: our choice 0.2,
  /// across the plane of the face the limb is attached to.
  double p_reflect = 0;
  /// Probability that a random edge is terminal-only. Our choice.
  double p_terminal_only = 0;
  /// Largest |roll| of a random edge about the face normal (rad). Our choice;
  /// miconi2006 has no roll (two polar angles only, sec. 2).
  double edge_roll_max = 0;
  /// Creation: a new limb's direction is drawn again (up to 32 times) while
  /// the limb overlaps its neighbours or lies closer than this to a
  /// sibling's direction (or a reflected copy's). Our choice (pi/3); it makes
  /// random creatures likely viable.
  double min_sibling_angle = 0;

  // ---- brains
  /// Neurons per part of a random genome (miconi2006: our choice, within its
  /// 6 slots; Table 1 gives the maximum only).
  IntRange neurons_at_creation{};
  /// Global neurons of a random genome (dialects that have them). Our choice.
  IntRange global_neurons_at_creation{};
  /// Sensors per part of a random genome (graph dialects; miconi2006: one
  /// joint-angle sensor per non-root limb, sec. 3.1). Our choice.
  IntRange sensors_at_creation{};
  /// Graph dialects: probability that a random non-root part gets an
  /// effector on each degree of freedom of its joint. Our choice.
  double p_effector_per_dof = 0;
  /// Graph dialects: inputs of a random effector. Our choice.
  IntRange effector_inputs_at_creation{};
  /// Muscle dialects (lessin2015): muscles of a random non-root part, to
  /// its parent (two make an antagonistic pair). Our choice.
  IntRange muscles_at_creation{};
  /// Muscle dialects: a random muscle's strength, log-uniform, and the range
  /// mutation keeps it in (N/m at full activation; lessin2015 gives none).
  Range muscle_strength_range{};
  /// Fraction of connection slots filled in a new miconi2006 neuron or
  /// actuator (Table 1: 75%). Positional neurons fill every argument.
  double connection_fraction = 0;
  /// Connection slots per neuron or actuator (miconi2006 Table 1: 3).
  int connection_slots = 0;
  /// Neuron slots per limb (miconi2006 Table 1: 6).
  int neuron_slots = 0;
  /// Range of input weights: miconi2006 sec. 3: [-1, 1] (a torus for
  /// mutation); graph dialects: our choice.
  Range weight_range{};
  /// Range of neuron thresholds (miconi2006 sec. 3: [-3/2, 3/2], a torus for
  /// mutation) and of effector biases. Graph dialects: our choice.
  Range bias_range{};
  Range effector_bias_range{};
  /// Graph dialects: share of new neurons that are global. Our choice.
  double p_global_neuron = 0;
  /// Graph dialects: the chance that the add_neuron mutation puts its neuron
  /// in front of a unit: a random weighted-sum neuron or effector that may
  /// take an input (as add_input draws them) reads the new neuron, placed in
  /// that unit's node (a global unit's: global). Otherwise (and when no unit
  /// may take one) the new neuron has no reader until a later mutation wires
  /// it, as Sims' does. 0 in every dialect's defaults (no draw then): config
  /// operators.wired_neurons. A new ESP skill grows its control this way in
  /// front of the shared muscles (lessin2015 IV-B): on a frozen genome an
  /// unread neuron changes nothing.
  double p_wired_neuron = 0;

  // ---- mutation (the per-parameter rate is mutate()'s argument: the
  // evolutionary loop's EvolutionDef holds the rates and the operator mix)
  /// miconi2006 5.1: thresholds and weights move by U(-0.33, 0.33) on their torus.
  double bias_step = 0;
  double weight_step = 0;
  /// miconi2006 sec. 2: edge angles are multiples of pi/8. Sec. 5.1 says a
  /// mutated angle is a multiple of pi/4 within +-pi/2 of the current value:
  /// we keep pi/8 as the lattice and draw the new value within +-pi/2 on it
  /// (our reading of the contradiction).
  double angle_step = 0;
  double angle_mutation_range = 0;
  /// Which of miconi2006's mutation steps run (MiconiStep bits).
  unsigned miconi_steps = 0;
  /// Graph dialects: a mutated real moves by a Gaussian with this standard
  /// deviation times its range (parameters, at, limits, weights, biases).
  /// Our choice, after Sims' "scaled relative to the range".
  double param_sigma = 0;
  /// Graph dialects: sizes and scales are multiplied by exp(N(0, size_sigma)).
  double size_sigma = 0;
  /// Graph dialects: edge angles and joint axes move by N(0, angle_sigma) rad.
  double angle_sigma = 0;
  /// Structural mutations of graph genomes (per mutate() call).
  StructuralRates structure;

  // ---- catapults
  CatapultDef catapult;

  /// A reconciliation stage's skill (lessin2015 Algorithm 2, genome/reconcile.h;
  /// set from the stage's `reconcile` key, not a config key): when set, the
  /// graph operators change only that skill's wires' weights (mutation) and
  /// mix them (crossover and grafting), and nothing else.
  std::string reconcile_skill;
  friend bool operator==(const OperatorDef&, const OperatorDef&) = default;
};

/// The defaults of dialect `d`: the papers' constants and our choices.
OperatorDef default_operators(Dialect d);

/// A random genome of `d` (`def.dialect` is ignored in favour of `d`).
/// With def.catapult.enabled and `d` chaumont2007, a random catapult
/// (random_catapult()); other dialects ignore the flag.
Genome random_genome(Dialect d, const OperatorDef& def, Rng& rng);

/// Mutates `g` in place. `rate` is the per-parameter probability
/// (miconi2006: P_mut for every step; graph dialects: every numeric field;
/// their structural mutations use def.structure). Rate 0 leaves a
/// miconi2006 genome unchanged. A catapult stays one: its arm and body
/// mutate as a genome of max_genes - 1; its release inputs, the projectile's
/// attachment and (with def.catapult.mutate_projectile) the projectile's
/// size at `rate`; never the release delay.
void mutate(Genome& g, const OperatorDef& def, double rate, Rng& rng);

/// Crossover (miconi2006 5.1, Sims 1994): the node lists of both parents
/// aligned, the child takes nodes [0, cut) from `a` and [cut, end) from `b`
/// for a random cut, then is repaired. Parents must share a dialect.
/// Catapults (chaumont2007 Fig. 6): the bodies are crossed (the projectile
/// left out of the rows); the child gets the projectile, its edge and the
/// release mechanism of `a` (of `b` if only `b` is a catapult).
Genome crossover(const Genome& a, const Genome& b, Rng& rng);

/// Crossover at a given cut (nodes [0, cut) from `a`, [cut, end) from `b`;
/// cut is clamped to [1, max(sizes)]), as crossover() after drawing the cut.
/// For tests and callers that choose the cut themselves. For catapults the
/// cut indexes the bodies' rows (each parent without its projectile).
Genome crossover_at(const Genome& a, const Genome& b, int cut, const OperatorDef& def, Rng& rng);

/// Grafting: the trunk comes from `trunk`, a new branch from `branch`
/// (miconi2006 5.1: a branch of the trunk replaced by a branch of the other
/// parent; Sims 1994: an edge of the trunk pointed at a copy of a subgraph of
/// the other parent). The root is the trunk's. Catapults (chaumont2007
/// Fig. 5): the arm, projectile and release mechanism are the trunk's (the
/// branch's if only the branch is a catapult); the branch is a subgraph of
/// the other body, never its arm or projectile.
Genome graft(const Genome& trunk, const Genome& branch, Rng& rng);

/// Crossover and graft with explicit constants (def.max_genes, the lattice,
/// ...); the forms without `def` use default_operators(a.dialect).
Genome crossover(const Genome& a, const Genome& b, const OperatorDef& def, Rng& rng);
Genome graft(const Genome& trunk, const Genome& branch, const OperatorDef& def, Rng& rng);

// ---------------------------------------------------------------- building blocks
// Shared by the operators and usable on their own.

/// A standard normal draw (Box-Muller; uses two uniforms).
double normal(Rng& rng);

/// The ranges a dialect and a def allow together: input weights, neuron
/// biases (thresholds; positional neurons have none) and effector biases.
Range weight_bounds(const OperatorDef& def, Dialect d);
Range bias_bounds(const OperatorDef& def, Dialect d);
Range effector_bias_bounds(const OperatorDef& def, Dialect d);

/// A random unit vector (uniform on the sphere): a photoreceptor's or a
/// muscle anchor's direction from its part's centre.
Vec3 random_direction(Rng& rng);

/// A random muscle (lessin2015 III-E): random anchor directions on the
/// parent and on the part, a strength log-uniform in def.muscle_strength_range.
MuscleGene random_muscle(const OperatorDef& def, Rng& rng);

/// A random part of `d`'s dialect: shape, size, joint, sensors, effectors
/// and neurons (without inputs). A root part has no joint-angle sensor and
/// no effector (miconi2006 Fig. 1: the root has no sensor or actuator).
NodeGene random_part(Dialect d, bool root, const OperatorDef& def, Rng& rng);

/// A random edge from node `parent` to node `to` (not added to the genome):
/// the child extends along a random direction (miconi2006: polar angles on
/// the pi/8 lattice) from where the ray from the parent's centre leaves it,
/// away from the parent's other children and, for a non-root parent, from
/// its own joint (the parent's -x side). Reflected with def.p_reflect
/// (miconi2006: across the parent's xz plane, attached on its +-y face;
/// graph dialects: across the plane of the face it is attached to).
EdgeGene random_edge(const Genome& g, int parent, int to, const OperatorDef& def, Rng& rng);

/// A random part appended to `g` and joined by random_edge() from
/// `parent`. Returns its index. Its inputs are not wired: call wire_node().
int add_random_node(Genome& g, int parent, const OperatorDef& def, Rng& rng);

/// A random neuron of the dialect's set, without inputs: a random function,
/// parameters uniform in their ranges, a random threshold if it takes one.
NeuronGene random_neuron(Dialect d, const OperatorDef& def, Rng& rng);

/// A random input of node `owner` (-1: a global neuron): a random source
/// among source_candidates(), a random weight. False if there is none.
bool random_input(const Genome& g, int owner, const OperatorDef& def, Rng& rng, InputGene& out);

/// Replaces every input of every neuron and effector of node `n` (-1: the
/// global neurons) with random ones: miconi2006 fills each of the
/// connection slots with probability def.connection_fraction; positional
/// neurons get one input per argument; graph effectors a number in
/// def.effector_inputs_at_creation.
void wire_node(Genome& g, int n, const OperatorDef& def, Rng& rng);

/// Inputs for one neuron or effector of `owner` as wire_node() makes them.
std::vector<InputGene> random_inputs(const Genome& g, int owner, int count, const OperatorDef& def,
                                     Rng& rng);

/// Brings a genome back within its dialect's structural rules after an
/// edit: unreachable nodes dropped; miconi2006 limbs carry exactly one
/// joint-angle sensor and one actuator (the root none), hinges on y or z,
/// angles on the lattice; graph dialects: allowed shapes, joints, sensors;
/// dofs, arities and parameters within range; canonical unused fields;
/// every source existing (reassigned at random otherwise). A catapult's
/// projectile stays a box grown once on its fixed joint.
void normalize(Genome& g, const OperatorDef& def, Rng& rng);

// ---------------------------------------------------------------- catapults
// chaumont2007 section 4 (docs/operators.md, "Catapults"). A catapult's arm
// and projectile are locked (genome/locks.h), so the ordinary operators keep
// it one arm and one projectile; mutation also rewires its release.

/// Whether `g` is a catapult: Genome::catapult set, naming a node other
/// than the root as its projectile.
bool is_catapult(const Genome& g);

/// The lock of a catapult's projectile: its joint, units and edges, and its
/// body unless its size may mutate (chaumont2007 4.2, "in some
/// experiments": CatapultDef::mutate_projectile). The arm's lock is
/// kLockInEdges (no second arm).
unsigned catapult_projectile_lock(bool mutable_size);

/// A random catapult (chaumont2007 4.1, Fig. 3): a random chaumont2007
/// genome of at most max_genes - 1 genes whose root is the arm (edges back
/// to the root removed), its release fed by a number of random sources of
/// the arm in def.catapult.release_inputs_at_creation and delayed
/// def.catapult.release_delay_steps; the projectile (a box of
/// def.catapult.projectile_size and projectile_density on a fixed joint) is
/// node 1, held by the arm's last edge, placed as random_edge() places a
/// limb (clear of the arm's other children where it can; scale 1, no
/// reflection, not terminal-only). The arm and projectile are locked.
Genome random_catapult(const OperatorDef& def, Rng& rng);

}  // namespace bx
