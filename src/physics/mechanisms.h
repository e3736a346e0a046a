#pragma once
// The pieces of our physics built on top of ODE, shared by World and the
// raw-ODE benchmark baseline (bench/raw_ode.h) so the two cannot drift
// apart: the lagged friction bound's memory of the last step's contacts
// (docs/physics.md cause 6) a joint's own motor (cause 12) and the motors' lag (cause 13).
#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <vector>

#include "core/math.h"

namespace bx {

/// A contact of the last step: its bodies, point, and normal force then
/// (`now`) and the step before (`before`; -1: it was new then).
struct CarriedContact {
  dBodyID a, b;
  Vec3 p;
  double now, before;
};

/// A contact between the same bodies within this distance (m) of one of the
/// last step is the same contact; its normal force is steady if it changed
/// by at most this share between the last two steps.
constexpr double kSameContact = 0.02, kSteadyNormal = 0.3;

/// The contact of the last step between `a` and `b` nearest `p` within
/// kSameContact, or null.
inline const CarriedContact* find_carried(const std::vector<CarriedContact>& carried, dBodyID a,
                                          dBodyID b, Vec3 p) {
  double nearest = kSameContact;
  const CarriedContact* same = nullptr;
  for (const CarriedContact& was : carried) {
    if (was.a != a || was.b != b) continue;
    double d = norm(was.p - p);
    if (d < nearest) {
      nearest = d;
      same = &was;
    }
  }
  return same;
}

/// mu times the lesser of the contact's last two normal forces if they are
/// steady, or -1 (the contact keeps ODE's pyramid).
inline double lagged_bound(const CarriedContact& was, double mu) {
  bool steady = was.before >= 0 &&
                std::abs(was.now - was.before) <= kSteadyNormal * std::max(was.now, was.before);
  return steady ? mu * std::min(was.now, was.before) : -1;
}

/// The normal force a contact carried: its feedback force on body a along
/// its normal.
inline double normal_force(const dJointFeedback& f, const dReal* normal) {
  return std::abs(f.f1[0] * normal[0] + f.f1[1] * normal[1] + f.f1[2] * normal[2]);
}

/// MotorDef::response_time: the share of the gap between the motor's
/// command and the signal the first-order lag closes in one step of `dt`
/// (0: no lag, the motor takes the signal at once).
inline double motor_lag_share(double dt, double response_time) {
  return response_time > 0 ? -std::expm1(-dt / response_time) : 0;
}

/// PoweredStops::Separate: an angular motor of its own for a joint's axes
/// (world frame now, each fixed to body `rel`: 1 the parent, 2 the child),
/// unpowered until driven.
inline dJointID create_axis_motor(dWorldID world, dBodyID b1, dBodyID b2,
                                  std::initializer_list<Vec3> axes, std::initializer_list<int> rel) {
  dJointID m = dJointCreateAMotor(world, nullptr);
  dJointAttach(m, b1, b2);
  dJointSetAMotorMode(m, dAMotorUser);
  dJointSetAMotorNumAxes(m, static_cast<int>(axes.size()));
  auto r = rel.begin();
  int k = 0;
  for (const Vec3& a : axes) dJointSetAMotorAxis(m, k++, *r++, a.x, a.y, a.z);
  return m;
}

}  // namespace bx
