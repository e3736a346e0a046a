// The world's props (World::add_prop): solids beside the creature and the
// ground, fixed or spinning about the vertical, that the creature's parts
// collide with and rays hit (lessin2015's targets). Their contacts are made
// with the creature's in contacts.cpp.
#include <ode/ode.h>

#include "physics/world_impl.h"

namespace bx {

int World::add_prop(const Prop& p) {
  auto& w = *impl_;
  const int k = static_cast<int>(w.props.size());
  Impl::PropState st;
  st.def = p;
  st.geom = make_geom(w.space, p.shape, p.size, 0.0);
  dGeomSetData(st.geom, entity_data({WorldEntity::Kind::Prop, k}));
  if (p.spin != 0) {
    // a kinematic body: moved by its velocity alone, of unlimited mass to
    // the contacts, so it turns at `spin` whatever pushes on it
    st.body = dBodyCreate(w.world);
    dBodySetKinematic(st.body);
    dBodySetPosition(st.body, p.pose.p.x, p.pose.p.y, p.pose.p.z);
    dMatrix3 R;
    to_ode(p.pose.R, R);
    dBodySetRotation(st.body, R);
    dBodySetAngularVel(st.body, 0, 0, p.spin);
    // the exact rotation of each step (ODE's default, a first-order
    // quaternion update, loses 3e-5 of the angle)
    dBodySetFiniteRotationMode(st.body, 1);
    dGeomSetBody(st.geom, st.body);
    if (p.shape == Shape::Capsule || p.shape == Shape::Cylinder) {
      dMatrix3 off;
      to_ode(z_to_x(), off);
      dGeomSetOffsetRotation(st.geom, off);
    }
  } else {
    place_geom(st.geom, p.shape, p.pose);
  }
  w.props.push_back(st);
  w.prop_touched.push_back(0);
  return k;
}

int World::n_props() const { return static_cast<int>(impl_->props.size()); }

Pose World::prop_pose(int k) const {
  const Impl::PropState& st = impl_->props[static_cast<std::size_t>(k)];
  if (!st.body) return st.def.pose;
  return {vec(dBodyGetPosition(st.body)), from_ode(dBodyGetRotation(st.body))};
}

bool World::prop_touched(int k) const { return impl_->prop_touched[static_cast<std::size_t>(k)] != 0; }

}  // namespace bx
