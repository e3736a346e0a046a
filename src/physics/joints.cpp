// The world's joints (World::Impl's half of them): building each joint with
// its stops, its degrees of freedom as ODE reads them, how far it has come
// apart, and breaking it (a catapult's release).
#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "physics/world_impl.h"

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

}  // namespace

void World::Impl::add_joint(const CreatureModel& m, std::size_t k, const Pose& placement) {
  const JointModel& jm = m.joints[k];
  Joint& j = joints[k];
  j.type = jm.type;
  j.parent = jm.parent;
  j.child = jm.child;
  if (jm.parts_collide) colliding_joints.push_back(static_cast<int>(k));
  Vec3 an = placement.apply(jm.anchor);
  Vec3 a1 = placement.R * jm.axis1, a2 = placement.R * jm.axis2;
  dBodyID b1 = bodies[jm.parent], b2 = bodies[jm.child];
  // what joint_gap watches: a second point along the axis at the child's
  // size, so a hinge bent off its axis shows as a gap too
  Vec3 child_centre = vec(dBodyGetPosition(b2));
  const Vec3& cs = m.parts[jm.child].size;
  Vec3 along = an + std::max(0.5 * std::max({cs.x, cs.y, cs.z}), 0.01) * a1;
  switch (jm.type) {
    case JointType::Fixed: hold_points(j, {an, child_centre}, false, a1); break;
    case JointType::Hinge: hold_points(j, {an, along}, false, a1); break;
    case JointType::Universal:
    case JointType::Spherical: hold_points(j, {an}, false, a1); break;
    case JointType::Slider: hold_points(j, {an, child_centre}, true, a1); break;
    case JointType::Cylindrical: hold_points(j, {an, along}, true, a1); break;
  }
  switch (jm.type) {
    case JointType::Fixed:
      j.id = dJointCreateFixed(world, nullptr);
      dJointAttach(j.id, b1, b2);
      dJointSetFixed(j.id);
      break;
    case JointType::Hinge:
      j.id = dJointCreateHinge(world, nullptr);
      dJointAttach(j.id, b1, b2);
      dJointSetHingeAnchor(j.id, an.x, an.y, an.z);
      dJointSetHingeAxis(j.id, a1.x, a1.y, a1.z);
      if (def.powered_stops == PoweredStops::Separate) j.motor = create_axis_motor(world, b1, b2, {a1}, {1});
      break;
    case JointType::Universal:
      j.id = dJointCreateUniversal(world, nullptr);
      dJointAttach(j.id, b1, b2);
      dJointSetUniversalAnchor(j.id, an.x, an.y, an.z);
      dJointSetUniversalAxis1(j.id, a1.x, a1.y, a1.z);
      dJointSetUniversalAxis2(j.id, a2.x, a2.y, a2.z);
      // axis 1 turns with the parent, axis 2 with the child
      if (def.powered_stops == PoweredStops::Separate) j.motor = create_axis_motor(world, b1, b2, {a1, a2}, {1, 2});
      break;
    case JointType::Slider:
      j.id = dJointCreateSlider(world, nullptr);
      dJointAttach(j.id, b1, b2);
      dJointSetSliderAxis(j.id, a1.x, a1.y, a1.z);
      break;
    case JointType::Cylindrical:
      j.id = dJointCreatePiston(world, nullptr);
      dJointAttach(j.id, b1, b2);
      dJointSetPistonAnchor(j.id, an.x, an.y, an.z);
      dJointSetPistonAxis(j.id, a1.x, a1.y, a1.z);
      break;
    case JointType::Spherical:
      j.id = dJointCreateBall(world, nullptr);
      dJointAttach(j.id, b1, b2);
      dJointSetBallAnchor(j.id, an.x, an.y, an.z);
      // Euler motor: axis 0 fixed to the parent, axis 2 to the child
      j.amotor = dJointCreateAMotor(world, nullptr);
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
    set_param(j, dof, dParamLoStop, j.limits[d].lo);
    set_param(j, dof, dParamHiStop, j.limits[d].hi);
    if (def_stop(def.stop_erp)) set_param(j, dof, dParamStopERP, def.stop_erp);
    if (def_stop(def.stop_cfm)) set_param(j, dof, dParamStopCFM, def.stop_cfm);
    set_param(j, dof, dParamFudgeFactor, def.fudge_factor);
  }
}

void World::Impl::hold_points(Joint& j, std::initializer_list<Vec3> points, bool linear, Vec3 axis) {
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

double World::Impl::overshoot(const Joint& j, int dof) const {
  double x = position(j, dof);
  const Limit& l = j.limits[dof];
  return std::max({0.0, x - l.hi, l.lo - x});
}

double World::Impl::gap(const Joint& j) const {
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

void World::Impl::set_param(const Joint& j, int dof, int param, double v) const {
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

double World::Impl::read_position(const Joint& j, int dof) const {
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

double World::Impl::rate(const Joint& j, int dof) const {
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

double World::joint_position(int j, int dof) const {
  return impl_->position(impl_->joints[j], dof);
}
double World::joint_rate(int j, int dof) const { return impl_->rate(impl_->joints[j], dof); }
double World::joint_gap(int j) const { return impl_->gap(impl_->joints[j]); }

}  // namespace bx
