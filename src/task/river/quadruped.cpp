#include "task/river/quadruped.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace bx {

namespace {

Error bad(const char* field, double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", value);
  return Error{"quadruped: " + std::string(field) + " is " + buf + ", must be a finite number above 0"};
}

PartModel box(Vec3 size, double density, Pose pose, PartIndex parent, int depth) {
  PartModel p;
  p.shape = Shape::Box;
  p.size = size;
  p.mass = density * size.x * size.y * size.z;
  p.pose = pose;
  p.parent = parent;
  p.depth = depth;
  return p;
}

// leg k's corner signs: (+,+), (-,+), (-,-), (+,-)
Vec3 corner_signs(int leg) {
  const double sx = (leg == 0 || leg == 3) ? 1 : -1;
  const double sy = leg < 2 ? 1 : -1;
  return {sx, sy, 0};
}

}  // namespace

Status check_quadruped_def(const QuadrupedDef& def) {
  if (!(def.unit > 0) || !std::isfinite(def.unit)) return bad("unit", def.unit);
  if (!(def.density > 0) || !std::isfinite(def.density)) return bad("density", def.density);
  return Ok{};
}

CreatureModel make_quadruped(const QuadrupedDef& def) {
  const double u = def.unit;
  const Vec3 up{0, 0, 1};
  const Vec3 limb = u * kLimbSize;
  CreatureModel m;
  m.parts.push_back(box(u * kTorsoSize, def.density, {{0, 0, 0}, Mat3::identity()}, -1, 0));
  for (int leg = 0; leg < kLegs; ++leg) {
    const Vec3 s = corner_signs(leg);
    // the hip at the torso's lower corner; the leg points out along the diagonal
    const Vec3 hip{0.5 * kTorsoSize.x * u * s.x, 0.5 * kTorsoSize.y * u * s.y, -0.5 * kTorsoSize.z * u};
    const Vec3 out = normalized(s);
    // the tangent at the corner: level, across the diagonal (a limb's local
    // y). ODE counts a joint's angle as the parent's turn about the axis
    // relative to the child, so about lift_axis (-tangent) a positive hip
    // lift or knee angle lowers the limb
    const Vec3 tangent = cross(up, out);
    const Vec3 lift_axis = -tangent;
    // upper limb: level, its local x out, y along the tangent, z up
    const Pose upper_pose{hip + 0.5 * limb.x * out, Mat3::from_columns(out, tangent, up)};
    m.parts.push_back(box(limb, def.density, upper_pose, kTorso, 1));
    // lower limb: from the knee at the upper limb's outer end, kKneeBend down
    const Vec3 knee = hip + limb.x * out;
    const Vec3 along = std::cos(kKneeBend) * out - std::sin(kKneeBend) * up;
    const Pose lower_pose{knee + 0.5 * limb.x * along, Mat3::from_columns(along, tangent, cross(along, tangent))};
    m.parts.push_back(box(limb, def.density, lower_pose, upper_limb(leg), 2));

    JointModel h;
    h.type = JointType::Universal;
    h.parent = kTorso;
    h.child = upper_limb(leg);
    h.anchor = hip;
    h.axis1 = up;         // turns with the torso; a positive angle turns the leg clockwise seen from above
    h.axis2 = lift_axis;  // turns with the upper limb
    h.limits = {kHipYawLimit, kHipLiftLimit};
    m.joints.push_back(h);

    JointModel k;
    k.type = JointType::Hinge;
    k.parent = upper_limb(leg);
    k.child = lower_limb(leg);
    k.anchor = knee;
    k.axis1 = lift_axis;  // parallel to the hip's lift axis: the knee bends in the lift's plane
    k.limits = {kKneeLimit};
    m.joints.push_back(k);

    m.effectors.push_back({.joint = hip_joint(leg), .dof = 0});
    m.effectors.push_back({.joint = hip_joint(leg), .dof = 1});
    m.effectors.push_back({.joint = knee_joint(leg), .dof = 0});
  }
  return m;
}

std::array<Vec3, 4> quadruped_sensor_points(const QuadrupedDef& def) {
  const double x = 0.5 * kTorsoSize.x * def.unit, y = 0.5 * kTorsoSize.y * def.unit;
  return {Vec3{x, 0, 0}, Vec3{0, y, 0}, Vec3{-x, 0, 0}, Vec3{0, -y, 0}};
}

double quadruped_foot_depth(const QuadrupedDef& def) {
  // the lower limb's far end, then half its thickness along its local down
  const double hip = 0.5 * kTorsoSize.z;
  const double end = hip + kLimbSize.x * std::sin(kKneeBend);
  return def.unit * (end + 0.5 * kLimbSize.z * std::cos(kKneeBend));
}

PhysicsDef river_physics(const QuadrupedDef& def) {
  PhysicsDef p;
  p.dt = 0.01;
  p.erp = 0.2;
  p.cfm = 5e-5;
  p.friction = 10;
  // PD motors damp implicitly through each joint's motor of its own
  p.powered_stops = PoweredStops::Separate;
  // the paper's "friction pyramid approximation", ODE's own: under the lagged
  // bound an evolved walker's turn at 0.01 s was the bound's, gone at 0.005 s
  // (docs/rivercrossing.md, "Choice: ODE's friction pyramid")
  p.friction_bound = FrictionBound::Ode;
  // per cell width what the defaults are per metre
  p.max_speed *= def.unit;
  p.max_step_jump *= def.unit;
  p.max_joint_gap *= def.unit;
  return p;
}

MotorDef river_motor() {
  MotorDef m;
  m.model = MotorModel::PD;
  m.kp = 0.25;
  m.kd = 0.175;
  return m;
}

}  // namespace bx
