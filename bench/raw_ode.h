// raw_ode.h: a creature built and stepped with direct ODE calls only, as a
// plain ODE program would, replaying the motor commands of one of our
// evaluations (docs/benchmarks.md). The baseline of bench_step,
// bench_evolve and bench_river.
//
//   record_motor_tape()  the motor commands of every step of our run, from a
//                        replay with a frame every step
//   run_raw()            builds the same bodies, geoms, joints, ground,
//                        contact rules and solver settings as World, steps
//                        them replaying the tape, and destroys them
//
// Same inputs, same physics: with the same ODE seed the raw run ends
// bit-identical to ours (max_part_deviation() == 0). If it does not,
// src/physics/ has changed how it builds or steps the world and this
// copy must follow.
#pragma once

#include <ode/ode.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "develop/creature_model.h"
#include "eval/evaluate.h"
#include "eval/sim_config.h"
#include "physics/mechanisms.h"
#include "physics/world.h"

namespace bx::bench {

// ---------------------------------------------------------------------------
// Timing

/// Thread CPU time (s): the work itself, not time the scheduler gave others on
/// a shared machine.
inline double cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The median of a non-empty sample.
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// ---------------------------------------------------------------------------
// Raw ODE: the creature built and stepped by hand, as a plain ODE program
// would, with World's settings and call order (so ODE does the same work).

inline void to_ode(const Mat3& R, dMatrix3 out) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out[i * 4 + j] = R.m[i][j];
    out[i * 4 + 3] = 0;
  }
}

/// One motor-driven joint (torque motors) or degree of freedom (velocity
/// motors) of the recorded run.
struct Drive {
  int joint = 0;
  int dof = 0;  ///< velocity motors only: torques are per joint, 3 per drive
  JointType type = JointType::Hinge;
};

struct RawWorld {
  RawWorld(const RawWorld&) = delete;
  RawWorld& operator=(const RawWorld&) = delete;

  PhysicsDef def;
  dWorldID world = nullptr;
  dSpaceID space = nullptr;
  dJointGroupID contact_group = nullptr;
  dThreadingImplementationID threading = nullptr;
  std::vector<dBodyID> bodies;
  std::vector<dJointID> joints;
  std::vector<dJointID> amotors;
  std::vector<dJointID> motors;  ///< PoweredStops::Separate: hinges' and universals' own motors
  std::vector<dContact> contact_buf;
  // the contacts of a step, attached after collision detection, and (the
  // lagged friction bound) what each carried in the last two steps
  struct Contact {
    dContact c;
    dBodyID a, b;
    bool rolls;
    double was = -1;
  };
  std::vector<Contact> contacts;
  std::vector<dJointFeedback> feedback;
  std::vector<CarriedContact> carried;

  static bool round_geom(dGeomID g) {
    int c = dGeomGetClass(g);
    return c == dSphereClass || c == dCapsuleClass || c == dCylinderClass;
  }

  static void near_callback(void* data, dGeomID a, dGeomID b) {
    auto& w = *static_cast<RawWorld*>(data);
    dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
    if (ba && bb && (!w.def.self_collision || dAreConnectedExcluding(ba, bb, dJointTypeContact)))
      return;
    int n = dCollide(a, b, w.def.max_contacts, &w.contact_buf[0].geom, sizeof(dContact));
    for (int i = 0; i < n; ++i) {
      dContact& c = w.contact_buf[i];
      c.surface.mode = dContactApprox1;
      c.surface.mu = w.def.friction;
      if (w.def.rolling_friction > 0 && (round_geom(a) || round_geom(b))) {
        c.surface.mode |= dContactRolling;
        c.surface.rho = c.surface.rho2 = w.def.rolling_friction;
        c.surface.rhoN = 0;
      }
      Contact ct{c, ba, bb, (c.surface.mode & dContactRolling) != 0};
      if (!ct.a) {
        std::swap(ct.a, ct.b);
        std::swap(ct.c.geom.g1, ct.c.geom.g2);
        for (int k = 0; k < 3; ++k) ct.c.geom.normal[k] = -ct.c.geom.normal[k];
      }
      w.contacts.push_back(ct);
    }
  }

  // the contacts of this step, each steady one bounded by mu times the
  // lesser of its last two normal forces (FrictionBound::Lagged)
  void attach_contacts() {
    const bool lagged = def.friction_bound == FrictionBound::Lagged;
    feedback.resize(contacts.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      Contact& ct = contacts[k];
      if (lagged) {
        const dReal* q = ct.c.geom.pos;
        if (const CarriedContact* same = find_carried(carried, ct.a, ct.b, {q[0], q[1], q[2]})) {
          ct.was = same->now;
          double bound = ct.rolls ? -1 : lagged_bound(*same, def.friction);
          if (bound >= 0) {
            ct.c.surface.mode &= ~dContactApprox1;
            ct.c.surface.mu = bound;
          }
        }
      }
      dJointID cj = dJointCreateContact(world, contact_group, &ct.c);
      dJointAttach(cj, ct.a, ct.b);
      if (lagged) dJointSetFeedback(cj, &feedback[k]);
    }
  }

  void remember_contacts() {
    carried.clear();
    if (def.friction_bound != FrictionBound::Lagged) return;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      const Contact& ct = contacts[k];
      carried.push_back({ct.a, ct.b, {ct.c.geom.pos[0], ct.c.geom.pos[1], ct.c.geom.pos[2]},
                         normal_force(feedback[k], ct.c.geom.normal), ct.was});
    }
  }

  RawWorld(const CreatureModel& m, const PhysicsDef& d, const Pose& placement) : def(d) {
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, def.gravity);
    dWorldSetERP(world, def.erp);
    dWorldSetCFM(world, def.cfm);
    dWorldSetQuickStepNumIterations(world, def.solver_iterations);
    dWorldSetAutoDisableFlag(world, 0);
    threading = dThreadingAllocateSelfThreadedImplementation();
    dWorldSetStepThreadingImplementation(world, dThreadingImplementationGetFunctions(threading),
                                         threading);
    space = dSimpleSpaceCreate(nullptr);
    contact_group = dJointGroupCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);
    contact_buf.resize(std::max(def.max_contacts, 1));

    // bodies: mass, inertia, pose, geom
    const Mat3 z_to_x = Mat3::rotation({0, 1, 0}, kPi / 2);
    for (const PartModel& part : m.parts) {
      Pose pose{placement.apply(part.pose.p), placement.R * part.pose.R};
      dBodyID b = dBodyCreate(world);
      dMass mass;
      const Vec3& s = part.size;
      dGeomID g = nullptr;
      switch (part.shape) {
        case Shape::Box:
          dMassSetBoxTotal(&mass, part.mass, s.x, s.y, s.z);
          g = dCreateBox(space, s.x, s.y, s.z);
          break;
        case Shape::Sphere:
          dMassSetSphereTotal(&mass, part.mass, s.x / 2);
          g = dCreateSphere(space, s.x / 2);
          break;
        case Shape::Capsule:
          dMassSetCapsuleTotal(&mass, part.mass, 1, s.y / 2, std::max(s.x - s.y, 0.0));
          g = dCreateCapsule(space, s.y / 2, std::max(s.x - s.y, 0.0));
          break;
        case Shape::Cylinder:
          dMassSetCylinderTotal(&mass, part.mass, 1, s.y / 2, s.x);
          g = dCreateCylinder(space, s.y / 2, s.x);
          break;
      }
      dBodySetMass(b, &mass);
      dBodySetPosition(b, pose.p.x, pose.p.y, pose.p.z);
      dMatrix3 R;
      bench::to_ode(pose.R, R);
      dBodySetRotation(b, R);
      dGeomSetBody(g, b);
      if (part.shape == Shape::Capsule || part.shape == Shape::Cylinder) {
        dMatrix3 off;
        bench::to_ode(z_to_x, off);
        dGeomSetOffsetRotation(g, off);
      }
      bodies.push_back(b);
    }

    // joints: type, anchor, axes, limits
    for (const JointModel& jm : m.joints) {
      Vec3 an = placement.apply(jm.anchor);
      Vec3 a1 = placement.R * jm.axis1, a2 = placement.R * jm.axis2;
      dBodyID b1 = bodies[jm.parent], b2 = bodies[jm.child];
      dJointID j = nullptr, am = nullptr, mo = nullptr;
      const bool separate = def.powered_stops == PoweredStops::Separate;
      switch (jm.type) {
        case JointType::Fixed:
          j = dJointCreateFixed(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetFixed(j);
          break;
        case JointType::Hinge:
          j = dJointCreateHinge(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetHingeAnchor(j, an.x, an.y, an.z);
          dJointSetHingeAxis(j, a1.x, a1.y, a1.z);
          if (separate) mo = create_axis_motor(world, b1, b2, {a1}, {1});
          break;
        case JointType::Universal:
          j = dJointCreateUniversal(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetUniversalAnchor(j, an.x, an.y, an.z);
          dJointSetUniversalAxis1(j, a1.x, a1.y, a1.z);
          dJointSetUniversalAxis2(j, a2.x, a2.y, a2.z);
          if (separate) mo = create_axis_motor(world, b1, b2, {a1, a2}, {1, 2});
          break;
        case JointType::Slider:
          j = dJointCreateSlider(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetSliderAxis(j, a1.x, a1.y, a1.z);
          break;
        case JointType::Cylindrical:
          j = dJointCreatePiston(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetPistonAnchor(j, an.x, an.y, an.z);
          dJointSetPistonAxis(j, a1.x, a1.y, a1.z);
          break;
        case JointType::Spherical:
          j = dJointCreateBall(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetBallAnchor(j, an.x, an.y, an.z);
          am = dJointCreateAMotor(world, nullptr);
          dJointAttach(am, b1, b2);
          dJointSetAMotorMode(am, dAMotorEuler);
          dJointSetAMotorAxis(am, 0, 1, a1.x, a1.y, a1.z);
          dJointSetAMotorAxis(am, 2, 2, a2.x, a2.y, a2.z);
          break;
      }
      for (std::size_t d = 0; d < jm.limits.size(); ++d) {
        int g = static_cast<int>(d) * dParamGroup;
        for (auto [param, v] : {std::pair{dParamLoStop, jm.limits[d].lo},
                                std::pair{dParamHiStop, jm.limits[d].hi}}) {
          switch (jm.type) {
            case JointType::Hinge: dJointSetHingeParam(j, param, v); break;
            case JointType::Universal: dJointSetUniversalParam(j, param + g, v); break;
            case JointType::Slider: dJointSetSliderParam(j, param, v); break;
            case JointType::Cylindrical: dJointSetPistonParam(j, param + g, v); break;
            case JointType::Spherical: dJointSetAMotorParam(am, param + g, v); break;
            case JointType::Fixed: break;
          }
        }
      }
      joints.push_back(j);
      amotors.push_back(am);
      motors.push_back(mo);
    }
  }

  ~RawWorld() {
    dJointGroupDestroy(contact_group);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dThreadingFreeImplementation(threading);
  }

  // sets one motor parameter (dParamVel, dParamFMax) of a driven degree of
  // freedom, as World::Impl::set_param does
  void set_param(const Drive& d, int param, double v) {
    dJointID j = joints[d.joint];
    int p = param + dParamGroup * d.dof;
    if (motors[d.joint]) {
      dJointSetAMotorParam(motors[d.joint], p, v);
      return;
    }
    switch (d.type) {
      case JointType::Hinge: dJointSetHingeParam(j, param, v); break;
      case JointType::Universal: dJointSetUniversalParam(j, p, v); break;
      case JointType::Slider: dJointSetSliderParam(j, param, v); break;
      case JointType::Cylindrical: dJointSetPistonParam(j, p, v); break;
      case JointType::Spherical: dJointSetAMotorParam(amotors[d.joint], p, v); break;
      case JointType::Fixed: break;
    }
  }

  // the angle of a driven degree of freedom (hinges and universal joints:
  // the joints with a motor of their own), as World::Impl::position reads it
  double angle(const Drive& d) const {
    dJointID j = joints[d.joint];
    if (d.type == JointType::Universal)
      return d.dof == 0 ? dJointGetUniversalAngle1(j) : dJointGetUniversalAngle2(j);
    return dJointGetHingeAngle(j);
  }

  // adds one recorded joint torque (per degree of freedom)
  void add_torque(const Drive& d, const double* tq) {
    dJointID j = joints[d.joint];
    switch (d.type) {
      case JointType::Hinge: dJointAddHingeTorque(j, tq[0]); break;
      case JointType::Universal: dJointAddUniversalTorques(j, tq[0], tq[1]); break;
      case JointType::Slider: dJointAddSliderForce(j, tq[0]); break;
      case JointType::Cylindrical: {
        dJointAddPistonForce(j, tq[0]);
        dVector3 a;
        dJointGetPistonAxis(j, a);
        dBodyAddTorque(dJointGetBody(j, 0), tq[1] * a[0], tq[1] * a[1], tq[1] * a[2]);
        dBodyAddTorque(dJointGetBody(j, 1), -tq[1] * a[0], -tq[1] * a[1], -tq[1] * a[2]);
        break;
      }
      case JointType::Spherical: dJointAddAMotorTorques(amotors[d.joint], tq[0], tq[1], tq[2]); break;
      case JointType::Fixed: break;
    }
  }

  // one step, as World::step does it
  void step() {
    contacts.clear();
    dSpaceCollide(space, this, &near_callback);
    attach_contacts();
    if (def.solver == Solver::Exact)
      dWorldStep(world, def.dt);
    else
      dWorldQuickStep(world, def.dt);
    remember_contacts();
    dJointGroupEmpty(contact_group);
  }
};

/// The motor commands of every step of one of our runs, as World gave them.
/// Torque motors (Torque model): the joint torques World added, 3 per joint
/// (one per degree of freedom, summed in effector order). Velocity motors
/// (Servo, Saturation): dParamVel and dParamFMax per degree of freedom. PD
/// motors (the river crossing's): the target angle per degree of freedom;
/// the raw run reads the angle each step, as World does.
struct MotorTape {
  bool torques = true;
  bool pd = false;        ///< MotorModel::PD: v holds targets (rad)
  double kp = 0, kd = 0;  ///< the PD's gains
  std::vector<Drive> drives;
  std::vector<double> v;  ///< steps x drives x width()
  long steps = 0;
  std::size_t width() const { return torques ? 3 : pd ? 1 : 2; }
};

/// Why the raw replay cannot reproduce runs of this config, or empty. The
/// tape records effector signals, so the motor's command must follow from
/// the signal alone, or (PD) from the signal and the joint's angle through a
/// joint motor of its own (powered_stops "separate", kd above 0: World's
/// implicit damper; the explicit torque of kd = 0 is not replayed), and the
/// controller must be on from the first step (Activation::Always).
inline std::string raw_replay_unsupported(const SimConfig& cfg) {
  if (cfg.motor.model == MotorModel::PD &&
      (cfg.physics.powered_stops != PoweredStops::Separate || !(cfg.motor.kd > 0)))
    return "the raw replay supports PD motors only with their damper in a joint motor (powered_stops "
           "\"separate\", kd > 0)";
  if (cfg.task.activation != Activation::Always)
    return "the raw replay needs the controller on from the first step (activation always)";
  return {};
}

/// The tape of a run of `steps` steps from its replay, which must hold a
/// frame every step (replay_fps = 1 / dt: steps + 1 frames). Computes each
/// command with World::apply_effectors' own expressions, so the values are
/// bit for bit those our run gave ODE.
inline MotorTape record_motor_tape(const CreatureModel& m, const SimConfig& cfg,
                                   const Replay& replay, long steps) {
  MotorTape tape;
  tape.steps = steps;
  const MotorDef& motor = cfg.motor;
  // torque motors with a speed limit are ODE velocity motors, as Saturation
  const bool limited = motor.torque_max_speed > 0 || motor.torque_max_linear_speed > 0;
  tape.torques = motor.model == MotorModel::Torque && !limited;
  tape.pd = motor.model == MotorModel::PD;
  tape.kp = motor.kp;
  tape.kd = motor.kd;
  // drives: torque motors per joint, in joint order (as World adds torques);
  // velocity motors per degree of freedom, the last effector's command winning
  std::vector<int> drive_of(m.joints.size() * 3, -1);
  auto key = [&](const EffectorModel& e) { return tape.torques ? e.joint * 3 : e.joint * 3 + e.dof; };
  for (const EffectorModel& e : m.effectors) {
    if (drive_of[key(e)] >= 0) continue;
    drive_of[key(e)] = static_cast<int>(tape.drives.size());
    tape.drives.push_back({e.joint, tape.torques ? 0 : e.dof, m.joints[e.joint].type});
  }
  std::sort(tape.drives.begin(), tape.drives.end(), [](const Drive& a, const Drive& b) {
    return a.joint != b.joint ? a.joint < b.joint : a.dof < b.dof;
  });
  for (std::size_t k = 0; k < tape.drives.size(); ++k)
    drive_of[tape.drives[k].joint * 3 + tape.drives[k].dof] = static_cast<int>(k);
  const std::size_t nd = tape.drives.size(), w = tape.width();
  tape.v.assign(static_cast<std::size_t>(steps) * nd * w, 0.0);
  // the motors' first-order lag (MotorDef::response_time), as World applies it
  const double lag = motor_lag_share(cfg.physics.dt, motor.response_time);
  std::vector<double> lagged(m.effectors.size(), 0.0);
  // frame 0 is the initial state; frame k+1 holds the signals of step k
  for (long s = 0; s < steps; ++s) {
    const std::vector<double>& sig = replay.frames[s + 1].effectors;
    double* row = &tape.v[static_cast<std::size_t>(s) * nd * w];
    for (std::size_t e = 0; e < m.effectors.size(); ++e) {
      const EffectorModel& em = m.effectors[e];
      double sv = sig[e];
      if (lag > 0) sv = lagged[e] += lag * (sv - lagged[e]);
      if (tape.torques) {
        row[drive_of[em.joint * 3] * 3 + em.dof] += sv * motor.strength * em.cross_section;
        continue;
      }
      if (tape.pd) {
        // the target within the joint's range, as World::apply_effectors has it
        const JointModel& jm = m.joints[em.joint];
        const Limit& l = jm.limits[em.dof];
        row[drive_of[em.joint * 3 + em.dof]] = 0.5 * (l.lo + l.hi) + 0.5 * sv * (l.hi - l.lo);
        continue;
      }
      double* cmd = row + drive_of[em.joint * 3 + em.dof] * 2;
      if (motor.model == MotorModel::Servo) {
        cmd[0] = motor.max_speed * sv;
        cmd[1] = motor.max_force;
      } else if (motor.model == MotorModel::Torque) {  // with its speed limit
        const JointType t = m.joints[em.joint].type;
        bool linear = t == JointType::Slider || (t == JointType::Cylindrical && em.dof == 0);
        double torque = sv * motor.strength * em.cross_section;
        double limit = linear ? motor.torque_max_linear_speed : motor.torque_max_speed;
        cmd[0] = torque >= 0 ? limit : -limit;
        cmd[1] = std::abs(torque);
      } else {  // Saturation
        cmd[0] = sv >= 0 ? motor.max_speed : -motor.max_speed;
        cmd[1] = std::abs(sv) * motor.strength * em.cross_section;
      }
    }
  }
  return tape;
}

/// One raw run: reseed ODE, build, step `tape.steps` steps replaying the
/// tape, destroy. Torque motors: one dJointAdd*Torque call per driven joint
/// per step. Velocity motors: dParamVel per driven degree of freedom per step
/// and dParamFMax when it changes (a plain ODE program's cheapest way to give
/// the same commands). PD motors: FMax (none) and CFM 1/kd set once, then
/// per driven degree of freedom per step the joint's angle read and
/// dParamVel set to kp (target - angle) / kd (World's implicit damper).
/// Returns the final body positions for the check.
inline std::vector<Vec3> run_raw(const CreatureModel& m, const SimConfig& cfg,
                                 const Pose& placement, const MotorTape& tape,
                                 std::uint64_t seed) {
  dRandSetSeed(static_cast<unsigned long>(seed & 0xffffffffULL));
  RawWorld w(m, cfg.physics, placement);
  const std::size_t nd = tape.drives.size();
  const double* v = tape.v.data();
  if (tape.torques) {
    for (long s = 0; s < tape.steps; ++s) {
      for (std::size_t k = 0; k < nd; ++k, v += 3) w.add_torque(tape.drives[k], v);
      w.step();
    }
  } else if (tape.pd) {
    for (const Drive& d : tape.drives) {
      w.set_param(d, dParamFMax, dInfinity);
      w.set_param(d, dParamCFM, 1 / tape.kd);
    }
    for (long s = 0; s < tape.steps; ++s) {
      for (std::size_t k = 0; k < nd; ++k, ++v) {
        const Drive& d = tape.drives[k];
        const double err = *v - w.angle(d);
        w.set_param(d, dParamVel, tape.kp * err / tape.kd);
      }
      w.step();
    }
  } else {
    std::vector<double> fmax(nd, -1.0);  // ODE ignores negative FMax: never a match
    for (long s = 0; s < tape.steps; ++s) {
      for (std::size_t k = 0; k < nd; ++k, v += 2) {
        const Drive& d = tape.drives[k];
        w.set_param(d, dParamVel, v[0]);
        if (v[1] != fmax[k]) w.set_param(d, dParamFMax, fmax[k] = v[1]);
      }
      w.step();
    }
  }
  std::vector<Vec3> pos;
  for (dBodyID b : w.bodies) {
    const dReal* p = dBodyGetPosition(b);
    pos.push_back({p[0], p[1], p[2]});
  }
  return pos;
}

/// Largest distance between a part's final position in our run (the
/// replay's last frame) and in the raw run: 0 when bit-identical.
inline double max_part_deviation(const CreatureModel& m, const Replay& replay,
                                 const std::vector<Vec3>& raw_end) {
  double max_dev = 0;
  const std::vector<double>& ours_end = replay.frames.back().poses;
  for (int i = 0; i < m.n_parts(); ++i) {
    Vec3 o{ours_end[7 * i], ours_end[7 * i + 1], ours_end[7 * i + 2]};
    double d = norm(o - raw_end[i]);
    if (std::isnan(d)) return d;
    max_dev = std::max(max_dev, d);
  }
  return max_dev;
}

}  // namespace bx::bench
