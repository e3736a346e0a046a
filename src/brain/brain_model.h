// A creature's compiled brain: wiring and parameters in flat arrays (part of
// the immutable CreatureModel), and the per-evaluation state that changes.
#pragma once

#include <cstdint>
#include <vector>

#include "brain/neuron_set.h"

namespace bx {

/// The brain of one developed creature. Values are read from one array of
/// slots: [0, n_sensors) are sensor readings written by the simulation before
/// each brain step; [n_sensors, n_sensors + n_neurons) are neuron outputs.
/// All neurons update synchronously from the previous step's values.
struct BrainModel {
  NeuronSetId set = NeuronSetId::Sims1994;
  int n_sensors = 0;

  // neurons, in update order
  std::vector<NeuronFnId> fn;
  std::vector<double> bias;               ///< added to the weighted sum (WeightedSum fns)
  std::vector<std::uint32_t> param_begin; ///< size n_neurons + 1, into `params`
  std::vector<double> params;
  std::vector<std::uint32_t> state_begin; ///< size n_neurons + 1, into BrainState::state
  std::vector<std::uint32_t> input_begin; ///< size n_neurons + 1, into input_src/weight
  std::vector<std::int32_t> input_src;    ///< value slot, or -1 for "reads 0" (positional hole)
  std::vector<double> input_weight;
  /// Gates (lessin2015 IV-B, genome/encapsulate.h): per input, the value
  /// slot of the switch that scales it (w * value * switch), or -1 for none;
  /// empty when no input of the brain is gated (the plain loop runs).
  std::vector<std::int32_t> input_gate;

  // pandemonium groups (lessin2015 IV-C; brain/pandemonium.h): after each
  // step only the largest output of a group's members passes, the rest read
  // 0. Members are neuron indices (not value slots), in the group's order
  // (ties go to the first); a neuron belongs to one group at most, once.
  std::vector<std::uint32_t> group_begin;  ///< size n_groups + 1, into group_member; empty: no groups
  std::vector<std::int32_t> group_member;

  // effectors, in CreatureModel effector order
  std::vector<double> effector_bias;
  std::vector<std::uint32_t> effector_input_begin;  ///< size n_effectors + 1
  std::vector<std::int32_t> effector_input_src;
  std::vector<double> effector_input_weight;
  std::vector<std::int32_t> effector_input_gate;  ///< as input_gate, for effector inputs

  // task outputs (ControllerState::task_outputs: what the brain asks of the
  // task beside its effectors, e.g. a catapult's release, chaumont2007 4.1,
  // Fig. 4). Each is a latch: 0 until the first brain step its signal reaches
  // its threshold, 1 from then on. Its signal is the weighted sum of its
  // inputs clamped to [-1, 1], or the value of its floor slot when that is
  // higher (-1: no floor), computed from the same values as the effectors.
  std::vector<std::int32_t> task_output_floor;
  std::vector<double> task_output_threshold;
  std::vector<std::uint32_t> task_output_input_begin;  ///< size n_task_outputs + 1 (empty: none)
  std::vector<std::int32_t> task_output_input_src;
  std::vector<double> task_output_input_weight;

  /// Owning part of each neuron (-1: global), for viewers and lesion studies.
  std::vector<std::int32_t> neuron_part;

  int n_neurons() const { return static_cast<int>(fn.size()); }
  int n_effectors() const { return static_cast<int>(effector_bias.size()); }
  int n_groups() const { return group_begin.empty() ? 0 : static_cast<int>(group_begin.size()) - 1; }
  int n_values() const { return n_sensors + n_neurons(); }
  int n_task_outputs() const { return static_cast<int>(task_output_floor.size()); }
};

/// What changes in a brain during one evaluation.
struct BrainState {
  std::vector<double> values;  ///< current slot values (sensors then neurons)
  std::vector<double> next;    ///< scratch for the synchronous update
  std::vector<double> state;   ///< per-neuron internal state
  std::vector<double> effector_out;  ///< last effector signals, in [-1,1]
  std::vector<double> task_output_signal;  ///< each task output's last signal
  std::vector<double> task_out;            ///< each task output: 0, or 1 once fired
  double t = 0;                ///< brain time (s)
};

/// State for a fresh evaluation: all zeros.
BrainState make_brain_state(const BrainModel& m);

/// One brain step of length dt: every neuron computes from the current values
/// (sensor slots must already hold this step's readings), then all outputs are
/// published at once, each pandemonium group keeps only its largest output
/// (brain/pandemonium.h), and effector signals are recomputed.
void brain_step(const BrainModel& m, BrainState& s, double dt);

}  // namespace bx
