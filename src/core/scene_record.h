// A replay's scene record: everything a task (and its controller) shows
// beside the creature, in one generic shape, so a new task's scene needs no
// member of its own in EvalResult, Replay or the task interface
// (docs/replay-format.md, `scene.record`). Two halves:
// - items that hold for the whole replay: named moments (a catapult's
//   release), named points (its target), props (solids shown from a time
//   on: a fight-or-flight target), named parts to highlight (its
//   projectile), and the kinds of cell a grid may hold;
// - events in time order, each stamped with its time: a grid laid, one cell
//   changed, an item carried, a field over the grid, a counter's new value.
// A task appends to it through Task::record and a controller through
// ControllerState::record, only while a replay is recorded.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/math.h"

namespace bx {

/// A named moment (s): a catapult's "release".
struct SceneMarker {
  std::string name;
  double t = 0;
  friend bool operator==(const SceneMarker&, const SceneMarker&) = default;
};

/// A named point (m), drawn as a sphere of diameter `size` in `color`
/// ("#rrggbb"): an aim task's "target".
struct ScenePoint {
  std::string name;
  Vec3 p;
  double size = 0.1;
  std::string color;
  friend bool operator==(const ScenePoint&, const ScenePoint&) = default;
};

/// A solid shown beside the creature from time `t` (s) on (a fight-or-flight
/// target): shaped as a creature's part is ("box", "sphere", "capsule" or
/// "cylinder"; a capsule's or cylinder's axis along its pose's x axis, its
/// length size.x and diameter size.y; a sphere's diameter size.x), at `pose`
/// (world frame) when it appears, turning from then on about the world's
/// vertical through its centre at `spin` rad/s (counterclockwise seen from
/// above), in `color` ("#rrggbb").
struct SceneProp {
  std::string name;
  std::string shape;
  Vec3 size;
  Pose pose;
  double spin = 0;
  double t = 0;
  std::string color;
  friend bool operator==(const SceneProp&, const SceneProp&) = default;
};

/// A named part of the creature, drawn in `color`: a catapult's "projectile".
/// `scored`: the task scores this part's path over its scored span (a
/// thrown projectile's), not the creature's centre of mass's; at most one
/// part is scored (what `crosscheck` compares, io/mujoco_replay.h).
struct ScenePart {
  std::string name;
  int part = 0;
  std::string color;
  bool scored = false;
  friend bool operator==(const ScenePart&, const ScenePart&) = default;
};

/// A kind of grid cell: its name and ground colour; an `item` kind also has
/// a small box of its colour standing on each of its cells (a stone), and is
/// what a carried item is drawn as.
struct SceneCellKind {
  std::string name;
  std::string color;
  bool item = false;
  friend bool operator==(const SceneCellKind&, const SceneCellKind&) = default;
};

/// A grid laid on the ground, replacing any earlier one: cell (x, y) spans
/// [x, x+1) x [y, y+1) cell widths from `origin` (m) along the world's x and
/// y; `cells` holds a kind (an index into SceneRecord::cell_kinds) per cell,
/// row by row (cell (x, y) at y * width + x).
struct SceneGrid {
  Vec3 origin;
  double cell = 1;  ///< m
  int width = 0, height = 0;
  std::vector<int> cells;
  friend bool operator==(const SceneGrid&, const SceneGrid&) = default;
};

/// Cell (x, y) of the current grid is now of kind `kind`.
struct SceneCell {
  int x = 0, y = 0;
  int kind = 0;
  friend bool operator==(const SceneCell&, const SceneCell&) = default;
};

/// Part `part` now carries an item of cell kind `kind` (-1: nothing).
struct SceneCarry {
  int part = 0;
  int kind = -1;
  friend bool operator==(const SceneCarry&, const SceneCarry&) = default;
};

/// A named scalar field over the current grid, one value per cell in the
/// grid's order (width x height), on the scale [lo, hi] (a heat map's):
/// its values from now until the field of that name is recorded again.
struct SceneField {
  std::string name;
  int width = 0, height = 0;
  double lo = 0, hi = 1;
  std::vector<double> values;
  friend bool operator==(const SceneField&, const SceneField&) = default;
};

/// A named counter's value from now on: "level", "score", "deaths"; the
/// locomotion task's "distance" (m, its distance so far over the scored span).
struct SceneCounter {
  std::string name;
  double value = 0;
  std::string unit;  ///< what the value counts in ("m"), or empty: a count
  friend bool operator==(const SceneCounter&, const SceneCounter&) = default;
};

/// One change of the scene at time t (s).
struct SceneEvent {
  double t = 0;
  std::variant<SceneGrid, SceneCell, SceneCarry, SceneField, SceneCounter> what;
  friend bool operator==(const SceneEvent&, const SceneEvent&) = default;
};

/// The markers of the span a task scores (its measured time: after a
/// settling, a skipped fraction, ...), for a viewer to mark on its time bar:
/// "scored from" when measuring began and "scored to" when it ended.
inline constexpr std::string_view kScoredFrom = "scored from";
inline constexpr std::string_view kScoredTo = "scored to";

/// The record: what holds throughout, then the events in time order.
struct SceneRecord {
  std::vector<SceneMarker> markers;
  std::vector<ScenePoint> points;
  std::vector<SceneProp> props;
  std::vector<ScenePart> parts;
  std::vector<SceneCellKind> cell_kinds;
  std::vector<SceneEvent> events;

  /// Appends an event at time t; times never go back.
  template <class What>
  void add(double t, What what) {
    events.push_back({t, std::move(what)});
  }
  /// The time of the first marker named `name`, if there is one.
  std::optional<double> marker(std::string_view name) const {
    for (const SceneMarker& m : markers)
      if (m.name == name) return m.t;
    return std::nullopt;
  }
  bool empty() const {
    return markers.empty() && points.empty() && props.empty() && parts.empty() && cell_kinds.empty() && events.empty();
  }
  friend bool operator==(const SceneRecord&, const SceneRecord&) = default;
};

}  // namespace bx
