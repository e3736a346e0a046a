// The physical network: readings and one-hot max flags in, tanh hidden,
// sigmoid out, no bias; against values worked out by hand.
#include "brain/river/physical_network.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace bx {
namespace {

using Flags = std::array<double, kRiverSensors>;

Flags flags_of(std::vector<double> readings) { return max_flags(readings); }

TEST(PhysicalNetwork, MaxFlagMarksTheStrictlyLargestReading) {
  EXPECT_EQ(flags_of({0.1, 0.7, 0.3, -1}), (Flags{0, 1, 0, 0}));
  EXPECT_EQ(flags_of({0.9, 0.7, 0.3, 0.8}), (Flags{1, 0, 0, 0}));
  EXPECT_EQ(flags_of({0.1, 0.2, 0.3, 0.30001}), (Flags{0, 0, 0, 1}));
  // negatives: the least negative is the largest
  EXPECT_EQ(flags_of({-0.5, -0.9, -0.2, -1}), (Flags{0, 0, 1, 0}));
}

TEST(PhysicalNetwork, MaxFlagsAreAllZeroWhenTheLargestIsShared) {
  EXPECT_EQ(flags_of({0.5, 0.5, 0.1, 0}), (Flags{0, 0, 0, 0}));
  EXPECT_EQ(flags_of({0, 0, 0, 0}), (Flags{0, 0, 0, 0}));
  // a shared smaller value does not matter
  EXPECT_EQ(flags_of({0.1, 0.1, 0.6, 0}), (Flags{0, 0, 1, 0}));
}

TEST(PhysicalNetwork, InputsAreReadingsThenFlags) {
  PhysicalNetwork pn(WeightMatrix(3, kPhysicalInputs), WeightMatrix(5, 3));
  pn.run(std::vector<double>{0.2, 0.1, 0.6, 0.0});
  EXPECT_EQ(std::vector<double>(pn.inputs().begin(), pn.inputs().end()),
            (std::vector<double>{0.2, 0.1, 0.6, 0.0, 0, 0, 1, 0}));
}

TEST(PhysicalNetwork, TanhHiddenSigmoidOutputsWithoutBias) {
  WeightMatrix in(2, kPhysicalInputs), out(2, 2);
  in.at(0, 0) = 2;   // reading 0
  in.at(0, 6) = 1;   // flag 2
  in.at(1, 1) = -1;  // reading 1
  out.at(0, 0) = 1;
  out.at(0, 1) = 0.5;
  out.at(1, 0) = -1;
  PhysicalNetwork pn(in, out);
  std::span<const double> o = pn.run(std::vector<double>{0.25, 0.5, 0.75, 0});
  const double h0 = std::tanh(2 * 0.25 + 1 * 1), h1 = std::tanh(-0.5);
  EXPECT_DOUBLE_EQ(pn.hidden()[0], h0);
  EXPECT_DOUBLE_EQ(pn.hidden()[1], h1);
  ASSERT_EQ(o.size(), 2u);
  EXPECT_DOUBLE_EQ(o[0], 1 / (1 + std::exp(-(h0 + 0.5 * h1))));
  EXPECT_DOUBLE_EQ(o[1], 1 / (1 + std::exp(h0)));

  // flat ground: no reading and no flag, so every sum is 0 and every output
  // the sigmoid's 0.5
  pn.run(std::vector<double>{0, 0, 0, 0});
  EXPECT_EQ(pn.hidden()[0], 0);
  EXPECT_EQ(pn.outputs()[0], 0.5);
  EXPECT_EQ(pn.outputs()[1], 0.5);
}

}  // namespace
}  // namespace bx
