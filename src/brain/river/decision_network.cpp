#include "brain/river/decision_network.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace bx {

int threshold_decision(double y) {
  if (y > kDecisionThreshold) return 1;
  if (y < -kDecisionThreshold) return -1;
  return 0;
}

DecisionNetwork::DecisionNetwork(WeightMatrix input_hidden, WeightMatrix hidden_output)
    : input_hidden_(std::move(input_hidden)), hidden_output_(std::move(hidden_output)) {
  assert(input_hidden_.cols == kDecisionInputs);
  assert(hidden_output_.rows == kDecisionOutputs && hidden_output_.cols == input_hidden_.rows);
  hidden_.assign(static_cast<std::size_t>(input_hidden_.rows), 0.0);
}

const Decision& DecisionNetwork::decide(int cell, bool carrying) {
  assert(cell >= 0 && cell < river_cell::kCount);
  std::array<double, kDecisionInputs> in{};
  in[static_cast<std::size_t>(cell)] = 1;
  in[river_cell::kCount] = carrying ? 1 : 0;
  return run(in);
}

const Decision& DecisionNetwork::run(std::span<const double> inputs) {
  assert(static_cast<int>(inputs.size()) == kDecisionInputs);
  std::copy(inputs.begin(), inputs.end(), inputs_.begin());

  // both layers: tanh of the weighted sum, no bias
  input_hidden_.apply(inputs_, hidden_);
  for (double& h : hidden_) h = std::tanh(h);
  hidden_output_.apply(hidden_, outputs_);
  for (double& o : outputs_) o = std::tanh(o);

  // output 0 is the action; output k the iota of cell code k, grass's staying 0
  decision_.action = threshold_decision(outputs_[0]);
  decision_.iota[river_cell::kGrass] = 0;
  for (int k = 1; k < kDecisionOutputs; ++k)
    decision_.iota[static_cast<std::size_t>(k)] = threshold_decision(outputs_[static_cast<std::size_t>(k)]);
  return decision_;
}

}  // namespace bx
