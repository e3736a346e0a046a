#include "eval/spectrum.h"

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace bx {

namespace {

// In-place radix-2 FFT (Cooley-Tukey, iterative); a.size() a power of two.
void fft(std::vector<std::complex<double>>& a) {
  const std::size_t n = a.size();
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const double ang = -2 * std::numbers::pi / static_cast<double>(len);
    const std::complex<double> wl(std::cos(ang), std::sin(ang));
    for (std::size_t i = 0; i < n; i += len) {
      std::complex<double> w(1);
      for (std::size_t k = 0; k < len / 2; ++k) {
        const std::complex<double> u = a[i + k], v = a[i + k + len / 2] * w;
        a[i + k] = u + v;
        a[i + k + len / 2] = u - v;
        w *= wl;
      }
    }
  }
}

}  // namespace

double dominant_frequency(std::span<const double> samples, double rate) {
  const std::size_t n = samples.size();
  if (n < 4 || !(rate > 0)) return 0;
  double mean = 0;
  for (double x : samples) mean += x;
  mean /= static_cast<double>(n);
  double power = 0;
  for (double x : samples) power += (x - mean) * (x - mean);
  if (power / static_cast<double>(n) < 1e-6) return 0;  // s.d. under 0.001: constant
  std::size_t size = 1;
  while (size < n) size <<= 1;
  std::vector<std::complex<double>> a(size);
  for (std::size_t i = 0; i < n; ++i) a[i] = samples[i] - mean;
  fft(a);
  // the largest bin from 1 to size/2 (Nyquist); ties go to the lower one
  std::size_t best = 1;
  double best_power = -1;
  for (std::size_t k = 1; k <= size / 2; ++k) {
    const double p = std::norm(a[k]);
    if (p > best_power * (1 + 1e-12)) {
      best_power = p;
      best = k;
    }
  }
  return static_cast<double>(best) * rate / static_cast<double>(size);
}

}  // namespace bx
