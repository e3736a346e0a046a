// The fitness of the river crossing's pattern generator motif (Stanton &
// Channon 2015, "The Pattern Generator Network"): a three-neuron CTRNN is
// simulated for 10 s twice, once with a high input and once with none, and
// scored from the Fourier transform of its output neuron's signal: under
// input, how much of the signal's power lies at the target frequency (1 Hz)
// rather than at every other frequency; without input, how little power
// there is at all. It also decodes a float vector into a motif, so that the
// motif can be evolved as the paper's was, from a real-valued genotype.
// docs/rivercrossing.md ("The motif's fitness") gives the formula.
#pragma once

#include <span>
#include <vector>

#include "brain/river/pattern_generator.h"
#include "core/result.h"

namespace bx {

/// The constants of the motif's fitness. The defaults are the paper's where
/// it gives them (10 s runs, dt 0.01 s, 1 Hz).
struct MotifFitnessDef {
  double seconds = 10;   ///< each run's length (s); with dt, a whole number of steps
  double dt = 0.01;      ///< the Euler step (s), the controller's
  /// The "high input" into the input neuron during the first run. The paper
  /// gives no value. 1 is the most one PN output (a sigmoid, below 1) can
  /// put into a motif through one PG interconnection weight at the edge of
  /// the genome's [-1, 1] box, so it is a high input the controller can
  /// actually deliver.
  double high_input = 1;
  /// The frequency (Hz) to oscillate at under input. It must fall on a bin of
  /// the transform (a whole number of cycles in `seconds`) below the Nyquist
  /// frequency 1 / (2 dt).
  double target_hz = 1;
  /// The amplitude of the reference oscillation: a sine of this amplitude at
  /// the target scores full marks under input, a smaller one scores the
  /// square of its share of it, and without input a wobble of this amplitude
  /// scores nothing. 0.5 is half the output's range (-1, 1): through a motor
  /// weight of 1 it swings a motor neuron's sigmoid between 0.38 and 0.62.
  /// Demanding more would only reward squaring the wave toward +-1, whose
  /// harmonics the score penalises anyway.
  double amplitude = 0.5;
  friend bool operator==(const MotifFitnessDef&, const MotifFitnessDef&) = default;
};

/// An error naming the field and value if the def cannot score: a time or
/// step not above 0, `seconds` not a whole number of steps (to 1e-9) or
/// fewer than 4 of them, a target not on a bin of the transform or not
/// between 0 and the Nyquist frequency (exclusive), a non-finite input, an
/// amplitude not above 0.
Status check_motif_fitness_def(const MotifFitnessDef& d);

/// The parts of a motif's score; `fitness` is the number to maximise.
/// Powers are mean squares: a sine of amplitude a has power a^2 / 2, and a
/// signal's powers over every frequency sum to its variance.
struct MotifScore {
  /// Every output sample of both runs was finite. When false every other
  /// field is 0 (fitness the worst, 0).
  bool finite = true;
  double target_power = 0;  ///< under input: the power at the target frequency
  double other_power = 0;   ///< under input: the power at every other frequency
  double dominant_hz = 0;   ///< under input: the frequency of the largest power (0 if constant)
  double quiet_power = 0;   ///< without input: the output's power at all frequencies (its variance)
  double quiet_range = 0;   ///< without input: the output's largest minus its smallest sample
  double quiet_dominant_hz = 0;  ///< without input: the frequency of the largest power (0 if constant)
  double oscillation = 0;   ///< the input run's part of the fitness, in [0, 1]
  double quiescence = 0;    ///< the quiet run's part of the fitness, in [0, 1]
  double fitness = 0;       ///< oscillation * quiescence, in [0, 1]; higher is better
};

/// The output neuron's output after each of the `seconds / dt` Euler steps
/// of a motif started at rest, with `input` into its input neuron
/// throughout. `m` must pass check_motif.
std::vector<double> motif_trace(const Motif& m, double input, double seconds, double dt);

/// The one-sided power spectrum of `samples` after removing their mean, by a
/// plain discrete Fourier transform over exactly the samples given (no
/// padding, no window): entry k, for k = 0 .. n/2, is the power at k cycles
/// per n samples (k / seconds Hz for samples taken every dt over seconds).
/// With X_k = sum_t x_t e^(-2 pi i k t / n), the power is 2 |X_k|^2 / n^2,
/// except |X_k|^2 / n^2 at k = 0 and, for even n, at k = n / 2, so the
/// entries sum to the samples' variance. Samples whose variance is below
/// 1e-18 (constant to rounding) have no power at any frequency. Empty for
/// no samples.
std::vector<double> power_spectrum(std::span<const double> samples);

/// The motif's score and its parts under `d` (which must pass
/// check_motif_fitness_def); `m` must pass check_motif. Both runs start a
/// fresh motif at rest. With P_k the power spectrum of the output under the
/// high input, t the target's bin, P = sum_k P_k (the variance), Q the
/// variance of the output without input and R = amplitude^2 / 2:
///   oscillation = P_t / max(P, R)
///   quiescence  = max(0, 1 - sqrt(Q / R))
///   fitness     = oscillation * quiescence
/// A non-finite output sample in either run scores 0 with `finite` false.
MotifScore score_motif(const Motif& m, const MotifFitnessDef& d);

/// The score of two output signals as score_motif scores a motif's:
/// `driven` under the high input, `quiet` without input, each `seconds / dt`
/// samples taken every dt (d must pass check_motif_fitness_def). For
/// scoring a signal built by hand.
MotifScore score_motif_outputs(std::span<const double> driven, std::span<const double> quiet,
                               const MotifFitnessDef& d);

/// score_motif's fitness alone, without the dominant frequencies' full
/// transforms (the target's bin and the variances are all it needs): the
/// number to maximise when evolving a motif, in [0, 1].
double motif_fitness(const Motif& m, const MotifFitnessDef& d);

/// How a float vector decodes into a motif: every gene lies in [-1, 1] (the
/// box of the float vector genotype, genome/float_vector.h, so the
/// controller's own operators can evolve it) and maps onto a parameter's
/// range. Which neuron takes the input and which is read are fixed here,
/// not genes: the three neurons are interchangeable, so input 0 and output 2
/// stand for every choice of two different neurons, and a real-valued
/// genotype, as the paper's, keeps every gene continuous.
struct MotifGeneDef {
  double weight_max = 16;  ///< weights in [-weight_max, weight_max]
  double bias_max = 16;    ///< biases in [-bias_max, bias_max]
  /// Time constants (s) in [tau_min, tau_max] on a log scale: a gene moves
  /// tau by the same factor anywhere in the range. tau_min = 0.05 is 5 Euler
  /// steps of 0.01 s, so dt / tau stays at most 0.2 (Euler is stable below 2
  /// and does not overshoot below 1); tau_max = 2 is twice the target period.
  double tau_min = 0.05;
  double tau_max = 2;
  int input = 0;   ///< the neuron that takes the external input
  int output = 2;  ///< the neuron the motor neurons read
  friend bool operator==(const MotifGeneDef&, const MotifGeneDef&) = default;
};

/// An error naming the field and value if the def cannot decode: a
/// non-finite or non-positive range bound, tau_min above tau_max, a neuron
/// index outside 0..2.
Status check_motif_gene_def(const MotifGeneDef& d);

/// Genes in a motif: 9 weights, 3 time constants, 3 biases.
inline constexpr int kMotifGenes = kMotifNeurons * kMotifNeurons + 2 * kMotifNeurons;

/// How many genes motif_from_genes takes (15).
constexpr int motif_gene_count() { return kMotifGenes; }

/// The motif the genes stand for: genes 0-8 the weights, w[i][j] at 3 i + j
/// (row-major, receiving neuron first, as in the controller's genome), each
/// gene g giving g * weight_max; genes 9-11 the time constants tau[i], each
/// tau_min * (tau_max / tau_min)^((g + 1) / 2); genes 12-14 the biases
/// alpha[i], each g * bias_max; input and output from the def. An error
/// naming both counts for a wrong count, the gene and value for one outside
/// [-1, 1] or not finite, or the field of an invalid def.
Result<Motif> motif_from_genes(std::span<const double> genes, const MotifGeneDef& d);

}  // namespace bx
