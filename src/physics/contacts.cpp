// The world's contacts: collision (which pairs may touch), the contact joints
// of each step with their friction bound (ODE's pyramid, or the lagged bound),
// and the contact flags sensors and tasks read.
#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "physics/world_impl.h"

namespace bx {

namespace {
// two contact points of one pair this close, with normals this close, are one (m)
constexpr double kRepeatedContact = 1e-9;
}  // namespace

void World::Impl::collide(dGeomID a, dGeomID b) {
  dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
  const int prop_a = prop_of(a), prop_b = prop_of(b);
  const bool prop = prop_a >= 0 || prop_b >= 0;
  // a prop touches the creature's parts only (not the ground, not a prop)
  if (prop && (part_of(a) < 0) == (part_of(b) < 0)) return;
  if (ba && bb && !prop) {
    // parts joined by a joint collide only when it says so
    // (JointModel::parts_collide); others only with self_collision, unless
    // one of them was set free
    bool freed = free_part[part_of(a)] || free_part[part_of(b)];
    if (colliding_joints.empty()) {
      if ((!def.self_collision && !freed) || dAreConnectedExcluding(ba, bb, dJointTypeContact)) return;
    } else if (dAreConnectedExcluding(ba, bb, dJointTypeContact)) {
      if (!joined_parts_collide(part_of(a), part_of(b))) return;
    } else if (!def.self_collision && !freed) {
      return;
    }
  }
  int n = dCollide(a, b, def.max_contacts, &contact_buf[0].geom, sizeof(dContact));
  if (n > 0 && prop) prop_touched[static_cast<std::size_t>(std::max(prop_a, prop_b))] = 1;
  else if (n > 0 && ba && bb) touching[part_of(a)] = touching[part_of(b)] = 1;
  for (int i = 0; i < n; ++i) {
    dContact& c = contact_buf[i];
    // a point ODE's collider gave twice (a capsule against a box or a capsule
    // can): two identical rows make the exact solver's LCP singular ("LCP
    // internal error, s <= 0"), and the second adds nothing
    bool repeated = false;
    for (int k = 0; k < i && !repeated; ++k) {
      const dContactGeom &p = contact_buf[k].geom, &q = c.geom;
      repeated = std::abs(p.pos[0] - q.pos[0]) <= kRepeatedContact && std::abs(p.pos[1] - q.pos[1]) <= kRepeatedContact &&
                 std::abs(p.pos[2] - q.pos[2]) <= kRepeatedContact && std::abs(p.normal[0] - q.normal[0]) <= kRepeatedContact &&
                 std::abs(p.normal[1] - q.normal[1]) <= kRepeatedContact && std::abs(p.normal[2] - q.normal[2]) <= kRepeatedContact;
    }
    if (repeated) continue;
    c.surface.mode = dContactApprox1;
    c.surface.mu = def.friction;
    if (def.rolling_friction > 0 && (round_geom(a) || round_geom(b))) {
      // rolling resistance, bounded by rho times the normal force (Approx1_N)
      c.surface.mode |= dContactRolling;
      c.surface.rho = c.surface.rho2 = def.rolling_friction;
      c.surface.rhoN = 0;
    }
    if (def.contact_erp >= 0) {
      c.surface.mode |= dContactSoftERP;
      c.surface.soft_erp = def.contact_erp;
    }
    if (def.contact_cfm >= 0) {
      c.surface.mode |= dContactSoftCFM;
      c.surface.soft_cfm = def.contact_cfm;
    }
    stats.max_penetration = std::max(stats.max_penetration, static_cast<double>(c.geom.depth));
    // the first body never the ground's (nor a prop's: a spinning one has a body)
    Contact ct{c, ba, bb, (c.surface.mode & dContactRolling) != 0};
    if (!ct.a || prop_a >= 0) {
      std::swap(ct.a, ct.b);
      std::swap(ct.c.geom.g1, ct.c.geom.g2);
      for (int i = 0; i < 3; ++i) ct.c.geom.normal[i] = -ct.c.geom.normal[i];
    }
    contacts.push_back(ct);
    // ODE's normal points into geom a: a is touched on the face facing -n, b on +n
    mark_face(a, c.geom.normal, -1);
    mark_face(b, c.geom.normal, +1);
  }
}

void World::Impl::attach_contacts() {
  const bool lagged = def.friction_bound == FrictionBound::Lagged;
  feedback.resize(contacts.size());
  for (Contact& ct : contacts) {
    dContact& c = ct.c;
    if (lagged) {
      if (const CarriedContact* same = find_carried(carried, ct.a, ct.b, vec(c.geom.pos))) {
        ct.was = same->now;
        double bound = ct.rolls ? -1 : lagged_bound(*same, def.friction);
        if (bound >= 0) {
          c.surface.mode &= ~dContactApprox1;
          c.surface.mu = bound;
        }
      }
    }
    dJointID cj = dJointCreateContact(world, contact_group, &c);
    dJointAttach(cj, ct.a, ct.b);
    if (lagged) dJointSetFeedback(cj, &feedback[&ct - contacts.data()]);
  }
}

void World::Impl::remember_contacts() {
  carried.clear();
  if (def.friction_bound != FrictionBound::Lagged) return;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const Contact& ct = contacts[k];
    carried.push_back({ct.a, ct.b, vec(ct.c.geom.pos), normal_force(feedback[k], ct.c.geom.normal), ct.was});
  }
}

void World::Impl::mark_face(dGeomID g, const dReal* n, double sign) {
  const int part = part_of(g);
  if (part < 0) return;  // the ground
  dVector3 local;
  dBodyVectorFromWorld(bodies[part], sign * n[0], sign * n[1], sign * n[2], local);
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(local[k]) > std::abs(local[axis])) axis = k;
  contact_mask[part] |= static_cast<std::uint8_t>(1u << static_cast<int>(make_face(axis, local[axis])));
}

std::uint8_t World::contact_mask(int i) const { return impl_->contact_mask[i]; }
bool World::touches_part(int i) const { return impl_->touching[i] != 0; }

}  // namespace bx
