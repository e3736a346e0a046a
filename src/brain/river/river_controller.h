// The river crossing's hybrid controller (river_brain.h) as a ControllerModel:
// what the evaluation loop drives. It takes no body sensors; the task gives
// it the grid, the agent's cell, whether it carries a stone and where the
// torso's four sensors are (RiverInputs), and it gives the joints' targets
// as effector signals and the pick-up / put-down action as its one task
// output.
#pragma once

#include <memory>

#include "brain/controller.h"
#include "brain/river/river_brain.h"

namespace bx {

/// The order of the task inputs, for a grid of width x height cells.
struct RiverInputs {
  int width = 20, height = 20;
  /// [0, cells()): the grid, a river_cell code per cell, row-major (cell
  /// (i, j) at j * width + i), food passed as kResource.
  int cells() const { return width * height; }
  /// The code of the cell under the agent.
  int here() const { return cells(); }
  /// 1 while the agent carries a stone, else 0.
  int carrying() const { return cells() + 1; }
  /// Then the four sensors' points (x, y) in cell widths, in the grid's
  /// frame (cell (i, j) spans [i, i+1) x [j, j+1)), in a fixed sensor order.
  int sensors() const { return cells() + 2; }
  int count() const { return sensors() + 2 * kRiverSensors; }
};

/// The controller of one individual: its brain model (shared, immutable).
/// Effector j's signal is 2 m_j - 1 for motor neuron j's value m_j in
/// (0, 1), so a PD motor (MotorModel::PD) takes m_j as the share of its
/// joint's range (0: the low stop, 1: the high one). Task output 0 is the
/// decision network's action: 1 pick up, -1 put down, 0 neither. For a
/// replay its state records the landscape (ControllerState::record) as the
/// field "landscape" over the task's grid, on the scale [-iota_scale, maxI],
/// whenever its values change.
class RiverController : public ControllerModel {
 public:
  explicit RiverController(RiverBrainModel m)
      : m_(std::move(m)), in_{m_.def.landscape.width, m_.def.landscape.height} {}
  int n_sensors() const override { return 0; }
  int n_effectors() const override { return m_.def.shape.motors; }
  int n_task_inputs() const override { return in_.count(); }
  int n_task_outputs() const override { return 1; }
  std::unique_ptr<ControllerState> make_state() const override;

  const RiverBrainModel& model() const { return m_; }
  const RiverInputs& inputs() const { return in_; }

 private:
  RiverBrainModel m_;
  RiverInputs in_;
};

}  // namespace bx
