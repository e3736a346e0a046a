// A developed creature as MuJoCo's MJCF (`bestiary export CREATURE --mjcf
// OUT.xml`; docs/export.md): its parts as bodies of a kinematic tree with
// their shapes and masses, its joints with their axes and limits, an
// actuator per effector, and the physics that matter (step, gravity,
// friction, which parts collide), so that another simulator can run the same
// body. Lengths in metres, angles in radians, masses in kilograms.
#pragma once

#include <span>
#include <string>

#include "develop/creature_model.h"
#include "eval/sim_config.h"
#include "physics/world_edits.h"

namespace bx {

/// What creature_mjcf left out or approximated, for the user (one line
/// each; empty when it is exact as far as MJCF goes).
struct MjcfNotes {
  std::vector<std::string> lines;
};

/// The MJCF of `m` standing as `cfg` starts it (the root `drop_height` above
/// the floor at the pose built), named `name`. Each joint degree of freedom
/// is a MuJoCo joint named "j<joint>_<dof>" whose angle has ODE's sign (the
/// parent's turn relative to the child about the joint's axis: the MJCF axis
/// is the negated one), its range the joint's limits; each effector an
/// actuator "e<index>" on its joint (cfg.motor.model: torque and saturation
/// a motor of the torque at signal 1, servo a velocity actuator, pd a
/// position actuator with the joint's damping kd); each muscle (lessin2015) a
/// spatial tendon "m<k>" between sites on its two parts, its damping
/// motor.muscle_damping, its spring length the muscle's rest length, its
/// stiffness 0 (its activation times its strength, which a simulator sets
/// each step: `notes` says so). Each joint in `broken_joints` (a catapult's
/// release, World::break_joint) is left out: its child part heads a body of
/// its own at the top level, free ("free<part>"), colliding with every part.
std::string creature_mjcf(const CreatureModel& m, const SimConfig& cfg, const std::string& name,
                          MjcfNotes* notes = nullptr, std::span<const int> broken_joints = {});

/// A prop (physics/world_edits.h: a lessin2015 target) as an MJCF body
/// "prop<k>" for creature_mjcf's worldbody: a mocap body (kinematic: moved by
/// setting its pose, of unlimited mass to the contacts) at its pose, its
/// geom colliding with every part (contype 4, conaffinity 3), not the floor
/// (MuJoCo leaves two static bodies' geoms alone).
std::string mjcf_prop_body(const Prop& p, int k);

/// The MuJoCo joint creature_mjcf names for degree of freedom `dof` of joint `joint`.
std::string mjcf_joint_name(int joint, int dof);
/// The free joint creature_mjcf gives part `part` when it heads a tree: the
/// root's "root", a freed part's "free<part>".
std::string mjcf_free_joint_name(int part);
/// The spatial tendon creature_mjcf writes for muscle `muscle` (its end sites
/// are the name with "a" and "b").
std::string mjcf_muscle_name(int muscle);

}  // namespace bx
