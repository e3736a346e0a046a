// The Sims directed-graph genome (docs/papers.md S0): morphology nodes joined by
// connections (edges), each node carrying its part's neurons, sensors and
// effectors. This is what evolution edits; development compiles it into an
// immutable CreatureModel and the simulation never reads it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "brain/brain_model.h"
#include "core/math.h"

namespace bx {

/// Which paper's constraints and neuron set a genome follows.
enum class Dialect { Sims1994, Miconi2006, Chaumont2007, Lessin2015 };

/// Primitive shape of a part. Dimensions (`NodeGene::size`) are full extents
/// along the part's local x, y, z: a sphere uses x as its diameter; a capsule
/// or cylinder lies along local x with length x and diameter y.
enum class Shape { Box, Sphere, Capsule, Cylinder };

/// Joint from a part to its parent. Degrees of freedom, in order:
/// hinge: 1 (axis1); universal: 2 (axis1, axis2); spherical: 3 (Euler angles
/// about axis1, the third axis, axis2); slider: 1 (translation along axis1);
/// cylindrical: 2 (translation along axis1, rotation about axis1); fixed: 0.
enum class JointType { Fixed, Hinge, Universal, Spherical, Slider, Cylindrical };

/// Number of degrees of freedom of a joint type.
int joint_dofs(JointType t);

/// A face of a part's bounding box: the outward normal's axis and sign.
enum class Face { PosX, NegX, PosY, NegY, PosZ, NegZ };
inline int face_axis(Face f) { return static_cast<int>(f) / 2; }
inline double face_sign(Face f) { return static_cast<int>(f) % 2 == 0 ? 1.0 : -1.0; }
inline Face make_face(int axis, double sign) {
  return static_cast<Face>(axis * 2 + (sign > 0 ? 0 : 1));
}

/// Lower and upper limit of one degree of freedom (radians or metres).
struct Limit {
  double lo = 0;
  double hi = 0;
  friend bool operator==(const Limit&, const Limit&) = default;
};

/// The joint that attaches a node's part to its parent. Axes are unit
/// vectors in the child part's local frame.
struct JointGene {
  JointType type = JointType::Hinge;
  Vec3 axis1{0, 0, 1};
  Vec3 axis2{0, 1, 0};
  /// One entry per degree of freedom; empty means unlimited.
  std::vector<Limit> limits;
  friend bool operator==(const JointGene&, const JointGene&) = default;
};

/// Where a neuron or effector input reads from, relative to the part
/// instance that owns the neuron.
enum class SourcePlace { Self, Parent, Child, Root, Global };
/// What it reads there: a neuron's output, a sensor's reading, or the
/// length of a muscle (the proprioceptive node each muscle adds, lessin2015
/// III-E; `index` is the muscle's effector index on that part).
enum class SourceKind { Neuron, Sensor, Muscle };

/// One weighted input of a neuron or effector.
/// `Child` sources read the part grown through `edge` (an index into the
/// owning node's `edges`); when that edge grows several instances (reflection)
/// they read the first, unreflected one (a mirrored parent reads its own
/// unreflected child, so the wiring is mirrored too). A source that does not exist in the developed
/// creature (no parent for the root, an edge that grew nothing, a recursion
/// cut short) reads 0 and is reported as a development warning.
///
/// A gated input (lessin2015 IV-B's encapsulation, genome/encapsulate.h) is
/// a wire leaving an encapsulated skill: its signal is multiplied by the
/// output of the skill's switch, global neuron `gate`, read in the same step
/// as its source (so a switch at 1 passes the wire bit for bit, at 0 silences
/// it). A gated input is frozen: no operator changes or removes it.
struct InputGene {
  /// No gate (InputGene::gate).
  static constexpr int kNoGate = -1;
  SourcePlace place = SourcePlace::Self;
  SourceKind kind = SourceKind::Neuron;
  int index = 0;
  int edge = 0;
  double weight = 1.0;
  int gate = kNoGate;  ///< the global neuron (a skill's switch) that scales it, or kNoGate
  friend bool operator==(const InputGene&, const InputGene&) = default;
};

/// A neuron: a function of the dialect's neuron set with its parameters
/// (by the function's parameter order), a bias (threshold theta of
/// weighted-sum neurons; 0 for positional ones) and inputs.
struct NeuronGene {
  /// No pandemonium group (NeuronGene::group).
  static constexpr int kNoGroup = -1;
  std::string fn;
  std::vector<double> params;
  double bias = 0;
  std::vector<InputGene> inputs;
  bool locked = false;  ///< no operator changes or removes it (genome/locks.h)
  /// Pandemonium group (lessin2015 IV-C), or kNoGroup: every developed copy
  /// of every neuron with the same group id competes, and at each brain step
  /// only the largest output passes (brain/pandemonium.h). Only a lessin2015
  /// `sigma` (a skill's switch) may have one. Set by the syllabus, never by
  /// an operator: mutation, crossover and random genomes copy it or leave it
  /// out.
  int group = kNoGroup;
  /// A skill's switch (lessin2015 IV-B's sigma node, genome/encapsulate.h):
  /// the name of the encapsulated skill whose outgoing wires it gates, or
  /// empty. A switch is a global neuron of the dialect's group_fn; its
  /// function, bias and gated inputs are frozen, never removed; while it is
  /// not `locked` ("open" to the skill being learned) new inputs may join.
  std::string skill{};
  friend bool operator==(const NeuronGene&, const NeuronGene&) = default;
};

/// Kinds of sensor a part can carry.
enum class SensorType {
  JointAngle,
  Contact,
  /// lessin2015 III-D: the light it sees along its direction
  Photoreceptor,
  /// lessin2015 III-E: a muscle's length (not a gene of its own: every muscle
  /// adds one, read through SourceKind::Muscle)
  MuscleLength,
};

/// A sensor of a part: joint angle of one degree of freedom of the part's
/// joint to its parent (scaled to [-1,1]), contact on one face (+1/-1), or a
/// photoreceptor looking along `direction` from the part's centre, sitting
/// where that direction meets the part's surface (lessin2015 III-D).
struct SensorGene {
  SensorType type = SensorType::JointAngle;
  int dof = 0;
  Face face = Face::NegZ;
  Vec3 direction{1, 0, 0};  ///< Photoreceptor: in the part's frame, not zero (any length)
  bool locked = false;  ///< no operator changes or removes it (genome/locks.h)
  friend bool operator==(const SensorGene&, const SensorGene&) = default;
};

/// A muscle (lessin2015 III-E) between a part and its parent: "two
/// attachment points on adjacent segments, along with a maximum strength".
/// Each point is where a direction from its part's centre meets that part's
/// surface (as a photoreceptor's), so it stays on the surface whatever the
/// part's size. The parent's direction is given in the frame of the edge
/// that grows the part (x out of the parent's face, as the child extends),
/// so every copy grown by multiple, recursive or reflected edges pulls from
/// its own side of the parent. Development makes it a spring whose
/// stiffness the activation sets (MuscleModel).
struct MuscleGene {
  Vec3 parent_dir{0, 0, 1};  ///< from the parent's centre, in the growing edge's frame; not zero
  Vec3 child_dir{0, 0, 1};   ///< from this part's centre, its own frame; not zero
  double strength = 100;     ///< N/m: its stiffness at full activation
  friend bool operator==(const MuscleGene&, const MuscleGene&) = default;
};

/// An effector driving one degree of freedom of the part's joint to its
/// parent, or, in a dialect whose actuators are muscles (lessin2015), the
/// activation of `muscle`. Its signal is the dialect's squashing of (sum of
/// weighted inputs + bias) into the neuron set's range; the motor model
/// (config) turns it into force.
struct EffectorGene {
  int dof = 0;  ///< the joint's degree of freedom; 0 for a muscle
  double bias = 0;
  std::vector<InputGene> inputs;
  std::optional<MuscleGene> muscle = std::nullopt;  ///< present exactly in muscle dialects
  bool locked = false;  ///< no operator changes or removes it (genome/locks.h)
  friend bool operator==(const EffectorGene&, const EffectorGene&) = default;
};

/// A connection from the owning node (parent) to node `to` (child).
/// The child is attached at point (u, v) in [-1,1]^2 of the parent's `face`
/// (u, v run along the face's two other axes in x,y,z order), rotated by
/// `rotation` (intrinsic x-y-z Euler angles) relative to a frame whose x axis
/// is the face's outward normal; the child's -x end sits at the attachment
/// point. `reflect` lists the parent's local planes (by normal axis 0,1,2)
/// across which mirrored copies are also grown (2^n instances).
struct EdgeGene {
  int to = 0;
  Face face = Face::PosX;
  double u = 0;
  double v = 0;
  Vec3 rotation{0, 0, 0};
  double scale = 1.0;
  std::vector<int> reflect;
  bool terminal_only = false;
  friend bool operator==(const EdgeGene&, const EdgeGene&) = default;
};

/// What of a node no operator may change (genome/locks.h): bits of
/// NodeGene::lock. ESP's encapsulated skills, Fast ESP's frozen skeleton and
/// a catapult's mechanism are all locks.
enum NodeLock : unsigned {
  kLockBody = 1,      ///< shape, size, density, recursive limit
  kLockJoint = 2,     ///< its joint to its parent: type, axes, limits
  kLockInEdges = 4,   ///< the edges that grow it: none added, removed, retargeted or changed
  kLockOutEdges = 8,  ///< its own edges: likewise
  kLockUnits = 16,    ///< its neurons, sensors and effectors: none added, removed or changed
};
constexpr unsigned kLockAll = 31;

/// A morphology node: one kind of part.
struct NodeGene {
  Shape shape = Shape::Box;
  Vec3 size{1, 1, 1};
  double density = 1000;  ///< kg/m^3 (water)
  JointGene joint;
  /// How many times this node may appear on one root-to-leaf path.
  int recursive_limit = 1;
  std::vector<NeuronGene> neurons;
  std::vector<SensorGene> sensors;
  std::vector<EffectorGene> effectors;
  std::vector<EdgeGene> edges;
  unsigned lock = 0;  ///< NodeLock bits
  friend bool operator==(const NodeGene&, const NodeGene&) = default;
};

/// A catapult's release mechanism (chaumont2007 4.1, Fig. 4). Fixed except
/// for its wiring: a constant feeds a delay of `delay_steps` brain steps, so
/// the release effector fires at that step at the latest; it fires earlier at
/// the first step where the weighted sum of `inputs` (signals of the body's
/// network, read as from the arm's part) reaches the firing threshold.
struct ReleaseGene {
  /// The weighted sum of `inputs` fires the release from this value on.
  static constexpr double kFiringThreshold = 0.5;
  int delay_steps = 30;  ///< chaumont2007 4.1: 30 steps (0.5 s at 60 Hz)
  std::vector<InputGene> inputs;
  friend bool operator==(const ReleaseGene&, const ReleaseGene&) = default;
};

/// What makes a genome a catapult (chaumont2007 4.1, Fig. 3): the root
/// (node 0) is the arm and carries the release mechanism; node `projectile`
/// is the block it throws: a box without neurons, sensors, effectors or
/// edges, grown once, through exactly one edge of the root (no reflection),
/// held by a fixed joint until the release breaks it. The other nodes form
/// the body.
struct CatapultGene {
  int projectile = 1;
  ReleaseGene release;
  friend bool operator==(const CatapultGene&, const CatapultGene&) = default;
};

/// A whole genome: node 0 is the root.
struct Genome {
  Dialect dialect = Dialect::Sims1994;
  std::vector<NodeGene> nodes;
  std::vector<NeuronGene> global_neurons;
  /// Present for catapults (chaumont2007 section 4), absent otherwise.
  std::optional<CatapultGene> catapult;
  friend bool operator==(const Genome&, const Genome&) = default;
};

std::string_view to_string(Dialect d);
std::string_view to_string(Shape s);
std::string_view to_string(JointType t);
std::string_view to_string(Face f);
std::string_view to_string(SourcePlace p);
std::string_view to_string(SensorType t);

}  // namespace bx
