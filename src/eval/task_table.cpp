#include "eval/task_table.h"

#include "task/locomotion.h"
#include "task/throwing.h"

namespace bx {

namespace {

Result<std::unique_ptr<Task>> make_locomotion(const CreatureModel& m, const SimConfig& cfg, std::uint64_t) {
  return std::unique_ptr<Task>(new LocomotionTask(cfg.task, cfg.physics.dt, m.n_parts()));
}

Result<std::unique_ptr<Task>> make_throwing(const CreatureModel& m, const SimConfig& cfg, std::uint64_t) {
  if (m.projectile < 0) return Error{"not a catapult: the throwing task needs a genome with a catapult block"};
  return std::unique_ptr<Task>(new ThrowingTask(cfg.throwing, cfg.physics.dt, m.projectile, m.release_joint));
}

// one row per TaskKind, in its order
const TaskRow kTasks[] = {
    {TaskKind::Locomotion, "locomotion", make_locomotion},
    {TaskKind::Throwing, "throwing", make_throwing},
};

}  // namespace

const TaskRow& task_row(TaskKind kind) { return kTasks[static_cast<int>(kind)]; }

std::vector<std::string_view> task_kind_names() {
  std::vector<std::string_view> out;
  for (const TaskRow& r : kTasks) out.push_back(r.name);
  return out;
}

Result<std::unique_ptr<Task>> make_task(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed) {
  return task_row(cfg.task_kind).make(m, cfg, seed);
}

}  // namespace bx
