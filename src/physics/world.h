// The physics world: one ODE world, a ground plane and the creature's parts,
// joints and motors. Every ODE call of Bestiary lives in physics/; the rest of
// the code speaks of parts, joints, motors and contacts.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/math.h"
#include "develop/creature_model.h"
#include "physics/physics_def.h"
#include "physics/world_edits.h"

namespace bx {

/// Reseeds ODE's process-wide random generator (QuickStep's constraint
/// order). Call before every evaluation for reproducible results.
void reseed_physics(std::uint64_t seed);

/// What a world has measured of its own accuracy since it was made: maxima
/// over every check_explosion() (joints) and every step (contacts).
struct WorldStats {
  double max_joint_gap = 0;       ///< m: the largest joint_gap() seen
  int worst_joint = -1;           ///< the joint that had it
  double max_stop_overshoot = 0;  ///< rad or m: farthest a degree of freedom went past its stop
  double max_penetration = 0;     ///< m: the deepest contact, with the ground or between parts
};

/// What a geom of the world belongs to: the ground, part `index` of the
/// creature, or prop `index` (World::add_prop).
struct WorldEntity {
  enum class Kind { Ground, Part, Prop };
  Kind kind = Kind::Ground;
  int index = 0;
  friend bool operator==(const WorldEntity&, const WorldEntity&) = default;
};

/// The nearest surface along a ray (World::ray).
struct RayHit {
  bool hit = false;
  double distance = 0;  ///< m from the ray's origin
  Vec3 point;           ///< where it struck (world frame)
  Vec3 normal;          ///< the surface's outward normal there
  WorldEntity entity;   ///< what it struck
};

/// A simulated world holding one creature. Not copyable; one per evaluation.
/// What a task may change in it (WorldEdits) it changes in ODE.
class World : public WorldEdits {
 public:
  explicit World(const PhysicsDef& def);
  ~World();
  /// How many worlds this process has made (diagnostics: what builds one;
  /// an evaluation of a kind without a body builds none).
  static long made();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Adds the creature's parts and joints, its frame placed at `placement`.
  /// Call once.
  void add_creature(const CreatureModel& m, const Pose& placement);

  /// Fixes part i to the static world (a pendulum's pivot, a test rig).
  void fix_part_to_world(int i);

  /// Breaks joint j for good (a catapult's release, chaumont2007 4.1): its
  /// child part flies free and from then on collides with every part,
  /// whatever self_collision says (it no longer belongs to the creature).
  /// Breaking a broken joint does nothing.
  void break_joint(int j) override;
  /// Whether joint j has been broken.
  bool joint_broken(int j) const;

  /// Sets every motor from the effector signals (in [-1,1], brain order).
  /// MotorModel::PD damps implicitly through each hinge's and universal
  /// joint's motor of its own, so it needs PoweredStops::Separate: under
  /// PoweredStops::Ode it throws std::invalid_argument. With kd = 0, and on
  /// sliders, pistons and ball joints (no motor of their own), the PD is an
  /// explicit torque from the angle and rate at the start of the step.
  void apply_effectors(const CreatureModel& m, const MotorDef& motor,
                       std::span<const double> signals);

  /// Brakes every motor: speed 0 with `share` of its full force (MotorDef::
  /// off_brake while a task holds the controller off; 1 to hold each joint
  /// still), in place of what apply_effectors set.
  void brake_effectors(const CreatureModel& m, const MotorDef& motor, double share);

  /// Advances one step: contacts, solver, then the contact flags of sensors.
  void step();

  /// Writes every sensor's reading into `out` (size = m.sensors.size()).
  void read_sensors(const CreatureModel& m, std::span<double> out) const;

  /// Empty if the world is sane, else why it exploded (NaN, too fast, a jump,
  /// a torn joint, or a step ODE's solver gave up on), naming the part or
  /// joint and the value, or ODE's message.
  std::string check_explosion();

  /// How far joint j has come apart now (m): the largest distance between
  /// the points it holds together on its two parts (PhysicsDef::max_joint_gap);
  /// for a slider or cylindrical joint, off its line or past its stops.
  /// 0 for a broken joint.
  double joint_gap(int j) const;
  /// Accuracy measured so far.
  const WorldStats& stats() const;

  /// Current pose of part i.
  Pose part_pose(int i) const;
  /// Current linear velocity of part i.
  Vec3 part_velocity(int i) const;
  /// Mass-weighted centre of the creature.
  Vec3 centre_of_mass() const;
  /// Position of one degree of freedom of joint j (rad or m).
  double joint_position(int j, int dof) const;
  /// Rate of one degree of freedom of joint j.
  double joint_rate(int j, int dof) const;
  /// Bit f set when face f of part i touched something this step.
  std::uint8_t contact_mask(int i) const;
  /// Whether part i touched another part of the creature in the last step.
  bool touches_part(int i) const;
  /// The nearest surface of the ground or any part (the creature occludes
  /// itself) along the ray from `origin` in direction `dir` (need not be
  /// unit length) within `length` m; hit = false when nothing is that close.
  RayHit ray(Vec3 origin, Vec3 dir, double length) const;

  /// Adds a prop (at any time: a task places its props when it needs them)
  /// and returns its index, from 0 in the order they were added.
  int add_prop(const Prop& p) override;
  int n_props() const;
  /// Where prop k is now (a spinning one has turned spin x time since it was added).
  Pose prop_pose(int k) const;
  /// Whether any part of the creature touched prop k in the last step.
  bool prop_touched(int k) const;

  /// The lights photoreceptors see from now on (a task may move them each step).
  void set_lights(std::vector<Light> lights) override;
  const std::vector<Light>& lights() const;

  /// Simulated time (s).
  double time() const;
  const PhysicsDef& def() const;
  /// The work the creature's muscles have done since it was added (J): the
  /// sum over steps of |power| x dt, power being each muscle's constraint
  /// forces on its two anchors times their velocities. Shortening and
  /// lengthening both cost, as a muscle's metabolism does (its damper
  /// included). Joint motors are not metered.
  double muscle_work() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  friend bool needs_own_motor_row(MotorModel m);  // reads the actuator table
};

}  // namespace bx
