// The brain runtime on hand-built models, against values worked out by hand.
#include "brain/brain_model.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <numbers>
#include <stdexcept>
#include <string>

// Count heap allocations, to check that brain_step makes none.
namespace {
std::atomic<long> g_allocations{0};
}  // namespace

// GCC flags free() of memory from a replaced operator new once both are
// inlined (-Wmismatched-new-delete); here they are a matched pair.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace bx {
namespace {

/// Builds a BrainModel one neuron and one effector at a time.
struct Builder {
  BrainModel m;
  std::uint32_t state_size = 0;

  explicit Builder(NeuronSetId set, int n_sensors) {
    m.set = set;
    m.n_sensors = n_sensors;
    m.param_begin = {0};
    m.state_begin = {0};
    m.input_begin = {0};
    m.effector_input_begin = {0};
  }
  /// Adds a neuron; inputs are (slot or -1, weight). Returns its value slot.
  int neuron(std::string_view name, std::vector<std::pair<int, double>> inputs,
             std::vector<double> params = {}, double bias = 0) {
    const NeuronFnSpec* f = find_neuron_fn(m.set, name);
    if (!f) throw std::runtime_error("no neuron function " + std::string(name));
    m.fn.push_back(f->id);
    m.bias.push_back(bias);
    if (params.empty())
      for (const ParamSpec& p : f->params) params.push_back(p.default_value);
    m.params.insert(m.params.end(), params.begin(), params.end());
    m.param_begin.push_back(static_cast<std::uint32_t>(m.params.size()));
    state_size += f->state_size(params);
    m.state_begin.push_back(state_size);
    for (auto [src, w] : inputs) {
      m.input_src.push_back(src);
      m.input_weight.push_back(w);
    }
    m.input_begin.push_back(static_cast<std::uint32_t>(m.input_src.size()));
    m.neuron_part.push_back(-1);
    return m.n_sensors + m.n_neurons() - 1;
  }
  /// Adds an effector; returns its index.
  int effector(std::vector<std::pair<int, double>> inputs, double bias = 0) {
    m.effector_bias.push_back(bias);
    for (auto [src, w] : inputs) {
      m.effector_input_src.push_back(src);
      m.effector_input_weight.push_back(w);
    }
    m.effector_input_begin.push_back(static_cast<std::uint32_t>(m.effector_input_src.size()));
    return m.n_effectors() - 1;
  }
  /// Adds a task output (a latch at `threshold`, `floor` a slot or -1); returns its index.
  int task_output(std::vector<std::pair<int, double>> inputs, int floor, double threshold) {
    if (m.task_output_input_begin.empty()) m.task_output_input_begin = {0};
    m.task_output_floor.push_back(floor);
    m.task_output_threshold.push_back(threshold);
    for (auto [src, w] : inputs) {
      m.task_output_input_src.push_back(src);
      m.task_output_input_weight.push_back(w);
    }
    m.task_output_input_begin.push_back(static_cast<std::uint32_t>(m.task_output_input_src.size()));
    return m.n_task_outputs() - 1;
  }
};

// 2 sensors, a recurrent pair n0 <-> n1, a mem delay of 2 steps, 1 effector:
//   n0 = sum(0.5*s0, 0.5*n1)   n1 = sum(1.0*n0, hole)   n2 = mem[n=2](1.0*s1)
//   eff = clamp(1.0*n1 + 0.5*n2 + 0.25*s0 + 0.1)
BrainModel loop_model() {
  Builder b(NeuronSetId::Chaumont2007, 2);
  const int n0 = 2, n1 = 3;
  EXPECT_EQ(b.neuron("sum", {{0, 0.5}, {n1, 0.5}}), n0);
  EXPECT_EQ(b.neuron("sum", {{n0, 1.0}, {-1, 0.7}}), n1);
  EXPECT_EQ(b.neuron("mem", {{1, 1.0}}, {2}), 4);
  b.effector({{n1, 1.0}, {4, 0.5}, {0, 0.25}}, 0.1);
  return b.m;
}

TEST(Brain, FreshStateIsSizedAndZero) {
  BrainModel m = loop_model();
  BrainState s = make_brain_state(m);
  EXPECT_EQ(s.values, std::vector<double>(5, 0.0));
  EXPECT_EQ(s.next, std::vector<double>(5, 0.0));
  EXPECT_EQ(s.state, std::vector<double>(3, 0.0));  // mem n=2: two slots and an index
  EXPECT_EQ(s.effector_out, std::vector<double>(1, 0.0));
  EXPECT_EQ(s.t, 0.0);

  BrainState empty = make_brain_state(BrainModel{});
  EXPECT_TRUE(empty.values.empty());
  EXPECT_TRUE(empty.state.empty());
  EXPECT_TRUE(empty.effector_out.empty());
}

// Assertions are on in every build, the tested one included (CMakeLists.txt
// removes NDEBUG): a state that does not belong to the model stops the process
// where the brain reads it, instead of reading past its arrays.
TEST(BrainDeathTest, AStateOfAnotherModelIsCaughtByAnAssertion) {
  BrainModel m = loop_model();
  BrainState wrong = make_brain_state(BrainModel{});
  EXPECT_DEATH(brain_step(m, wrong, 0.01), "values.size");
}

TEST(Brain, HandComputedSteps) {
  BrainModel m = loop_model();
  BrainState s = make_brain_state(m);
  s.values[0] = 0.4;
  s.values[1] = 0.6;
  // per step: n0, n1, n2, effector (worked by hand from the model above)
  const double want[5][4] = {
      {0.2, 0.0, 0.0, 0.2},  // s0 reaches n0; the effector reads s0 in the same step
      {0.2, 0.2, 0.0, 0.4},  // n0 reaches n1 one step later: the chain takes two steps
      {0.3, 0.2, 0.6, 0.7},  // n1 feeds back into n0; mem emits s1 of two steps ago
      {0.3, 0.3, 0.6, 0.8},
      {0.35, 0.3, 0.6, 0.8},
  };
  for (int k = 0; k < 5; ++k) {
    brain_step(m, s, 0.01);
    EXPECT_NEAR(s.values[2], want[k][0], 1e-12) << "step " << k;
    EXPECT_NEAR(s.values[3], want[k][1], 1e-12) << "step " << k;
    EXPECT_NEAR(s.values[4], want[k][2], 1e-12) << "step " << k;
    EXPECT_NEAR(s.effector_out[0], want[k][3], 1e-12) << "step " << k;
    // sensor slots belong to the simulation
    EXPECT_EQ(s.values[0], 0.4);
    EXPECT_EQ(s.values[1], 0.6);
    EXPECT_NEAR(s.t, 0.01 * (k + 1), 1e-12);
  }
  // the loop settles at n0 = 0.2 + 0.5*n0
  for (int k = 0; k < 200; ++k) brain_step(m, s, 0.01);
  EXPECT_NEAR(s.values[2], 0.4, 1e-12);
  EXPECT_NEAR(s.values[3], 0.4, 1e-12);
  EXPECT_NEAR(s.effector_out[0], 0.4 + 0.3 + 0.1 + 0.1, 1e-12);
}

TEST(Brain, SensorChangeReachesMemAfterDelay) {
  BrainModel m = loop_model();
  BrainState s = make_brain_state(m);
  // s1 is 1 only during the first step: mem (n=2) shows it at the third
  s.values[1] = 1.0;
  brain_step(m, s, 0.01);
  s.values[1] = 0.0;
  brain_step(m, s, 0.01);
  EXPECT_EQ(s.values[4], 0.0);
  brain_step(m, s, 0.01);
  EXPECT_EQ(s.values[4], 1.0);
  brain_step(m, s, 0.01);
  EXPECT_EQ(s.values[4], 0.0);
}

TEST(Brain, PositionalPaddingHolesAndExtraInputs) {
  Builder b(NeuronSetId::Sims1994, 1);
  b.neuron("if", {{0, 1.0}});                                // b, c missing: read 0
  b.neuron("divide", {{-1, 1.0}, {0, 2.0}});                 // a is a hole: 0/(2*s0)
  b.neuron("interpolate", {{0, 1.0}, {-1, 5.0}, {0, 4.0}});  // b + (c-b)*clamp(a)
  b.neuron("sum", {{0, 1.0}, {0, 1.0}, {0, 100.0}});         // third input ignored
  b.neuron("oscillate-wave", {}, {0.5, 0.0});                // uses brain time
  BrainState s = make_brain_state(b.m);
  s.values[0] = 0.5;
  brain_step(b.m, s, 0.25);
  EXPECT_EQ(s.values[1], 0.0);               // a > 0 -> b = 0
  EXPECT_EQ(s.values[2], 0.0);
  EXPECT_DOUBLE_EQ(s.values[3], 0.5 * 2.0);  // 0 + (2 - 0) * 0.5
  EXPECT_DOUBLE_EQ(s.values[4], 1.0);
  EXPECT_NEAR(s.values[5], 0.0, 1e-12);      // t = 0 at the first step
  brain_step(b.m, s, 0.25);
  EXPECT_NEAR(s.values[5], std::sin(2 * std::numbers::pi * 0.5 * 0.25), 1e-12);  // t = 0.25
  EXPECT_EQ(s.t, 0.5);
}

TEST(Brain, MiconiWeightedSumBiasAndTanhEffector) {
  Builder b(NeuronSetId::Miconi2006, 1);
  const int n0 = b.neuron("tanh", {{0, 0.8}}, {}, 0.25);
  const int n1 = b.neuron("sigmoid", {{n0, -1.0}, {-1, 1.0}, {0, 0.5}}, {}, -0.1);
  b.effector({{n1, 1.0}, {n0, 0.5}}, 0.2);
  BrainState s = make_brain_state(b.m);
  s.values[0] = 0.5;

  // step 1: n0 from s0; n1 sees n0 = 0 (previous step)
  brain_step(b.m, s, 0.01);
  const double a0 = std::tanh(2 * (0.8 * 0.5 + 0.25));
  const double b0 = 1 / (1 + std::exp(-3 * (0.5 * 0.5 - 0.1)));
  EXPECT_DOUBLE_EQ(s.values[n0], a0);
  EXPECT_DOUBLE_EQ(s.values[n1], b0);
  EXPECT_DOUBLE_EQ(s.effector_out[0], std::tanh(b0 + 0.5 * a0 + 0.2));

  // step 2: n1 now sees n0
  brain_step(b.m, s, 0.01);
  const double b1 = 1 / (1 + std::exp(-3 * (-a0 + 0.25 - 0.1)));
  EXPECT_DOUBLE_EQ(s.values[n0], a0);
  EXPECT_DOUBLE_EQ(s.values[n1], b1);
  EXPECT_DOUBLE_EQ(s.effector_out[0], std::tanh(b1 + 0.5 * a0 + 0.2));
}

TEST(Brain, NeuronlessEffectorFollowsSensorAtOnce) {
  Builder b(NeuronSetId::Sims1994, 2);
  b.effector({{1, 3.0}, {-1, 9.0}}, -0.5);
  BrainState s = make_brain_state(b.m);
  s.values[1] = 0.3;
  brain_step(b.m, s, 0.01);
  EXPECT_NEAR(s.effector_out[0], 0.4, 1e-12);
  s.values[1] = 1.0;
  brain_step(b.m, s, 0.01);
  EXPECT_EQ(s.effector_out[0], 1.0);  // 2.5 clamped
}

// A task output (a catapult's release): its signal is the clamped weighted
// sum of its inputs or its floor slot, whichever is higher; it reads 0 until
// the first step its signal reaches the threshold and 1 from then on, even
// when the signal falls again.
TEST(Brain, ATaskOutputLatchesAtItsThresholdOnTheLargerOfItsSumAndItsFloor) {
  Builder b(NeuronSetId::Chaumont2007, 2);
  b.task_output({{0, 2.0}, {-1, 9.0}}, -1, 0.5);  // sensor 0 alone, no floor
  b.task_output({{0, -1.0}}, 1, 0.5);             // floor: sensor 1
  BrainState s = make_brain_state(b.m);
  ASSERT_EQ(s.task_out.size(), 2u);
  EXPECT_EQ(s.task_out[0], 0.0);
  s.values[0] = 0.2;  // sum 0.4; the second's -0.2 under its floor 0.3
  s.values[1] = 0.3;
  brain_step(b.m, s, 0.01);
  EXPECT_DOUBLE_EQ(s.task_output_signal[0], 0.4);
  EXPECT_DOUBLE_EQ(s.task_output_signal[1], 0.3);
  EXPECT_EQ(s.task_out[0], 0.0);
  EXPECT_EQ(s.task_out[1], 0.0);
  s.values[0] = 0.8;  // sum 1.6 clamped to 1: the first fires
  brain_step(b.m, s, 0.01);
  EXPECT_EQ(s.task_output_signal[0], 1.0);
  EXPECT_EQ(s.task_out[0], 1.0);
  EXPECT_EQ(s.task_out[1], 0.0);
  s.values[0] = -0.8;  // the first's signal falls, its latch holds; the floor fires the second
  s.values[1] = 0.5;
  brain_step(b.m, s, 0.01);
  EXPECT_EQ(s.task_output_signal[0], -1.0);
  EXPECT_EQ(s.task_out[0], 1.0);
  EXPECT_DOUBLE_EQ(s.task_output_signal[1], 0.8);  // the sum 0.8 over the floor 0.5
  EXPECT_EQ(s.task_out[1], 1.0);
}

// a busy brain with every kind of state, driven by a fixed sensor sequence
BrainModel busy_model() {
  Builder b(NeuronSetId::Sims1994, 2);
  b.neuron("integrate", {{0, 1.0}});
  b.neuron("differentiate", {{1, 1.0}});
  b.neuron("smooth", {{3, 1.0}}, {0.3});
  b.neuron("memory", {{4, 1.0}, {0, 1.0}});
  b.neuron("oscillate-saw", {{2, 0.1}}, {2.0, 0.5});
  b.neuron("product", {{6, 1.0}, {5, 1.0}});
  b.neuron("if", {{7, 1.0}, {2, 1.0}, {3, -1.0}});
  b.effector({{8, 1.0}, {2, 0.2}});
  b.effector({{6, 0.7}}, 0.1);
  return b.m;
}

std::vector<double> run(const BrainModel& m, int steps) {
  BrainState s = make_brain_state(m);
  std::vector<double> trace;
  for (int k = 0; k < steps; ++k) {
    s.values[0] = std::sin(0.05 * k);
    s.values[1] = std::cos(0.11 * k) * 0.5;
    brain_step(m, s, 0.01);
    trace.insert(trace.end(), s.values.begin(), s.values.end());
    trace.insert(trace.end(), s.effector_out.begin(), s.effector_out.end());
  }
  trace.insert(trace.end(), s.state.begin(), s.state.end());
  return trace;
}

TEST(Brain, Deterministic) {
  const BrainModel m = busy_model();
  std::vector<double> a = run(m, 400), b = run(m, 400);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << i;  // bit for bit
  bool moved = false;
  for (double v : a) moved = moved || v != 0.0;
  EXPECT_TRUE(moved);
}

TEST(Brain, StepAllocatesNothing) {
  const BrainModel m = busy_model();
  BrainState s = make_brain_state(m);
  brain_step(m, s, 0.01);  // the function table is built on first use
  const long before = g_allocations.load();
  for (int k = 0; k < 100; ++k) {
    s.values[0] = 0.01 * k;
    brain_step(m, s, 0.01);
  }
  EXPECT_EQ(g_allocations.load(), before);
}

}  // namespace
}  // namespace bx
