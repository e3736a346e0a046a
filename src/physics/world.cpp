// The physics world (World): the ODE world, its ground and the creature's
// bodies, the step and the explosion tests. Joints, actuators, contacts and
// sensors are in files of their own (physics/world_impl.h says which).
#include "physics/world.h"

#include <ode/ode.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "physics/world_impl.h"

namespace bx {

void reseed_physics(std::uint64_t seed) {
  ensure_ode_initialized();
  dRandSetSeed(static_cast<unsigned long>(seed & 0xffffffffULL));
}

PhysicsDef softness_at_step(PhysicsDef d) {
  const double h0 = d.erp_cfm_dt, h = d.dt;
  if (!(h0 > 0) || h == h0) return d;
  // the pair (erp, cfm) given at h0, restated at h with the same spring and damper
  auto restate = [&](double& erp, double& cfm) {
    const double kp = erp / (h0 * cfm), kd = (1 - erp) / cfm;
    erp = h * kp / (h * kp + kd);
    cfm = 1 / (h * kp + kd);
  };
  const double world_erp = d.erp, world_cfm = d.cfm;
  restate(d.erp, d.cfm);
  // a contact or stop pair with a value of its own: both restated from what
  // it is at h0 (a value it does not set is the world's there)
  auto own = [&](double& erp, double& cfm) {
    if (erp < 0 && cfm < 0) return;  // the world's, restated above
    if (erp < 0) erp = world_erp;
    if (cfm < 0) cfm = world_cfm;
    restate(erp, cfm);
  };
  own(d.contact_erp, d.contact_cfm);
  own(d.stop_erp, d.stop_cfm);
  return d;
}

namespace {
std::atomic<long> g_worlds_made{0};
}  // namespace

long World::made() { return g_worlds_made.load(); }

World::World(const PhysicsDef& given) : impl_(std::make_unique<Impl>()) {
  ++g_worlds_made;
  ensure_ode_initialized();
  auto& w = *impl_;
  w.def = softness_at_step(given);
  const PhysicsDef& def = w.def;
  w.world = dWorldCreate();
  dWorldSetGravity(w.world, 0, 0, def.gravity);
  dWorldSetERP(w.world, def.erp);
  dWorldSetCFM(w.world, def.cfm);
  dWorldSetQuickStepNumIterations(w.world, def.solver_iterations);
  if (def.contact_max_correcting_vel > 0)
    dWorldSetContactMaxCorrectingVel(w.world, def.contact_max_correcting_vel);
  dWorldSetContactSurfaceLayer(w.world, def.contact_surface_layer);
  dWorldSetAutoDisableFlag(w.world, 0);
  // each world its own threading implementation (docs/design.md)
  w.threading = dThreadingAllocateSelfThreadedImplementation();
  dWorldSetStepThreadingImplementation(w.world, dThreadingImplementationGetFunctions(w.threading),
                                       w.threading);
  w.space = dSimpleSpaceCreate(nullptr);
  w.contact_group = dJointGroupCreate(0);
  dGeomID ground = dCreatePlane(w.space, 0, 0, 1, 0);
  dGeomSetData(ground, entity_data({WorldEntity::Kind::Ground, 0}));
  w.contact_buf.resize(std::max(def.max_contacts, 1));
}

World::~World() {
  auto& w = *impl_;
  dJointGroupDestroy(w.contact_group);
  dSpaceDestroy(w.space);  // destroys its geoms
  dWorldDestroy(w.world);  // destroys bodies and joints
  if (ode_thread_log().faulted)
    ode_thread_log().faulted = false;  // after a PhysicsFault: leak the threading implementation
  else
    dThreadingFreeImplementation(w.threading);
}

void World::add_creature(const CreatureModel& m, const Pose& placement) {
  auto& w = *impl_;
  int n = m.n_parts();
  w.bodies.resize(n);
  w.geoms.resize(n);
  w.masses.resize(n);
  w.contact_mask.assign(n, 0);
  w.touching.assign(n, 0);
  w.free_part.assign(n, false);
  w.prev_pos.resize(n);
  // bodies with shape, mass and pose
  for (int i = 0; i < n; ++i) {
    const PartModel& part = m.parts[i];
    Pose pose{placement.apply(part.pose.p), placement.R * part.pose.R};
    dBodyID b = dBodyCreate(w.world);
    dMass mass;
    const Vec3& s = part.size;
    switch (part.shape) {
      case Shape::Box: dMassSetBoxTotal(&mass, part.mass, s.x, s.y, s.z); break;
      case Shape::Sphere: dMassSetSphereTotal(&mass, part.mass, s.x / 2); break;
      case Shape::Capsule:
        dMassSetCapsuleTotal(&mass, part.mass, 1, s.y / 2, std::max(s.x - s.y, 0.0));
        break;
      case Shape::Cylinder: dMassSetCylinderTotal(&mass, part.mass, 1, s.y / 2, s.x); break;
    }
    dBodySetMass(b, &mass);
    dBodySetPosition(b, pose.p.x, pose.p.y, pose.p.z);
    dMatrix3 R;
    to_ode(pose.R, R);
    dBodySetRotation(b, R);
    dGeomID g = make_geom(w.space, part.shape, s, 0.0);
    dGeomSetBody(g, b);
    if (part.shape == Shape::Capsule || part.shape == Shape::Cylinder) {
      dMatrix3 off;
      to_ode(z_to_x(), off);
      dGeomSetOffsetRotation(g, off);
    }
    dGeomSetData(g, entity_data({WorldEntity::Kind::Part, i}));
    w.bodies[i] = b;
    w.geoms[i] = g;
    w.masses[i] = part.mass;
    w.total_mass += part.mass;
    w.prev_pos[i] = pose.p;
  }
  // joints, with anchors and axes moved by the placement
  w.joints.resize(m.joints.size());
  w.joint_torque.assign(m.joints.size(), {0, 0, 0});
  w.positions.assign(m.joints.size(), {0, 0, 0});
  w.positions_read.assign(m.joints.size(), 0);
  for (std::size_t k = 0; k < m.joints.size(); ++k) w.add_joint(m, k, placement);
  // muscles: soft distance constraints between their anchors, slack until
  // an effector activates them (MotorModel::Muscle)
  w.muscles.clear();
  w.muscle_feedback.assign(m.muscles.size(), dJointFeedback{});
  w.muscle_hold.assign(m.muscles.size(), std::numeric_limits<double>::quiet_NaN());
  w.muscle_work = 0;
  for (const MuscleModel& mm : m.muscles) {
    dJointID mj = dJointCreateDBall(w.world, nullptr);
    dJointAttach(mj, w.bodies[mm.part_a], w.bodies[mm.part_b]);
    const Vec3 a = placement.apply(mm.anchor_a), b = placement.apply(mm.anchor_b);
    dJointSetDBallAnchor1(mj, a.x, a.y, a.z);
    dJointSetDBallAnchor2(mj, b.x, b.y, b.z);
    dJointSetDBallDistance(mj, mm.rest_length);
    dJointSetFeedback(mj, &w.muscle_feedback[w.muscles.size()]);
    dJointDisable(mj);
    w.muscles.push_back(mj);
  }
  w.place_receptors(m);
}

void World::fix_part_to_world(int i) {
  auto& w = *impl_;
  dJointID j = dJointCreateFixed(w.world, nullptr);
  dJointAttach(j, w.bodies[i], nullptr);
  dJointSetFixed(j);
}

void World::step() {
  auto& w = *impl_;
  std::fill(w.contact_mask.begin(), w.contact_mask.end(), 0);
  std::fill(w.touching.begin(), w.touching.end(), 0);
  std::fill(w.prop_touched.begin(), w.prop_touched.end(), 0);
  w.contacts.clear();
  dSpaceCollide(w.space, &w, &Impl::near_callback);
  w.attach_contacts();
  OdeThreadLog& log = ode_thread_log();
  long messages = log.messages;
  w.forget_positions();  // the bodies move
  if (w.def.solver == Solver::Exact)
    dWorldStep(w.world, w.def.dt);
  else
    dWorldQuickStep(w.world, w.def.dt);
  if (log.messages != messages && w.solver_failure.empty()) {
    char buf[300];
    std::snprintf(buf, sizeof buf, "ODE could not solve the step at t=%.4g s (%s)", w.t, log.last_message);
    w.solver_failure = buf;
  }
  w.remember_contacts();
  w.meter_muscles();
  dJointGroupEmpty(w.contact_group);
  w.t += w.def.dt;
}

std::string World::check_explosion() {
  auto& w = *impl_;
  // a step the solver gave up on left constraint rows at zero force
  if (!w.solver_failure.empty()) return w.solver_failure;
  char buf[160];
  for (std::size_t i = 0; i < w.bodies.size(); ++i) {
    Vec3 p = vec(dBodyGetPosition(w.bodies[i]));
    Vec3 v = vec(dBodyGetLinearVel(w.bodies[i]));
    if (!std::isfinite(p.x + p.y + p.z + v.x + v.y + v.z)) {
      std::snprintf(buf, sizeof buf, "part %zu: position or velocity is not finite", i);
      return buf;
    }
    double speed = norm(v);
    if (speed > w.def.max_speed) {
      std::snprintf(buf, sizeof buf, "part %zu: speed %.3g m/s above max_speed %.3g", i, speed,
                    w.def.max_speed);
      return buf;
    }
    double jump = norm(p - w.prev_pos[i]);
    if (jump > w.def.max_step_jump) {
      std::snprintf(buf, sizeof buf, "part %zu: moved %.3g m in one step, above max_step_jump %.3g",
                    i, jump, w.def.max_step_jump);
      return buf;
    }
    w.prev_pos[i] = p;
  }
  for (std::size_t k = 0; k < w.joints.size(); ++k) {
    const Impl::Joint& j = w.joints[k];
    if (j.broken) continue;
    for (std::size_t d = 0; d < j.limits.size(); ++d)
      w.stats.max_stop_overshoot = std::max(w.stats.max_stop_overshoot, w.overshoot(j, static_cast<int>(d)));
    double gap = w.gap(j);
    if (gap > w.stats.max_joint_gap) {
      w.stats.max_joint_gap = gap;
      w.stats.worst_joint = static_cast<int>(k);
    }
    if (gap > w.def.max_joint_gap) {
      std::snprintf(buf, sizeof buf, "joint %zu (%s): %.3g m apart, above max_joint_gap %.3g", k,
                    std::string(to_string(j.type)).c_str(), gap, w.def.max_joint_gap);
      return buf;
    }
  }
  return {};
}

Pose World::part_pose(int i) const {
  dBodyID b = impl_->bodies[i];
  return {vec(dBodyGetPosition(b)), from_ode(dBodyGetRotation(b))};
}

Vec3 World::part_velocity(int i) const { return vec(dBodyGetLinearVel(impl_->bodies[i])); }

Vec3 World::centre_of_mass() const {
  const auto& w = *impl_;
  Vec3 c;
  for (std::size_t i = 0; i < w.bodies.size(); ++i)
    c = c + w.masses[i] * vec(dBodyGetPosition(w.bodies[i]));
  return (1.0 / w.total_mass) * c;
}

const WorldStats& World::stats() const { return impl_->stats; }
double World::time() const { return impl_->t; }
const PhysicsDef& World::def() const { return impl_->def; }

}  // namespace bx
