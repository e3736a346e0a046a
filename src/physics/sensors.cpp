// The world's sensors: a joint's angle (scaled to its range) or a face's
// contact, as the brain reads them.
#include <algorithm>

#include "physics/world_impl.h"

namespace bx {

void World::read_sensors(const CreatureModel& m, std::span<double> out) const {
  const auto& w = *impl_;
  for (std::size_t i = 0; i < m.sensors.size(); ++i) {
    const SensorModel& s = m.sensors[i];
    if (s.type == SensorType::Contact) {
      out[i] = (w.contact_mask[s.part] >> static_cast<int>(s.face)) & 1 ? 1.0 : -1.0;
      continue;
    }
    if (s.joint < 0) {
      out[i] = 0;  // the root has no joint to its parent
      continue;
    }
    const JointModel& jm = m.joints[s.joint];
    double x = w.position(w.joints[s.joint], s.dof);
    double v;
    if (s.dof < static_cast<int>(jm.limits.size()) && jm.limits[s.dof].hi > jm.limits[s.dof].lo) {
      const Limit& l = jm.limits[s.dof];
      v = 2 * (x - l.lo) / (l.hi - l.lo) - 1;
    } else {
      v = is_linear_dof(jm.type, s.dof) ? x : x / kPi;
    }
    out[i] = std::clamp(v, -1.0, 1.0);
  }
}

}  // namespace bx
