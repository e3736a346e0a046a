// The motor models' laws as pure functions (MotorDef: servo, saturation,
// torque, PD): what an effector's signal asks of its joint's degree of
// freedom. The world's actuator table (physics/actuators.cpp) applies them
// with ODE's rows; a second simulator's replay (io/mujoco_replay.h) with its
// own, so both follow one law.
#pragma once

#include <cmath>

#include "core/math.h"
#include "develop/creature_model.h"
#include "physics/physics_def.h"

namespace bx {

/// Whether degree of freedom `dof` of a joint of type `t` is a length (m),
/// not an angle.
inline bool is_linear_dof(JointType t, int dof) {
  return t == JointType::Slider || (t == JointType::Cylindrical && dof == 0);
}

/// What a motor asks of its degree of freedom in one step.
struct MotorDemand {
  enum class Kind {
    Velocity,  ///< reach `speed` with at most `force` (servo, saturation, a torque's no-load speed, a brake)
    Torque,    ///< apply `torque`
    Target,    ///< a PD spring toward `target` (rad or m), its damper the joint's
  };
  Kind kind = Kind::Torque;
  double speed = 0, force = 0, torque = 0, target = 0;
};

/// The demand of effector `em` (on joint `jm`) at signal `s` (after the
/// motors' lag), by motor.model; a muscle's (MotorModel::Muscle) is not a
/// joint's: a Torque of 0.
inline MotorDemand motor_demand(const MotorDef& motor, const JointModel& jm, const EffectorModel& em, double s) {
  using K = MotorDemand::Kind;
  switch (motor.model) {
    case MotorModel::Servo:  // miconi2006: target velocity max_speed s, force capped at max_force
      return {K::Velocity, motor.max_speed * s, motor.max_force, 0, 0};
    case MotorModel::Saturation:  // chaumont2007 5.3: target velocity sign(s) max_speed, cap |s| strength x cross-section
      return {K::Velocity, s >= 0 ? motor.max_speed : -motor.max_speed,
              std::abs(s) * motor.strength * em.cross_section, 0, 0};
    case MotorModel::Torque: {  // sims1994: s strength x cross-section, up to the no-load speed if it has one
      const double torque = s * motor.strength * em.cross_section;
      const double limit = is_linear_dof(jm.type, em.dof) ? motor.torque_max_linear_speed : motor.torque_max_speed;
      if (limit > 0) return {K::Velocity, torque >= 0 ? limit : -limit, std::abs(torque), 0, 0};
      return {K::Torque, 0, 0, torque, 0};
    }
    case MotorModel::PD: {  // rivercrossing: theta_d from s within the joint's range
      double target;
      if (em.dof < static_cast<int>(jm.limits.size())) {
        const Limit& l = jm.limits[em.dof];
        target = 0.5 * (l.lo + l.hi) + 0.5 * s * (l.hi - l.lo);
      } else {
        target = s * (is_linear_dof(jm.type, em.dof) ? 1.0 : kPi);
      }
      return {K::Target, 0, 0, 0, target};
    }
    case MotorModel::Muscle: break;
  }
  return {};
}

/// A joint's brake (World::brake_effectors): speed 0 with `share` of its full
/// force, a servo's cap or the others' strength x cross-section.
inline MotorDemand brake_demand(const MotorDef& motor, const EffectorModel& em, double share) {
  return {MotorDemand::Kind::Velocity, 0,
          motor.model == MotorModel::Servo ? share * motor.max_force : share * (motor.strength * em.cross_section), 0,
          0};
}

}  // namespace bx
