// dominant_frequency against signals whose spectrum is known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "eval/spectrum.h"

namespace bx {
namespace {

std::vector<double> sampled(double seconds, double rate, auto f) {
  std::vector<double> v;
  for (int k = 0; k < static_cast<int>(seconds * rate); ++k) v.push_back(f(k / rate, k));
  return v;
}

TEST(Spectrum, ASineIsFoundAtItsFrequencyWithinOneBin) {
  for (double hz : {0.5, 1.0, 3.0, 7.3}) {
    const double rate = 240;
    auto v = sampled(10, rate, [&](double t, int) { return 0.3 + 0.8 * std::sin(2 * std::numbers::pi * hz * t); });
    // 2400 samples padded to 4096: bins of 240 / 4096 Hz
    EXPECT_NEAR(dominant_frequency(v, rate), hz, rate / 4096) << hz;
  }
}

TEST(Spectrum, ASignalFlippingEverySampleIsAtHalfTheRate) {
  // a buzzer at the brain's rate: +0.79, -0.70, ... at 60 Hz is a 30 Hz square wave
  auto v = sampled(10, 60, [](double, int k) { return k % 2 ? -0.70 : 0.79; });
  EXPECT_DOUBLE_EQ(dominant_frequency(v, 60), 30);
  // held over 4 physics steps a brain step (a 60 Hz brain at 240 Hz): still 30 Hz
  auto held = sampled(10, 240, [](double, int k) { return (k / 4) % 2 ? -0.70 : 0.79; });
  EXPECT_NEAR(dominant_frequency(held, 240), 30, 240.0 / 4096);
}

TEST(Spectrum, AOneInFourPulseIsAtAQuarterOfTheRate) {
  auto v = sampled(8, 64, [](double, int k) { return k % 4 == 0 ? 0.73 : 0.0; });
  EXPECT_DOUBLE_EQ(dominant_frequency(v, 64), 16);
}

TEST(Spectrum, AConstantOrTooShortSignalHasNone) {
  EXPECT_EQ(dominant_frequency(std::vector<double>(1000, 0.4), 100), 0);
  // constant to a thousandth: solver noise is not a rhythm
  auto tiny = sampled(10, 100, [](double, int k) { return 0.2 + 5e-4 * (k % 2 ? 1 : -1); });
  EXPECT_EQ(dominant_frequency(tiny, 100), 0);
  EXPECT_EQ(dominant_frequency(std::vector<double>{1, -1, 1}, 100), 0);
  EXPECT_EQ(dominant_frequency({}, 100), 0);
}

}  // namespace
}  // namespace bx
