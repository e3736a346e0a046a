// The river crossing's physical network (PN; Stanton & Channon 2015, "The
// Physical Network"): from the shunting landscape as the agent's four
// sensors read it, the drive of each pattern-generator motif. Feed-forward:
// tanh hidden layer (to keep negative values, the paper says), sigmoid
// outputs, no bias.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "brain/river/dense_layer.h"

namespace bx {

/// The agent's sensors, one on each side face of the torso.
inline constexpr int kRiverSensors = 4;
/// The PN's inputs: the sensors' readings, then one flag per sensor marking
/// the largest reading.
inline constexpr int kPhysicalInputs = 2 * kRiverSensors;

/// The flags of the PN's inputs: 1 for the sensor whose reading is strictly
/// the largest, 0 for the others; all 0 when the largest reading is shared
/// (on a flat landscape no sensor "has the maximum value", and flagging the
/// first would bias every flat-ground walk to one side).
std::array<double, kRiverSensors> max_flags(std::span<const double> readings);

/// A PN with its weights, and the values of its last run (for replays).
class PhysicalNetwork {
 public:
  /// `input_hidden` is hidden x kPhysicalInputs, `hidden_output` is
  /// outputs x hidden (one output per motif).
  PhysicalNetwork(WeightMatrix input_hidden, WeightMatrix hidden_output);

  /// Runs the network on the kRiverSensors readings, in sensor order, each
  /// the SM activity at that sensor divided by maxI; returns the outputs.
  std::span<const double> run(std::span<const double> readings);

  /// The last run's inputs: readings then flags (0 before the first run).
  std::span<const double> inputs() const { return inputs_; }
  /// The hidden layer's last outputs, tanh of the weighted sums.
  std::span<const double> hidden() const { return hidden_; }
  /// The last outputs, sigmoids of the weighted sums, in (0, 1) (0 before the
  /// first run).
  std::span<const double> outputs() const { return outputs_; }

 private:
  WeightMatrix input_hidden_;
  WeightMatrix hidden_output_;
  std::array<double, kPhysicalInputs> inputs_{};
  std::vector<double> hidden_;
  std::vector<double> outputs_;
};

}  // namespace bx
