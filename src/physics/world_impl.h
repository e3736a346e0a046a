// The physics world's private state (World::Impl), shared by the files that
// implement World by concept: world.cpp (the world, its bodies, the step and
// the explosion tests), joints.cpp (joints, their degrees of freedom, stops
// and gaps), actuators.cpp (the actuator table: motor models, muscles),
// contacts.cpp (collision, contact joints, the friction bound, contact
// flags), sensors.cpp (the sensor table, lights) and rays.cpp. Not part of
// the physics layer's interface: only physics/*.cpp include it.
#pragma once

#include <ode/ode.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "geometry/ode.h"
#include "physics/mechanisms.h"
#include "physics/motor_law.h"
#include "physics/world.h"

namespace bx {


// what a geom belongs to, held in its data pointer: the entity's kind in
// the low 4 bits, its index above them (the ground: 0, a null pointer)
inline void* entity_data(WorldEntity e) {
  return reinterpret_cast<void*>((static_cast<std::intptr_t>(e.index) << 4) | static_cast<std::intptr_t>(e.kind));
}
inline WorldEntity entity_of(dGeomID g) {
  const auto data = reinterpret_cast<std::intptr_t>(dGeomGetData(g));
  return {static_cast<WorldEntity::Kind>(data & 15), static_cast<int>(data >> 4)};
}

// a ray geom in no space, from `origin` along the unit vector `dir` for
// `length` m, reporting its closest hit (dCollide it; dGeomDestroy it after)
inline dGeomID make_ray(Vec3 origin, Vec3 dir, double length) {
  dGeomID ray = dCreateRay(nullptr, length);
  dGeomRaySet(ray, origin.x, origin.y, origin.z, dir.x, dir.y, dir.z);
  dGeomRaySetClosestHit(ray, 1);
  return ray;
}

struct World::Impl {
  struct Joint {
    dJointID id = nullptr;
    dJointID amotor = nullptr;  // spherical joints: Euler angular motor for angles/limits/motors
    dJointID motor = nullptr;   // PoweredStops::Separate: the hinge's or universal's own motor
    mutable bool pd_softened = false;  // drive_pd gave the motor's rows CFM 1/kd
    JointType type = JointType::Fixed;
    int parent = 0, child = 0;
    bool broken = false;
    // points the joint holds together, in the parent's and the child's frame
    // (joint_gap); for a linear joint only their offset across axis_local
    // (parent frame) counts, and its position past [lo, hi]
    int n_points = 0;
    std::array<Vec3, 2> on_parent, on_child;
    Vec3 axis_local;
    bool linear = false;
    std::vector<Limit> limits;  // per degree of freedom, as ODE has them (angular ones inside_angle_wrap)
  };

  PhysicsDef def;
  dWorldID world = nullptr;
  dSpaceID space = nullptr;
  dJointGroupID contact_group = nullptr;
  dThreadingImplementationID threading = nullptr;
  std::vector<dBodyID> bodies;
  std::vector<dGeomID> geoms;
  std::vector<double> masses;
  std::vector<Joint> joints;
  std::vector<std::uint8_t> contact_mask;
  std::vector<std::uint8_t> touching;  // per part: touched another part this step
  std::vector<bool> free_part;  // freed by a broken joint: collides with every part
  std::vector<Light> lights;
  // props.cpp: each prop's geom, its body (a spinning one's kinematic body,
  // else none) and whether a part touched it in the step
  struct PropState {
    dGeomID geom = nullptr;
    dBodyID body = nullptr;
    Prop def;
  };
  std::vector<PropState> props;
  std::vector<std::uint8_t> prop_touched;
  // per sensor: a photoreceptor's place on its part's surface (part frame)
  std::vector<Vec3> receptor_points;
  // the joints whose two parts collide (JointModel::parts_collide)
  std::vector<int> colliding_joints;
  std::vector<Vec3> prev_pos;
  std::vector<std::array<double, 3>> joint_torque;  // Torque/PD accumulation per joint
  std::vector<double> motor_signal;  // each effector's signal after the motor's lag
  std::vector<dContact> contact_buf;
  // the contacts of the step being taken (made by collide(), attached
  // after it) and the forces they carry
  struct Contact {
    dContact c;
    dBodyID a, b;     // a is never the ground's (the feedback's f1 is a's force)
    bool rolls;       // has rolling friction rows: left to ODE's pyramid
    double was = -1;  // its normal force in the last step (-1: a new contact)
  };
  std::vector<Contact> contacts;
  std::vector<dJointFeedback> feedback;
  // FrictionBound::Lagged: each contact of the last step, with its normal
  // force then and the step before
  std::vector<CarriedContact> carried;
  std::string solver_failure;  // the message of a step ODE could not solve
  // each joint's degrees of freedom as ODE reads them, once per step: the
  // motors, the explosion test and the sensors ask for the same angles
  // between two steps, and ODE builds each from quaternions and an atan2
  mutable std::vector<std::array<double, 3>> positions;
  mutable std::vector<std::uint8_t> positions_read;  // bit d: dof d is in `positions`
  double total_mass = 0;
  double t = 0;
  WorldStats stats;

  Vec3 world_point(int part, Vec3 local) const {
    dVector3 out;
    dBodyGetRelPointPos(bodies[part], local.x, local.y, local.z, out);
    return vec(out);
  }
  // a direction of part `part`'s frame in the world's, as a unit vector
  Vec3 world_direction(int part, Vec3 local) const {
    dVector3 out;
    dBodyVectorToWorld(bodies[part], local.x, local.y, local.z, out);
    return (1.0 / norm(vec(out))) * vec(out);
  }
  Vec3 local_point(int part, Vec3 world) const {
    dVector3 out;
    dBodyGetPosRelPoint(bodies[part], world.x, world.y, world.z, out);
    return vec(out);
  }

  // the world points of `j` that must coincide, from the current body poses
  void hold_points(Joint& j, std::initializer_list<Vec3> points, bool linear, Vec3 axis);

  // how far degree of freedom `dof` is past its stops (0 within them)
  double overshoot(const Joint& j, int dof) const;

  double gap(const Joint& j) const;

  // ODE's velocity motor of one degree of freedom: pushes with up to `force`
  // towards `speed` (through the joint's own motor, or its angular motor
  // beside the stops)
  void drive(const Joint& j, int dof, double speed, double force) const;

  // MotorModel::PD on a joint with a motor of its own (PoweredStops::
  // Separate), its damper implicit: the motor's row gets the target speed
  // kp err / kd, no force limit and CFM 1/kd. ODE solves each motor row for
  // J v' = speed - CFM lambda, lambda being the row's torque and v' the
  // joint's rate at the end of the step (step.cpp: cfm / h on the diagonal
  // of J M^-1 J', speed / h in the right-hand side), so the motor applies
  // lambda = kp err - kd v': the spring from the angle at the start of the
  // step, the damper from the rate the step ends with, stable whatever the
  // limb's inertia (docs/physics.md cause 28). The motor's rows are apart
  // from the joint's stop rows, so the unlimited force never meets ODE's
  // powered-stop fallback (a plain torque of FMax x fudge).
  void drive_pd(const Joint& j, int dof, double kp_err, double kd) const;

  // joint parameter of one degree of freedom
  void set_param(const Joint& j, int dof, int param, double v) const;

  // the position of a degree of freedom now (read_position), read from ODE
  // once between two steps
  double position(const Joint& j, int dof) const {
    const std::size_t k = static_cast<std::size_t>(&j - joints.data());
    const auto bit = static_cast<std::uint8_t>(1u << dof);
    if (positions_read[k] & bit) return positions[k][static_cast<std::size_t>(dof)];
    const double x = read_position(j, dof);
    positions[k][static_cast<std::size_t>(dof)] = x;
    positions_read[k] |= bit;
    return x;
  }

  // the bodies moved: every position must be read again
  void forget_positions() { std::fill(positions_read.begin(), positions_read.end(), 0); }

  double read_position(const Joint& j, int dof) const;

  double rate(const Joint& j, int dof) const;

  // adds the accumulated torques (Torque and PD motor models)
  void apply_torques();

  static void near_callback(void* data, dGeomID a, dGeomID b) {
    static_cast<Impl*>(data)->collide(a, b);
  }

  void collide(dGeomID a, dGeomID b);

  // makes the contact joints of this step. FrictionBound::Lagged: a contact
  // that persists from the last step with a steady normal force gets mu times
  // the lesser of its last two normal forces as a fixed friction bound (ODE's
  // Approx0: a bound in newtons); new, changing and rolling contacts keep
  // ODE's pyramid. ODE's exact solver sets a pyramid's bound from the normal
  // force as it stands when the solver reaches the friction row, and could
  // leave a resting creature gliding on frictionless ground (docs/physics.md)
  void attach_contacts();

  // after the step: the normal force each contact carried
  void remember_contacts();

  // whether a joint between parts p and q (not broken) lets them collide
  bool joined_parts_collide(int p, int q) const {
    for (int k : colliding_joints) {
      const Joint& j = joints[static_cast<std::size_t>(k)];
      if (!j.broken && ((j.parent == p && j.child == q) || (j.parent == q && j.child == p))) return true;
    }
    return false;
  }

  // the prop index of a geom, or -1
  static int prop_of(dGeomID g) {
    const WorldEntity e = entity_of(g);
    return e.kind == WorldEntity::Kind::Prop ? e.index : -1;
  }

  // the part index of a creature geom, or -1 (the ground, a prop)
  static int part_of(dGeomID g) {
    const WorldEntity e = entity_of(g);
    return e.kind == WorldEntity::Kind::Part ? e.index : -1;
  }

  // sets the contact bit of the face of part geom `g` whose outward normal is
  // closest to sign * n (a contact normal, world frame); the normal, unlike the
  // contact point, is unambiguous at edges and corners
  void mark_face(dGeomID g, const dReal* n, double sign);

  // actuators.cpp: the actuator table, one row per motor model (MuJoCo's
  // actuator_gaintype beside its biastype): how a signal drives an
  // effector's degree of freedom, and the full force a brake takes its share
  // of. A motor model is its row; nothing else switches on the model.
  // (What an actuator pulls, MuJoCo's actuator_trntype, is a joint's degree
  // of freedom for every row so far: EffectorModel's joint and dof.)
  struct Actuation {
    const CreatureModel& m;
    const EffectorModel& em;
    const MotorDef& motor;
    double s;  // the signal, after the motors' lag
  };
  struct GainRow {
    MotorModel model;
    /// It needs each hinge's and universal joint's motor row of its own
    /// (PoweredStops::Separate).
    bool own_motor_row;
    /// Drives what the effector pulls (a joint's degree of freedom, a
    /// muscle); true when it left a torque in joint_torque, for
    /// apply_torques to add.
    bool (*drive)(Impl&, const Actuation&);
    /// Holds it with `share` of its full force, whatever the signal
    /// (World::brake_effectors): the Actuation's signal is the share.
    void (*brake)(Impl&, const Actuation&);
  };
  // each muscle's soft distance constraint (MotorModel::Muscle), by CreatureModel::muscles
  std::vector<dJointID> muscles;
  // the forces each muscle's constraint applied in the last step (ODE fills
  // them; sized once per creature, so their addresses hold)
  std::vector<dJointFeedback> muscle_feedback;
  // J: the muscles' work so far, sum over steps of |power| dt
  double muscle_work = 0;
  // adds the last step's muscle work (after each step)
  void meter_muscles();
  // the length (m) each braked muscle is held at: its anchors' distance when
  // the brake began; NaN while it is driven (World::brake_effectors)
  std::vector<double> muscle_hold;
  // sets muscle k's spring (N/m) and damper (N s/m) for the coming step
  void set_muscle(std::size_t k, double kp, double kd);
  // muscle k pulls towards `length` (m) from the coming step
  void set_muscle_length(std::size_t k, double length);
  // its anchors' distance now (m)
  double muscle_length(std::size_t k) const;
  static const GainRow& gain(MotorModel m);

  // sensors.cpp: the sensor table, one row per kind of sensor: what it
  // reads of the world, as the brain takes it.
  struct SensorRow {
    SensorType type;
    /// The reading of sensor i of the creature.
    double (*read)(const Impl&, const CreatureModel&, std::size_t i);
  };
  static const SensorRow& sensor(SensorType type);
  // where each photoreceptor sits on its part (receptor_points), from the
  // parts' shapes as built
  void place_receptors(const CreatureModel& m);

  // rays.cpp: the nearest surface along a ray (World::ray)
  RayHit cast(Vec3 origin, Vec3 dir, double length) const;

  // joints.cpp: builds joint k of the creature, its anchors and axes moved
  // by the placement, with its stops
  void add_joint(const CreatureModel& m, std::size_t k, const Pose& placement);
};

}  // namespace bx
