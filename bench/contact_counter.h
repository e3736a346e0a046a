// contact_counter.h: counts the contact joints ODE makes, for a benchmark's
// contacts/step figure (docs/benchmarks.md). The definition below takes the
// place of ODE's dJointCreateContact for every call in the executable that
// includes it (ours in bx_sim and raw in raw_ode.h alike): it counts, then
// calls ODE's own, found with dlsym(RTLD_NEXT). One increment and one
// indirect call per contact, on both sides. Needs ODE as a shared library
// (Debian's libode.so). Include it in one source file of an executable, and
// call bind_contact_counter() once before the first step.
#pragma once

#include <ode/ode.h>

#include <dlfcn.h>

namespace bx::bench {

using CreateContactFn = dJointID (*)(dWorldID, dJointGroupID, const dContact*);
inline CreateContactFn g_real_create_contact = nullptr;
/// Contact joints made so far, by every world of the process.
inline long g_contacts = 0;

/// Finds ODE's own dJointCreateContact; false if it cannot.
inline bool bind_contact_counter() {
  g_real_create_contact = reinterpret_cast<CreateContactFn>(dlsym(RTLD_NEXT, "dJointCreateContact"));
  return g_real_create_contact != nullptr;
}

}  // namespace bx::bench

extern "C" dJointID dJointCreateContact(dWorldID w, dJointGroupID g, const dContact* c) {
  ++bx::bench::g_contacts;
  return bx::bench::g_real_create_contact(w, g, c);
}
