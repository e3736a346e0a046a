// Every function of every neuron set against its definition (docs/neurons.md).
#include "brain/neuron_set.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace bx {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr NeuronSetId kSims = NeuronSetId::Sims1994;
constexpr NeuronSetId kChau = NeuronSetId::Chaumont2007;
constexpr NeuronSetId kMico = NeuronSetId::Miconi2006;
constexpr NeuronSetId kLess = NeuronSetId::Lessin2015;

// One neuron with its own parameters and state, called as a function.
struct Neuron {
  const NeuronFnSpec* f;
  std::vector<double> params;
  std::vector<double> state;

  // params empty: the spec's defaults
  Neuron(NeuronSetId set, std::string_view name, std::vector<double> p = {})
      : f(find_neuron_fn(set, name)), params(std::move(p)) {
    if (!f) throw std::runtime_error("no neuron function " + std::string(name));
    if (params.empty())
      for (const ParamSpec& ps : f->params) params.push_back(ps.default_value);
    state.assign(f->state_size(params), 0.0);
  }
  // args padded with zeros to the arity, as brain_step does
  double operator()(std::vector<double> args, double t = 0.0, double dt = 0.01) {
    args.resize(f->mode == InputMode::WeightedSum ? 1 : f->max_inputs, 0.0);
    return eval_neuron(f->id, args, params, state, NeuronClock{t, dt});
  }
};

double sims(std::string_view name, std::vector<double> args, std::vector<double> params = {}) {
  return Neuron(kSims, name, std::move(params))(std::move(args));
}
double chau(std::string_view name, std::vector<double> args, std::vector<double> params = {}) {
  return Neuron(kChau, name, std::move(params))(std::move(args));
}

// --- the table -------------------------------------------------------------

TEST(NeuronTable, IdsAreDenseAndMatchIndex) {
  const auto& fns = all_neuron_fns();
  ASSERT_EQ(fns.size(), 23u + 7u + 2u + 14u);
  for (std::size_t i = 0; i < fns.size(); ++i) {
    EXPECT_EQ(fns[i].id, i);
    EXPECT_FALSE(fns[i].name.empty());
    EXPECT_NE(fns[i].state_size, nullptr);
  }
}

TEST(NeuronTable, NamesAndArityPerSet) {
  const std::map<std::string, int> sims_arity = {
      {"sum", 2},       {"product", 2},     {"divide", 2},    {"sum-threshold", 2},
      {"greater-than", 2}, {"sign-of", 1},  {"min", 2},       {"max", 2},
      {"abs", 1},       {"if", 3},          {"interpolate", 3}, {"sin", 1},
      {"cos", 1},       {"atan", 1},        {"log", 1},       {"expt", 1},
      {"sigmoid", 1},   {"integrate", 1},   {"differentiate", 1}, {"smooth", 1},
      {"memory", 2},    {"oscillate-wave", 1}, {"oscillate-saw", 1}};
  const std::map<std::string, int> chau_arity = {{"sumT", 2}, {"div", 2}, {"mem", 1}, {"wav", 3},
                                                 {"mul", 2},  {"sum", 2}, {"cst", 0}};
  auto check = [](NeuronSetId set, const std::map<std::string, int>& want, InputMode mode) {
    auto names = neuron_fn_names(set);
    EXPECT_EQ(names.size(), want.size());
    for (const auto& [name, arity] : want) {
      const NeuronFnSpec* f = find_neuron_fn(set, name);
      ASSERT_NE(f, nullptr) << name;
      EXPECT_EQ(f->name, name);
      EXPECT_EQ(f->set, set);
      EXPECT_EQ(f->mode, mode) << name;
      EXPECT_EQ(f->max_inputs, arity) << name;
      EXPECT_LE(f->max_inputs, kMaxNeuronArity) << name;
    }
  };
  check(kSims, sims_arity, InputMode::Positional);
  check(kChau, chau_arity, InputMode::Positional);
  // lessin2015 III-C's thirteen node types, then IV-B's sigma
  const std::map<std::string, int> less_arity = {
      {"sinusoidal", 0}, {"complement", 1}, {"constant", 0}, {"scale", 1}, {"multiply", 2},
      {"divide", 2},     {"sum", 2},        {"difference", 2}, {"derivative", 1}, {"threshold", 1},
      {"switch", 3},     {"delay", 1},      {"absolute-difference", 2}};
  auto less = neuron_fn_names(kLess);
  EXPECT_EQ(less.size(), less_arity.size() + 1);
  for (const auto& [name, arity] : less_arity) {
    const NeuronFnSpec* f = find_neuron_fn(kLess, name);
    ASSERT_NE(f, nullptr) << name;
    EXPECT_EQ(f->mode, InputMode::Positional) << name;
    EXPECT_EQ(f->max_inputs, arity) << name;
  }
  const NeuronFnSpec* sigma = find_neuron_fn(kLess, "sigma");
  ASSERT_NE(sigma, nullptr);
  EXPECT_EQ(sigma->mode, InputMode::WeightedSum);
  EXPECT_GE(sigma->max_inputs, 64);  // it switches a whole skill

  auto mico = neuron_fn_names(kMico);
  EXPECT_EQ(mico, (std::vector<std::string_view>{"sigmoid", "tanh"}));
  for (auto name : mico) {
    const NeuronFnSpec* f = find_neuron_fn(kMico, name);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(f->mode, InputMode::WeightedSum);
    EXPECT_EQ(f->max_inputs, 3);
    EXPECT_TRUE(f->params.empty());
  }
}

TEST(NeuronTable, FindIsPerSet) {
  EXPECT_EQ(find_neuron_fn(kSims, "no-such-fn"), nullptr);
  EXPECT_EQ(find_neuron_fn(kChau, ""), nullptr);
  EXPECT_EQ(find_neuron_fn(kSims, "sumT"), nullptr);     // chaumont only
  EXPECT_EQ(find_neuron_fn(kChau, "product"), nullptr);  // sims only
  EXPECT_EQ(find_neuron_fn(kMico, "sum"), nullptr);
  EXPECT_EQ(find_neuron_fn(kChau, "Sum"), nullptr);      // case matters
  // "sum" and "sigmoid" exist in two sets, as different functions
  ASSERT_NE(find_neuron_fn(kSims, "sum"), nullptr);
  ASSERT_NE(find_neuron_fn(kChau, "sum"), nullptr);
  EXPECT_NE(find_neuron_fn(kSims, "sum")->id, find_neuron_fn(kChau, "sum")->id);
  EXPECT_NE(find_neuron_fn(kSims, "sigmoid")->id, find_neuron_fn(kMico, "sigmoid")->id);
}

TEST(NeuronTable, ParamsDefaultsInsideRanges) {
  for (const NeuronFnSpec& f : all_neuron_fns())
    for (const ParamSpec& p : f.params) {
      EXPECT_LE(p.min, p.default_value) << f.name << "." << p.name;
      EXPECT_LE(p.default_value, p.max) << f.name << "." << p.name;
    }
  auto only = [](NeuronSetId set, std::string_view fn) {
    const NeuronFnSpec* f = find_neuron_fn(set, fn);
    if (!f || f->params.size() != 1) throw std::runtime_error("one param expected");
    return f->params[0];
  };
  ParamSpec t = only(kChau, "sumT");
  EXPECT_EQ(t.name, "T");
  EXPECT_EQ(t.default_value, 0.0);
  EXPECT_EQ(t.min, -2.0);
  EXPECT_EQ(t.max, 2.0);
  ParamSpec eps = only(kChau, "div");
  EXPECT_EQ(eps.name, "eps");
  EXPECT_EQ(eps.default_value, 0.001);
  ParamSpec n = only(kChau, "mem");
  EXPECT_EQ(n.name, "n");
  EXPECT_TRUE(n.integer);
  EXPECT_EQ(n.min, 1.0);
  EXPECT_EQ(n.max, 1000.0);
  ParamSpec v = only(kChau, "cst");
  EXPECT_EQ(v.name, "V");
  EXPECT_EQ(v.min, -1.0);
  EXPECT_EQ(v.max, 1.0);
  EXPECT_EQ(only(kSims, "smooth").default_value, 0.1);
  const NeuronFnSpec* osc = find_neuron_fn(kSims, "oscillate-wave");
  ASSERT_EQ(osc->params.size(), 2u);
  EXPECT_EQ(osc->params[0].name, "freq");
  EXPECT_EQ(osc->params[0].default_value, 1.0);
  EXPECT_EQ(osc->params[1].name, "phase");
  EXPECT_DOUBLE_EQ(osc->params[1].max, kPi);
}

TEST(NeuronTable, StateSizes) {
  auto size = [](NeuronSetId set, std::string_view name, std::vector<double> p) {
    return find_neuron_fn(set, name)->state_size(p);
  };
  EXPECT_EQ(size(kChau, "mem", {1}), 2);
  EXPECT_EQ(size(kChau, "mem", {30}), 31);
  EXPECT_EQ(size(kChau, "mem", {}), 2);        // default n = 1
  EXPECT_EQ(size(kChau, "mem", {2.6}), 4);     // rounded to 3
  EXPECT_EQ(size(kChau, "mem", {5000}), 1001); // held to the range
  EXPECT_EQ(size(kSims, "integrate", {}), 1);
  EXPECT_EQ(size(kSims, "differentiate", {}), 2);
  EXPECT_EQ(size(kSims, "smooth", {0.1}), 1);
  EXPECT_EQ(size(kSims, "memory", {}), 1);
  EXPECT_EQ(size(kLess, "derivative", {}), 2);
  EXPECT_EQ(size(kLess, "delay", {30}), 31);
  const std::set<std::string_view> stateful = {"integrate", "differentiate", "smooth", "memory",
                                               "mem", "derivative", "delay"};
  for (const NeuronFnSpec& f : all_neuron_fns()) {
    std::vector<double> defaults;
    for (const ParamSpec& p : f.params) defaults.push_back(p.default_value);
    if (!stateful.count(f.name)) {
      EXPECT_EQ(f.state_size(defaults), 0) << f.name;
    }
  }
}

// --- sims1994 --------------------------------------------------------------

TEST(Sims1994, Arithmetic) {
  EXPECT_DOUBLE_EQ(sims("sum", {0.3, 0.4}), 0.7);
  EXPECT_DOUBLE_EQ(sims("sum", {-2.0, 0.5}), -1.5);  // no [-1,1] clamp in this set
  EXPECT_DOUBLE_EQ(sims("sum", {900, 900}), 1000);   // the +-1e3 clamp
  EXPECT_DOUBLE_EQ(sims("product", {0.5, -4}), -2);
  EXPECT_DOUBLE_EQ(sims("product", {-100, 100}), -1000);
  EXPECT_DOUBLE_EQ(sims("divide", {1, 4}), 0.25);
  EXPECT_DOUBLE_EQ(sims("divide", {1, -2}), -0.5);
  EXPECT_EQ(sims("divide", {1, 0}), 0.0);
  EXPECT_EQ(sims("divide", {1, 1e-10}), 0.0);
  EXPECT_EQ(sims("divide", {1, -5e-10}), 0.0);
  EXPECT_DOUBLE_EQ(sims("divide", {1, 1e-8}), 1000);  // 1e8, clamped
}

TEST(Sims1994, Comparisons) {
  EXPECT_EQ(sims("sum-threshold", {0.3, -0.1}), 1.0);
  EXPECT_EQ(sims("sum-threshold", {0.3, -0.3}), 0.0);  // strictly greater than T
  EXPECT_EQ(sims("sum-threshold", {-0.5, 0.2}), 0.0);
  EXPECT_EQ(sims("sum-threshold", {0.3, 0.3}, {0.5}), 1.0);
  EXPECT_EQ(sims("sum-threshold", {0.2, 0.2}, {0.5}), 0.0);
  EXPECT_EQ(sims("sum-threshold", {5, 5}), 1.0);  // a step, not the sum
  EXPECT_EQ(sims("greater-than", {0.5, 0.4}), 1.0);
  EXPECT_EQ(sims("greater-than", {0.4, 0.4}), 0.0);
  EXPECT_EQ(sims("greater-than", {-1, 0}), 0.0);
  EXPECT_EQ(sims("sign-of", {2.5}), 1.0);
  EXPECT_EQ(sims("sign-of", {-0.1}), -1.0);
  EXPECT_EQ(sims("sign-of", {0.0}), 0.0);
  EXPECT_EQ(sims("min", {0.2, -0.7}), -0.7);
  EXPECT_EQ(sims("max", {0.2, -0.7}), 0.2);
  EXPECT_EQ(sims("abs", {-3.5}), 3.5);
  EXPECT_EQ(sims("abs", {2}), 2.0);
}

TEST(Sims1994, IfAndInterpolate) {
  EXPECT_EQ(sims("if", {0.1, 2, 3}), 2.0);
  EXPECT_EQ(sims("if", {0.0, 2, 3}), 3.0);
  EXPECT_EQ(sims("if", {-1, 2, 3}), 3.0);
  EXPECT_DOUBLE_EQ(sims("interpolate", {0.25, 1, 3}), 1.5);
  EXPECT_DOUBLE_EQ(sims("interpolate", {0.5, -1, 1}), 0.0);
  EXPECT_DOUBLE_EQ(sims("interpolate", {-1, 1, 3}), 1.0);  // a clamped to 0
  EXPECT_DOUBLE_EQ(sims("interpolate", {2, 1, 3}), 3.0);   // a clamped to 1
}

TEST(Sims1994, Transcendental) {
  EXPECT_DOUBLE_EQ(sims("sin", {0.7}), std::sin(0.7));
  EXPECT_DOUBLE_EQ(sims("cos", {0.7}), std::cos(0.7));
  EXPECT_DOUBLE_EQ(sims("atan", {-2}), std::atan(-2.0));
  EXPECT_DOUBLE_EQ(sims("log", {std::exp(2.0)}), 2.0);
  EXPECT_DOUBLE_EQ(sims("log", {-std::exp(1.0)}), 1.0);  // log |a|
  EXPECT_EQ(sims("log", {0.0}), 0.0);
  EXPECT_EQ(sims("log", {1e-10}), 0.0);
  EXPECT_DOUBLE_EQ(sims("log", {1e-6}), std::log(1e-6));
  EXPECT_DOUBLE_EQ(sims("expt", {1}), std::exp(1.0));
  EXPECT_DOUBLE_EQ(sims("expt", {-3}), std::exp(-3.0));
  EXPECT_DOUBLE_EQ(sims("expt", {5}), std::exp(5.0));
  EXPECT_DOUBLE_EQ(sims("expt", {7}), 1000);    // e^7 = 1096.6, clamped
  EXPECT_DOUBLE_EQ(sims("expt", {1e6}), 1000);  // capped at e^20, then clamped
  EXPECT_DOUBLE_EQ(sims("sigmoid", {0}), 0.5);
  EXPECT_DOUBLE_EQ(sims("sigmoid", {2}), 1 / (1 + std::exp(-2.0)));
  EXPECT_EQ(sims("sigmoid", {-1000}), 0.0);
  EXPECT_EQ(sims("sigmoid", {1000}), 1.0);
}

TEST(Sims1994, IntegrateOverKnownSteps) {
  Neuron n(kSims, "integrate");
  EXPECT_DOUBLE_EQ(n({1}, 0.0, 0.1), 0.1);
  EXPECT_DOUBLE_EQ(n({1}, 0.1, 0.1), 0.2);
  EXPECT_DOUBLE_EQ(n({2}, 0.2, 0.1), 0.4);
  EXPECT_DOUBLE_EQ(n({-4}, 0.3, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(n({0.5}, 0.4, 0.5), 0.25);
  // held inside the output range, so it comes back at once
  Neuron w(kSims, "integrate");
  EXPECT_DOUBLE_EQ(w({1000}, 0, 10), 1000);
  EXPECT_DOUBLE_EQ(w({1000}, 0, 10), 1000);
  EXPECT_DOUBLE_EQ(w({-1}, 0, 1), 999);
}

TEST(Sims1994, Differentiate) {
  Neuron n(kSims, "differentiate");
  EXPECT_EQ(n({1}, 0.0, 0.5), 0.0);  // no previous input yet
  EXPECT_DOUBLE_EQ(n({3}, 0.5, 0.5), 4.0);
  EXPECT_DOUBLE_EQ(n({3}, 1.0, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(n({2}, 1.5, 0.25), -4.0);
  // a first input of 0 still counts as a previous value
  Neuron z(kSims, "differentiate");
  EXPECT_EQ(z({0}, 0, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(z({0.1}, 0.1, 0.1), 1.0);
}

TEST(Sims1994, Smooth) {
  Neuron n(kSims, "smooth", {0.5});
  EXPECT_DOUBLE_EQ(n({1}), 0.5);
  EXPECT_DOUBLE_EQ(n({1}), 0.75);
  EXPECT_DOUBLE_EQ(n({0}), 0.375);
  Neuron d(kSims, "smooth");  // rate 0.1
  EXPECT_DOUBLE_EQ(d({1}), 0.1);
  EXPECT_DOUBLE_EQ(d({1}), 0.19);
  Neuron one(kSims, "smooth", {1.0});  // rate 1 follows its input
  EXPECT_DOUBLE_EQ(one({-0.3}), -0.3);
  EXPECT_DOUBLE_EQ(one({0.8}), 0.8);
}

TEST(Sims1994, MemoryLatch) {
  Neuron n(kSims, "memory");
  EXPECT_EQ(n({0.9, 0}), 0.0);  // nothing stored yet
  EXPECT_EQ(n({0.7, 1}), 0.7);
  EXPECT_EQ(n({0.2, 0}), 0.7);
  EXPECT_EQ(n({0.2, -1}), 0.7);
  EXPECT_EQ(n({-0.4, 0.5}), -0.4);
  EXPECT_EQ(n({5, 0}), -0.4);
}

TEST(Sims1994, OscillateWave) {
  Neuron n(kSims, "oscillate-wave");  // 1 Hz, phase 0
  EXPECT_NEAR(n({0}, 0.0), 0.0, 1e-12);
  EXPECT_NEAR(n({0}, 0.25), 1.0, 1e-12);
  EXPECT_NEAR(n({0}, 0.5), 0.0, 1e-12);
  EXPECT_NEAR(n({0}, 0.75), -1.0, 1e-12);
  for (double t : {0.1, 0.37, 0.8})  // period 1 s
    EXPECT_NEAR(n({0}, t), n({0}, t + 1.0), 1e-12);
  EXPECT_NEAR(n({1}, 0.125), 1.0, 1e-12);  // input adds to the frequency: 2 Hz
  Neuron p(kSims, "oscillate-wave", {0.5, kPi / 2});
  EXPECT_NEAR(p({0}, 0.0), 1.0, 1e-12);
  EXPECT_NEAR(p({0}, 1.0), -1.0, 1e-12);  // half a period at 0.5 Hz
  for (double t : {0.1, 0.6})             // period 2 s
    EXPECT_NEAR(p({0}, t), p({0}, t + 2.0), 1e-12);
  Neuron still(kSims, "oscillate-wave", {0.0, 0.3});
  EXPECT_NEAR(still({0}, 7.0), std::sin(0.3), 1e-12);
}

TEST(Sims1994, OscillateSaw) {
  Neuron n(kSims, "oscillate-saw");  // 1 Hz, phase 0
  EXPECT_NEAR(n({0}, 0.0), 0.0, 1e-12);
  EXPECT_NEAR(n({0}, 0.25), 0.5, 1e-12);
  EXPECT_NEAR(n({0}, 0.49), 0.98, 1e-9);
  EXPECT_NEAR(n({0}, 0.51), -0.98, 1e-9);  // the drop at half period
  EXPECT_NEAR(n({0}, 0.75), -0.5, 1e-12);
  for (double t : {0.1, 0.37, 0.8})
    EXPECT_NEAR(n({0}, t), n({0}, t + 1.0), 1e-9);
  for (double t = 0; t < 3; t += 0.013) {
    double v = n({0.3}, t);
    EXPECT_GE(v, -1.0);
    EXPECT_LE(v, 1.0);
  }
  Neuron p(kSims, "oscillate-saw", {1.0, kPi / 2});
  EXPECT_NEAR(p({0}, 0.0), 0.5, 1e-12);
  EXPECT_NEAR(n({1}, 0.125), 0.5, 1e-12);  // 2 Hz
}

TEST(Sims1994, NonFiniteBecomesZero) {
  EXPECT_EQ(sims("sum", {kInf, 0}), 0.0);
  EXPECT_EQ(sims("sum", {kNaN, 1}), 0.0);
  EXPECT_EQ(sims("product", {kInf, 0}), 0.0);
  EXPECT_EQ(sims("sin", {kInf}), 0.0);
  EXPECT_EQ(sims("abs", {-kInf}), 0.0);
  EXPECT_EQ(sims("divide", {kNaN, 2}), 0.0);
  Neuron i(kSims, "integrate");
  EXPECT_DOUBLE_EQ(i({1}, 0, 1), 1.0);
  EXPECT_EQ(i({kNaN}, 0, 1), 0.0);  // and the integral restarts from 0
  EXPECT_DOUBLE_EQ(i({1}, 0, 1), 1.0);
  Neuron d(kSims, "differentiate");
  d({1}, 0, 0.1);
  EXPECT_EQ(d({2}, 0.1, 0.0), 0.0);  // dt = 0
}

// --- chaumont2007 ----------------------------------------------------------

TEST(Chaumont2007, SumT) {
  EXPECT_DOUBLE_EQ(chau("sumT", {0.3, 0.2}), 0.5);
  EXPECT_DOUBLE_EQ(chau("sumT", {0.3, -0.3}), 0.0);
  EXPECT_EQ(chau("sumT", {-0.3, 0.1}), 0.0);  // below T = 0
  EXPECT_DOUBLE_EQ(chau("sumT", {-0.2, -0.2}, {-0.5}), -0.4);
  EXPECT_EQ(chau("sumT", {-0.3, -0.3}, {-0.5}), 0.0);
  EXPECT_DOUBLE_EQ(chau("sumT", {0.25, 0.25}, {0.5}), 0.5);  // a+b >= T: equal passes
  EXPECT_EQ(chau("sumT", {0.2, 0.2}, {0.5}), 0.0);
  EXPECT_EQ(chau("sumT", {0.8, 0.9}), 1.0);  // clamped
}

TEST(Chaumont2007, Div) {
  EXPECT_EQ(chau("div", {0.5, 0.0}), 1.0);
  EXPECT_EQ(chau("div", {0.5, 0.001}), 1.0);  // b <= eps
  EXPECT_EQ(chau("div", {0.5, -0.5}), 1.0);   // literal Table I: b <= eps, not |b|
  EXPECT_EQ(chau("div", {-0.5, -1}), 1.0);
  EXPECT_DOUBLE_EQ(chau("div", {0.2, 0.5}), 0.4);
  EXPECT_DOUBLE_EQ(chau("div", {-0.1, 0.4}), -0.25);
  EXPECT_EQ(chau("div", {0.9, 0.3}), 1.0);    // 3, clamped
  EXPECT_EQ(chau("div", {-0.9, 0.3}), -1.0);  // -3, clamped
  EXPECT_EQ(chau("div", {0.2, 0.5}, {0.5}), 1.0);
  EXPECT_DOUBLE_EQ(chau("div", {0.2, 0.6}, {0.5}), 0.2 / 0.6);
}

TEST(Chaumont2007, MemDelaysExactlyNSteps) {
  Neuron one(kChau, "mem");  // n = 1
  EXPECT_EQ(one({0.5}), 0.0);
  EXPECT_EQ(one({-0.25}), 0.5);
  EXPECT_EQ(one({0.0}), -0.25);

  Neuron three(kChau, "mem", {3});
  const std::vector<double> in = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7};
  const std::vector<double> want = {0, 0, 0, 0.1, 0.2, 0.3, 0.4};
  for (std::size_t k = 0; k < in.size(); ++k) EXPECT_EQ(three({in[k]}), want[k]) << "step " << k;

  // the catapult release: a pulse appears exactly 30 steps later
  Neuron thirty(kChau, "mem", {30});
  ASSERT_EQ(thirty.state.size(), 31u);
  for (int k = 0; k < 65; ++k) {
    double out = thirty({k == 0 || k == 31 ? 1.0 : 0.0});
    EXPECT_EQ(out, (k == 30 || k == 61) ? 1.0 : 0.0) << "step " << k;
  }

  Neuron clamp(kChau, "mem", {1});
  clamp({4.0});
  EXPECT_EQ(clamp({0}), 1.0);
}

TEST(Chaumont2007, WavAtKnownTimes) {
  Neuron n(kChau, "wav");
  EXPECT_DOUBLE_EQ(n({2, 0.5, 0.3}, 0.4), 0.5 * std::sin(2 * 0.4 + 0.3));
  EXPECT_DOUBLE_EQ(n({2, 0.5, 0.3}, 0.0), 0.5 * std::sin(0.3));
  EXPECT_NEAR(n({kPi, -1, 0}, 0.5), -1.0, 1e-12);
  EXPECT_EQ(n({1, 0, 1}, 3.0), 0.0);               // amplitude 0
  EXPECT_EQ(n({0, 3, kPi / 2}, 1.0), 1.0);          // 3, clamped
  EXPECT_EQ(n({0, -3, kPi / 2}, 1.0), -1.0);
  EXPECT_DOUBLE_EQ(n({0.5, 0.8}, 2.0), 0.8 * std::sin(1.0));  // missing c reads 0
}

TEST(Chaumont2007, MulSumCst) {
  EXPECT_DOUBLE_EQ(chau("mul", {0.5, -0.6}), -0.3);
  EXPECT_EQ(chau("mul", {2, 3}), 1.0);
  EXPECT_DOUBLE_EQ(chau("sum", {0.5, -0.6}), -0.1);
  EXPECT_EQ(chau("sum", {0.7, 0.6}), 1.0);
  EXPECT_EQ(chau("sum", {-0.7, -0.6}), -1.0);
  EXPECT_DOUBLE_EQ(chau("sum", {0.4}), 0.4);  // missing b reads 0
  EXPECT_EQ(chau("cst", {}, {0.3}), 0.3);
  EXPECT_EQ(chau("cst", {}), 0.0);
  EXPECT_EQ(chau("cst", {}, {4}), 1.0);
}

TEST(Chaumont2007, OutputsStayInUnitRange) {
  for (const NeuronFnSpec& f : all_neuron_fns()) {
    if (f.set != kChau) continue;
    Neuron n(kChau, f.name);
    for (double x : {-50.0, -3.0, -1.0, 0.0, 0.7, 2.0, 90.0})
      for (double t : {0.0, 0.3, 11.0}) {
        double v = n({x, -x * 1.5, x * 0.5}, t);
        EXPECT_GE(v, -1.0) << f.name;
        EXPECT_LE(v, 1.0) << f.name;
      }
  }
}

TEST(Chaumont2007, NonFiniteBecomesZero) {
  EXPECT_EQ(chau("sum", {kNaN, 0.5}), 0.0);
  EXPECT_EQ(chau("mul", {kInf, 0}), 0.0);
  EXPECT_EQ(chau("div", {kInf, 0.5}), 0.0);
  EXPECT_EQ(chau("sumT", {kInf, 0}), 0.0);
  Neuron w(kChau, "wav");
  EXPECT_EQ(w({kInf, 1, 0}, 1.0), 0.0);
  Neuron m(kChau, "mem");
  m({kNaN});
  EXPECT_EQ(m({0}), 0.0);
}

// --- miconi2006 ------------------------------------------------------------

TEST(Miconi2006, TableGains) {
  Neuron s(kMico, "sigmoid"), t(kMico, "tanh");
  EXPECT_DOUBLE_EQ(s({0}), 0.5);
  EXPECT_DOUBLE_EQ(s({1}), 1 / (1 + std::exp(-3.0)));
  EXPECT_DOUBLE_EQ(s({-0.4}), 1 / (1 + std::exp(1.2)));
  EXPECT_DOUBLE_EQ(t({0.5}), std::tanh(1.0));
  EXPECT_DOUBLE_EQ(t({-0.3}), std::tanh(-0.6));
  EXPECT_EQ(t({0}), 0.0);
  EXPECT_EQ(s({1e6}), 1.0);
  EXPECT_EQ(s({-1e6}), 0.0);
  EXPECT_EQ(t({-1e6}), -1.0);
  EXPECT_EQ(s({kNaN}), 0.0);
  EXPECT_EQ(t({kNaN}), 0.0);
}

// --- effectors -------------------------------------------------------------

TEST(EffectorSignal, TanhForMiconiClampOtherwise) {
  EXPECT_DOUBLE_EQ(effector_signal(kMico, 0.5), std::tanh(0.5));
  EXPECT_DOUBLE_EQ(effector_signal(kMico, -2.0), std::tanh(-2.0));
  EXPECT_DOUBLE_EQ(effector_signal(kMico, 0.0), 0.0);
  for (NeuronSetId set : {kSims, kChau}) {
    EXPECT_EQ(effector_signal(set, 0.5), 0.5);
    EXPECT_EQ(effector_signal(set, -0.25), -0.25);
    EXPECT_EQ(effector_signal(set, 2.0), 1.0);
    EXPECT_EQ(effector_signal(set, -7.0), -1.0);
  }
  for (NeuronSetId set : {kSims, kChau, kMico}) {
    EXPECT_EQ(effector_signal(set, kNaN), 0.0);
    EXPECT_EQ(effector_signal(set, kInf), 0.0);
    EXPECT_EQ(effector_signal(set, -kInf), 0.0);
  }
}

// --- lessin2015 ------------------------------------------------------------

double less(std::string_view name, std::vector<double> args, std::vector<double> params = {}) {
  return Neuron(kLess, name, std::move(params))(std::move(args));
}

TEST(Lessin2015, ArithmeticHeldInZeroToOne) {
  EXPECT_DOUBLE_EQ(less("complement", {0.3}), 0.7);
  EXPECT_DOUBLE_EQ(less("complement", {1.4}), 0.0);  // held at 0
  EXPECT_DOUBLE_EQ(less("constant", {}), 0.5);
  EXPECT_DOUBLE_EQ(less("constant", {}, {0.2}), 0.2);
  EXPECT_NEAR(less("scale", {0.2}, {3}), 0.6, 1e-15);
  EXPECT_DOUBLE_EQ(less("scale", {0.5}, {3}), 1.0);
  EXPECT_DOUBLE_EQ(less("multiply", {0.5, 0.4}), 0.2);
  EXPECT_DOUBLE_EQ(less("divide", {0.2, 0.5}), 0.4);
  EXPECT_DOUBLE_EQ(less("divide", {0.2, 0.0}), 1.0);      // by eps: held at 1
  EXPECT_DOUBLE_EQ(less("divide", {0.0, 0.0}), 0.0);
  EXPECT_DOUBLE_EQ(less("sum", {0.25, 0.5}), 0.75);
  EXPECT_DOUBLE_EQ(less("sum", {0.75, 0.5}), 1.0);
  EXPECT_DOUBLE_EQ(less("difference", {0.75, 0.5}), 0.25);
  EXPECT_DOUBLE_EQ(less("difference", {0.5, 0.75}), 0.0);  // no negative outputs
  EXPECT_DOUBLE_EQ(less("absolute-difference", {0.5, 0.75}), 0.25);
  EXPECT_DOUBLE_EQ(less("threshold", {0.5}), 1.0);  // at T: on
  EXPECT_DOUBLE_EQ(less("threshold", {0.49}), 0.0);
  EXPECT_DOUBLE_EQ(less("threshold", {0.3}, {0.2}), 1.0);
  EXPECT_DOUBLE_EQ(less("switch", {0.2, 0.9, 0.0}), 0.2);  // c < 0.5: a
  EXPECT_DOUBLE_EQ(less("switch", {0.2, 0.9, 0.5}), 0.9);  // c >= 0.5: b
  EXPECT_DOUBLE_EQ(less("sigma", {0.3}), 0.3);              // its weighted sum (+ bias)
  EXPECT_DOUBLE_EQ(less("sigma", {-2.0}), 0.0);
  EXPECT_DOUBLE_EQ(less("sigma", {}), 0.0);  // no inputs: off
}

TEST(Lessin2015, SinusoidalSwingsBetweenZeroAndOneAtItsFrequency) {
  Neuron n(kLess, "sinusoidal", {2.0, 0.0});  // 2 Hz
  EXPECT_NEAR(n({}, 0.0), 0.5, 1e-12);
  EXPECT_NEAR(n({}, 0.125), 1.0, 1e-12);  // a quarter period
  EXPECT_NEAR(n({}, 0.375), 0.0, 1e-12);
  EXPECT_NEAR(n({}, 0.5), 0.5, 1e-12);
  Neuron shifted(kLess, "sinusoidal", {2.0, kPi / 2});
  EXPECT_NEAR(shifted({}, 0.0), 1.0, 1e-12);
}

TEST(Lessin2015, DerivativeReadsHalfForNoChange) {
  Neuron n(kLess, "derivative", {2.0});  // gain 2 s
  const double dt = 0.01;
  EXPECT_DOUBLE_EQ(n({0.3}, 0, dt), 0.5);  // first step: no previous input
  // a rise of 0.001 per step is 0.1/s: 0.5 + 0.5 x 2 x 0.1
  EXPECT_NEAR(n({0.301}, dt, dt), 0.6, 1e-9);
  EXPECT_NEAR(n({0.300}, 2 * dt, dt), 0.4, 1e-9);
  EXPECT_DOUBLE_EQ(n({0.9}, 3 * dt, dt), 1.0);  // 60/s: held at 1
  EXPECT_DOUBLE_EQ(n({0.9}, 4 * dt, dt), 0.5);
}

TEST(Lessin2015, DelayGivesTheInputOfNStepsAgo) {
  Neuron n(kLess, "delay", {3});
  std::vector<double> out;
  for (double x : {0.1, 0.2, 0.3, 0.4, 0.5, 1.7}) out.push_back(n({x}));
  EXPECT_EQ(out, (std::vector<double>{0, 0, 0, 0.1, 0.2, 0.3}));
  EXPECT_DOUBLE_EQ(n({0}), 0.4);
  EXPECT_DOUBLE_EQ(n({0}), 0.5);
  EXPECT_DOUBLE_EQ(n({0}), 1.0);  // stored held at 1
}

TEST(Lessin2015, EveryOutputIsFiniteAndInZeroToOne) {
  // III-C: "always in the range [0,1]", whatever reaches a node
  const std::vector<double> values = {-1e300, -3, -0.5, 0, 1e-300, 0.25, 0.5, 1, 2.5, 1e300, kInf, -kInf, kNaN};
  for (std::string_view name : neuron_fn_names(kLess)) {
    Neuron n(kLess, name);
    int k = 0;
    for (double a : values)
      for (double b : {0.0, 0.5, -2.0, kNaN})
        for (double c : {0.0, 1.0}) {
          const double y = n({a, b, c}, 0.01 * k, 0.01);
          ++k;
          EXPECT_TRUE(std::isfinite(y) && y >= 0 && y <= 1) << name << "(" << a << ", " << b << ", " << c << ") = " << y;
        }
  }
}

TEST(Lessin2015, AnEffectorsSignalIsAnActivationInZeroToOne) {
  EXPECT_DOUBLE_EQ(effector_signal(kLess, 0.3), 0.3);
  EXPECT_DOUBLE_EQ(effector_signal(kLess, -0.3), 0.0);
  EXPECT_DOUBLE_EQ(effector_signal(kLess, 4), 1.0);
  EXPECT_DOUBLE_EQ(effector_signal(kLess, kNaN), 0.0);
  EXPECT_DOUBLE_EQ(effector_signal(kChau, -0.3), -0.3);  // the other sets keep [-1, 1]
}

}  // namespace
}  // namespace bx
