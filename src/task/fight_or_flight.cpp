#include "task/fight_or_flight.h"

#include <algorithm>

#include "core/text.h"
#include "physics/world_edits.h"

namespace bx {

namespace {

// the inner light task of trial `trial`: attack towards the vulnerable
// target, retreat from the dangerous one, whose discs shine together
LightDef inner_def(const FightDef& fight, LightDef light, int trial) {
  const std::size_t n = fight.headings.size();
  const std::size_t pair = static_cast<std::size_t>(std::max(0, trial)) / 2;
  const bool dangerous = trial % 2 == 1;
  light.headings = {n ? fight.headings[pair % n] : 0.0};
  light.dark_trials = 0;
  light.goal = dangerous ? LightGoal::Retreat : LightGoal::Attack;
  if (dangerous) light.strength *= fight.stack_discs;
  return light;
}

}  // namespace

FightOrFlightTask::FightOrFlightTask(const FightDef& fight, const LightDef& light, const StrikeDef& strike, double dt,
                                     int n_parts, int trial)
    : def_(fight), dangerous_(trial % 2 == 1), inner_(inner_def(fight, light, trial), strike, dt, n_parts, 0) {}

std::string FightOrFlightTask::describe() const {
  return std::string(dangerous_ ? "dangerous" : "vulnerable") + " target at " + g_number(inner_.bearing()) + " degrees";
}

void FightOrFlightTask::act(const CreatureModel& m, std::span<const double> out, WorldEdits& w, const Observation& o) {
  inner_.act(m, out, w, o);
  const auto light = inner_.light();
  if (!light || !prop_ids_.empty()) return;
  // the target on the ground under the light: one disc, or the spinning stack
  const int n = dangerous_ ? std::max(1, def_.stack_discs) : 1;
  for (int i = 0; i < n; ++i) {
    Prop d;
    d.shape = Shape::Cylinder;
    d.size = {def_.disc_height, def_.disc_diameter, def_.disc_diameter};
    d.pose = {{light->position.x, light->position.y, (i + 0.5) * def_.disc_height},
              Mat3::rotation({0, 1, 0}, -kPi / 2)};  // the cylinder's axis (its x) up
    d.spin = dangerous_ ? def_.spin : 0;
    discs_.push_back(d);
    prop_ids_.push_back(w.add_prop(d));
  }
  t_on_ = o.time();
}

void FightOrFlightTask::observe(const Observation& o) {
  inner_.observe(o);
  if (!dangerous_) return;
  for (int k : prop_ids_)
    if (o.touches_prop(k)) destroyed_ = true;
}

TaskScore FightOrFlightTask::score(const CreatureModel& m) const {
  TaskScore s = inner_.score(m);
  s.fitness = fitness();
  s.metrics.push_back({"dangerous", dangerous_ ? 1.0 : 0.0});
  s.metrics.push_back({"destroyed", destroyed_ ? 1.0 : 0.0});
  return s;
}

void FightOrFlightTask::record(const Observation& o, SceneRecord& out) {
  inner_.record(o, out);
  if (recorded_ || discs_.empty()) return;
  // the vulnerable disc green, the dangerous stack red
  const char* color = dangerous_ ? "#d03030" : "#30a050";
  for (std::size_t i = 0; i < discs_.size(); ++i) {
    const Prop& d = discs_[i];
    out.props.push_back({i == 0 ? std::string("target") : "target " + std::to_string(i + 1), "cylinder", d.size,
                         d.pose, d.spin, t_on_, color});
  }
  recorded_ = true;
}

double fight_fold(std::span<const double> trials) {
  const std::size_t pairs = trials.size() / 2;
  if (pairs == 0) return 0;
  double hi = 0, lo = 0;
  for (std::size_t k = 0; k < pairs; ++k) {
    hi += std::max(trials[2 * k], trials[2 * k + 1]);
    lo += std::min(trials[2 * k], trials[2 * k + 1]);
  }
  const double n = static_cast<double>(pairs);
  return (hi / n + 2 * n * (lo / n)) / (2 * n + 1);
}

}  // namespace bx
