#include "task/river/river_task.h"

#include <algorithm>
#include <cmath>

namespace bx {

namespace {
// the layouts' stream within a trial's physics seed
constexpr std::uint64_t kLayoutStream = 11;
}  // namespace

int river_cell_code(Cell c) {
  switch (c) {
    case Cell::Grass: return river_cell::kGrass;
    case Cell::Resource:
    case Cell::Food: return river_cell::kResource;
    case Cell::Stone: return river_cell::kStone;
    case Cell::Water: return river_cell::kWater;
    case Cell::Trap: return river_cell::kTrap;
  }
  return river_cell::kGrass;
}

RiverTask::RiverTask(const RiverTaskDef& def, double dt, std::uint64_t seed, int torso, std::array<Vec3, 4> sensors)
    : def_(def),
      dt_(dt),
      torso_(torso),
      sensors_(sensors),
      world_(Rng(stream_seed({seed, kLayoutStream})), def.first_level),
      scene_(torso) {
  in_.width = world_.grid().width();
  in_.height = world_.grid().height();
  refresh_codes();
}

void RiverTask::refresh_codes() {
  if (world_.changes() == codes_changes_) return;
  const std::span<const Cell> cells = world_.grid().cells();
  codes_.resize(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) codes_[k] = river_cell_code(cells[k]);
  codes_changes_ = world_.changes();
}

long RiverTask::max_steps() const { return std::lround(def_.seconds / dt_); }

void RiverTask::place_grid(Vec3 torso) {
  const CellIndex s = world_.agent();
  origin_ = {torso.x - (s.x + 0.5) * def_.cell, torso.y - (s.y + 0.5) * def_.cell, 0};
  levels_seen_ = world_.levels_completed();
  level_d0_ = level_dmin_ = to_resource(torso);
}

double RiverTask::to_resource(Vec3 torso) const {
  const GridPoint g = to_grid(torso);
  const CellIndex r = world_.layout().resource;
  return std::hypot(g.x - (r.x + 0.5), g.y - (r.y + 0.5));
}

double RiverTask::approach() const {
  const double current = level_d0_ > 0 ? std::max(0.0, 1 - level_dmin_ / level_d0_) : 0;
  return world_.levels_completed() + current;
}

void RiverTask::begin(const Observation& o) {
  start_ = last_ = o.part_pose(torso_).p;
  place_grid(start_);
}

void RiverTask::inputs(const Observation& o, std::span<double> out) const {
  std::copy(codes_.begin(), codes_.end(), out.begin());
  out[static_cast<std::size_t>(in_.here())] = river_cell_code(world_.under_agent());
  out[static_cast<std::size_t>(in_.carrying())] = world_.carrying() ? 1 : 0;
  const Pose torso = o.part_pose(torso_);
  for (int s = 0; s < kRiverSensors; ++s) {
    const GridPoint g = to_grid(torso.p + torso.R * sensors_[static_cast<std::size_t>(s)]);
    out[static_cast<std::size_t>(in_.sensors() + 2 * s)] = g.x;
    out[static_cast<std::size_t>(in_.sensors() + 2 * s + 1)] = g.y;
  }
}

void RiverTask::act(const CreatureModel&, std::span<const double> outputs, WorldEdits&, const Observation&) {
  world_.act(outputs[0]);
  refresh_codes();
}

void RiverTask::observe(const Observation& o) {
  const Vec3 torso = o.part_pose(torso_).p;
  last_ = torso;
  const GridPoint g = to_grid(torso);
  world_.enter(cell_under(g.x, g.y));
  refresh_codes();
  // a resource reached: the next level's grid is laid with its start under the walker
  if (world_.levels_completed() != levels_seen_)
    place_grid(torso);
  else if (world_.alive())
    level_dmin_ = std::min(level_dmin_, to_resource(torso));
}

void RiverTask::record(const Observation& o, SceneRecord& out) {
  scene_.record(o.time(), world_, origin_, def_.cell, out);
}

TaskScore RiverTask::score(const CreatureModel&) const {
  TaskScore s;
  s.fitness = world_.score() + def_.approach * approach();
  s.distance = std::hypot(last_.x - start_.x, last_.y - start_.y);
  const std::optional<Cell> killer = world_.killed_by();
  s.metrics = {{"level", static_cast<double>(world_.level())},
               {"levels completed", static_cast<double>(world_.levels_completed())},
               {"food eaten", static_cast<double>(world_.food_eaten())},
               {"died", killer ? 1.0 : 0.0},
               {"killed by", killer ? static_cast<double>(river_cell_code(*killer)) : 0.0}};
  for (int level = 1; level <= kRiverLevels; ++level)
    s.metrics.push_back({"level " + std::to_string(level) + " completed", static_cast<double>(world_.completions(level))});
  s.metrics.push_back({"approach", approach()});
  return s;
}

}  // namespace bx
