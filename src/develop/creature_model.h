// CreatureModel: what development compiles a genome into. Immutable after
// construction and shared by every evaluation of the creature; the simulation
// reads only this, never the genome (docs/design.md: model vs data).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "brain/brain_model.h"
#include "core/math.h"
#include "genome/genome.h"

namespace bx {

using PartIndex = std::int32_t;
using JointIndex = std::int32_t;

/// One rigid part of a developed creature.
struct PartModel {
  Shape shape = Shape::Box;
  Vec3 size;          ///< full extents in the part's local frame (see Shape)
  double mass = 1;
  Pose pose;          ///< initial pose in the creature frame (root at origin)
  PartIndex parent = -1;
  int gene = 0;       ///< node index in the genome
  bool mirrored = false;  ///< grown through an odd number of reflections
  int depth = 0;      ///< edges from the root
};

/// The joint between a part and its parent. Anchor and axes are in the
/// creature frame at the initial pose; `child` moves relative to `parent`.
struct JointModel {
  JointType type = JointType::Hinge;
  PartIndex parent = 0;
  PartIndex child = 0;
  Vec3 anchor;
  Vec3 axis1{0, 0, 1};
  Vec3 axis2{0, 1, 0};
  std::vector<Limit> limits;  ///< per degree of freedom; empty: unlimited
  /// Its two parts collide with each other, so their shapes limit how far it
  /// turns (lessin2015 III-B: limits "through natural collisions between
  /// adjacent segments"); false, as in the other dialects: joined parts pass
  /// through each other. Whatever PhysicsDef::self_collision says, which is
  /// for parts not joined.
  bool parts_collide = false;
};

/// A sensor of the developed creature; its reading goes to brain slot
/// `index in CreatureModel::sensors`.
struct SensorModel {
  SensorType type = SensorType::JointAngle;
  PartIndex part = 0;
  JointIndex joint = -1;  ///< JointAngle: the part's joint to its parent
  int dof = 0;
  Face face = Face::NegZ; ///< Contact: face in the part's (proper) local frame
  /// Photoreceptor: its orientation in the part's frame (need not be unit
  /// length); it sits where that direction from the part's centre meets the
  /// part's surface (lessin2015 III-D)
  Vec3 direction{1, 0, 0};
  /// MuscleLength: an index into CreatureModel::muscles
  int muscle = -1;
};

/// A muscle (lessin2015 III-E): a spring between a point on each of two
/// parts whose stiffness its activation sets: `strength` at full
/// activation, none when silent; at `rest_length` it pulls and pushes nothing.
struct MuscleModel {
  PartIndex part_a = 0, part_b = 0;
  Vec3 anchor_a, anchor_b;  ///< its two ends, in the creature's frame at the initial pose (m)
  double strength = 0;      ///< N/m: its stiffness at full activation
  double rest_length = 0;   ///< m
  /// m: its length as built (its anchors' distance at the initial pose), the
  /// unit of its length sensor (SensorType::MuscleLength); 0: rest_length
  double length = 0;
};

/// An effector: brain effector i drives degree of freedom `dof` of `joint`,
/// or, under MotorModel::Muscle, activates muscle `muscle`.
struct EffectorModel {
  JointIndex joint = 0;
  int dof = 0;
  int muscle = -1;  ///< MotorModel::Muscle: an index into CreatureModel::muscles
  /// sims1994 torque mode: strength scales with the cross-section (area) of
  /// the larger of the two parts, perpendicular to the part's x axis.
  double cross_section = 1;
};

/// A developed creature.
struct CreatureModel {
  Dialect dialect = Dialect::Sims1994;
  std::vector<PartModel> parts;    ///< parts[0] is the root; parents precede children
  std::vector<JointModel> joints;  ///< joints[i] attaches some part to its parent
  std::vector<SensorModel> sensors;
  std::vector<EffectorModel> effectors;
  std::vector<MuscleModel> muscles;
  BrainModel brain;
  /// A catapult's projectile (chaumont2007 4.1) and the fixed joint that
  /// holds it to the arm until the release effector fires; -1 otherwise.
  PartIndex projectile = -1;
  JointIndex release_joint = -1;
  /// Non-fatal remarks from development (e.g. a neuron input whose source
  /// does not exist in this body and so reads 0).
  std::vector<std::string> warnings;

  int n_parts() const { return static_cast<int>(parts.size()); }
  double total_mass() const;
  /// Largest extent of the creature's bounding box at the initial pose (m):
  /// the "body length" of locomotion results.
  double body_length() const;
  /// Lowest z of any part at the initial pose.
  double min_z() const;
};

}  // namespace bx
