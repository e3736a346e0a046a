// The world's actuators: each effector's signal drives its joint's degree of
// freedom by the motor model (MotorDef: servo, saturation, torque, PD), after
// the motors' lag; a brake holds them. The muscles' work is metered here.
#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "physics/motor_law.h"
#include "physics/world_impl.h"

namespace bx {

void World::Impl::drive(const Joint& j, int dof, double speed, double force) const {
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

void World::Impl::drive_pd(const Joint& j, int dof, double kp_err, double kd) const {
  if (j.broken) return;
  dJointSetAMotorParam(j.motor, dParamVel + dParamGroup * dof, kp_err / kd);
  dJointSetAMotorParam(j.motor, dParamFMax + dParamGroup * dof, dInfinity);
  dJointSetAMotorParam(j.motor, dParamCFM + dParamGroup * dof, 1 / kd);
  j.pd_softened = true;
}

void World::Impl::apply_torques() {
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

void World::Impl::set_muscle(std::size_t k, double kp, double kd) {
  dJointID mj = muscles[k];
  const double h = def.dt, both = h * kp + kd;
  if (!(both > 0)) {
    dJointDisable(mj);  // neither spring nor damper: slack
    return;
  }
  // ODE's soft constraint as a spring and damper at step h (its manual):
  // ERP = h kp / (h kp + kd), CFM = 1 / (h kp + kd)
  dJointEnable(mj);
  dJointSetDBallParam(mj, dParamERP, h * kp / both);
  dJointSetDBallParam(mj, dParamCFM, 1 / both);
}

void World::Impl::set_muscle_length(std::size_t k, double length) { dJointSetDBallDistance(muscles[k], length); }

double World::Impl::muscle_length(std::size_t k) const {
  dVector3 a, b;
  dJointGetDBallAnchor1(muscles[k], a);
  dJointGetDBallAnchor2(muscles[k], b);
  return norm(vec(a) - vec(b));
}

const World::Impl::GainRow& World::Impl::gain(MotorModel model) {
  // the joint rows drive by the motor's law (physics/motor_law.h) and brake a
  // degree of freedom at speed 0 with a share of their full force
  static constexpr auto velocity = [](Impl& w, const Actuation& a) {
    const MotorDemand d = motor_demand(a.motor, a.m.joints[a.em.joint], a.em, a.s);
    w.drive(w.joints[a.em.joint], a.em.dof, d.speed, d.force);
    return false;
  };
  static constexpr auto brake = [](Impl& w, const Actuation& a) {
    const MotorDemand d = brake_demand(a.motor, a.em, a.s);
    w.drive(w.joints[a.em.joint], a.em.dof, d.speed, d.force);
  };
  static const GainRow rows[] = {
      {MotorModel::Servo, false, velocity, brake},
      {MotorModel::Saturation, false, velocity, brake},
      // a torque, or up to the no-load speed if it has one (as Saturation, with its own speed)
      {MotorModel::Torque, false,
       [](Impl& w, const Actuation& a) {
         const MotorDemand d = motor_demand(a.motor, a.m.joints[a.em.joint], a.em, a.s);
         if (d.kind == MotorDemand::Kind::Velocity) {
           w.drive(w.joints[a.em.joint], a.em.dof, d.speed, d.force);
           return false;
         }
         w.joint_torque[a.em.joint][a.em.dof] += d.torque;
         return true;
       },
       brake},
      // T = kp (theta_d - theta) - kd theta'
      {MotorModel::PD, true,
       [](Impl& w, const Actuation& a) {
         const Joint& j = w.joints[a.em.joint];
         const double target = motor_demand(a.motor, a.m.joints[a.em.joint], a.em, a.s).target;
         const double err = target - w.position(j, a.em.dof);
         if (j.motor && a.motor.kd > 0) {
           // hinges and universal joints: the damper implicit in the joint's own motor
           w.drive_pd(j, a.em.dof, a.motor.kp * err, a.motor.kd);
           return false;
         }
         // no damper (kd = 0: the spring alone, explicit; the motor row off),
         // or a joint without a motor of its own (slider, piston, ball): the
         // explicit torque from the angle and rate at the start of the step
         if (j.motor) w.drive(j, a.em.dof, 0, 0);
         w.joint_torque[a.em.joint][a.em.dof] += a.motor.kp * err - a.motor.kd * w.rate(j, a.em.dof);
         return true;
       },
       brake},
      // lessin2015 III-E: the muscle's stiffness is its activation (held to [0, 1]) times its strength
      {MotorModel::Muscle, false,
       [](Impl& w, const Actuation& a) {
         const auto k = static_cast<std::size_t>(a.em.muscle);
         if (!std::isnan(w.muscle_hold[k])) {  // released: back to its rest length
           w.muscle_hold[k] = std::numeric_limits<double>::quiet_NaN();
           w.set_muscle_length(k, a.m.muscles[k].rest_length);
         }
         w.set_muscle(k, std::clamp(a.s, 0.0, 1.0) * a.m.muscles[k].strength, a.motor.muscle_damping);
         return false;
       },
       // held where it was when the brake began (as a joint's brake holds its
       // speed at 0), with a share of its full stiffness: not pulled to its
       // rest length, which would be a full contraction
       [](Impl& w, const Actuation& a) {
         const auto k = static_cast<std::size_t>(a.em.muscle);
         if (std::isnan(w.muscle_hold[k])) {
           w.muscle_hold[k] = w.muscle_length(k);
           w.set_muscle_length(k, w.muscle_hold[k]);
         }
         w.set_muscle(k, a.s * a.m.muscles[k].strength, a.motor.muscle_damping);
       }},
  };
  const GainRow& row = rows[static_cast<std::size_t>(model)];
  if (row.model != model) throw std::logic_error("the actuator table's rows are out of MotorModel's order");
  return row;
}

void World::Impl::meter_muscles() {
  // a muscle's constraint pushes its two anchors apart or together with equal
  // and opposite forces: its power is f1 . v1 + f2 . v2 at the anchors'
  // velocities after the step (the ones the step moved them with)
  for (std::size_t k = 0; k < muscles.size(); ++k) {
    if (!dJointIsEnabled(muscles[k])) continue;
    const dJointFeedback& f = muscle_feedback[k];
    dVector3 a, b, va, vb;
    dJointGetDBallAnchor1(muscles[k], a);
    dJointGetDBallAnchor2(muscles[k], b);
    dBodyGetPointVel(dJointGetBody(muscles[k], 0), a[0], a[1], a[2], va);
    dBodyGetPointVel(dJointGetBody(muscles[k], 1), b[0], b[1], b[2], vb);
    double p = 0;
    for (int i = 0; i < 3; ++i) p += f.f1[i] * va[i] + f.f2[i] * vb[i];
    muscle_work += std::abs(p) * def.dt;
  }
}

double World::muscle_work() const { return impl_->muscle_work; }

bool needs_own_motor_row(MotorModel m) { return World::Impl::gain(m).own_motor_row; }

void World::brake_effectors(const CreatureModel& m, const MotorDef& motor, double share) {
  auto& w = *impl_;
  const Impl::GainRow& gain = Impl::gain(motor.model);
  for (const EffectorModel& em : m.effectors) gain.brake(w, {m, em, motor, share});
}

void World::apply_effectors(const CreatureModel& m, const MotorDef& motor,
                            std::span<const double> signals) {
  auto& w = *impl_;
  const Impl::GainRow& gain = Impl::gain(motor.model);
  if (gain.own_motor_row && w.def.powered_stops != PoweredStops::Separate)
    throw std::invalid_argument(
        "World: PD motors need physics.powered_stops = \"separate\" (their damper is a joint motor "
        "row of its own, beside the stops; docs/physics.md cause 28)");
  bool torques = false;
  // the motors' first-order lag: the share of the gap closed in one step
  const double lag = motor_lag_share(w.def.dt, motor.response_time);
  if (lag > 0 && w.motor_signal.size() != m.effectors.size()) w.motor_signal.assign(m.effectors.size(), 0);
  for (std::size_t e = 0; e < m.effectors.size(); ++e) {
    const EffectorModel& em = m.effectors[e];
    double s = signals[e];
    if (lag > 0) s = w.motor_signal[e] += lag * (s - w.motor_signal[e]);
    torques |= gain.drive(w, {m, em, motor, s});
  }
  if (torques) w.apply_torques();
}

}  // namespace bx
