// The world's actuators: each effector's signal drives its joint's degree of
// freedom by the motor model (MotorDef: servo, saturation, torque, PD), after
// the motors' lag; a brake holds them.
#include <ode/ode.h>

#include <cmath>
#include <stdexcept>

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

}  // namespace bx
