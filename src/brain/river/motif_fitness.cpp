#include "brain/river/motif_fitness.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>

#include "core/text.h"

namespace bx {

namespace {


// How many steps of dt make `seconds`, when check_motif_fitness_def has
// accepted them.
std::size_t step_count(double seconds, double dt) { return static_cast<std::size_t>(std::llround(seconds / dt)); }

// Below this variance (a standard deviation of 1e-9) a signal is constant to
// rounding: what is left after removing its mean is noise, not a frequency.
constexpr double kConstantVariance = 1e-18;

// A signal with its mean removed, and its variance.
struct Centered {
  std::vector<double> x;
  double variance = 0;
};

Centered center(std::span<const double> samples) {
  Centered c;
  if (samples.empty()) return c;
  const double n = static_cast<double>(samples.size());
  double mean = 0;
  for (double v : samples) mean += v;
  mean /= n;
  c.x.reserve(samples.size());
  for (double v : samples) {
    c.x.push_back(v - mean);
    c.variance += (v - mean) * (v - mean);
  }
  c.variance /= n;
  // the mean of equal samples can miss them by a rounding error, which would
  // leave a constant signal a power of 1e-30 or so at some frequency
  if (c.variance < kConstantVariance) {
    std::fill(c.x.begin(), c.x.end(), 0.0);
    c.variance = 0;
  }
  return c;
}

// cos and sin of 2 pi m / n for m = 0 .. n-1: every bin's twiddle factors,
// since (k t) mod n is all a bin k needs at sample t.
struct Twiddles {
  std::vector<double> cos, sin;
  explicit Twiddles(std::size_t n) : cos(n), sin(n) {
    for (std::size_t m = 0; m < n; ++m) {
      const double angle = 2 * std::numbers::pi * static_cast<double>(m) / static_cast<double>(n);
      cos[m] = std::cos(angle);
      sin[m] = std::sin(angle);
    }
  }
};

// The twiddles of n samples, made once per thread for the last n asked:
// a motif run scores every motif over the same count, and 2n cos and sin
// calls cost as much as the rest of a score.
const Twiddles& twiddles(std::size_t n) {
  thread_local std::unique_ptr<Twiddles> last;
  if (!last || last->cos.size() != n) last = std::make_unique<Twiddles>(n);
  return *last;
}

using Complex = std::complex<double>;

// X_k = sum_t x_t e^(-2 pi i k t / n) of the n values x[0], x[s], ...,
// x[(n-1) s], into out[0 .. n): decimation in time over the smallest prime
// factor p of n, recursively (mixed radix), so 1000 = 2^3 5^3 samples cost
// n (2 + 2 + 2 + 5 + 5 + 5) products instead of the plain transform's n^2.
// tw holds the twiddles of the outermost size N; `step` is N / n.
void fft(const Complex* x, std::size_t s, std::size_t n, Complex* out, const Twiddles& tw, std::size_t step) {
  if (n == 1) {
    out[0] = x[0];
    return;
  }
  std::size_t p = 2;
  while (n % p != 0 && p * p <= n) ++p;
  if (n % p != 0) p = n;  // n prime: one plain transform of its n values
  const std::size_t m = n / p;
  // the p interleaved subsequences x[r], x[r + p], ... each transformed
  for (std::size_t r = 0; r < p; ++r) fft(x + r * s, s * p, m, out + r * m, tw, step * p);
  // X[k + m q] = sum_r e^(-2 pi i r (k + m q) / n) Y_r[k], in place over the
  // p entries k, k + m, ... (which hold Y_0[k], Y_1[k], ...)
  std::vector<Complex> y(p);
  for (std::size_t k = 0; k < m; ++k) {
    for (std::size_t r = 0; r < p; ++r) y[r] = out[r * m + k];
    for (std::size_t q = 0; q < p; ++q) {
      const std::size_t j = k + m * q;
      Complex sum = y[0];
      std::size_t at = 0;  // (r j) mod n, kept without a division
      for (std::size_t r = 1; r < p; ++r) {
        at += j;
        if (at >= n) at -= n;
        sum += Complex(tw.cos[at * step], -tw.sin[at * step]) * y[r];
      }
      out[j] = sum;
    }
  }
}

// The one-sided power at bin k of centered samples x (power_spectrum's entry
// k): one row of the plain DFT.
double bin_power(const std::vector<double>& x, std::size_t k, const Twiddles& tw) {
  const std::size_t n = x.size();
  double re = 0, im = 0;
  std::size_t m = 0;  // (k t) mod n, kept without overflow
  for (std::size_t t = 0; t < n; ++t) {
    re += x[t] * tw.cos[m];
    im -= x[t] * tw.sin[m];
    m += k;
    if (m >= n) m -= n;
  }
  const double nn = static_cast<double>(n) * static_cast<double>(n);
  // the bins above n/2 mirror those below it, so each interior bin counts twice
  const bool own_mirror = k == 0 || 2 * k == n;
  return (own_mirror ? 1 : 2) * (re * re + im * im) / nn;
}

// The frequency (Hz) of the largest bin above 0 of a signal of `seconds`, or
// 0 for a constant one: every bin of power_spectrum, by the fast transform
// (the same powers to rounding), the first of equal ones.
double dominant(const Centered& c, double seconds) {
  if (c.variance == 0) return 0;
  const std::size_t n = c.x.size();
  const std::vector<Complex> x(c.x.begin(), c.x.end());
  std::vector<Complex> X(n);
  fft(x.data(), 1, n, X.data(), twiddles(n), 1);
  std::size_t best = 0;
  double best_power = -1;
  for (std::size_t k = 1; 2 * k <= n; ++k) {
    // bin_power's scale: each interior bin counts twice
    const double p = (2 * k == n ? 1 : 2) * std::norm(X[k]);
    if (p > best_power) {
      best_power = p;
      best = k;
    }
  }
  return static_cast<double>(best) / seconds;
}

bool all_finite(std::span<const double> v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// Every part of the score of the two signals; the dominant frequencies,
// which need every bin, only when asked.
MotifScore score_signals(std::span<const double> driven, std::span<const double> quiet,
                         const MotifFitnessDef& d, bool dominant_frequencies) {
  assert(check_motif_fitness_def(d).ok());
  assert(driven.size() == step_count(d.seconds, d.dt) && quiet.size() == driven.size());
  // a diverging motif (a time constant too short for dt) scores the worst
  if (!all_finite(driven) || !all_finite(quiet)) return MotifScore{.finite = false};

  MotifScore s;
  const Centered in = center(driven);
  const Centered q = center(quiet);
  const std::size_t target_bin = static_cast<std::size_t>(std::llround(d.target_hz * d.seconds));
  s.target_power = bin_power(in.x, target_bin, twiddles(in.x.size()));
  // Parseval: the bins sum to the variance, so the rest is the variance less
  // the target's share (rounding can leave a hair below 0)
  s.other_power = std::max(0.0, in.variance - s.target_power);
  s.quiet_power = q.variance;
  const auto [lo, hi] = std::minmax_element(quiet.begin(), quiet.end());
  s.quiet_range = *hi - *lo;

  // R, the reference oscillation's power. Under input, the target's share of
  // the power, but of at least R, so that a faint pure sine (or a constant,
  // share 0 / 0) cannot score as well as a full one.
  const double reference = d.amplitude * d.amplitude / 2;
  s.oscillation = s.target_power / std::max(in.variance, reference);
  // Without input, the wobble's RMS as a share of the reference's: linear in
  // amplitude, so a wobble a tenth of the wanted oscillation costs a tenth
  // (a power ratio would charge it a hundredth, and evolution would leave
  // it), and one as large as the wanted oscillation costs everything.
  s.quiescence = std::max(0.0, 1 - std::sqrt(s.quiet_power / reference));
  // a product, so that failing either run fails the motif: one that
  // oscillates with and without input scores 0, as one that never does
  s.fitness = s.oscillation * s.quiescence;

  if (dominant_frequencies) {
    s.dominant_hz = dominant(in, d.seconds);
    s.quiet_dominant_hz = dominant(q, d.seconds);
  }
  return s;
}

// Both runs of a motif, each from rest, scored.
MotifScore score(const Motif& m, const MotifFitnessDef& d, bool dominant_frequencies) {
  assert(check_motif(m).ok());
  return score_signals(motif_trace(m, d.high_input, d.seconds, d.dt), motif_trace(m, 0, d.seconds, d.dt), d,
                       dominant_frequencies);
}

}  // namespace

Status check_motif_fitness_def(const MotifFitnessDef& d) {
  const auto bad = [](const std::string& field, double v, const std::string& why) {
    return Error{"motif fitness: " + field + " is " + g_number(v) + ", " + why};
  };
  if (!(d.seconds > 0) || !std::isfinite(d.seconds)) return bad("seconds", d.seconds, "not a finite time above 0");
  if (!(d.dt > 0) || !std::isfinite(d.dt)) return bad("dt", d.dt, "not a finite step above 0");
  const double steps = d.seconds / d.dt;
  if (std::abs(steps - std::round(steps)) > 1e-9 * steps)
    return bad("seconds", d.seconds, "not a whole number of steps of dt " + g_number(d.dt));
  if (std::round(steps) < 4) return bad("seconds", d.seconds, "fewer than 4 steps of dt " + g_number(d.dt));
  const double bin = d.target_hz * d.seconds;
  if (!std::isfinite(bin) || std::abs(bin - std::round(bin)) > 1e-9 * std::max(1.0, bin))
    return bad("target_hz", d.target_hz,
               "not a whole number of cycles in " + g_number(d.seconds) + " s (a bin of the transform)");
  if (std::round(bin) < 1 || 2 * std::round(bin) >= std::round(steps))
    return bad("target_hz", d.target_hz,
               "not between 0 and the Nyquist frequency " + g_number(0.5 / d.dt) + " Hz (exclusive)");
  if (!std::isfinite(d.high_input)) return bad("high_input", d.high_input, "not a finite number");
  if (!(d.amplitude > 0) || !std::isfinite(d.amplitude))
    return bad("amplitude", d.amplitude, "not a finite amplitude above 0");
  return Ok{};
}

std::vector<double> motif_trace(const Motif& m, double input, double seconds, double dt) {
  CtrnnMotif c(m);
  const std::size_t n = step_count(seconds, dt);
  std::vector<double> out;
  out.reserve(n);
  for (std::size_t t = 0; t < n; ++t) {
    c.step(input, dt);
    out.push_back(c.output());
  }
  return out;
}

std::vector<double> power_spectrum(std::span<const double> samples) {
  const Centered c = center(samples);
  if (c.x.empty()) return {};
  const Twiddles& tw = twiddles(c.x.size());
  std::vector<double> p(c.x.size() / 2 + 1);
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = bin_power(c.x, k, tw);
  return p;
}

MotifScore score_motif(const Motif& m, const MotifFitnessDef& d) { return score(m, d, true); }

MotifScore score_motif_outputs(std::span<const double> driven, std::span<const double> quiet,
                               const MotifFitnessDef& d) {
  return score_signals(driven, quiet, d, true);
}

double motif_fitness(const Motif& m, const MotifFitnessDef& d) { return score(m, d, false).fitness; }

Status check_motif_gene_def(const MotifGeneDef& d) {
  const std::pair<const char*, double> bounds[] = {
      {"weight_max", d.weight_max}, {"bias_max", d.bias_max}, {"tau_min", d.tau_min}, {"tau_max", d.tau_max}};
  for (const auto& [name, v] : bounds)
    if (!(v > 0) || !std::isfinite(v))
      return Error{"motif genes: " + std::string(name) + " is " + g_number(v) + ", not a finite number above 0"};
  if (d.tau_min > d.tau_max)
    return Error{"motif genes: tau_min " + g_number(d.tau_min) + " is above tau_max " + g_number(d.tau_max)};
  if (d.input < 0 || d.input >= kMotifNeurons)
    return Error{"motif genes: input is " + std::to_string(d.input) + ", not a neuron 0..2"};
  if (d.output < 0 || d.output >= kMotifNeurons)
    return Error{"motif genes: output is " + std::to_string(d.output) + ", not a neuron 0..2"};
  return Ok{};
}

Result<Motif> motif_from_genes(std::span<const double> genes, const MotifGeneDef& d) {
  if (Status ok = check_motif_gene_def(d); !ok) return Error{ok.error()};
  if (genes.size() != static_cast<std::size_t>(kMotifGenes))
    return Error{"motif genes: " + std::to_string(genes.size()) + " given, " + std::to_string(kMotifGenes) +
                 " expected"};
  for (std::size_t g = 0; g < genes.size(); ++g)
    if (!(genes[g] >= -1 && genes[g] <= 1))
      return Error{"motif genes: gene " + std::to_string(g) + " is " + g_number(genes[g]) +
                   ", not a finite number in [-1, 1]"};

  constexpr std::size_t n = kMotifNeurons;
  Motif m;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) m.w[i][j] = genes[n * i + j] * d.weight_max;
    m.tau[i] = d.tau_min * std::pow(d.tau_max / d.tau_min, (genes[n * n + i] + 1) / 2);
    m.alpha[i] = genes[n * n + n + i] * d.bias_max;
  }
  m.input = d.input;
  m.output = d.output;
  return m;
}

}  // namespace bx
