// Brain runtime: a fresh state per evaluation, and one synchronous step.
// brain_step runs every physics step for every creature: it allocates
// nothing and reads the model's flat arrays in order.
#include <cassert>
#include <span>

#include "brain/brain_model.h"
#include "brain/pandemonium.h"

namespace bx {

BrainState make_brain_state(const BrainModel& m) {
  BrainState s;
  s.values.assign(m.n_values(), 0.0);
  s.next.assign(m.n_values(), 0.0);
  s.state.assign(m.state_begin.empty() ? 0 : m.state_begin.back(), 0.0);
  s.effector_out.assign(m.n_effectors(), 0.0);
  s.task_output_signal.assign(m.n_task_outputs(), 0.0);
  s.task_out.assign(m.n_task_outputs(), 0.0);
  s.t = 0;
  return s;
}

void brain_step(const BrainModel& m, BrainState& s, double dt) {
  const int n_neurons = m.n_neurons();
  const int n_sensors = m.n_sensors;
  assert(static_cast<int>(s.values.size()) == m.n_values());
  assert(static_cast<int>(s.next.size()) == m.n_values());
  assert(static_cast<int>(m.bias.size()) == n_neurons);
  assert(static_cast<int>(m.param_begin.size()) == n_neurons + 1 || n_neurons == 0);
  assert(static_cast<int>(m.state_begin.size()) == n_neurons + 1 || n_neurons == 0);
  assert(static_cast<int>(m.input_begin.size()) == n_neurons + 1 || n_neurons == 0);
  assert(static_cast<int>(s.effector_out.size()) == m.n_effectors());
  assert(static_cast<int>(s.task_out.size()) == m.n_task_outputs());
  assert(m.n_task_outputs() == 0 || m.task_output_input_begin.size() == m.task_output_floor.size() + 1);
  assert(m.task_output_threshold.size() == m.task_output_floor.size());

  const std::vector<NeuronFnSpec>& fns = all_neuron_fns();
  const NeuronClock clock{s.t, dt};
  const double* values = s.values.data();
  const bool gated = !m.input_gate.empty();

  // every neuron from the current values, into next
  for (int i = 0; i < n_neurons; ++i) {
    const NeuronFnSpec& f = fns[m.fn[i]];
    const std::uint32_t in_b = m.input_begin[i], in_e = m.input_begin[i + 1];
    double args[kMaxNeuronArity] = {};
    std::size_t n_args;
    if (f.mode == InputMode::WeightedSum) {
      // one argument: weighted sum plus bias
      double sum = m.bias[i];
      if (gated) {
        for (std::uint32_t j = in_b; j < in_e; ++j) {
          const std::int32_t src = m.input_src[j], gate = m.input_gate[j];
          if (src >= 0) sum += gate >= 0 ? m.input_weight[j] * values[src] * values[gate] : m.input_weight[j] * values[src];
        }
      } else {
        for (std::uint32_t j = in_b; j < in_e; ++j) {
          const std::int32_t src = m.input_src[j];
          if (src >= 0) sum += m.input_weight[j] * values[src];
        }
      }
      args[0] = sum;
      n_args = 1;
    } else {
      // positional: input k is argument k; holes and missing inputs read 0
      assert(f.max_inputs <= kMaxNeuronArity);
      n_args = static_cast<std::size_t>(f.max_inputs);
      const std::size_t n_in = in_e - in_b;
      const std::size_t used = n_in < n_args ? n_in : n_args;
      for (std::size_t k = 0; k < used; ++k) {
        const std::int32_t src = m.input_src[in_b + k];
        if (src >= 0) args[k] = m.input_weight[in_b + k] * values[src];
        if (src >= 0 && gated && m.input_gate[in_b + k] >= 0) args[k] *= values[m.input_gate[in_b + k]];
      }
    }
    const std::span<const double> params(m.params.data() + m.param_begin[i],
                                         m.param_begin[i + 1] - m.param_begin[i]);
    const std::span<double> state(s.state.data() + m.state_begin[i],
                                  m.state_begin[i + 1] - m.state_begin[i]);
    s.next[n_sensors + i] = eval_neuron(m.fn[i], std::span<const double>(args, n_args), params,
                                        state, clock);
  }

  // publish all neuron outputs at once (sensor slots belong to the simulation)
  for (int i = n_sensors; i < n_sensors + n_neurons; ++i) s.values[i] = s.next[i];

  // pandemonium: in each group only the largest output passes, before the
  // effectors (and the next step's neurons) read the values
  apply_pandemonium(m, s.values);

  // effectors from the updated values, so sensor->effector acts this step
  // (a gated input reads its switch in the same step: at 1 it passes the
  // wire exactly, w * v * 1 == w * v)
  const bool effectors_gated = !m.effector_input_gate.empty();
  for (int e = 0; e < m.n_effectors(); ++e) {
    double sum = m.effector_bias[e];
    const std::uint32_t b = m.effector_input_begin[e], end = m.effector_input_begin[e + 1];
    if (effectors_gated) {
      for (std::uint32_t j = b; j < end; ++j) {
        const std::int32_t src = m.effector_input_src[j], gate = m.effector_input_gate[j];
        if (src >= 0)
          sum += gate >= 0 ? m.effector_input_weight[j] * values[src] * values[gate] : m.effector_input_weight[j] * values[src];
      }
    } else {
      for (std::uint32_t j = b; j < end; ++j) {
        const std::int32_t src = m.effector_input_src[j];
        if (src >= 0) sum += m.effector_input_weight[j] * values[src];
      }
    }
    s.effector_out[e] = effector_signal(m.set, sum);
  }

  // task outputs: the clamped network sum or the floor, whichever is higher,
  // latched at the threshold
  for (int k = 0; k < m.n_task_outputs(); ++k) {
    double sum = 0;
    for (std::uint32_t j = m.task_output_input_begin[k]; j < m.task_output_input_begin[k + 1]; ++j) {
      const std::int32_t src = m.task_output_input_src[j];
      if (src >= 0) sum += m.task_output_input_weight[j] * values[src];
    }
    sum = sum < -1 ? -1 : (sum > 1 ? 1 : sum);
    const std::int32_t floor = m.task_output_floor[k];
    const double signal = floor >= 0 && values[floor] > sum ? values[floor] : sum;
    s.task_output_signal[k] = signal;
    if (signal >= m.task_output_threshold[k]) s.task_out[k] = 1;
  }

  s.t += dt;
}

}  // namespace bx
