#include "eval/task_table.h"

#include "task/locomotion.h"
#include "task/river/river_task.h"
#include "task/throwing.h"

namespace bx {

namespace {

Result<std::unique_ptr<Task>> make_locomotion(const CreatureModel& m, const SimConfig& cfg, std::uint64_t) {
  return std::unique_ptr<Task>(new LocomotionTask(cfg.task, cfg.physics.dt, m.n_parts(), cfg.physics.gravity));
}

Result<std::unique_ptr<Task>> make_throwing(const CreatureModel& m, const SimConfig& cfg, std::uint64_t) {
  if (m.projectile < 0) return Error{"not a catapult: the throwing task needs a genome with a catapult block"};
  return std::unique_ptr<Task>(new ThrowingTask(cfg.throwing, cfg.physics.dt, m.projectile, m.release_joint));
}

// the river crossing: its quadruped's torso is the agent, its sensor points
// the controller's, and a cell is as wide as the body's unit
Result<std::unique_ptr<Task>> make_river(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed) {
  if (cfg.creature != CreatureKind::River)
    return Error{"the river crossing's task needs its quadruped: genotype.kind = \"river\""};
  RiverTaskDef def = cfg.river.task;
  def.cell = cfg.river.body.unit;
  return std::unique_ptr<Task>(
      new RiverTask(def, cfg.physics.dt, seed, kTorso, quadruped_sensor_points(cfg.river.body)));
}

std::vector<SimField> river_fields() {
  return {
      {"river", "seconds", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.river.task.seconds; }, "river crossing: evaluation length (s; the paper: 10 minutes)"},
      {"river", "drop_height", SimField::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.river.task.drop_height; }, "river crossing: gap between the feet and the ground at the start (m)"},
      {"river", "first_level", SimField::Int, 1, 6, {}, [](SimConfig& c) -> void* { return &c.river.task.first_level; }, "river crossing: the level an evaluation starts on (1: food)"},
  };
}

double& locomotion_seconds(SimConfig& c) { return c.task.seconds; }
double& throwing_seconds(SimConfig& c) { return c.throwing.seconds; }
double& river_seconds(SimConfig& c) { return c.river.task.seconds; }
double locomotion_drop(const SimConfig& c) { return c.task.drop_height; }
double throwing_drop(const SimConfig& c) { return c.throwing.drop_height; }
double river_drop(const SimConfig& c) { return c.river.task.drop_height; }

// one row per TaskKind, in its order
const TaskRow kTasks[] = {
    {TaskKind::Locomotion, "locomotion", make_locomotion, locomotion_seconds, locomotion_drop, "task.seconds",
     "task.drop_height", nullptr},
    {TaskKind::Throwing, "throwing", make_throwing, throwing_seconds, throwing_drop, "throwing.seconds",
     "throwing.drop_height", nullptr},
    {TaskKind::River, "river", make_river, river_seconds, river_drop, "river.seconds", "river.drop_height",
     river_fields},
};

}  // namespace

const TaskRow& task_row(TaskKind kind) { return kTasks[static_cast<int>(kind)]; }

std::vector<std::string_view> task_kind_names() {
  std::vector<std::string_view> out;
  for (const TaskRow& r : kTasks) out.push_back(r.name);
  return out;
}

std::vector<SimField> task_fields() {
  std::vector<SimField> out;
  for (const TaskRow& r : kTasks)
    if (r.fields)
      for (SimField& f : r.fields()) out.push_back(std::move(f));
  return out;
}

Result<std::unique_ptr<Task>> make_task(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed) {
  return task_row(cfg.task_kind).make(m, cfg, seed);
}

}  // namespace bx
