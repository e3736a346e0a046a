// A second simulator's opinion (issue 36): a creature's evaluation in ODE,
// closed loop, then the effector signals it recorded replayed open loop into
// the same body exported to MuJoCo (io/mjcf.h), with the same motor laws.
// Whether the creature moves the same way there (direction and distance of
// its centre of mass over the task's scored span) is evidence that what it
// does is not an artefact of ODE's contacts, joints or solver.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "brain/controller.h"
#include "core/math.h"
#include "core/result.h"
#include "develop/creature_model.h"
#include "eval/sim_config.h"

namespace bx {

/// What the two simulators did with the same signals.
struct CrossSimReport {
  double from = 0, to = 0;  ///< the span compared (s): the task's scored span, else the whole run
  double seconds = 0;       ///< simulated in each
  long steps = 0;           ///< physics steps in each (the same dt)
  Vec3 ode, mujoco;         ///< the centre of mass's displacement over the span (m)
  /// The horizontal displacements' angle (rad, 0..pi) and length ratio
  /// (MuJoCo's over ODE's; 0 when ODE's is 0).
  double heading_difference = 0, distance_ratio = 0;
  /// The largest difference of any joint's angle (rad or m) between the two
  /// over the first second: whether the motors drive the joints alike
  /// before the two paths part.
  double first_second_angle_gap = 0;
  /// MuJoCo's lowest centre of mass and the warnings it raised, if any.
  double mujoco_min_height = 0;
  std::vector<std::string> warnings;
};

/// Evaluates the creature in ODE as `evaluate` does its first trial (the same
/// seed, start, task and controller), recording at every physics step what
/// its motors did (driven by which signals, braked or held), then replays
/// those steps open loop in MuJoCo: the body as `creature_mjcf` writes it,
/// started in ODE's start pose, each step's motor computed by ODE's laws
/// (motor.model, its lag, brakes) from MuJoCo's joint state: a velocity
/// motor with a force cap (servo, saturation, a torque's no-load speed, a
/// brake) as the force that reaches its speed in one step, capped, solved
/// for all motors together; a torque as itself; a PD's spring explicit, its
/// damper the joint's (implicit in MuJoCo's Euler step). `seconds` > 0
/// replaces the task's length. Refused, with the reason: muscles (lessin2015:
/// not exported yet), a task that breaks joints or adds props (a throw).
Result<CrossSimReport> crosscheck_mujoco(const CreatureModel& m, const ControllerModel& controller,
                                         const SimConfig& cfg, std::uint64_t seed, double seconds = 0);

}  // namespace bx
