// The river crossing as a Task (Stanton & Channon 2015; docs/rivercrossing.md):
// a quadruped walks a grid world laid on flat ground. The grid's rules are
// GridWorld's; this joins them to the physics: the agent's cell is the one
// under the torso's centre, the controller's task output is the pick-up /
// put-down action, and its task inputs (RiverInputs) are the grid, the
// agent's cell, whether it carries a stone and where the torso's four
// sensors are, in cell widths.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "brain/river/river_controller.h"
#include "task/river/grid_world.h"
#include "task/river/river_scene.h"
#include "task/task.h"

namespace bx {

/// The task's constants. Defaults are the paper's where it gives them.
struct RiverTaskDef {
  /// An evaluation's length (s): 10 simulated minutes (the paper).
  double seconds = 600;
  /// A cell's width (m): the body's length unit (docs/rivercrossing.md).
  double cell = 1;
  /// Gap between the lowest part and the ground at the start (m).
  double drop_height = 0.05;
  /// The level an evaluation starts on (1..6): 1, the paper's.
  int first_level = 1;
  /// Points for getting closer to the level's resource (0: the paper's
  /// fitness). Each level adds approach * (1 - d_min / d_0), d the torso
  /// centre's distance to the resource cell's centre in cells, d_0 when the
  /// level began, d_min the least since: a level completed gives all of it.
  /// A bootstrap for runs too short for the paper's food level to select
  /// walkers (rivercrossing-small; docs/rivercrossing.md).
  double approach = 0;
  friend bool operator==(const RiverTaskDef&, const RiverTaskDef&) = default;
};

/// One evaluation's river crossing. The grid is not a body: it is a frame on
/// the ground, placed at the start so that the torso's centre is over the
/// middle of the level's start cell, and placed again so whenever a level
/// begins (the resource reached), which puts the walker on the new level's
/// start cell without moving it.
class RiverTask : public Task {
 public:
  /// `seed` draws the layouts; `torso` is the part whose centre is the
  /// agent's position and `sensors` the four sensor points in its frame (m).
  RiverTask(const RiverTaskDef& def, double dt, std::uint64_t seed, int torso, std::array<Vec3, 4> sensors);

  Scenario scenario() const override { return {def_.drop_height}; }
  long max_steps() const override;
  void begin(const Observation& o) override;
  int n_inputs() const override { return in_.count(); }
  void inputs(const Observation& o, std::span<double> out) const override;
  /// Output 0: the action (RiverController's task output).
  int n_outputs() const override { return 1; }
  /// The action on the agent's cell, then the death test (GridWorld::act).
  void act(const CreatureModel&, std::span<const double> outputs, WorldEdits&, const Observation&) override;
  void observe(const Observation& o) override;
  /// Over once the agent died (or the time is up: max_steps).
  bool done() const override { return !world_.alive(); }
  /// Fitness: +100 per resource reached, +1 per food eaten (the paper),
  /// plus the approach credit (RiverTaskDef::approach);
  /// distance: the torso's travel in the ground plane from its start to its
  /// last position (m);
  /// metrics: the level reached, levels completed, food eaten, whether it
  /// died (1) and of what (cell codes: 3 water, 4 trap), the approach: the
  /// levels' progress toward their resources (each completed level 1, the
  /// current one 1 - d_min / d_0).
  TaskScore score(const CreatureModel&) const override;
  /// The world as a replay shows it (RiverScene): its grid as each level
  /// lays it, the cells that change, the stone carried (on the torso), and
  /// the level, score and deaths.
  void record(const Observation& o, SceneRecord& out) override;

  const GridWorld& world() const { return world_; }
  /// Where a world point (m) is in the grid, in cell widths.
  GridPoint to_grid(Vec3 p) const { return {(p.x - origin_.x) / def_.cell, (p.y - origin_.y) / def_.cell}; }

 private:
  // places the grid so the torso's centre is over the start cell's middle
  void place_grid(Vec3 torso);
  // the torso's distance to the level's resource cell's centre (cells)
  double to_resource(Vec3 torso) const;
  // the levels' progress toward their resources (score()'s "approach")
  double approach() const;
  // the cells' codes as inputs, made again only when the cells changed
  void refresh_codes();

  RiverTaskDef def_;
  double dt_;
  int torso_;
  std::array<Vec3, 4> sensors_;
  RiverInputs in_;
  GridWorld world_;
  Vec3 origin_;  ///< the world point (m) of the grid's corner (0, 0)
  Vec3 start_, last_;  ///< the torso's centre at the start and after the last step (m)
  int levels_seen_ = 0;
  double level_d0_ = 0;     ///< to_resource when the level began
  double level_dmin_ = 0;   ///< the least to_resource since
  RiverScene scene_;
  std::vector<double> codes_;  ///< river_cell_code of every cell, row-major
  long codes_changes_ = -1;    ///< world_.changes() when codes_ was made
};

/// The river_cell code the controller sees for a cell (food as the resource).
int river_cell_code(Cell c);

}  // namespace bx
