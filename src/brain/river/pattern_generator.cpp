#include "brain/river/pattern_generator.h"

#include <cassert>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "core/text.h"

namespace bx {

namespace {


std::string index_name(const char* field, int i) { return std::string(field) + "[" + std::to_string(i) + "]"; }

}  // namespace

Status check_motif(const Motif& m) {
  for (int i = 0; i < kMotifNeurons; ++i) {
    const std::size_t ui = static_cast<std::size_t>(i);
    for (int j = 0; j < kMotifNeurons; ++j)
      if (!std::isfinite(m.w[ui][static_cast<std::size_t>(j)]))
        return Error{"motif: w[" + std::to_string(i) + "][" + std::to_string(j) + "] is " +
                     g_number(m.w[ui][static_cast<std::size_t>(j)]) + ", not a finite number"};
    if (!(m.tau[ui] > 0) || !std::isfinite(m.tau[ui]))
      return Error{"motif: " + index_name("tau", i) + " is " + g_number(m.tau[ui]) +
                   ", not a finite time constant above 0"};
    if (!std::isfinite(m.alpha[ui]))
      return Error{"motif: " + index_name("alpha", i) + " is " + g_number(m.alpha[ui]) +
                   ", not a finite number"};
  }
  if (m.input < 0 || m.input >= kMotifNeurons)
    return Error{"motif: input is " + std::to_string(m.input) + ", not a neuron 0..2"};
  if (m.output < 0 || m.output >= kMotifNeurons)
    return Error{"motif: output is " + std::to_string(m.output) + ", not a neuron 0..2"};
  return Ok{};
}

CtrnnMotif::CtrnnMotif(const Motif& m) : m_(m) {
  assert(check_motif(m).ok());
  for (std::size_t i = 0; i < kMotifNeurons; ++i) o_[i] = std::tanh(m_.alpha[i] / 2);
}

void CtrnnMotif::step(double input, double dt) {
  // eq. 5 for every neuron, reading only the old outputs: A_i's update needs
  // the old A_i and the old O, so A can be written in place
  for (std::size_t i = 0; i < kMotifNeurons; ++i) {
    double drive = -a_[i];
    for (std::size_t j = 0; j < kMotifNeurons; ++j) drive += m_.w[i][j] * o_[j];
    if (static_cast<int>(i) == m_.input) drive += input;
    a_[i] += dt / m_.tau[i] * drive;
  }
  // then eq. 6 for every output
  for (std::size_t i = 0; i < kMotifNeurons; ++i) o_[i] = std::tanh((m_.alpha[i] - a_[i]) / 2);
}

PatternGenerator::PatternGenerator(const Motif& motif, WeightMatrix motif_input, WeightMatrix motor)
    : motif_input_(std::move(motif_input)), motor_(std::move(motor)) {
  const int n = motif_input_.rows;
  assert(n > 0 && motif_input_.cols == n && motor_.cols == n);
  motifs_.assign(static_cast<std::size_t>(n), CtrnnMotif(motif));
  motif_input_values_.assign(static_cast<std::size_t>(n), 0.0);
  outputs_.assign(static_cast<std::size_t>(n), 0.0);
  motors_.assign(static_cast<std::size_t>(motor_.rows), 0.0);
  update_motors();
}

void PatternGenerator::step(std::span<const double> pn_outputs, double dt) {
  // each motif's input: the interconnection weights over the PN's outputs
  motif_input_.apply(pn_outputs, motif_input_values_);
  for (std::size_t m = 0; m < motifs_.size(); ++m) motifs_[m].step(motif_input_values_[m], dt);
  update_motors();
}

void PatternGenerator::update_motors() {
  // every motor neuron: sigmoid of the weighted motif outputs, no bias
  for (std::size_t m = 0; m < motifs_.size(); ++m) outputs_[m] = motifs_[m].output();
  motor_.apply(outputs_, motors_);
  for (double& v : motors_) v = logistic(v);
}

}  // namespace bx
