// How a replay shows the river crossing's world (core/scene_record.h): the
// grid as each level lays it, each cell that changes (food eaten, a stone
// picked up, a stone put down as a bridge), the stone carried, and the
// level, score and deaths. Only changes are recorded, so a replay stays small.
#pragma once

#include <vector>

#include "core/scene_record.h"
#include "task/river/grid_world.h"

namespace bx {

/// The kinds a river grid is recorded with: Cell's six in its order (a
/// stone an item, drawn as a small box on its cell and when carried), then
/// a bridge: water a stone filled, which the world counts as grass.
std::vector<SceneCellKind> river_scene_kinds();
/// The index of the bridge kind in river_scene_kinds().
inline constexpr int kBridgeKind = 6;

/// The world's current cells as kinds of river_scene_kinds(), row by row:
/// each cell's Cell, bridges as kBridgeKind.
std::vector<int> river_scene_cells(const GridWorld& w);

/// Records one evaluation's world, call after call: what changed since the
/// last call.
class RiverScene {
 public:
  /// `carrier` is the part drawn carrying a stone (the torso).
  explicit RiverScene(int carrier) : carrier_(carrier) {}

  /// Appends to `out`, stamped t (s): on the first call the cell kinds; a
  /// grid (SceneGrid, with its corner at `origin` and cells `cell` m wide)
  /// on the first call and whenever a level was laid since the last; else
  /// each cell that differs from the last recorded; the carried stone
  /// (SceneCarry) when it changed; the counters "level", "score" and
  /// "deaths" on the first call and when they changed.
  void record(double t, const GridWorld& w, Vec3 origin, double cell, SceneRecord& out);

 private:
  int carrier_;
  bool started_ = false;
  int levels_ = 0;        // levels completed at the last grid laid
  long changes_ = 0;      // the world's changes() last recorded
  std::vector<int> cells_;  // the cells as last recorded
  bool carrying_ = false;
  double level_ = 0, score_ = 0, deaths_ = 0;
};

}  // namespace bx
