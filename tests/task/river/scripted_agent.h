// A scripted agent for the river crossing's grid world: it walks shortest
// safe paths (breadth-first over 4-neighbour steps, kinematically: one
// enter() and one act() per cell, no physics), carries stones one at a time
// to the nearest water cell of a crossing row until the river is bridged,
// then walks to the resource. It plans from the grid alone, with its own
// search, so it checks the layout generator's solvability as well as the rules.
#pragma once

#include <algorithm>
#include <array>
#include <cstdlib>
#include <functional>
#include <optional>
#include <vector>

#include "task/river/grid_world.h"

namespace bx::test {

/// The shortest path from `from` to the nearest cell `goal` accepts, over
/// cells `passable` accepts (the goal cell need not be passable): the cells
/// after `from`, the goal last; nothing if no goal is reachable. Neighbours
/// are tried in a fixed order, so the path is deterministic.
inline std::optional<std::vector<CellIndex>> shortest_path(
    const Grid& g, CellIndex from, const std::function<bool(CellIndex)>& goal,
    const std::function<bool(CellIndex)>& passable) {
  auto slot = [&](CellIndex c) { return static_cast<std::size_t>(c.y) * g.width() + c.x; };
  std::vector<int> parent(g.cells().size(), -1);
  std::vector<bool> seen(g.cells().size(), false);
  std::vector<CellIndex> queue{from};
  seen[slot(from)] = true;
  constexpr std::array<CellIndex, 4> steps{{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const CellIndex c = queue[head];
    if (head > 0 && goal(c)) {
      std::vector<CellIndex> path;
      for (CellIndex p = c; p != from;) {
        path.push_back(p);
        const int up = parent[slot(p)];
        p = {up % g.width(), up / g.width()};
      }
      std::reverse(path.begin(), path.end());
      return path;
    }
    if (head > 0 && !passable(c)) continue;  // a reached goal-only cell leads nowhere
    for (CellIndex s : steps) {
      const CellIndex n{c.x + s.x, c.y + s.y};
      if (!g.contains(n) || seen[slot(n)]) continue;
      if (!passable(n) && !goal(n)) continue;
      seen[slot(n)] = true;
      parent[slot(n)] = static_cast<int>(slot(c));
      queue.push_back(n);
    }
  }
  return std::nullopt;
}

/// Plays a GridWorld as a perfect walker would.
class ScriptedAgent {
 public:
  explicit ScriptedAgent(GridWorld& world) : world_(world) {}

  /// A shortest path to `target` over cells that do not kill (nor the
  /// resource, unless it is the target): the cells after the agent's.
  std::optional<std::vector<CellIndex>> path_to(CellIndex target) const {
    const Grid& g = world_.grid();
    return shortest_path(
        g, world_.agent(), [&](CellIndex c) { return c == target; },
        [&](CellIndex c) { return crossable(g.at(c)); });
  }

  /// Walks path_to(target), entering each cell and acting 0 on it, and
  /// acting `action_there` on the target. False if there is no such path or
  /// the agent died on the way.
  bool go_to(CellIndex target, double action_there) {
    const std::optional<std::vector<CellIndex>> path = path_to(target);
    if (!path) return false;
    for (std::size_t i = 0; i < path->size(); ++i) {
      world_.enter((*path)[i]);
      world_.act(i + 1 == path->size() ? action_there : 0.0);
      if (!world_.alive()) return false;
    }
    return true;
  }

  /// The nearest cell of a kind the agent can walk to safely.
  std::optional<CellIndex> nearest(Cell kind) const {
    const Grid& g = world_.grid();
    auto path = shortest_path(
        g, world_.agent(), [&](CellIndex c) { return g.at(c) == kind; },
        [&](CellIndex c) { return crossable(g.at(c)); });
    if (!path) return std::nullopt;
    return path->back();
  }

  /// The row to bridge: the one nearest the resource's row (the lower row on a
  /// tie) across which a bridge would open a safe path to the resource.
  std::optional<int> crossing_row() const {
    const Layout& l = world_.layout();
    std::vector<int> rows(l.grid.height());
    for (int y = 0; y < l.grid.height(); ++y) rows[y] = y;
    std::stable_sort(rows.begin(), rows.end(), [&](int a, int b) {
      return std::abs(a - l.resource.y) < std::abs(b - l.resource.y);
    });
    for (int y : rows) {
      Grid bridged = l.grid;
      for (int x = kRiverColumn; x < kRiverColumn + l.river_width; ++x) bridged.set({x, y}, Cell::Grass);
      auto path = shortest_path(
          bridged, world_.agent(), [&](CellIndex c) { return c == l.resource; },
          [&](CellIndex c) { return crossable(bridged.at(c)); });
      if (path) return y;
    }
    return std::nullopt;
  }

  /// Plays the current level to its resource, first bridging the river if it
  /// stands between them: a stone for each water cell of the crossing row,
  /// nearest the bank first. True once the resource is reached (the world is
  /// then on the next level).
  bool complete_level() {
    const int completed = world_.levels_completed();
    const Layout& l = world_.layout();
    const CellIndex resource = l.resource;
    if (!path_to(resource)) {
      const std::optional<int> row = crossing_row();
      if (!row) return false;
      for (int x = kRiverColumn; x < kRiverColumn + l.river_width; ++x) {
        if (world_.grid().at({x, *row}) != Cell::Water) continue;  // bridged already
        const std::optional<CellIndex> stone = nearest(Cell::Stone);
        if (!stone || !go_to(*stone, 1.0) || !world_.carrying()) return false;
        if (!go_to({x, *row}, -1.0) || world_.carrying()) return false;
      }
    }
    return go_to(resource, 0.0) && world_.levels_completed() == completed + 1;
  }

 private:
  // cells a path may cross on its way: none that kills, nor the resource,
  // which would end the level on the way to somewhere else
  static bool crossable(Cell c) { return c != Cell::Water && c != Cell::Trap && c != Cell::Resource; }
  GridWorld& world_;
};

}  // namespace bx::test
