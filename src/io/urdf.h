// A developed creature as URDF (`bestiary export CREATURE --urdf OUT.urdf`;
// docs/export.md), the robot description ROS, PyBullet, Drake and MuJoCo
// read: its parts as links with their masses, inertias and shapes, its
// joints with their axes and limits. Lengths in metres, angles in radians,
// masses in kilograms.
#pragma once

#include <string>
#include <vector>

#include "develop/creature_model.h"
#include "eval/sim_config.h"

namespace bx {

/// The URDF of `m` in the pose it was built in, named `name`. Link "p<i>" is
/// part i, its frame at its joint's anchor turned as the part (the root's:
/// its centre), so each joint's origin is its anchor. Joint degree of
/// freedom k of joint j is a one-axis joint "j<j>_<k>" whose angle has ODE's
/// sign (the axis is the negated one, as in the MJCF export); a joint of
/// several degrees of freedom chains them through massless links
/// "p<i>_dof<k>" (mass 1e-9 kg). A joint with limits is "revolute" within
/// them, one without "continuous"; each joint's `effort` is the largest
/// torque (N m) or force (N) an effector applies on it (0: none, or a PD
/// motor, which has no cap), `velocity` motor.max_speed.
/// Capsules, which URDF lacks, are a cylinder and two spheres.
/// `notes` gets what URDF cannot say (actuators, muscles, the physics).
std::string creature_urdf(const CreatureModel& m, const SimConfig& cfg, const std::string& name,
                          std::vector<std::string>* notes = nullptr);

/// The mass of each massless link a joint's extra degrees of freedom add.
inline constexpr double kUrdfDofLinkMass = 1e-9;

}  // namespace bx
