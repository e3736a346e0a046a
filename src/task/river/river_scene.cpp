#include "task/river/river_scene.h"

namespace bx {

std::vector<SceneCellKind> river_scene_kinds() {
  // in Cell's order, then the bridge
  return {
      {"grass", "#a3c98a", false},    {"resource", "#f08c00", false}, {"food", "#e64980", false},
      {"stone", "#7c838b", true},     {"water", "#3b82c4", false},    {"trap", "#343a40", false},
      {"bridge", "#b49a7a", false},
  };
}

std::vector<int> river_scene_cells(const GridWorld& w) {
  std::vector<int> out;
  out.reserve(w.grid().cells().size());
  for (Cell c : w.grid().cells()) out.push_back(static_cast<int>(c));
  for (CellIndex b : w.bridges()) out[static_cast<std::size_t>(b.y * w.grid().width() + b.x)] = kBridgeKind;
  return out;
}

void RiverScene::record(double t, const GridWorld& w, Vec3 origin, double cell, SceneRecord& out) {
  const int width = w.grid().width();
  if (!started_) out.cell_kinds = river_scene_kinds();
  // a new grid, or the cells that changed on this one
  if (!started_ || w.levels_completed() != levels_) {
    cells_ = river_scene_cells(w);
    out.add(t, SceneGrid{origin, cell, width, w.grid().height(), cells_});
    levels_ = w.levels_completed();
  } else if (w.changes() != changes_) {
    const std::vector<int> now = river_scene_cells(w);
    for (std::size_t k = 0; k < now.size(); ++k)
      if (now[k] != cells_[k]) out.add(t, SceneCell{static_cast<int>(k) % width, static_cast<int>(k) / width, now[k]});
    cells_ = now;
  }
  changes_ = w.changes();
  // the stone carried, or none
  if (started_ ? w.carrying() != carrying_ : w.carrying())
    out.add(t, SceneCarry{carrier_, w.carrying() ? static_cast<int>(Cell::Stone) : -1});
  carrying_ = w.carrying();
  // the counters
  const double level = w.level(), score = w.score(), deaths = w.alive() ? 0 : 1;
  if (!started_ || level != level_) out.add(t, SceneCounter{"level", level, {}});
  if (!started_ || score != score_) out.add(t, SceneCounter{"score", score, {}});
  if (!started_ || deaths != deaths_) out.add(t, SceneCounter{"deaths", deaths, {}});
  level_ = level;
  score_ = score;
  deaths_ = deaths;
  started_ = true;
}

}  // namespace bx
