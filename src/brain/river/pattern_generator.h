// The river crossing's pattern generator (PG; Stanton & Channon 2015, "The
// Pattern Generator Network" and "Neuromotor Controllers"): five copies of
// one pre-evolved three-neuron CTRNN motif, each driven through the PG
// interconnection weights by the physical network's outputs, and 12 motor
// neurons, each a sigmoid of a weighted sum of the motifs' output neurons.
// The body maps a motor neuron's value in (0, 1) to its joint's PD target.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "brain/river/dense_layer.h"
#include "core/result.h"

namespace bx {

/// Neurons in one motif.
inline constexpr int kMotifNeurons = 3;

/// One motif's parameters, evolved beforehand to oscillate at 1 Hz under
/// input and rest without it; every copy in a PG shares them.
struct Motif {
  /// w[i][j]: the weight from neuron j's output into neuron i (eq. 5; j = i
  /// is a self-connection).
  std::array<std::array<double, kMotifNeurons>, kMotifNeurons> w{};
  std::array<double, kMotifNeurons> tau{1, 1, 1};  ///< time constants (s), > 0
  std::array<double, kMotifNeurons> alpha{};       ///< biases (eq. 6)
  int input = 0;   ///< the neuron whose eq. 5 sum takes the external input
  int output = 0;  ///< the neuron the motor neurons read
  friend bool operator==(const Motif&, const Motif&) = default;
};

/// An error naming the field and value if a motif cannot run: a non-finite
/// weight or bias, a time constant not above 0, a neuron index outside 0..2.
Status check_motif(const Motif& m);

/// One motif's neurons during an evaluation: leaky integrators, as printed
/// in the paper,
///   tau_i dA_i/dt = -A_i + sum_j w_ij O_j + I_i   (eq. 5; I only into the
///                                                   input neuron)
///   O_i = tanh((alpha_i - A_i) / 2)                 (eq. 6)
/// integrated by forward Euler.
class CtrnnMotif {
 public:
  /// At rest: every activation 0, every output eq. 6 of it.
  explicit CtrnnMotif(const Motif& m);

  /// One Euler step of `dt` seconds with external input `input`: first every
  /// neuron's new activation from the old outputs (eq. 5), then every output
  /// from the new activations (eq. 6).
  void step(double input, double dt);

  /// Activations A, by neuron.
  std::span<const double> activations() const { return a_; }
  /// Outputs O, by neuron.
  std::span<const double> outputs() const { return o_; }
  /// The output neuron's output.
  double output() const { return o_[static_cast<std::size_t>(m_.output)]; }

 private:
  Motif m_;
  std::array<double, kMotifNeurons> a_{};
  std::array<double, kMotifNeurons> o_{};
};

/// The motifs and motor neurons during an evaluation.
class PatternGenerator {
 public:
  /// `motif_input` (the genome's PG interconnection weights) is motifs x
  /// motifs: at(m, k) weighs PN output k into motif m's input neuron.
  /// `motor` is motors x motifs: at(j, m) weighs motif m's output into motor
  /// neuron j. Motors start from the motifs' resting outputs.
  PatternGenerator(const Motif& motif, WeightMatrix motif_input, WeightMatrix motor);

  /// One step of `dt` seconds driven by the PN's outputs (one per motif):
  /// each motif's external input, one Euler step of every motif, then the
  /// motor neurons from the motifs' new outputs.
  void step(std::span<const double> pn_outputs, double dt);

  /// How many motifs.
  int n_motifs() const { return static_cast<int>(motifs_.size()); }
  /// Motif m.
  const CtrnnMotif& motif(int m) const { return motifs_[static_cast<std::size_t>(m)]; }
  /// The last external input into each motif's input neuron (0 before the
  /// first step).
  std::span<const double> motif_inputs() const { return motif_input_values_; }
  /// Each motif's output neuron's output.
  std::span<const double> outputs() const { return outputs_; }
  /// Each motor neuron's value in (0, 1), which the body maps to a target
  /// angle within its joint's range.
  std::span<const double> motors() const { return motors_; }

 private:
  void update_motors();

  WeightMatrix motif_input_;
  WeightMatrix motor_;
  std::vector<CtrnnMotif> motifs_;
  std::vector<double> motif_input_values_;
  std::vector<double> outputs_;
  std::vector<double> motors_;
};

}  // namespace bx
