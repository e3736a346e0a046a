// ODE implementation of the physics world.
#include "physics/world.h"

#include <ode/ode.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "geometry/ode.h"
#include "physics/mechanisms.h"

namespace bx {

namespace {

bool def_stop(double v) { return v >= 0; }

// ODE reads an angle in (-pi, pi]: a stop at +-pi sits where the reading
// wraps, so a joint pushed past it reads as beyond its other stop, which then
// turns it on the long way round; under a constant signal the limb spins like
// a wheel (docs/physics.md cause 22). Angular stops are kept this far inside.
constexpr double kAngleWrapMargin = 0.25;

Limit inside_angle_wrap(Limit l) {
  const double bound = kPi - kAngleWrapMargin;
  l.lo = std::clamp(l.lo, -bound, bound);
  l.hi = std::clamp(l.hi, -bound, bound);
  return l;
}

bool is_linear_dof(JointType t, int dof) {
  return t == JointType::Slider || (t == JointType::Cylindrical && dof == 0);
}

}  // namespace

void reseed_physics(std::uint64_t seed) {
  ensure_ode_initialized();
  dRandSetSeed(static_cast<unsigned long>(seed & 0xffffffffULL));
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
  Vec3 local_point(int part, Vec3 world) const {
    dVector3 out;
    dBodyGetPosRelPoint(bodies[part], world.x, world.y, world.z, out);
    return vec(out);
  }

  // the world points of `j` that must coincide, from the current body poses
  void hold_points(Joint& j, std::initializer_list<Vec3> points, bool linear, Vec3 axis) {
    j.n_points = 0;
    for (Vec3 p : points) {
      j.on_parent[j.n_points] = local_point(j.parent, p);
      j.on_child[j.n_points] = local_point(j.child, p);
      ++j.n_points;
    }
    j.linear = linear;
    if (linear) {
      dVector3 a;
      dBodyVectorFromWorld(bodies[j.parent], axis.x, axis.y, axis.z, a);
      j.axis_local = vec(a);
    }
  }

  // how far degree of freedom `dof` is past its stops (0 within them)
  double overshoot(const Joint& j, int dof) const {
    double x = position(j, dof);
    const Limit& l = j.limits[dof];
    return std::max({0.0, x - l.hi, l.lo - x});
  }

  double gap(const Joint& j) const {
    if (j.broken) return 0;
    double g = 0;
    Vec3 axis;
    if (j.linear) {
      dVector3 a;
      dBodyVectorToWorld(bodies[j.parent], j.axis_local.x, j.axis_local.y, j.axis_local.z, a);
      axis = vec(a);
    }
    for (int k = 0; k < j.n_points; ++k) {
      Vec3 d = world_point(j.child, j.on_child[k]) - world_point(j.parent, j.on_parent[k]);
      if (j.linear) d = d - dot(d, axis) * axis;  // free along the axis
      g = std::max(g, norm(d));
    }
    if (j.linear && !j.limits.empty()) g = std::max(g, overshoot(j, 0));
    return g;
  }

  // ODE's velocity motor of one degree of freedom: pushes with up to `force`
  // towards `speed` (through the joint's own motor, or its angular motor
  // beside the stops)
  void drive(const Joint& j, int dof, double speed, double force) const {
    if (j.motor) {
      if (j.broken) return;
      dJointSetAMotorParam(j.motor, dParamVel + dParamGroup * dof, speed);
      dJointSetAMotorParam(j.motor, dParamFMax + dParamGroup * dof, force);
      // the world's CFM, which the row had from its creation, when a PD
      // motor softened it (drive_pd); other motors never touch it
      if (j.pd_softened) dJointSetAMotorParam(j.motor, dParamCFM + dParamGroup * dof, def.cfm);
      return;
    }
    set_param(j, dof, dParamVel, speed);
    set_param(j, dof, dParamFMax, force);
  }

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
  void drive_pd(const Joint& j, int dof, double kp_err, double kd) const {
    if (j.broken) return;
    dJointSetAMotorParam(j.motor, dParamVel + dParamGroup * dof, kp_err / kd);
    dJointSetAMotorParam(j.motor, dParamFMax + dParamGroup * dof, dInfinity);
    dJointSetAMotorParam(j.motor, dParamCFM + dParamGroup * dof, 1 / kd);
    j.pd_softened = true;
  }

  // joint parameter of one degree of freedom
  void set_param(const Joint& j, int dof, int param, double v) const {
    if (j.broken) return;
    int p = param + dParamGroup * dof;
    switch (j.type) {
      case JointType::Hinge: dJointSetHingeParam(j.id, param, v); break;
      case JointType::Universal: dJointSetUniversalParam(j.id, p, v); break;
      case JointType::Slider: dJointSetSliderParam(j.id, param, v); break;
      case JointType::Cylindrical: dJointSetPistonParam(j.id, p, v); break;
      case JointType::Spherical: dJointSetAMotorParam(j.amotor, p, v); break;
      case JointType::Fixed: break;
    }
  }

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

  double read_position(const Joint& j, int dof) const {
    if (j.broken) return 0;
    switch (j.type) {
      case JointType::Hinge: return dJointGetHingeAngle(j.id);
      case JointType::Universal:
        return dof == 0 ? dJointGetUniversalAngle1(j.id) : dJointGetUniversalAngle2(j.id);
      case JointType::Slider: return dJointGetSliderPosition(j.id);
      case JointType::Cylindrical:
        return dof == 0 ? dJointGetPistonPosition(j.id) : dJointGetPistonAngle(j.id);
      case JointType::Spherical: return dJointGetAMotorAngle(j.amotor, dof);
      case JointType::Fixed: return 0;
    }
    return 0;
  }

  double rate(const Joint& j, int dof) const {
    if (j.broken) return 0;
    switch (j.type) {
      case JointType::Hinge: return dJointGetHingeAngleRate(j.id);
      case JointType::Universal:
        return dof == 0 ? dJointGetUniversalAngle1Rate(j.id) : dJointGetUniversalAngle2Rate(j.id);
      case JointType::Slider: return dJointGetSliderPositionRate(j.id);
      case JointType::Cylindrical:
        return dof == 0 ? dJointGetPistonPositionRate(j.id) : dJointGetPistonAngleRate(j.id);
      case JointType::Spherical: return dJointGetAMotorAngleRate(j.amotor, dof);
      case JointType::Fixed: return 0;
    }
    return 0;
  }

  // adds the accumulated torques (Torque and PD motor models)
  void apply_torques() {
    for (std::size_t k = 0; k < joints.size(); ++k) {
      auto& tq = joint_torque[k];
      const Joint& j = joints[k];
      if (j.broken) {
        tq = {0, 0, 0};
        continue;
      }
      switch (j.type) {
        case JointType::Hinge: dJointAddHingeTorque(j.id, tq[0]); break;
        case JointType::Universal: dJointAddUniversalTorques(j.id, tq[0], tq[1]); break;
        case JointType::Slider: dJointAddSliderForce(j.id, tq[0]); break;
        case JointType::Cylindrical: {
          dJointAddPistonForce(j.id, tq[0]);
          dVector3 a;
          dJointGetPistonAxis(j.id, a);
          dBodyAddTorque(bodies[j.parent], tq[1] * a[0], tq[1] * a[1], tq[1] * a[2]);
          dBodyAddTorque(bodies[j.child], -tq[1] * a[0], -tq[1] * a[1], -tq[1] * a[2]);
          break;
        }
        case JointType::Spherical: dJointAddAMotorTorques(j.amotor, tq[0], tq[1], tq[2]); break;
        case JointType::Fixed: break;
      }
      tq = {0, 0, 0};
    }
  }

  static void near_callback(void* data, dGeomID a, dGeomID b) {
    static_cast<Impl*>(data)->collide(a, b);
  }

  void collide(dGeomID a, dGeomID b) {
    dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
    if (ba && bb) {
      // parts joined by a joint never collide; others only with self_collision,
      // unless one of them was set free
      bool freed = free_part[part_of(a)] || free_part[part_of(b)];
      if ((!def.self_collision && !freed) || dAreConnectedExcluding(ba, bb, dJointTypeContact)) return;
    }
    int n = dCollide(a, b, def.max_contacts, &contact_buf[0].geom, sizeof(dContact));
    if (n > 0 && ba && bb) touching[part_of(a)] = touching[part_of(b)] = 1;
    for (int i = 0; i < n; ++i) {
      dContact& c = contact_buf[i];
      c.surface.mode = dContactApprox1;
      c.surface.mu = def.friction;
      if (def.rolling_friction > 0 && (round_geom(a) || round_geom(b))) {
        // rolling resistance, bounded by rho times the normal force (Approx1_N)
        c.surface.mode |= dContactRolling;
        c.surface.rho = c.surface.rho2 = def.rolling_friction;
        c.surface.rhoN = 0;
      }
      if (def.contact_erp >= 0) {
        c.surface.mode |= dContactSoftERP;
        c.surface.soft_erp = def.contact_erp;
      }
      if (def.contact_cfm >= 0) {
        c.surface.mode |= dContactSoftCFM;
        c.surface.soft_cfm = def.contact_cfm;
      }
      stats.max_penetration = std::max(stats.max_penetration, static_cast<double>(c.geom.depth));
      // the first body never the ground's
      Contact ct{c, ba, bb, (c.surface.mode & dContactRolling) != 0};
      if (!ct.a) {
        std::swap(ct.a, ct.b);
        std::swap(ct.c.geom.g1, ct.c.geom.g2);
        for (int i = 0; i < 3; ++i) ct.c.geom.normal[i] = -ct.c.geom.normal[i];
      }
      contacts.push_back(ct);
      // ODE's normal points into geom a: a is touched on the face facing -n, b on +n
      mark_face(a, c.geom.normal, -1);
      mark_face(b, c.geom.normal, +1);
    }
  }

  // makes the contact joints of this step. FrictionBound::Lagged: a contact
  // that persists from the last step with a steady normal force gets mu times
  // the lesser of its last two normal forces as a fixed friction bound (ODE's
  // Approx0: a bound in newtons); new, changing and rolling contacts keep
  // ODE's pyramid. ODE's exact solver sets a pyramid's bound from the normal
  // force as it stands when the solver reaches the friction row, and could
  // leave a resting creature gliding on frictionless ground (docs/physics.md)
  void attach_contacts() {
    const bool lagged = def.friction_bound == FrictionBound::Lagged;
    feedback.resize(contacts.size());
    for (Contact& ct : contacts) {
      dContact& c = ct.c;
      if (lagged) {
        if (const CarriedContact* same = find_carried(carried, ct.a, ct.b, vec(c.geom.pos))) {
          ct.was = same->now;
          double bound = ct.rolls ? -1 : lagged_bound(*same, def.friction);
          if (bound >= 0) {
            c.surface.mode &= ~dContactApprox1;
            c.surface.mu = bound;
          }
        }
      }
      dJointID cj = dJointCreateContact(world, contact_group, &c);
      dJointAttach(cj, ct.a, ct.b);
      if (lagged) dJointSetFeedback(cj, &feedback[&ct - contacts.data()]);
    }
  }

  // after the step: the normal force each contact carried
  void remember_contacts() {
    carried.clear();
    if (def.friction_bound != FrictionBound::Lagged) return;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      const Contact& ct = contacts[k];
      carried.push_back({ct.a, ct.b, vec(ct.c.geom.pos), normal_force(feedback[k], ct.c.geom.normal), ct.was});
    }
  }

  // the part index of a creature geom (geom data holds index + 1; 0: ground)
  static int part_of(dGeomID g) {
    return static_cast<int>(reinterpret_cast<std::intptr_t>(dGeomGetData(g))) - 1;
  }

  // sets the contact bit of the face of part geom `g` whose outward normal is
  // closest to sign * n (a contact normal, world frame); the normal, unlike the
  // contact point, is unambiguous at edges and corners
  void mark_face(dGeomID g, const dReal* n, double sign) {
    auto data = reinterpret_cast<std::intptr_t>(dGeomGetData(g));
    if (data <= 0) return;  // ground
    int part = static_cast<int>(data - 1);
    dVector3 local;
    dBodyVectorFromWorld(bodies[part], sign * n[0], sign * n[1], sign * n[2], local);
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(local[k]) > std::abs(local[axis])) axis = k;
    contact_mask[part] |= static_cast<std::uint8_t>(1u << static_cast<int>(make_face(axis, local[axis])));
  }
};

PhysicsDef softness_at_step(PhysicsDef d) {
  const double h0 = d.erp_cfm_dt, h = d.dt;
  if (!(h0 > 0) || h == h0) return d;
  // the pair (erp, cfm) given at h0, restated at h with the same spring and damper
  auto restate = [&](double& erp, double& cfm) {
    const double kp = erp / (h0 * cfm), kd = (1 - erp) / cfm;
    erp = h * kp / (h * kp + kd);
    cfm = 1 / (h * kp + kd);
  };
  const double world_erp = d.erp, world_cfm = d.cfm;
  restate(d.erp, d.cfm);
  // a contact or stop pair with a value of its own: both restated from what
  // it is at h0 (a value it does not set is the world's there)
  auto own = [&](double& erp, double& cfm) {
    if (erp < 0 && cfm < 0) return;  // the world's, restated above
    if (erp < 0) erp = world_erp;
    if (cfm < 0) cfm = world_cfm;
    restate(erp, cfm);
  };
  own(d.contact_erp, d.contact_cfm);
  own(d.stop_erp, d.stop_cfm);
  return d;
}

namespace {
std::atomic<long> g_worlds_made{0};
}  // namespace

long World::made() { return g_worlds_made.load(); }

World::World(const PhysicsDef& given) : impl_(std::make_unique<Impl>()) {
  ++g_worlds_made;
  ensure_ode_initialized();
  auto& w = *impl_;
  w.def = softness_at_step(given);
  const PhysicsDef& def = w.def;
  w.world = dWorldCreate();
  dWorldSetGravity(w.world, 0, 0, def.gravity);
  dWorldSetERP(w.world, def.erp);
  dWorldSetCFM(w.world, def.cfm);
  dWorldSetQuickStepNumIterations(w.world, def.solver_iterations);
  if (def.contact_max_correcting_vel > 0)
    dWorldSetContactMaxCorrectingVel(w.world, def.contact_max_correcting_vel);
  dWorldSetContactSurfaceLayer(w.world, def.contact_surface_layer);
  dWorldSetAutoDisableFlag(w.world, 0);
  // each world its own threading implementation (docs/design.md)
  w.threading = dThreadingAllocateSelfThreadedImplementation();
  dWorldSetStepThreadingImplementation(w.world, dThreadingImplementationGetFunctions(w.threading),
                                       w.threading);
  w.space = dSimpleSpaceCreate(nullptr);
  w.contact_group = dJointGroupCreate(0);
  dGeomID ground = dCreatePlane(w.space, 0, 0, 1, 0);
  dGeomSetData(ground, nullptr);
  w.contact_buf.resize(std::max(def.max_contacts, 1));
}

World::~World() {
  auto& w = *impl_;
  dJointGroupDestroy(w.contact_group);
  dSpaceDestroy(w.space);  // destroys its geoms
  dWorldDestroy(w.world);  // destroys bodies and joints
  if (ode_thread_log().faulted)
    ode_thread_log().faulted = false;  // after a PhysicsFault: leak the threading implementation
  else
    dThreadingFreeImplementation(w.threading);
}

void World::add_creature(const CreatureModel& m, const Pose& placement) {
  auto& w = *impl_;
  int n = m.n_parts();
  w.bodies.resize(n);
  w.geoms.resize(n);
  w.masses.resize(n);
  w.contact_mask.assign(n, 0);
  w.touching.assign(n, 0);
  w.free_part.assign(n, false);
  w.prev_pos.resize(n);
  // bodies with shape, mass and pose
  for (int i = 0; i < n; ++i) {
    const PartModel& part = m.parts[i];
    Pose pose{placement.apply(part.pose.p), placement.R * part.pose.R};
    dBodyID b = dBodyCreate(w.world);
    dMass mass;
    const Vec3& s = part.size;
    switch (part.shape) {
      case Shape::Box: dMassSetBoxTotal(&mass, part.mass, s.x, s.y, s.z); break;
      case Shape::Sphere: dMassSetSphereTotal(&mass, part.mass, s.x / 2); break;
      case Shape::Capsule:
        dMassSetCapsuleTotal(&mass, part.mass, 1, s.y / 2, std::max(s.x - s.y, 0.0));
        break;
      case Shape::Cylinder: dMassSetCylinderTotal(&mass, part.mass, 1, s.y / 2, s.x); break;
    }
    dBodySetMass(b, &mass);
    dBodySetPosition(b, pose.p.x, pose.p.y, pose.p.z);
    dMatrix3 R;
    to_ode(pose.R, R);
    dBodySetRotation(b, R);
    dGeomID g = make_geom(w.space, part.shape, s, 0.0);
    dGeomSetBody(g, b);
    if (part.shape == Shape::Capsule || part.shape == Shape::Cylinder) {
      dMatrix3 off;
      to_ode(z_to_x(), off);
      dGeomSetOffsetRotation(g, off);
    }
    dGeomSetData(g, reinterpret_cast<void*>(static_cast<std::intptr_t>(i + 1)));
    w.bodies[i] = b;
    w.geoms[i] = g;
    w.masses[i] = part.mass;
    w.total_mass += part.mass;
    w.prev_pos[i] = pose.p;
  }
  // joints, with anchors and axes moved by the placement
  w.joints.resize(m.joints.size());
  w.joint_torque.assign(m.joints.size(), {0, 0, 0});
  w.positions.assign(m.joints.size(), {0, 0, 0});
  w.positions_read.assign(m.joints.size(), 0);
  for (std::size_t k = 0; k < m.joints.size(); ++k) {
    const JointModel& jm = m.joints[k];
    Impl::Joint& j = w.joints[k];
    j.type = jm.type;
    j.parent = jm.parent;
    j.child = jm.child;
    Vec3 an = placement.apply(jm.anchor);
    Vec3 a1 = placement.R * jm.axis1, a2 = placement.R * jm.axis2;
    dBodyID b1 = w.bodies[jm.parent], b2 = w.bodies[jm.child];
    // what joint_gap watches: a second point along the axis at the child's
    // size, so a hinge bent off its axis shows as a gap too
    Vec3 child_centre = vec(dBodyGetPosition(b2));
    const Vec3& cs = m.parts[jm.child].size;
    Vec3 along = an + std::max(0.5 * std::max({cs.x, cs.y, cs.z}), 0.01) * a1;
    switch (jm.type) {
      case JointType::Fixed: w.hold_points(j, {an, child_centre}, false, a1); break;
      case JointType::Hinge: w.hold_points(j, {an, along}, false, a1); break;
      case JointType::Universal:
      case JointType::Spherical: w.hold_points(j, {an}, false, a1); break;
      case JointType::Slider: w.hold_points(j, {an, child_centre}, true, a1); break;
      case JointType::Cylindrical: w.hold_points(j, {an, along}, true, a1); break;
    }
    switch (jm.type) {
      case JointType::Fixed:
        j.id = dJointCreateFixed(w.world, nullptr);
        dJointAttach(j.id, b1, b2);
        dJointSetFixed(j.id);
        break;
      case JointType::Hinge:
        j.id = dJointCreateHinge(w.world, nullptr);
        dJointAttach(j.id, b1, b2);
        dJointSetHingeAnchor(j.id, an.x, an.y, an.z);
        dJointSetHingeAxis(j.id, a1.x, a1.y, a1.z);
        if (w.def.powered_stops == PoweredStops::Separate) j.motor = create_axis_motor(w.world, b1, b2, {a1}, {1});
        break;
      case JointType::Universal:
        j.id = dJointCreateUniversal(w.world, nullptr);
        dJointAttach(j.id, b1, b2);
        dJointSetUniversalAnchor(j.id, an.x, an.y, an.z);
        dJointSetUniversalAxis1(j.id, a1.x, a1.y, a1.z);
        dJointSetUniversalAxis2(j.id, a2.x, a2.y, a2.z);
        // axis 1 turns with the parent, axis 2 with the child
        if (w.def.powered_stops == PoweredStops::Separate) j.motor = create_axis_motor(w.world, b1, b2, {a1, a2}, {1, 2});
        break;
      case JointType::Slider:
        j.id = dJointCreateSlider(w.world, nullptr);
        dJointAttach(j.id, b1, b2);
        dJointSetSliderAxis(j.id, a1.x, a1.y, a1.z);
        break;
      case JointType::Cylindrical:
        j.id = dJointCreatePiston(w.world, nullptr);
        dJointAttach(j.id, b1, b2);
        dJointSetPistonAnchor(j.id, an.x, an.y, an.z);
        dJointSetPistonAxis(j.id, a1.x, a1.y, a1.z);
        break;
      case JointType::Spherical:
        j.id = dJointCreateBall(w.world, nullptr);
        dJointAttach(j.id, b1, b2);
        dJointSetBallAnchor(j.id, an.x, an.y, an.z);
        // Euler motor: axis 0 fixed to the parent, axis 2 to the child
        j.amotor = dJointCreateAMotor(w.world, nullptr);
        dJointAttach(j.amotor, b1, b2);
        dJointSetAMotorMode(j.amotor, dAMotorEuler);
        dJointSetAMotorAxis(j.amotor, 0, 1, a1.x, a1.y, a1.z);
        dJointSetAMotorAxis(j.amotor, 2, 2, a2.x, a2.y, a2.z);
        break;
    }
    // limits per degree of freedom, with the stops' own ERP, CFM and fudge
    j.limits = jm.limits;
    for (std::size_t d = 0; d < j.limits.size(); ++d) {
      int dof = static_cast<int>(d);
      if (!is_linear_dof(jm.type, dof)) j.limits[d] = inside_angle_wrap(j.limits[d]);
      w.set_param(j, dof, dParamLoStop, j.limits[d].lo);
      w.set_param(j, dof, dParamHiStop, j.limits[d].hi);
      if (def_stop(w.def.stop_erp)) w.set_param(j, dof, dParamStopERP, w.def.stop_erp);
      if (def_stop(w.def.stop_cfm)) w.set_param(j, dof, dParamStopCFM, w.def.stop_cfm);
      w.set_param(j, dof, dParamFudgeFactor, w.def.fudge_factor);
    }
  }
}

void World::fix_part_to_world(int i) {
  auto& w = *impl_;
  dJointID j = dJointCreateFixed(w.world, nullptr);
  dJointAttach(j, w.bodies[i], nullptr);
  dJointSetFixed(j);
}

void World::brake_effectors(const CreatureModel& m, const MotorDef& motor, double share) {
  auto& w = *impl_;
  for (const EffectorModel& em : m.effectors) {
    const double full = motor.model == MotorModel::Servo ? motor.max_force : motor.strength * em.cross_section;
    w.drive(w.joints[em.joint], em.dof, 0, share * full);
  }
}

void World::apply_effectors(const CreatureModel& m, const MotorDef& motor,
                            std::span<const double> signals) {
  auto& w = *impl_;
  if (motor.model == MotorModel::PD && w.def.powered_stops != PoweredStops::Separate)
    throw std::invalid_argument(
        "World: PD motors need physics.powered_stops = \"separate\" (their damper is a joint motor "
        "row of its own, beside the stops; docs/physics.md cause 28)");
  bool torques = false;
  auto drive = [&w](const Impl::Joint& j, int dof, double speed, double force) { w.drive(j, dof, speed, force); };
  // the motors' first-order lag: the share of the gap closed in one step
  const double lag = motor_lag_share(w.def.dt, motor.response_time);
  if (lag > 0 && w.motor_signal.size() != m.effectors.size()) w.motor_signal.assign(m.effectors.size(), 0);
  for (std::size_t e = 0; e < m.effectors.size(); ++e) {
    const EffectorModel& em = m.effectors[e];
    const Impl::Joint& j = w.joints[em.joint];
    double s = signals[e];
    if (lag > 0) s = w.motor_signal[e] += lag * (s - w.motor_signal[e]);
    switch (motor.model) {
      case MotorModel::Servo:
        drive(j, em.dof, motor.max_speed * s, motor.max_force);
        break;
      case MotorModel::Saturation:
        drive(j, em.dof, s >= 0 ? motor.max_speed : -motor.max_speed,
              std::abs(s) * motor.strength * em.cross_section);
        break;
      case MotorModel::Torque: {
        double torque = s * motor.strength * em.cross_section;
        double limit = is_linear_dof(j.type, em.dof) ? motor.torque_max_linear_speed
                                                     : motor.torque_max_speed;
        if (limit > 0) {
          // the torque up to the no-load speed (as Saturation, with its own speed)
          drive(j, em.dof, torque >= 0 ? limit : -limit, std::abs(torque));
          break;
        }
        w.joint_torque[em.joint][em.dof] += torque;
        torques = true;
        break;
      }
      case MotorModel::PD: {
        const JointModel& jm = m.joints[em.joint];
        double target;
        if (em.dof < static_cast<int>(jm.limits.size())) {
          const Limit& l = jm.limits[em.dof];
          target = 0.5 * (l.lo + l.hi) + 0.5 * s * (l.hi - l.lo);
        } else {
          target = s * (is_linear_dof(j.type, em.dof) ? 1.0 : kPi);
        }
        const double err = target - w.position(j, em.dof);
        if (j.motor && motor.kd > 0) {
          // hinges and universal joints: the damper implicit in the joint's own motor
          w.drive_pd(j, em.dof, motor.kp * err, motor.kd);
          break;
        }
        // no damper (kd = 0: the spring alone, explicit; the motor row off),
        // or a joint without a motor of its own (slider, piston, ball): the
        // explicit torque from the angle and rate at the start of the step
        if (j.motor) drive(j, em.dof, 0, 0);
        w.joint_torque[em.joint][em.dof] += motor.kp * err - motor.kd * w.rate(j, em.dof);
        torques = true;
        break;
      }
    }
  }
  if (torques) w.apply_torques();
}

void World::step() {
  auto& w = *impl_;
  std::fill(w.contact_mask.begin(), w.contact_mask.end(), 0);
  std::fill(w.touching.begin(), w.touching.end(), 0);
  w.contacts.clear();
  dSpaceCollide(w.space, &w, &Impl::near_callback);
  w.attach_contacts();
  OdeThreadLog& log = ode_thread_log();
  long messages = log.messages;
  w.forget_positions();  // the bodies move
  if (w.def.solver == Solver::Exact)
    dWorldStep(w.world, w.def.dt);
  else
    dWorldQuickStep(w.world, w.def.dt);
  if (log.messages != messages && w.solver_failure.empty()) {
    char buf[300];
    std::snprintf(buf, sizeof buf, "ODE could not solve the step at t=%.4g s (%s)", w.t, log.last_message);
    w.solver_failure = buf;
  }
  w.remember_contacts();
  dJointGroupEmpty(w.contact_group);
  w.t += w.def.dt;
}

void World::read_sensors(const CreatureModel& m, std::span<double> out) const {
  const auto& w = *impl_;
  for (std::size_t i = 0; i < m.sensors.size(); ++i) {
    const SensorModel& s = m.sensors[i];
    if (s.type == SensorType::Contact) {
      out[i] = (w.contact_mask[s.part] >> static_cast<int>(s.face)) & 1 ? 1.0 : -1.0;
      continue;
    }
    if (s.joint < 0) {
      out[i] = 0;  // the root has no joint to its parent
      continue;
    }
    const JointModel& jm = m.joints[s.joint];
    double x = w.position(w.joints[s.joint], s.dof);
    double v;
    if (s.dof < static_cast<int>(jm.limits.size()) && jm.limits[s.dof].hi > jm.limits[s.dof].lo) {
      const Limit& l = jm.limits[s.dof];
      v = 2 * (x - l.lo) / (l.hi - l.lo) - 1;
    } else {
      v = is_linear_dof(jm.type, s.dof) ? x : x / kPi;
    }
    out[i] = std::clamp(v, -1.0, 1.0);
  }
}

std::string World::check_explosion() {
  auto& w = *impl_;
  // a step the solver gave up on left constraint rows at zero force
  if (!w.solver_failure.empty()) return w.solver_failure;
  char buf[160];
  for (std::size_t i = 0; i < w.bodies.size(); ++i) {
    Vec3 p = vec(dBodyGetPosition(w.bodies[i]));
    Vec3 v = vec(dBodyGetLinearVel(w.bodies[i]));
    if (!std::isfinite(p.x + p.y + p.z + v.x + v.y + v.z)) {
      std::snprintf(buf, sizeof buf, "part %zu: position or velocity is not finite", i);
      return buf;
    }
    double speed = norm(v);
    if (speed > w.def.max_speed) {
      std::snprintf(buf, sizeof buf, "part %zu: speed %.3g m/s above max_speed %.3g", i, speed,
                    w.def.max_speed);
      return buf;
    }
    double jump = norm(p - w.prev_pos[i]);
    if (jump > w.def.max_step_jump) {
      std::snprintf(buf, sizeof buf, "part %zu: moved %.3g m in one step, above max_step_jump %.3g",
                    i, jump, w.def.max_step_jump);
      return buf;
    }
    w.prev_pos[i] = p;
  }
  for (std::size_t k = 0; k < w.joints.size(); ++k) {
    const Impl::Joint& j = w.joints[k];
    if (j.broken) continue;
    for (std::size_t d = 0; d < j.limits.size(); ++d)
      w.stats.max_stop_overshoot = std::max(w.stats.max_stop_overshoot, w.overshoot(j, static_cast<int>(d)));
    double gap = w.gap(j);
    if (gap > w.stats.max_joint_gap) {
      w.stats.max_joint_gap = gap;
      w.stats.worst_joint = static_cast<int>(k);
    }
    if (gap > w.def.max_joint_gap) {
      std::snprintf(buf, sizeof buf, "joint %zu (%s): %.3g m apart, above max_joint_gap %.3g", k,
                    std::string(to_string(j.type)).c_str(), gap, w.def.max_joint_gap);
      return buf;
    }
  }
  return {};
}

void World::break_joint(int j) {
  auto& w = *impl_;
  Impl::Joint& jt = w.joints[j];
  if (jt.broken) return;
  // destroy the joint and its motor; the rest of the code skips broken joints
  dJointDestroy(jt.id);
  if (jt.amotor) dJointDestroy(jt.amotor);
  if (jt.motor) dJointDestroy(jt.motor);
  jt.id = nullptr;
  jt.amotor = nullptr;
  jt.motor = nullptr;
  jt.broken = true;
  w.free_part[jt.child] = true;
  w.positions_read[static_cast<std::size_t>(j)] = 0;
}

bool World::joint_broken(int j) const { return impl_->joints[j].broken; }

Pose World::part_pose(int i) const {
  dBodyID b = impl_->bodies[i];
  return {vec(dBodyGetPosition(b)), from_ode(dBodyGetRotation(b))};
}

Vec3 World::part_velocity(int i) const { return vec(dBodyGetLinearVel(impl_->bodies[i])); }

Vec3 World::centre_of_mass() const {
  const auto& w = *impl_;
  Vec3 c;
  for (std::size_t i = 0; i < w.bodies.size(); ++i)
    c = c + w.masses[i] * vec(dBodyGetPosition(w.bodies[i]));
  return (1.0 / w.total_mass) * c;
}

double World::joint_position(int j, int dof) const {
  return impl_->position(impl_->joints[j], dof);
}
double World::joint_rate(int j, int dof) const { return impl_->rate(impl_->joints[j], dof); }
double World::joint_gap(int j) const { return impl_->gap(impl_->joints[j]); }
const WorldStats& World::stats() const { return impl_->stats; }
std::uint8_t World::contact_mask(int i) const { return impl_->contact_mask[i]; }
bool World::touches_part(int i) const { return impl_->touching[i] != 0; }
double World::time() const { return impl_->t; }
const PhysicsDef& World::def() const { return impl_->def; }


}  // namespace bx
