// The decision network: one-hot inputs, tanh layers without bias, and the
// +-0.3 thresholds, against values worked out by hand.
#include "brain/river/decision_network.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace bx {
namespace {

constexpr int kHidden = 4;

TEST(DecisionNetwork, ThresholdsAtPlusAndMinus0_3) {
  EXPECT_EQ(threshold_decision(0.3001), 1);
  EXPECT_EQ(threshold_decision(0.2999), 0);
  EXPECT_EQ(threshold_decision(0.3), 0);
  EXPECT_EQ(threshold_decision(0), 0);
  EXPECT_EQ(threshold_decision(-0.3), 0);
  EXPECT_EQ(threshold_decision(-0.2999), 0);
  EXPECT_EQ(threshold_decision(-0.3001), -1);
  EXPECT_EQ(threshold_decision(0.99), 1);
  EXPECT_EQ(threshold_decision(-0.99), -1);
}

// Hidden neuron 0 takes only the stone input, at a weight that makes it 0.5;
// each output takes only hidden neuron 0, at a weight that lands its tanh
// just beside a threshold.
DecisionNetwork near_threshold_network() {
  WeightMatrix in(kHidden, kDecisionInputs), out(kDecisionOutputs, kHidden);
  in.at(0, river_cell::kStone) = std::atanh(0.5);
  const std::array<double, kDecisionOutputs> target{0.31, 0.29, -0.31, -0.29, 0.9};
  for (int k = 0; k < kDecisionOutputs; ++k) out.at(k, 0) = 2 * std::atanh(target[static_cast<std::size_t>(k)]);
  return DecisionNetwork(in, out);
}

TEST(DecisionNetwork, OutputsBesideTheThresholdsThroughTheNetwork) {
  DecisionNetwork dn = near_threshold_network();
  const Decision& d = dn.decide(river_cell::kStone, false);
  EXPECT_NEAR(dn.hidden()[0], 0.5, 1e-12);
  EXPECT_EQ(dn.hidden()[1], 0);
  EXPECT_NEAR(dn.outputs()[0], 0.31, 1e-12);
  EXPECT_NEAR(dn.outputs()[1], 0.29, 1e-12);
  EXPECT_NEAR(dn.outputs()[2], -0.31, 1e-12);
  EXPECT_NEAR(dn.outputs()[3], -0.29, 1e-12);
  // output 0 is the action; outputs 1..4 the iotas of resource, stone, water, trap
  EXPECT_EQ(d.action, 1);
  EXPECT_EQ(d.iota, (std::array<int, river_cell::kCount>{0, 0, -1, 0, 1}));
  EXPECT_EQ(&d, &dn.decision());

  // on grass nothing reaches the hidden layer: every output 0
  const Decision& g = dn.decide(river_cell::kGrass, false);
  EXPECT_EQ(g, Decision{});
}

TEST(DecisionNetwork, HasNoBiasZeroInputsGiveZeroOutputs) {
  WeightMatrix in(kHidden, kDecisionInputs), out(kDecisionOutputs, kHidden);
  for (std::size_t k = 0; k < in.w.size(); ++k) in.w[k] = 0.3 + 0.1 * static_cast<double>(k);
  for (std::size_t k = 0; k < out.w.size(); ++k) out.w[k] = -1.5 + 0.2 * static_cast<double>(k);
  DecisionNetwork dn(in, out);
  const std::array<double, kDecisionInputs> zeros{};
  const Decision& d = dn.run(zeros);
  for (double h : dn.hidden()) EXPECT_EQ(h, 0);
  for (double o : dn.outputs()) EXPECT_EQ(o, 0);
  EXPECT_EQ(d, Decision{});
  // while any one-hot input does reach the outputs
  dn.decide(river_cell::kGrass, false);
  EXPECT_NE(dn.outputs()[0], 0);
}

TEST(DecisionNetwork, InputsAreTheCellOneHotThenTheCarryingFlag) {
  DecisionNetwork dn(WeightMatrix(kHidden, kDecisionInputs), WeightMatrix(kDecisionOutputs, kHidden));
  dn.decide(river_cell::kWater, true);
  EXPECT_EQ(std::vector<double>(dn.inputs().begin(), dn.inputs().end()), (std::vector<double>{0, 0, 0, 1, 0, 1}));
  dn.decide(river_cell::kGrass, false);
  EXPECT_EQ(std::vector<double>(dn.inputs().begin(), dn.inputs().end()), (std::vector<double>{1, 0, 0, 0, 0, 0}));
  dn.decide(river_cell::kTrap, false);
  EXPECT_EQ(std::vector<double>(dn.inputs().begin(), dn.inputs().end()), (std::vector<double>{0, 0, 0, 0, 1, 0}));
}

TEST(DecisionNetwork, CarryingFlagReachesTheOutputs) {
  // the flag alone drives the water iota down while carrying
  WeightMatrix in(kHidden, kDecisionInputs), out(kDecisionOutputs, kHidden);
  in.at(2, river_cell::kCount) = 1;
  out.at(river_cell::kWater, 2) = -2;
  DecisionNetwork dn(in, out);
  EXPECT_EQ(dn.decide(river_cell::kGrass, true).iota[river_cell::kWater], -1);  // tanh(-2 tanh 1) = -0.91
  EXPECT_EQ(dn.decide(river_cell::kGrass, false).iota[river_cell::kWater], 0);
}

}  // namespace
}  // namespace bx
