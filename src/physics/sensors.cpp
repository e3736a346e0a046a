// The world's sensors, a table of kinds (World::Impl::sensor): a joint's
// angle (scaled to its range), a face's contact, a photoreceptor's light or a
// muscle's length, as the brain reads them.
#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/world_impl.h"

namespace bx {

namespace {
// a photoreceptor looks for bodies in the way from this far off its part's surface (m)
constexpr double kReceptorLift = 1e-4;
}  // namespace

const World::Impl::SensorRow& World::Impl::sensor(SensorType type) {
  static const SensorRow rows[] = {
      // the angle (or length) of one degree of freedom of the part's joint to
      // its parent, scaled from its stops to [-1, 1] (without stops: angle / pi)
      {SensorType::JointAngle,
       [](const Impl& w, const CreatureModel& m, std::size_t i) {
         const SensorModel& s = m.sensors[i];
         if (s.joint < 0) return 0.0;  // the root has no joint to its parent
         const JointModel& jm = m.joints[s.joint];
         double x = w.position(w.joints[s.joint], s.dof);
         double v;
         if (s.dof < static_cast<int>(jm.limits.size()) && jm.limits[s.dof].hi > jm.limits[s.dof].lo) {
           const Limit& l = jm.limits[s.dof];
           v = 2 * (x - l.lo) / (l.hi - l.lo) - 1;
         } else {
           v = is_linear_dof(jm.type, s.dof) ? x : x / kPi;
         }
         return std::clamp(v, -1.0, 1.0);
       }},
      // whether one face of the part touched something in the last step: +1, else -1
      {SensorType::Contact,
       [](const Impl& w, const CreatureModel& m, std::size_t i) {
         const SensorModel& s = m.sensors[i];
         return (w.contact_mask[s.part] >> static_cast<int>(s.face)) & 1 ? 1.0 : -1.0;
       }},
      // the lights it sees (Light): each strength / (1 + (d / range)^2) times the
      // cosine of its angle off the receptor's direction, unless behind it or
      // hidden by any body (the creature's own parts too); in [0, 1]
      {SensorType::Photoreceptor,
       [](const Impl& w, const CreatureModel& m, std::size_t i) {
         const SensorModel& s = m.sensors[i];
         const Vec3 at = w.world_point(s.part, w.receptor_points[i]);
         const Vec3 facing = w.world_direction(s.part, s.direction);
         double sum = 0;
         for (const Light& l : w.lights) {
           const Vec3 to = l.position - at;
           const double d = norm(to);
           if (!(d > 0)) continue;
           const double cos = dot(to, facing) / d;
           if (cos <= 0) continue;  // behind it
           // a body in the way: a ray from just off the surface to the light
           const Vec3 from = at + kReceptorLift * facing, ahead = l.position - from;
           if (w.cast(from, ahead, norm(ahead)).hit) continue;
           sum += l.strength * cos / (1 + (d / l.range) * (d / l.range));
         }
         return std::clamp(sum, 0.0, 1.0);
       }},
      // a muscle's length (lessin2015 III-E's proprioceptive node): its
      // anchors' distance over twice its built length, so 0.5 as built; in [0, 1]
      {SensorType::MuscleLength,
       [](const Impl& w, const CreatureModel& m, std::size_t i) {
         const SensorModel& s = m.sensors[i];
         if (s.muscle < 0 || s.muscle >= static_cast<int>(w.muscles.size())) return 0.0;
         const MuscleModel& mm = m.muscles[s.muscle];
         const double unit = mm.length > 0 ? mm.length : mm.rest_length;
         if (!(unit > 0)) return 0.0;
         return std::clamp(w.muscle_length(static_cast<std::size_t>(s.muscle)) / (2 * unit), 0.0, 1.0);
       }},
  };
  const SensorRow& row = rows[static_cast<std::size_t>(type)];
  if (row.type != type) throw std::logic_error("the sensor table's rows are out of SensorType's order");
  return row;
}

void World::Impl::place_receptors(const CreatureModel& m) {
  receptor_points.assign(m.sensors.size(), Vec3{});
  for (std::size_t i = 0; i < m.sensors.size(); ++i) {
    const SensorModel& s = m.sensors[i];
    if (s.type != SensorType::Photoreceptor) continue;
    // where the direction from the centre leaves the part: a ray from outside
    // its bounds back towards the centre, against its own geom alone
    const Vec3 centre = vec(dBodyGetPosition(bodies[s.part]));
    const Vec3 dir = world_direction(s.part, s.direction);
    const double far = 2 * norm(m.parts[s.part].size) + 1;
    dGeomID ray = make_ray(centre + far * dir, -1.0 * dir, far);
    dContactGeom c;
    const Vec3 surface = dCollide(ray, geoms[s.part], 1, &c, sizeof(dContactGeom)) == 1 ? vec(c.pos) : centre;
    dGeomDestroy(ray);
    receptor_points[i] = local_point(s.part, surface);
  }
}

void World::read_sensors(const CreatureModel& m, std::span<double> out) const {
  const auto& w = *impl_;
  for (std::size_t i = 0; i < m.sensors.size(); ++i) out[i] = Impl::sensor(m.sensors[i].type).read(w, m, i);
}

void World::set_lights(std::vector<Light> lights) { impl_->lights = std::move(lights); }
const std::vector<Light>& World::lights() const { return impl_->lights; }

}  // namespace bx
