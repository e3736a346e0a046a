// The world's sensors, a table of kinds (World::Impl::sensor): a joint's
// angle (scaled to its range) or a face's contact, as the brain reads them.
#include <algorithm>
#include <stdexcept>

#include "physics/world_impl.h"

namespace bx {

const World::Impl::SensorRow& World::Impl::sensor(SensorType type) {
  static const SensorRow rows[] = {
      // the angle (or length) of one degree of freedom of the part's joint to
      // its parent, scaled from its stops to [-1, 1] (without stops: angle / pi)
      {SensorType::JointAngle,
       [](const Impl& w, const CreatureModel& m, const SensorModel& s) {
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
       [](const Impl& w, const CreatureModel&, const SensorModel& s) {
         return (w.contact_mask[s.part] >> static_cast<int>(s.face)) & 1 ? 1.0 : -1.0;
       }},
  };
  const SensorRow& row = rows[static_cast<std::size_t>(type)];
  if (row.type != type) throw std::logic_error("the sensor table's rows are out of SensorType's order");
  return row;
}

void World::read_sensors(const CreatureModel& m, std::span<double> out) const {
  const auto& w = *impl_;
  for (std::size_t i = 0; i < m.sensors.size(); ++i) {
    const SensorModel& s = m.sensors[i];
    out[i] = Impl::sensor(s.type).read(w, m, s);
  }
}

}  // namespace bx
