// The river crossing's world as its rules see it (rivercrossing; Stanton &
// Channon 2015, "Environment and Physical Model"; docs/papers.md S4): the
// agent's cell, what it carries, its score and level, and the grid those
// change. No physics: the caller says which cell the agent is on (in 3D, the
// one under the torso's centre, cell_under) and what the controller's pick-up
// action is.
// docs/rivercrossing.md gives the rules with the reason for each choice.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/rng.h"
#include "task/river/grid.h"
#include "task/river/layout.h"

namespace bx {

/// An agent carrying nothing picks up the stone it stands on when the action
/// is at least this (the Keele group's 2D code, docs/rivercrossing.md).
inline constexpr double kPickUpAction = 0.1;
/// An agent carrying a stone puts it down on the water it stands on when the
/// action is at most this.
inline constexpr double kPutDownAction = -0.1;

/// One evaluation's grid world, a state machine driven by two calls: enter()
/// when the agent's cell changes, act() with the controller's action. Rules:
/// - Entering food eats it: +1, the cell becomes grass.
/// - Entering the resource: +100, the level advances (after 6 comes 1), a
///   fresh layout is drawn from the same stream and the agent stands on its
///   start cell, carrying nothing. The caller moves the body there: the
///   resource lies on the same cell on every level, so a body left on it
///   would reach the next level's resource at once.
/// - act(): pick up, or put down (the water becomes a grass bridge cell), then
///   the death test: an agent on water or a trap dies. So an agent that steps
///   onto water carrying a stone and puts it down survives on the new bridge.
/// - An agent that enters another cell from water or a trap without an act()
///   between dies there: every hazard entered meets one death test.
/// - The grid's edge is a wall: a cell beyond it is taken as the nearest cell
///   inside.
/// - A death ends the evaluation, as a death ends the 2D code's run: every
///   later call does nothing.
class GridWorld {
 public:
  /// Level `first_level` (1..6), its layout drawn from `rng`; every later
  /// layout continues the same stream.
  explicit GridWorld(Rng rng, int first_level = 1);

  /// The agent's cell is now `c` (clamped into the grid: the wall). Entering
  /// the cell it is on does nothing.
  void enter(CellIndex c);
  /// The controller's pick-up / put-down action on the agent's cell, then the
  /// death test.
  void act(double action);

  /// The current level, 1..6.
  int level() const { return level_; }
  /// Fitness so far: +100 per resource reached, +1 per food eaten.
  int score() const { return score_; }
  bool alive() const { return !killed_by_.has_value(); }
  /// What killed the agent (Water or Trap), or nothing while it lives.
  std::optional<Cell> killed_by() const { return killed_by_; }
  int food_eaten() const { return food_eaten_; }
  /// Resources reached, over every level.
  int levels_completed() const { return levels_completed_; }
  /// How many times level `level` (1..6) was completed.
  int completions(int level) const;
  bool carrying() const { return carrying_; }
  /// The agent's cell.
  CellIndex agent() const { return agent_; }
  /// The kind of the agent's cell (the decision network's input).
  Cell under_agent() const { return layout_.grid.at(agent_); }
  /// The current level's layout, as the agent has changed it.
  const Layout& layout() const { return layout_; }
  /// The current level's cells (for a viewer and the shunting model).
  const Grid& grid() const { return layout_.grid; }
  /// The current level's bridge cells, in the order they were built: water
  /// that a stone turned into grass (for a viewer).
  const std::vector<CellIndex>& bridges() const { return bridges_; }
  /// Counts every change of the cells (food eaten, a stone picked up or put
  /// down, a new level), so a controller can tell when to recompute its map.
  long changes() const { return changes_; }

 private:
  void next_level();
  void die(Cell cause) { killed_by_ = cause; }

  Rng rng_;
  int level_;
  Layout layout_;
  CellIndex agent_;
  bool carrying_ = false;
  std::optional<Cell> killed_by_;
  int score_ = 0;
  int food_eaten_ = 0;
  int levels_completed_ = 0;
  std::array<int, kRiverLevels> completions_{};
  std::vector<CellIndex> bridges_;
  long changes_ = 0;
};

}  // namespace bx
