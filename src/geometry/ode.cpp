// ODE for this process: initialisation, error handlers, frame helpers (geometry/ode.h).
#include "geometry/ode.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <mutex>

namespace bx {

namespace {

std::once_flag g_ode_once;

thread_local OdeThreadLog g_log;

void ode_message(int num, const char* msg, va_list ap) {
  // ODE's messages (dMessage) report a step it could not solve: the exact
  // solver's "LCP internal error", after which it leaves the rows it did not
  // reach at zero force. Counted here, reported by the world that stepped.
  ++g_log.messages;
  std::vsnprintf(g_log.last_message, sizeof g_log.last_message, msg, ap);
}

[[noreturn]] void ode_fault(int num, const char* msg, va_list ap) {
  // ODE's error and debug handlers must not return (ODE aborts if they do).
  // After a fault ODE's threading implementation of the step is left mid-job
  // and asserts if freed, so the world that faulted leaks it (rare).
  g_log.faulted = true;
  char buf[256];
  std::vsnprintf(buf, sizeof buf, msg, ap);
  throw PhysicsFault("ODE internal error " + std::to_string(num) + ": " + buf);
}

}  // namespace

OdeThreadLog& ode_thread_log() { return g_log; }

void ensure_ode_initialized() {
  std::call_once(g_ode_once, [] {
    dInitODE2(0);
    // ODE prints and aborts on internal errors: failed steps are counted,
    // internal errors throw
    dSetMessageHandler(ode_message);
    dSetErrorHandler(ode_fault);
    dSetDebugHandler(ode_fault);
  });
  static thread_local bool thread_ready = false;
  if (!thread_ready) {
    dAllocateODEDataForThread(dAllocateMaskAll);
    thread_ready = true;
  }
}

// ODE matrices are 3x4 row-major
void to_ode(const Mat3& R, dMatrix3 out) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out[i * 4 + j] = R.m[i][j];
    out[i * 4 + 3] = 0;
  }
}

Mat3 from_ode(const dReal* r) {
  Mat3 R;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R.m[i][j] = r[i * 4 + j];
  return R;
}


// rotation taking ODE's z-aligned capsules and cylinders to our x-aligned ones
Mat3 z_to_x() { return Mat3::rotation({0, 1, 0}, kPi / 2); }

// geometry of one part, sizes shrunk by `margin` on every side
dGeomID make_geom(dSpaceID space, Shape shape, Vec3 size, double margin) {
  auto shrink = [&](double full) { return std::max(full - 2 * margin, 1e-4); };
  switch (shape) {
    case Shape::Box:
      return dCreateBox(space, shrink(size.x), shrink(size.y), shrink(size.z));
    case Shape::Sphere:
      return dCreateSphere(space, shrink(size.x) / 2);
    case Shape::Capsule: {
      double r = shrink(size.y) / 2;
      return dCreateCapsule(space, r, std::max(shrink(size.x) - 2 * r, 0.0));
    }
    case Shape::Cylinder:
      return dCreateCylinder(space, shrink(size.y) / 2, shrink(size.x));
  }
  return nullptr;
}

// sets a geom's world pose, turning z-aligned ODE primitives to lie along x
void place_geom(dGeomID g, Shape shape, const Pose& pose) {
  dGeomSetPosition(g, pose.p.x, pose.p.y, pose.p.z);
  Mat3 R = pose.R;
  if (shape == Shape::Capsule || shape == Shape::Cylinder) R = R * z_to_x();
  dMatrix3 m;
  to_ode(R, m);
  dGeomSetRotation(g, m);
}

// spheres, capsules and cylinders: the shapes that roll
bool round_geom(dGeomID g) {
  int c = dGeomGetClass(g);
  return c == dSphereClass || c == dCapsuleClass || c == dCylinderClass;
}

}  // namespace bx
