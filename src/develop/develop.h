// Development: the compiler from Genome to CreatureModel (docs/design.md).
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "develop/creature_model.h"
#include "genome/genome.h"

namespace bx {

/// Settings of development. Defaults come from the genome's dialect.
struct DevelopDef {
  /// Most parts after development; 0 takes the dialect's max_parts.
  int max_parts = 0;
  /// An encapsulated skill to run alone (lessin2015 IV-B, genome/encapsulate.h;
  /// config brain.skill): its switch is held at 1, and the wires of the skill
  /// being learned (effectors' biases and ungated inputs, switches' ungated
  /// inputs) are cut, so every other switch follows only the encapsulated
  /// skills' wires: those the selected skill drives (its subskills') pass,
  /// the rest read 0, as when it was learned. Empty: the switches follow
  /// the brain. A genome without that skill does not develop.
  std::string skill;
  /// Self-intersection test: parts are shrunk by this much (m) on every side,
  /// so parts that merely touch are not counted as overlapping.
  double overlap_margin = 0.005;
  /// Largest extent (m) of the creature's starting pose, its body length;
  /// 0: no limit (as in the papers). Recursive edges compound their scale
  /// (1.5 per level can grow 0.6 m genes into 9 m blocks), and a throwing task
  /// rewards giants that topple from a height.
  double max_body_length = 0;
  /// Where joined parts collide (lessin2015 III-B: "limitations on joint
  /// movement ... through natural collisions between adjacent segments"), a
  /// child starts this share of its half-thickness (a sphere's or capsule's
  /// radius, a box's thinner half-extent across its length) off its parent,
  /// the joint's anchor on the parent's surface: flush, a box child could
  /// not turn at all (its corner digs into the parent's face at once); at 1
  /// it turns up to 45 degrees about its thinner side before its corner
  /// meets the parent. Other dialects: flush, as Sims.
  double collide_gap = 1.0;
  /// A muscle's rest length as a share of its built length (lessin2015 III-E
  /// gives none): below 1, an active muscle contracts, so a pair across a
  /// joint moves it; at 1 a muscle could only hold the pose it was built in.
  double muscle_rest_fraction = 0.5;
  /// Where joined parts collide, a prismatic or cylindrical joint whose gene
  /// gives no limits slides at most this share of its child's half-thickness
  /// either way. Collisions stop a child sliding into its parent, never away
  /// from it: unlimited, a slider lets its child drift off (an evolved
  /// lessin2015 "walker" spread its parts 3.5 m along free sliders and
  /// stopped). lessin2015 III-B says "most" limits come from collisions;
  /// PhysX's prismatic joint, as ODE's, is free unless limited.
  double slide_range = 1.0;
  /// A muscle shorter than this as built (m) is not viable: its direction,
  /// and so its force, would be undefined.
  double min_muscle_length = 1e-3;
  friend bool operator==(const DevelopDef&, const DevelopDef&) = default;
};

/// What development made of a genome: a viable creature, or the reason it is
/// not viable. Non-viability is a value, never an exception.
struct Development {
  std::optional<CreatureModel> model;
  std::string reason;  ///< empty when viable
  bool viable() const { return model.has_value(); }
};

/// Grows the genome from its root: honours recursive limits, terminal-only
/// edges, reflections (mirrored geometry, joint axes and contact faces) and
/// scale; places each child by its edge; compiles the brain into flat arrays.
/// The genome must be valid (see validate()). Not viable when it would grow
/// more than max_parts parts, when two parts not joined to each other overlap,
/// or when its body is longer than max_body_length.
Development develop(const Genome& g, const DevelopDef& def = {});

/// Development's self-intersection test: the first pair of parts, not joined
/// by a joint, whose shapes (each shrunk by `margin` metres on every side)
/// overlap at the initial pose; {-1, -1} if none (geometry/overlap.h). A
/// part and its parent count as not joined when their joint lets them
/// collide (JointModel::parts_collide, lessin2015). Part
/// `released` (a catapult's projectile, whose joint breaks) may not overlap
/// its parent either: once free, the contact would push it out at the
/// solver's correcting speed, a launch by constraint error (docs/physics.md).
std::pair<int, int> find_self_intersection(const CreatureModel& m, double margin, int released = -1);

}  // namespace bx
