#include "brain/controller.h"

#include <algorithm>
#include <cassert>

namespace bx {

namespace {

class GraphBrainState : public ControllerState {
 public:
  explicit GraphBrainState(const BrainModel& m)
      : m_(m), s_(make_brain_state(m)) {}

  void step(std::span<const double> sensors, std::span<const double>, double dt) override {
    assert(static_cast<int>(sensors.size()) == m_.n_sensors);
    std::copy(sensors.begin(), sensors.end(), s_.values.begin());
    brain_step(m_, s_, dt);
  }
  std::span<const double> effectors() const override { return s_.effector_out; }
  std::span<const double> task_outputs() const override { return s_.task_out; }
  std::span<const double> sensors() const override {
    return std::span<const double>(s_.values).first(static_cast<std::size_t>(m_.n_sensors));
  }
  std::span<const double> internals() const override {
    return std::span<const double>(s_.values).subspan(static_cast<std::size_t>(m_.n_sensors));
  }

 private:
  const BrainModel& m_;
  BrainState s_;
};

}  // namespace

std::unique_ptr<ControllerState> GraphBrain::make_state() const { return std::make_unique<GraphBrainState>(m_); }

}  // namespace bx
