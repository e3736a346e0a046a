#include "brain/river/physical_network.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace bx {

std::array<double, kRiverSensors> max_flags(std::span<const double> readings) {
  assert(static_cast<int>(readings.size()) == kRiverSensors);
  std::array<double, kRiverSensors> flags{};
  const auto best = std::max_element(readings.begin(), readings.end());
  if (std::count(readings.begin(), readings.end(), *best) == 1)
    flags[static_cast<std::size_t>(best - readings.begin())] = 1;
  return flags;
}

PhysicalNetwork::PhysicalNetwork(WeightMatrix input_hidden, WeightMatrix hidden_output)
    : input_hidden_(std::move(input_hidden)), hidden_output_(std::move(hidden_output)) {
  assert(input_hidden_.cols == kPhysicalInputs);
  assert(hidden_output_.cols == input_hidden_.rows);
  hidden_.assign(static_cast<std::size_t>(input_hidden_.rows), 0.0);
  outputs_.assign(static_cast<std::size_t>(hidden_output_.rows), 0.0);
}

std::span<const double> PhysicalNetwork::run(std::span<const double> readings) {
  assert(static_cast<int>(readings.size()) == kRiverSensors);

  // readings, then which sensor reads the most
  const std::array<double, kRiverSensors> flags = max_flags(readings);
  std::copy(readings.begin(), readings.end(), inputs_.begin());
  std::copy(flags.begin(), flags.end(), inputs_.begin() + kRiverSensors);

  // tanh hidden layer, sigmoid outputs, no bias
  input_hidden_.apply(inputs_, hidden_);
  for (double& h : hidden_) h = std::tanh(h);
  hidden_output_.apply(hidden_, outputs_);
  for (double& o : outputs_) o = logistic(o);
  return outputs_;
}

}  // namespace bx
