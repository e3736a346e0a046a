// ODE for this process: initialisation, its error handlers, and the helpers
// every user of ODE's geoms needs (our frames to ODE's and back). The lowest
// layer that touches ODE: development's overlap test and the physics world
// both stand on it (docs/architecture.md).
#pragma once

#include <ode/ode.h>

#include <stdexcept>
#include <string>

#include "core/math.h"
#include "genome/genome.h"

namespace bx {

/// An internal error of ODE (a failed assertion, e.g. a singular matrix in
/// the exact solver's factorisation): thrown out of the ODE call instead of
/// ODE's abort, so that one evaluation fails, not the process. The world it
/// came from must be destroyed, not stepped again.
struct PhysicsFault : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Initialises ODE for this process (once) and this thread; ODE's internal
/// errors throw PhysicsFault.
void ensure_ode_initialized();

/// What ODE reported on this thread. `messages` counts its messages (dMessage:
/// a step it could not solve, e.g. the exact solver's "LCP internal error");
/// `last_message` is the latest; `faulted` is set when a PhysicsFault was
/// thrown (the faulted world must leak its threading implementation, which
/// ODE left mid-job).
struct OdeThreadLog {
  long messages = 0;
  char last_message[200] = "";
  bool faulted = false;
};
OdeThreadLog& ode_thread_log();

/// Our rotation as ODE's 3x4 row-major matrix, and back.
void to_ode(const Mat3& R, dMatrix3 out);
Mat3 from_ode(const dReal* r);
inline Vec3 vec(const dReal* v) { return {v[0], v[1], v[2]}; }

/// The rotation taking ODE's z-aligned capsules and cylinders to our x-aligned ones.
Mat3 z_to_x();

/// A part's geom (in `space`, or none), its sizes shrunk by `margin` on every side.
dGeomID make_geom(dSpaceID space, Shape shape, Vec3 size, double margin);

/// Sets a geom's world pose, turning z-aligned ODE primitives to lie along x.
void place_geom(dGeomID g, Shape shape, const Pose& pose);

/// Spheres, capsules and cylinders: the shapes that roll.
bool round_geom(dGeomID g);

}  // namespace bx
