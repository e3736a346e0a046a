// The river crossing's body (Stanton & Channon 2015, "Environment and
// Physical Model"; docs/rivercrossing.md, "The quadruped"): a fixed quadruped
// built in code, not grown from a genome. Dimensions are the paper's, in cell
// widths; QuadrupedDef says how long a cell width is and how dense the parts
// are, which the paper leaves open.
//
// Layout (creature frame, x and y along the torso's sides, z up; u = one cell
// width): a torso of 1 x 1 x 0.2 u centred at the origin; at each of its four
// lower corners a two-segment leg of 0.5 x 0.2 x 0.2 u limbs pointing outward
// along the torso's diagonal. The pose built is the middle of every joint's
// range: upper limbs level, lower limbs 45 degrees down, so the body stands on
// its four feet as constant mid-range PD targets hold it.
#pragma once

#include <array>

#include "core/math.h"
#include "core/result.h"
#include "develop/creature_model.h"
#include "physics/physics_def.h"

namespace bx {

/// The choices the paper leaves open. Every length of the body is a multiple
/// of `unit`; every part has `density`. The PD gains are fixed torques (N m
/// per rad), so the body's weight decides whether they hold it up
/// (docs/rivercrossing.md, "Unit and density"): the torque gravity puts on a
/// hip grows as density x unit^4. At 0.2 kg m (g = 9.81) mid-range targets
/// still hold the torso up; at 0.3 kg m it sags, at 0.4 kg m it sinks onto its
/// limbs. The limbs' inertia (density x unit^5) no longer matters for
/// stability: World's PD damps implicitly, stable for any inertia. The
/// defaults: a 1 m cell at 0.1 kg/m^3 (0.1 kg m; a body of 0.036 kg, its
/// torso 1 m square). What the size changes: under the paper's CFM the feet
/// creep (ODE's friction rows carry the world's CFM; in cell widths the creep
/// goes as 1 / unit^2), and at 0.1 m (water's density) that slip made evolved
/// gaits depend on the step: their speed changed by up to 45% from 0.01 s to
/// 0.005 s, where in 1 m cells the same controllers' speeds agree within 10%
/// from 0.01 s to 0.0025 s (docs/rivercrossing.md, "Unit and density").
struct QuadrupedDef {
  double unit = 1;         ///< metres per cell width
  double density = 0.1;    ///< kg/m^3 of every part
  friend bool operator==(const QuadrupedDef&, const QuadrupedDef&) = default;
};

/// An error naming the field and value if unit or density is not a finite
/// number above 0.
Status check_quadruped_def(const QuadrupedDef& def);

/// The paper's dimensions, in cell widths.
inline constexpr Vec3 kTorsoSize{1.0, 1.0, 0.2};
inline constexpr Vec3 kLimbSize{0.5, 0.2, 0.2};  ///< along the limb, across, up
inline constexpr double kSensorSize = 0.05;      ///< a sensor cube's side

/// Joint ranges (rad), each centred on the pose built: hip about the
/// vertical pi/2, hip about the torso's tangent pi, knee pi/2 (the paper's).
/// Positive hip lift and knee angles lower the limb: the lift runs from
/// straight up (-pi/2) to straight down (pi/2), the knee from straight
/// (-pi/4) to a right angle (pi/4). A positive hip yaw turns the leg
/// clockwise seen from above, from the diagonal towards a side.
inline constexpr Limit kHipYawLimit{-kPi / 4, kPi / 4};
inline constexpr Limit kHipLiftLimit{-kPi / 2, kPi / 2};
inline constexpr Limit kKneeLimit{-kPi / 4, kPi / 4};
/// The lower limb's angle below the upper limb's line in the pose built: the
/// middle of the knee's range of pi/2 from straight to a right angle.
inline constexpr double kKneeBend = kPi / 4;

/// Legs, parts, joints and effectors, in order. Leg k sits at the torso
/// corner (sx, sy) = (+,+), (-,+), (-,-), (+,-) for k = 0..3 (counter-
/// clockwise from +x+y seen from above).
inline constexpr int kLegs = 4;
inline constexpr PartIndex kTorso = 0;
inline constexpr PartIndex upper_limb(int leg) { return 1 + 2 * leg; }
inline constexpr PartIndex lower_limb(int leg) { return 2 + 2 * leg; }
inline constexpr JointIndex hip_joint(int leg) { return 2 * leg; }   ///< universal: yaw, lift
inline constexpr JointIndex knee_joint(int leg) { return 2 * leg + 1; }  ///< hinge
/// Effector 3 leg + 0: hip about the vertical; + 1: hip about the tangent
/// (lift); + 2: knee.
inline constexpr int kQuadrupedEffectors = 3 * kLegs;

/// The quadruped: 9 parts (torso, then each leg's upper and lower limb), 8
/// joints (each leg's hip, then its knee), 12 effectors, no sensors of the
/// graph kind and no graph brain (the river crossing's controller drives the
/// effectors). The torso is the root at the origin, its bottom at z =
/// -0.1 unit. Call check_quadruped_def first.
CreatureModel make_quadruped(const QuadrupedDef& def);

/// The four sensors, in the torso's frame (m): the centres of the torso's
/// four side faces, in the order +x, +y, -x, -y. The paper's 0.05 u sensor
/// cubes are not parts: a sensor is this point, which the task reads
/// (docs/rivercrossing.md, "Sensors"). Divide by def.unit for cell widths.
std::array<Vec3, 4> quadruped_sensor_points(const QuadrupedDef& def);

/// The lowest z of the body in the pose built (m), from the torso's centre:
/// the lower limbs' outer bottom edges.
double quadruped_foot_depth(const QuadrupedDef& def);

/// The paper's physics: step 0.01 s, ERP 0.2, CFM 5e-5, friction mu = 10
/// (ODE's friction pyramid for new contacts, the project's lagged bound for
/// steady ones: FrictionBound::Lagged). Powered stops "separate": the PD
/// motors' implicit damper is each joint's motor of its own. The explosion
/// tests' distances and speeds (PhysicsDef's defaults, set for bodies about
/// 1 m long) are scaled to def.unit; everything else is PhysicsDef's default
/// (the exact solver, gravity 9.81, parts collide with each other).
PhysicsDef river_physics(const QuadrupedDef& def);

/// The paper's motors: PD, T = ks (target - angle) - kd rate with ks = 0.25
/// N m/rad and kd = 0.175 N m s/rad (eq. 7), the target the signal's place
/// within the joint's range; the rate is the one the step ends with (World's
/// implicit damper).
MotorDef river_motor();

}  // namespace bx
