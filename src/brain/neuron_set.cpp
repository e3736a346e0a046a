// Neuron function sets: the table of every function and its evaluation.
// Definitions, and the choices made where a paper is silent, are listed in
// docs/neurons.md; keep the two in step.
#include "brain/neuron_set.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace bx {
namespace {

// Dense ids, in table order: sims1994, chaumont2007, miconi2006, lessin2015.
// eval_neuron switches on these; all_neuron_fns() places each spec at its id.
enum Fn : NeuronFnId {
  // sims1994
  kSum,
  kProduct,
  kDivide,
  kSumThreshold,
  kGreaterThan,
  kSignOf,
  kMin,
  kMax,
  kAbs,
  kIf,
  kInterpolate,
  kSin,
  kCos,
  kAtan,
  kLog,
  kExpt,
  kSigmoid,
  kIntegrate,
  kDifferentiate,
  kSmooth,
  kMemory,
  kOscWave,
  kOscSaw,
  // chaumont2007
  kCSumT,
  kCDiv,
  kCMem,
  kCWav,
  kCMul,
  kCSum,
  kCCst,
  // miconi2006
  kMSigmoid,
  kMTanh,
  // lessin2015
  kLSinusoidal,
  kLComplement,
  kLConstant,
  kLScale,
  kLMultiply,
  kLDivide,
  kLSum,
  kLDifference,
  kLDerivative,
  kLThreshold,
  kLSwitch,
  kLDelay,
  kLAbsDifference,
  kLSigma,
  kFnCount
};

constexpr double kSimsBound = 1e3;     // sims1994 outputs are clamped to +-this
constexpr double kTiny = 1e-9;         // sims1994 divide and log: |x| below this counts as 0
constexpr double kExptCap = 20;        // sims1994 expt: exp(min(a, 20))
constexpr int kMemMax = 1000;          // chaumont2007 mem, lessin2015 delay: longest delay (steps)
constexpr int kSigmaMaxInputs = 256;   // lessin2015 sigma: most inputs (an encapsulated skill's switch)
constexpr double kPi = std::numbers::pi;

/// Parameter i, or its default when the neuron carries fewer parameters.
inline double param(std::span<const double> p, std::size_t i, double dflt) {
  return i < p.size() ? p[i] : dflt;
}

/// Argument k, 0 when absent.
inline double arg(std::span<const double> a, std::size_t k) { return k < a.size() ? a[k] : 0.0; }

/// Non-finite -> 0, then clamp to [-bound, bound].
inline double finite_clamp(double x, double bound) {
  if (!std::isfinite(x)) return 0.0;
  return std::clamp(x, -bound, bound);
}

/// Delay length of a chaumont2007 mem neuron: parameter n rounded, in [1, 1000].
int mem_length(std::span<const double> params) {
  double n = param(params, 0, 1.0);
  if (!std::isfinite(n)) return 1;
  return static_cast<int>(std::lround(std::clamp(n, 1.0, double(kMemMax))));
}

/// Sawtooth in [-1, 1) with period 2*pi, 0 at phi = 0 and rising, like sin.
inline double sawtooth(double phi) {
  double u = phi / (2 * kPi) + 0.5;
  return 2 * (u - std::floor(u)) - 1;
}

/// A delay of n steps (chaumont2007 mem, lessin2015 delay): `state` is a ring
/// buffer of the n past inputs, then the write index; stores `in` and returns
/// the input of n steps ago (0 for the first n steps).
double delay_line(int n, std::span<double> state, double in) {
  assert(state.size() >= static_cast<std::size_t>(n) + 1);
  double& write = state[static_cast<std::size_t>(n)];
  auto k = static_cast<std::size_t>(write);
  if (k >= static_cast<std::size_t>(n)) k = 0;
  const double out = state[k];
  state[k] = in;
  write = static_cast<double>(k + 1 == static_cast<std::size_t>(n) ? 0 : k + 1);
  return out;
}

int state_none(std::span<const double>) { return 0; }
int state_one(std::span<const double>) { return 1; }
int state_two(std::span<const double>) { return 2; }
int state_mem(std::span<const double> p) { return mem_length(p) + 1; }

std::vector<NeuronFnSpec> build_table() {
  using S = NeuronSetId;
  using M = InputMode;
  std::vector<NeuronFnSpec> t(kFnCount);
  auto add = [&t](Fn id, S set, std::string_view name, M mode, int max_inputs,
                  std::vector<ParamSpec> params = {}, int (*state)(std::span<const double>) = state_none) {
    t[id] = NeuronFnSpec{id, set, name, mode, max_inputs, std::move(params), state};
  };
  const ParamSpec freq{"freq", 1.0, 0.0, 10.0};
  const ParamSpec phase{"phase", 0.0, -kPi, kPi};

  // sims1994: names from Sims 1994; definitions are ours (docs/neurons.md)
  add(kSum, S::Sims1994, "sum", M::Positional, 2);
  add(kProduct, S::Sims1994, "product", M::Positional, 2);
  add(kDivide, S::Sims1994, "divide", M::Positional, 2);
  add(kSumThreshold, S::Sims1994, "sum-threshold", M::Positional, 2, {{"T", 0.0, -2.0, 2.0}});
  add(kGreaterThan, S::Sims1994, "greater-than", M::Positional, 2);
  add(kSignOf, S::Sims1994, "sign-of", M::Positional, 1);
  add(kMin, S::Sims1994, "min", M::Positional, 2);
  add(kMax, S::Sims1994, "max", M::Positional, 2);
  add(kAbs, S::Sims1994, "abs", M::Positional, 1);
  add(kIf, S::Sims1994, "if", M::Positional, 3);
  add(kInterpolate, S::Sims1994, "interpolate", M::Positional, 3);
  add(kSin, S::Sims1994, "sin", M::Positional, 1);
  add(kCos, S::Sims1994, "cos", M::Positional, 1);
  add(kAtan, S::Sims1994, "atan", M::Positional, 1);
  add(kLog, S::Sims1994, "log", M::Positional, 1);
  add(kExpt, S::Sims1994, "expt", M::Positional, 1);
  add(kSigmoid, S::Sims1994, "sigmoid", M::Positional, 1);
  add(kIntegrate, S::Sims1994, "integrate", M::Positional, 1, {}, state_one);
  add(kDifferentiate, S::Sims1994, "differentiate", M::Positional, 1, {}, state_two);
  add(kSmooth, S::Sims1994, "smooth", M::Positional, 1, {{"rate", 0.1, 0.001, 1.0}}, state_one);
  add(kMemory, S::Sims1994, "memory", M::Positional, 2, {}, state_one);
  add(kOscWave, S::Sims1994, "oscillate-wave", M::Positional, 1, {freq, phase});
  add(kOscSaw, S::Sims1994, "oscillate-saw", M::Positional, 1, {freq, phase});

  // chaumont2007 Appendix Table I (sen and eff are a sensor and an effector, not neurons)
  add(kCSumT, S::Chaumont2007, "sumT", M::Positional, 2, {{"T", 0.0, -2.0, 2.0}});
  add(kCDiv, S::Chaumont2007, "div", M::Positional, 2, {{"eps", 0.001, 0.0, 1.0}});
  add(kCMem, S::Chaumont2007, "mem", M::Positional, 1, {{"n", 1.0, 1.0, double(kMemMax), true}},
      state_mem);
  add(kCWav, S::Chaumont2007, "wav", M::Positional, 3);
  add(kCMul, S::Chaumont2007, "mul", M::Positional, 2);
  add(kCSum, S::Chaumont2007, "sum", M::Positional, 2);
  add(kCCst, S::Chaumont2007, "cst", M::Positional, 0, {{"V", 0.0, -1.0, 1.0}});

  // miconi2006 section 3 and Table 1: McCulloch-Pitts, gains from Table 1
  add(kMSigmoid, S::Miconi2006, "sigmoid", M::WeightedSum, 3);
  add(kMTanh, S::Miconi2006, "tanh", M::WeightedSum, 3);

  // lessin2015 III-C: the names the paper lists; definitions are ours
  // (docs/neurons.md), every output in [0, 1]
  add(kLSinusoidal, S::Lessin2015, "sinusoidal", M::Positional, 0, {{"freq", 1.0, 0.0, 10.0}, phase});
  add(kLComplement, S::Lessin2015, "complement", M::Positional, 1);
  add(kLConstant, S::Lessin2015, "constant", M::Positional, 0, {{"V", 0.5, 0.0, 1.0}});
  add(kLScale, S::Lessin2015, "scale", M::Positional, 1, {{"k", 1.0, 0.0, 10.0}});
  add(kLMultiply, S::Lessin2015, "multiply", M::Positional, 2);
  add(kLDivide, S::Lessin2015, "divide", M::Positional, 2, {{"eps", 0.001, 1e-6, 1.0}});
  add(kLSum, S::Lessin2015, "sum", M::Positional, 2);
  add(kLDifference, S::Lessin2015, "difference", M::Positional, 2);
  add(kLDerivative, S::Lessin2015, "derivative", M::Positional, 1, {{"gain", 1.0, 0.01, 100.0}}, state_two);
  add(kLThreshold, S::Lessin2015, "threshold", M::Positional, 1, {{"T", 0.5, 0.0, 1.0}});
  add(kLSwitch, S::Lessin2015, "switch", M::Positional, 3);
  add(kLDelay, S::Lessin2015, "delay", M::Positional, 1, {{"n", 1.0, 1.0, double(kMemMax), true}}, state_mem);
  add(kLAbsDifference, S::Lessin2015, "absolute-difference", M::Positional, 2);
  // IV-B: the summation of zero or more inputs that switches an encapsulated skill
  add(kLSigma, S::Lessin2015, "sigma", M::WeightedSum, kSigmaMaxInputs);

  // every id filled, arities within brain_step's buffer
  for (std::size_t i = 0; i < t.size(); ++i) {
    assert(t[i].id == i && !t[i].name.empty());
    assert(t[i].max_inputs <= kMaxNeuronArity || t[i].mode == InputMode::WeightedSum);
  }
  return t;
}

// eval_neuron's per-set epilogues
inline double sims_out(double x) { return finite_clamp(x, kSimsBound); }
inline double chaumont_out(double x) { return finite_clamp(x, 1.0); }
inline double miconi_out(double x) { return std::isfinite(x) ? x : 0.0; }
inline double lessin_out(double x) { return std::isfinite(x) ? std::clamp(x, 0.0, 1.0) : 0.0; }

}  // namespace

const std::vector<NeuronFnSpec>& all_neuron_fns() {
  static const std::vector<NeuronFnSpec> table = build_table();
  return table;
}

const NeuronFnSpec* find_neuron_fn(NeuronSetId set, std::string_view name) {
  for (const NeuronFnSpec& f : all_neuron_fns())
    if (f.set == set && f.name == name) return &f;
  return nullptr;
}

std::vector<std::string_view> neuron_fn_names(NeuronSetId set) {
  std::vector<std::string_view> names;
  for (const NeuronFnSpec& f : all_neuron_fns())
    if (f.set == set) names.push_back(f.name);
  return names;
}

double eval_neuron(NeuronFnId fn, std::span<const double> args, std::span<const double> params,
                   std::span<double> state, NeuronClock clock) {
  const double a = arg(args, 0), b = arg(args, 1), c = arg(args, 2);
  switch (static_cast<Fn>(fn)) {
    // sims1994: stateless
    case kSum: return sims_out(a + b);
    case kProduct: return sims_out(a * b);
    case kDivide: return sims_out(std::abs(b) < kTiny ? 0.0 : a / b);
    case kSumThreshold: return sims_out(a + b > param(params, 0, 0.0) ? 1.0 : 0.0);
    case kGreaterThan: return sims_out(a > b ? 1.0 : 0.0);
    case kSignOf: return sims_out(a > 0 ? 1.0 : (a < 0 ? -1.0 : 0.0));
    case kMin: return sims_out(std::min(a, b));
    case kMax: return sims_out(std::max(a, b));
    case kAbs: return sims_out(std::abs(a));
    case kIf: return sims_out(a > 0 ? b : c);
    case kInterpolate: return sims_out(b + (c - b) * std::clamp(a, 0.0, 1.0));
    case kSin: return sims_out(std::sin(a));
    case kCos: return sims_out(std::cos(a));
    case kAtan: return sims_out(std::atan(a));
    case kLog: return sims_out(std::abs(a) < kTiny ? 0.0 : std::log(std::abs(a)));
    case kExpt: return sims_out(std::exp(std::min(a, kExptCap)));
    case kSigmoid: return sims_out(1.0 / (1.0 + std::exp(-a)));

    // sims1994: with state
    case kIntegrate: {
      // the integral is held inside the output range (no wind-up past it)
      assert(state.size() >= 1);
      state[0] = finite_clamp(state[0] + a * clock.dt, kSimsBound);
      return state[0];
    }
    case kDifferentiate: {
      // state: [previous input, has-previous flag]
      assert(state.size() >= 2);
      double d = state[1] != 0 ? (a - state[0]) / clock.dt : 0.0;
      state[0] = std::isfinite(a) ? a : 0.0;
      state[1] = 1;
      return sims_out(d);
    }
    case kSmooth: {
      assert(state.size() >= 1);
      state[0] = finite_clamp(state[0] + param(params, 0, 0.1) * (a - state[0]), kSimsBound);
      return state[0];
    }
    case kMemory: {
      assert(state.size() >= 1);
      if (b > 0) state[0] = finite_clamp(a, kSimsBound);
      return state[0];
    }
    case kOscWave:
    case kOscSaw: {
      double phi = 2 * kPi * (param(params, 0, 1.0) + a) * clock.t + param(params, 1, 0.0);
      return sims_out(fn == kOscWave ? std::sin(phi) : sawtooth(phi));
    }

    // chaumont2007, Table I; outputs in [-1, 1]
    case kCSumT: return chaumont_out(a + b >= param(params, 0, 0.0) ? a + b : 0.0);
    case kCDiv: return chaumont_out(b <= param(params, 0, 0.001) ? 1.0 : a / b);
    case kCMem: return delay_line(mem_length(params), state, chaumont_out(a));
    case kCWav: return chaumont_out(b * std::sin(a * clock.t + c));
    case kCMul: return chaumont_out(a * b);
    case kCSum: return chaumont_out(a + b);
    case kCCst: return chaumont_out(param(params, 0, 0.0));

    // miconi2006: args[0] = weighted sum + theta
    case kMSigmoid: return miconi_out(1.0 / (1.0 + std::exp(-3.0 * a)));
    case kMTanh: return miconi_out(std::tanh(2.0 * a));

    // lessin2015: every output in [0, 1] (III-C)
    case kLSinusoidal:
      return lessin_out(0.5 + 0.5 * std::sin(2 * kPi * param(params, 0, 1.0) * clock.t + param(params, 1, 0.0)));
    case kLComplement: return lessin_out(1.0 - a);
    case kLConstant: return lessin_out(param(params, 0, 0.5));
    case kLScale: return lessin_out(param(params, 0, 1.0) * a);
    case kLMultiply: return lessin_out(a * b);
    case kLDivide: return lessin_out(a / std::max(b, param(params, 0, 0.001)));
    case kLSum: return lessin_out(a + b);
    case kLDifference: return lessin_out(a - b);
    case kLDerivative: {
      // 0.5 is no change; a rise of 1/gain per second reads 1, a fall as fast 0.
      // state: [previous input, has-previous flag]
      assert(state.size() >= 2);
      double d = state[1] != 0 ? (a - state[0]) / clock.dt : 0.0;
      state[0] = std::isfinite(a) ? a : 0.0;
      state[1] = 1;
      return lessin_out(0.5 + 0.5 * param(params, 0, 1.0) * d);
    }
    case kLThreshold: return lessin_out(a >= param(params, 0, 0.5) ? 1.0 : 0.0);
    case kLSwitch: return lessin_out(c >= 0.5 ? b : a);
    case kLDelay: return delay_line(mem_length(params), state, lessin_out(a));  // as chaumont2007's mem
    case kLAbsDifference: return lessin_out(std::abs(a - b));
    case kLSigma: return lessin_out(a);  // args[0] = weighted sum + bias

    case kFnCount: break;
  }
  assert(false && "eval_neuron: unknown function id");
  return 0.0;
}

double effector_signal(NeuronSetId set, double x) {
  if (!std::isfinite(x)) return 0.0;
  if (set == NeuronSetId::Miconi2006) return std::tanh(x);
  if (set == NeuronSetId::Lessin2015) return std::clamp(x, 0.0, 1.0);
  return std::clamp(x, -1.0, 1.0);
}

}  // namespace bx
