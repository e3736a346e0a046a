// The CTRNN motif (eqs. 5 and 6, forward Euler) against its closed form and
// hand-stepped updates, and the pattern generator's input and motor wiring.
#include "brain/river/pattern_generator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace bx {
namespace {

// No weights, every time constant `tau`, biases `alpha`.
Motif lone_neurons(double tau, std::array<double, kMotifNeurons> alpha = {}, int input = 0, int output = 0) {
  Motif m;
  m.tau = {tau, tau, tau};
  m.alpha = alpha;
  m.input = input;
  m.output = output;
  return m;
}

TEST(CtrnnMotif, StartsAtRest) {
  CtrnnMotif c(lone_neurons(1, {0.4, -1, 2}));
  for (double a : c.activations()) EXPECT_EQ(a, 0);
  EXPECT_EQ(c.outputs()[0], std::tanh(0.2));
  EXPECT_EQ(c.outputs()[1], std::tanh(-0.5));
  EXPECT_EQ(c.outputs()[2], std::tanh(1.0));
}

// One neuron under a constant input I and no weights: tau dA/dt = -A + I from
// A = 0, whose solution is A(t) = I (1 - e^(-t / tau)). Forward Euler gives
// exactly A_n = I (1 - (1 - dt / tau)^n), which decays a little faster.
double euler_error(double dt, int steps) {
  const double input = 2, tau = 0.5;
  CtrnnMotif c(lone_neurons(tau, {0.4, 0, 0}));
  for (int n = 1; n <= steps; ++n) {
    c.step(input, dt);
    EXPECT_NEAR(c.activations()[0], input * (1 - std::pow(1 - dt / tau, n)), 1e-12) << "step " << n;
  }
  EXPECT_DOUBLE_EQ(c.outputs()[0], std::tanh((0.4 - c.activations()[0]) / 2));
  // only the input neuron takes the input
  EXPECT_EQ(c.activations()[1], 0);
  EXPECT_EQ(c.activations()[2], 0);
  const double t = dt * steps;
  return c.activations()[0] - input * (1 - std::exp(-t / tau));
}

TEST(CtrnnMotif, OneNeuronFollowsEulerAndTheClosedForm) {
  // 100 steps of 0.01 s = 2 time constants: Euler is ahead by
  // 2 (e^-2 - 0.98^100) = 0.0054
  const double e1 = euler_error(0.01, 100);
  EXPECT_GT(e1, 0);
  EXPECT_LT(e1, 0.006);
  // first order: half the step, half the error
  const double e2 = euler_error(0.005, 200);
  EXPECT_NEAR(e1 / e2, 2, 0.05);
}

TEST(CtrnnMotif, InputEntersOnlyTheInputNeuron) {
  CtrnnMotif c(lone_neurons(2, {}, 1));
  c.step(3, 0.1);
  EXPECT_EQ(c.activations()[0], 0);
  EXPECT_DOUBLE_EQ(c.activations()[1], 0.1 / 2 * 3);
  EXPECT_EQ(c.activations()[2], 0);
}

// Every activation comes from the old outputs, then every output from the
// new activations: nothing passes along a connection within one step.
TEST(CtrnnMotif, ActivationsFromOldOutputsThenOutputs) {
  Motif m = lone_neurons(1);
  m.w[0][0] = 0.5;  // self
  m.w[1][0] = 1;    // 0 -> 1
  m.w[2][1] = 2;    // 1 -> 2
  CtrnnMotif c(m);
  const double dt = 0.1, input = 10;

  // step 1: every old output is tanh(0) = 0
  c.step(input, dt);
  EXPECT_DOUBLE_EQ(c.activations()[0], 0.1 * 10);
  EXPECT_EQ(c.activations()[1], 0);  // in order, it would read tanh(-0.5)
  EXPECT_EQ(c.activations()[2], 0);
  const double o0 = std::tanh(-0.5);
  EXPECT_DOUBLE_EQ(c.outputs()[0], o0);
  EXPECT_EQ(c.outputs()[1], 0);

  // step 2: neuron 1 sees step 1's output of neuron 0; neuron 2 sees
  // neuron 1's, still 0
  c.step(input, dt);
  const double a0 = 1 + 0.1 * (-1 + 0.5 * o0 + 10), a1 = 0.1 * o0;
  EXPECT_DOUBLE_EQ(c.activations()[0], a0);
  EXPECT_DOUBLE_EQ(c.activations()[1], a1);
  EXPECT_EQ(c.activations()[2], 0);
  EXPECT_DOUBLE_EQ(c.outputs()[0], std::tanh(-a0 / 2));
  EXPECT_DOUBLE_EQ(c.outputs()[1], std::tanh(-a1 / 2));

  // step 3: it reaches neuron 2
  c.step(input, dt);
  EXPECT_DOUBLE_EQ(c.activations()[2], 0.1 * 2 * std::tanh(-a1 / 2));
}

TEST(Motif, CheckNamesTheBadField) {
  EXPECT_TRUE(check_motif(lone_neurons(1)).ok());
  Motif m = lone_neurons(1);
  m.tau[1] = 0;
  Status s = check_motif(m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("tau[1] is 0"), std::string::npos) << s.error();

  m = lone_neurons(1);
  m.w[0][2] = std::numeric_limits<double>::quiet_NaN();
  s = check_motif(m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("w[0][2]"), std::string::npos) << s.error();

  m = lone_neurons(1);
  m.alpha[2] = std::numeric_limits<double>::infinity();
  s = check_motif(m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("alpha[2]"), std::string::npos) << s.error();

  m = lone_neurons(1);
  m.input = 3;
  s = check_motif(m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("input is 3"), std::string::npos) << s.error();

  m = lone_neurons(1);
  m.output = -1;
  s = check_motif(m);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().find("output is -1"), std::string::npos) << s.error();
}

TEST(PatternGenerator, PnOutputsDriveEachMotifThroughTheInterconnectionWeights) {
  WeightMatrix in(2, 2);
  in.at(0, 0) = 1, in.at(0, 1) = 2;     // motif 0: pn0 + 2 pn1
  in.at(1, 0) = -1, in.at(1, 1) = 0.5;  // motif 1: -pn0 + pn1 / 2
  PatternGenerator pg(lone_neurons(1, {}, 2, 2), in, WeightMatrix(1, 2));
  pg.step(std::vector<double>{0.2, 0.4}, 0.01);
  EXPECT_DOUBLE_EQ(pg.motif_inputs()[0], 1.0);
  EXPECT_DOUBLE_EQ(pg.motif_inputs()[1], 0.0);
  // one Euler step from rest with tau 1: A = dt * input, in the input neuron
  EXPECT_DOUBLE_EQ(pg.motif(0).activations()[2], 0.01);
  EXPECT_EQ(pg.motif(0).activations()[0], 0);
  EXPECT_DOUBLE_EQ(pg.motif(1).activations()[2], 0.0);
  EXPECT_DOUBLE_EQ(pg.outputs()[0], std::tanh(-0.005));
  EXPECT_DOUBLE_EQ(pg.outputs()[1], 0.0);
}

TEST(PatternGenerator, MotorsAreSigmoidsOfTheWeightedMotifOutputs) {
  // each motif's output neuron is its input neuron 1, biased by 1
  WeightMatrix in(2, 2), motor(3, 2);
  in.at(0, 0) = 1;
  in.at(1, 1) = 1;
  motor.at(0, 0) = 1, motor.at(0, 1) = 0;
  motor.at(1, 0) = -2, motor.at(1, 1) = 3;
  motor.at(2, 0) = 0, motor.at(2, 1) = 0;
  PatternGenerator pg(lone_neurons(1, {0, 1, 0}, 1, 1), in, motor);
  auto sigmoid = [](double x) { return 1 / (1 + std::exp(-x)); };

  // at rest every output is tanh(1 / 2)
  const double rest = std::tanh(0.5);
  ASSERT_EQ(pg.motors().size(), 3u);
  EXPECT_DOUBLE_EQ(pg.motors()[0], sigmoid(rest));
  EXPECT_DOUBLE_EQ(pg.motors()[1], sigmoid(rest));
  EXPECT_EQ(pg.motors()[2], 0.5);

  // motif 0 driven by 1 for 0.1 s: A = 0.1, O = tanh((1 - 0.1) / 2)
  pg.step(std::vector<double>{1, 0}, 0.1);
  const double o0 = std::tanh(0.45);
  EXPECT_DOUBLE_EQ(pg.outputs()[0], o0);
  EXPECT_DOUBLE_EQ(pg.outputs()[1], rest);
  EXPECT_DOUBLE_EQ(pg.motors()[0], sigmoid(o0));
  EXPECT_DOUBLE_EQ(pg.motors()[1], sigmoid(-2 * o0 + 3 * rest));
  EXPECT_EQ(pg.motors()[2], 0.5);
}

}  // namespace
}  // namespace bx
