#include "brain/river/river_controller.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <vector>

namespace bx {

namespace {

class RiverControllerState : public ControllerState {
 public:
  RiverControllerState(const RiverBrainModel& m, RiverInputs in)
      : brain_(m), in_(in), grid_(static_cast<std::size_t>(in.cells()), 0),
        grid_in_(grid_.size(), 0.0), effectors_(static_cast<std::size_t>(m.def.shape.motors), 0.0) {}

  void step(std::span<const double>, std::span<const double> in, double dt) override {
    assert(static_cast<int>(in.size()) == in_.count());
    // the grid, read again only when its inputs changed (a stone moved, food
    // eaten, a new level: a few times an evaluation, where the task gives it
    // every step)
    const std::size_t n = grid_.size();
    if (!grid_seen_ || std::memcmp(in.data(), grid_in_.data(), n * sizeof(double)) != 0) {
      std::copy(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(n), grid_in_.begin());
      for (std::size_t k = 0; k < n; ++k) grid_[k] = static_cast<int>(std::lround(in[k]));
      brain_.set_grid(grid_);
      grid_seen_ = true;
    }
    brain_.decide(static_cast<int>(std::lround(in[static_cast<std::size_t>(in_.here())])),
                  in[static_cast<std::size_t>(in_.carrying())] > 0.5);
    GridPoint points[kRiverSensors];
    for (int s = 0; s < kRiverSensors; ++s)
      points[s] = {in[static_cast<std::size_t>(in_.sensors() + 2 * s)],
                   in[static_cast<std::size_t>(in_.sensors() + 2 * s + 1)]};
    brain_.step(points, dt);
    const std::span<const double> motors = brain_.motors();
    for (std::size_t j = 0; j < effectors_.size(); ++j) effectors_[j] = 2 * motors[j] - 1;
    action_[0] = brain_.action();
    // for replays: the physical network's outputs, then the motifs'
    internals_.assign(brain_.pn().outputs().begin(), brain_.pn().outputs().end());
    internals_.insert(internals_.end(), brain_.pg().outputs().begin(), brain_.pg().outputs().end());
  }
  std::span<const double> effectors() const override { return effectors_; }
  std::span<const double> task_outputs() const override { return action_; }
  std::span<const double> sensors() const override { return {}; }
  std::span<const double> internals() const override { return internals_; }
  // the landscape, each time its values differ from the last recorded (it
  // is recomputed only when the grid or the iotas change, and then may come
  // out the same), on the scale of its extremes: a held negative input and maxI
  void record(double t, SceneRecord& out) override {
    const std::span<const double> v = brain_.landscape().values();
    if (recorded_ && std::equal(v.begin(), v.end(), last_.begin())) return;
    last_.assign(v.begin(), v.end());
    recorded_ = true;
    const ShuntingDef& d = brain_.landscape().def();
    out.add(t, SceneField{"landscape", d.width, d.height, -d.iota_scale, d.max_activity, last_});
  }

 private:
  RiverBrain brain_;
  RiverInputs in_;
  std::vector<int> grid_;
  std::vector<double> grid_in_;  // the grid's inputs as last read
  bool grid_seen_ = false;
  std::vector<double> effectors_, internals_;
  double action_[1] = {0};
  // the landscape last recorded
  bool recorded_ = false;
  std::vector<double> last_;
};

}  // namespace

std::unique_ptr<ControllerState> RiverController::make_state() const {
  return std::make_unique<RiverControllerState>(m_, in_);
}

}  // namespace bx
