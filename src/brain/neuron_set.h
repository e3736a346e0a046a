// Neuron function sets (docs/papers.md S0): the functions a dialect's neurons may
// compute, with their arity, parameters and per-neuron state. Pure functions
// of (inputs, params, state, time): no engine, no genome.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace bx {

/// The neuron sets Bestiary knows. Lessin2015's nodes output [0, 1] (III-C),
/// with the sigma node of encapsulation (IV-B).
enum class NeuronSetId { Sims1994, Chaumont2007, Miconi2006, Lessin2015 };

/// How a function consumes its inputs.
enum class InputMode {
  Positional,   ///< inputs are a, b, c... in order (weight multiplies each); missing read 0
  WeightedSum,  ///< one argument: sum of weighted inputs (McCulloch-Pitts; lessin2015's sigma)
};

/// A named parameter with its default and legal range (inclusive).
struct ParamSpec {
  std::string_view name;
  double default_value;
  double min;
  double max;
  bool integer = false;
};

/// Dense function id, unique across all sets (index into `all_neuron_fns()`).
using NeuronFnId = std::uint16_t;

/// Largest arity of any Positional function (brain_step gathers arguments
/// into a fixed array of this size).
inline constexpr int kMaxNeuronArity = 3;

/// Description of one neuron function.
struct NeuronFnSpec {
  NeuronFnId id;
  NeuronSetId set;
  std::string_view name;       ///< as written in genome files, e.g. "sumT", "oscillate-wave"
  InputMode mode;
  int max_inputs;              ///< Positional: arity; WeightedSum: most inputs allowed
  std::vector<ParamSpec> params;
  /// Doubles of per-neuron state needed, given the neuron's parameters.
  int (*state_size)(std::span<const double> params);
};

/// Every function of every set, indexed by NeuronFnId.
const std::vector<NeuronFnSpec>& all_neuron_fns();
/// The function named `name` in `set`, or nullptr.
const NeuronFnSpec* find_neuron_fn(NeuronSetId set, std::string_view name);
/// Names of the functions of one set, for error messages and docs.
std::vector<std::string_view> neuron_fn_names(NeuronSetId set);

/// Context of one brain step.
struct NeuronClock {
  double t;   ///< brain time at this step (s)
  double dt;  ///< brain step length (s)
};

/// Output of function `fn` given its arguments. For Positional functions
/// `args` holds the weighted inputs (missing ones are 0, `args.size()` equals
/// the arity); for WeightedSum functions `args` has one element, the weighted
/// sum plus the neuron's bias. `state` is the neuron's own state (zeroed at the
/// start of an evaluation), updated in place. The result is finite and, for
/// sets with a bounded range, inside it.
double eval_neuron(NeuronFnId fn, std::span<const double> args, std::span<const double> params,
                   std::span<double> state, NeuronClock clock);

/// Effector signal from the weighted input sum plus bias: tanh for
/// Miconi2006 (MaxSpeed*tanh(sigma+theta), MaxSpeed applied by the motor), a
/// clamp to [0, 1] for Lessin2015 (a muscle's activation: its set's range),
/// a clamp to [-1,1] for the other sets.
double effector_signal(NeuronSetId set, double weighted_sum_plus_bias);

}  // namespace bx
