// The river crossing's decision network (DN; Stanton & Channon 2015, "The
// Decision Network", laid out as in Robinson et al. 2007): from the kind of
// cell the agent stands on and whether it carries a stone, an action and the
// iota (saliency) of each cell kind, which the shunting model turns into a
// landscape. Feed-forward, tanh in both layers, no bias, outputs thresholded
// to -1, 0 or 1.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "brain/river/dense_layer.h"
#include "brain/river/river_cell.h"

namespace bx {

/// The DN's inputs: the cell kind one-hot (in river_cell code order), then
/// the carrying flag (1 carrying, 0 not).
inline constexpr int kDecisionInputs = river_cell::kCount + 1;
/// The DN's outputs: output 0 is the action; output k (1..4) is the iota of
/// cell code k (resource, stone, water, trap). Grass has no output: iota 0.
inline constexpr int kDecisionOutputs = river_cell::kCount;
/// An output above this is 1, below its negative -1, else 0 (the paper's
/// "thresholds -0.3 and 0.3").
inline constexpr double kDecisionThreshold = 0.3;

/// One output thresholded: 1 if y > 0.3, -1 if y < -0.3, otherwise 0 (at
/// exactly +-0.3 too: the paper says neither way, and a tanh output lands on
/// the threshold exactly almost never).
int threshold_decision(double y);

/// What the DN decided, every value in {-1, 0, 1}.
struct Decision {
  /// 1 asks to pick a stone up, -1 to put it down; the task applies the
  /// rules (not carrying and on a stone; carrying and on water).
  int action = 0;
  /// Iota per cell code; iota[river_cell::kGrass] is always 0.
  std::array<int, river_cell::kCount> iota{};

  friend bool operator==(const Decision&, const Decision&) = default;
};

/// A DN with its weights, and the values of its last run (for replays).
class DecisionNetwork {
 public:
  /// `input_hidden` is hidden x kDecisionInputs, `hidden_output` is
  /// kDecisionOutputs x hidden (the paper's hidden layer has 4 neurons).
  DecisionNetwork(WeightMatrix input_hidden, WeightMatrix hidden_output);

  /// Runs the network on the cell code the agent stands on (river_cell) and
  /// whether it carries a stone; returns the decision.
  const Decision& decide(int cell, bool carrying);
  /// Runs the network on any kDecisionInputs inputs (decide's are one-hot
  /// plus the flag); returns the decision.
  const Decision& run(std::span<const double> inputs);

  /// The last run's inputs (0 before the first run).
  std::span<const double> inputs() const { return inputs_; }
  /// The hidden layer's last outputs, tanh of the weighted sums.
  std::span<const double> hidden() const { return hidden_; }
  /// The output layer's last values before the threshold, tanh of the
  /// weighted sums.
  std::span<const double> outputs() const { return outputs_; }
  /// The last decision (all 0 before the first run).
  const Decision& decision() const { return decision_; }

 private:
  WeightMatrix input_hidden_;
  WeightMatrix hidden_output_;
  std::array<double, kDecisionInputs> inputs_{};
  std::vector<double> hidden_;
  std::array<double, kDecisionOutputs> outputs_{};
  Decision decision_;
};

}  // namespace bx
