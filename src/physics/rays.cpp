// The world's ray query: the nearest surface along a ray, and what it
// belongs to (a photoreceptor's line of sight, lessin2015 III-D).
#include <ode/ode.h>

#include <cmath>

#include "physics/world_impl.h"

namespace bx {

namespace {

struct RayQuery {
  RayHit nearest;
};

void ray_callback(void* data, dGeomID ray, dGeomID g) {
  auto& q = *static_cast<RayQuery*>(data);
  dContactGeom c;
  if (dCollide(ray, g, 1, &c, sizeof(dContactGeom)) < 1) return;
  const double d = c.depth;  // a ray's contact depth is the distance along it
  if (q.nearest.hit && d >= q.nearest.distance) return;
  // ODE gives a ray's contact the surface's outward normal at the hit
  q.nearest = {true, d, {c.pos[0], c.pos[1], c.pos[2]}, {c.normal[0], c.normal[1], c.normal[2]},
               entity_of(g)};
}

}  // namespace

RayHit World::ray(Vec3 origin, Vec3 dir, double length) const { return impl_->cast(origin, dir, length); }

RayHit World::Impl::cast(Vec3 origin, Vec3 dir, double length) const {
  const double n = norm(dir);
  if (!(n > 0) || !(length > 0)) return {};
  dGeomID ray = make_ray(origin, (1.0 / n) * dir, length);
  RayQuery q;
  dSpaceCollide2(ray, reinterpret_cast<dGeomID>(space), &q, &ray_callback);
  dGeomDestroy(ray);
  return q.nearest;
}

}  // namespace bx
