// Dense layers for the river crossing's feed-forward stages (decision
// network, physical network, the pattern generator's input and motor
// weights): a weight matrix and the logistic sigmoid. No biases anywhere:
// the paper's genome lists only weights ("Genetic Representation").
#pragma once

#include <cassert>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace bx {

/// Weights from `cols` sources into `rows` receiving neurons, row-major:
/// at(r, c) is the weight from source c into neuron r. The weights into one
/// neuron are contiguous, which is also the order the genome lists them in
/// (river_genome.h).
struct WeightMatrix {
  int rows = 0;
  int cols = 0;
  std::vector<double> w;  ///< rows * cols weights; row r is [r * cols, (r + 1) * cols)

  WeightMatrix() = default;
  /// A rows x cols matrix of zeros.
  WeightMatrix(int rows, int cols)
      : rows(rows), cols(cols), w(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols), 0.0) {
    assert(rows >= 0 && cols >= 0);
  }

  /// The weight from source c into neuron r.
  double& at(int r, int c) {
    assert(r >= 0 && r < rows && c >= 0 && c < cols);
    return w[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c)];
  }
  /// The weight from source c into neuron r.
  double at(int r, int c) const {
    assert(r >= 0 && r < rows && c >= 0 && c < cols);
    return w[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c)];
  }

  /// Each neuron's weighted input sum: out[r] = sum over c of at(r, c) * in[c].
  void apply(std::span<const double> in, std::span<double> out) const {
    assert(static_cast<int>(in.size()) == cols && static_cast<int>(out.size()) == rows);
    const double* row = w.data();
    for (int r = 0; r < rows; ++r, row += cols) {
      double sum = 0;
      for (int c = 0; c < cols; ++c) sum += row[c] * in[static_cast<std::size_t>(c)];
      out[static_cast<std::size_t>(r)] = sum;
    }
  }
};

/// The logistic sigmoid 1 / (1 + e^-x), in (0, 1): the activation of the
/// physical network's outputs and of the motor neurons.
inline double logistic(double x) { return 1.0 / (1.0 + std::exp(-x)); }

}  // namespace bx
