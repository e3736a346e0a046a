// The motif's fitness: the transform against sines of known power, the
// formula against hand-built signals, the gene decoding's order and ranges,
// and a motif found by motif_search_test.cpp's search that oscillates at
// 1 Hz under input and rests without.
#include "brain/river/motif_fitness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "brain/river/found_motif.h"
#include "core/rng.h"

namespace bx {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::size_t kSamples = 1000;  // 10 s at 0.01 s

// f(t) sampled at t = 0, dt, ..., for the default def's 1000 samples.
template <class F>
std::vector<double> sampled(F f) {
  std::vector<double> v(kSamples);
  for (std::size_t s = 0; s < kSamples; ++s) v[s] = f(0.01 * static_cast<double>(s));
  return v;
}

std::vector<double> sine(double amplitude, double hz, double offset = 0) {
  return sampled([=](double t) { return offset + amplitude * std::sin(2 * kPi * hz * t); });
}

// Every bin but `bin` holds no power, to rounding.
void expect_only(const std::vector<double>& p, std::size_t bin, double power) {
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (k == bin)
      EXPECT_NEAR(p[k], power, 1e-12) << "bin " << k;
    else
      EXPECT_LT(p[k], 1e-20) << "bin " << k;
  }
}

TEST(MotifSpectrum, SineAtOneHertzIsBinTen) {
  // 10 s gives bins 0.1 Hz apart: 1 Hz is bin 10, and a sine of amplitude a
  // has power a^2 / 2
  const std::vector<double> p = power_spectrum(sine(1, 1));
  ASSERT_EQ(p.size(), kSamples / 2 + 1);
  expect_only(p, 10, 0.5);
}

TEST(MotifSpectrum, SineAtTwoHertzIsBinTwenty) { expect_only(power_spectrum(sine(0.3, 2)), 20, 0.045); }

TEST(MotifSpectrum, MeanIsRemovedAndPowersSumToTheVariance) {
  const std::vector<double> x =
      sampled([](double t) { return 3 + 0.5 * std::sin(2 * kPi * t) + 0.2 * std::cos(2 * kPi * 7.3 * t); });
  const std::vector<double> p = power_spectrum(x);
  EXPECT_LT(p[0], 1e-20);
  double mean = 0, variance = 0, total = 0;
  for (double v : x) mean += v / kSamples;
  for (double v : x) variance += (v - mean) * (v - mean) / kSamples;
  for (double v : p) total += v;
  EXPECT_NEAR(total, variance, 1e-12);
  EXPECT_NEAR(p[73], 0.02, 1e-12);
}

TEST(MotifSpectrum, NyquistBinCountsOnce) {
  // +1, -1, ...: the highest frequency, its own mirror image, all the variance
  expect_only(power_spectrum(sampled([](double t) { return std::lround(t * 100) % 2 == 0 ? 1.0 : -1.0; })), 500,
              1);
}

TEST(MotifFitnessDef, DefaultsPassAndBadFieldsAreNamed) {
  EXPECT_TRUE(check_motif_fitness_def(MotifFitnessDef{}).ok());
  const auto error = [](auto edit) {
    MotifFitnessDef d;
    edit(d);
    const Status s = check_motif_fitness_def(d);
    EXPECT_FALSE(s.ok());
    return s.ok() ? std::string() : s.error();
  };
  EXPECT_NE(error([](MotifFitnessDef& d) { d.target_hz = 1.05; }).find("target_hz is 1.05"), std::string::npos);
  // 50 Hz is the Nyquist frequency at dt 0.01
  EXPECT_NE(error([](MotifFitnessDef& d) { d.target_hz = 50; }).find("Nyquist"), std::string::npos);
  EXPECT_NE(error([](MotifFitnessDef& d) { d.seconds = 10.005; }).find("seconds is 10.005"), std::string::npos);
  EXPECT_NE(error([](MotifFitnessDef& d) { d.dt = 0; }).find("dt is 0"), std::string::npos);
  EXPECT_NE(error([](MotifFitnessDef& d) { d.amplitude = 0; }).find("amplitude is 0"), std::string::npos);
  EXPECT_NE(error([](MotifFitnessDef& d) { d.high_input = std::numeric_limits<double>::infinity(); })
                .find("high_input is inf"),
            std::string::npos);
}

// The dominant frequencies come from a fast transform (mixed radix), the
// spectrum from the plain one: the same largest bin, for motifs' outputs and
// for noise, over counts of samples that factor into small primes (1000,
// 1024), large ones (999 = 27 x 37) and none (997).
TEST(MotifSpectrum, TheDominantFrequencyIsTheLargestBinOfThePowerSpectrum) {
  const auto largest = [](const std::vector<double>& x, double seconds) {
    const std::vector<double> p = power_spectrum(x);
    const auto top = std::max_element(p.begin() + 1, p.end());
    return *top == 0 ? 0.0 : static_cast<double>(top - p.begin()) / seconds;
  };
  Rng rng(31);
  for (int n : {1000, 1024, 999, 997}) {
    const double seconds = 0.01 * n;
    const MotifFitnessDef d{seconds, 0.01, 1, 1 / seconds, 0.5};
    ASSERT_TRUE(check_motif_fitness_def(d).ok()) << check_motif_fitness_def(d).error();
    for (int k = 0; k < 40; ++k) {
      std::vector<double> genes(kMotifGenes);
      for (double& g : genes) g = rng.uniform(-1, 1);
      const Motif m = *motif_from_genes(genes, MotifGeneDef{});
      const std::vector<double> driven = motif_trace(m, 1, seconds, 0.01);
      std::vector<double> noise(static_cast<std::size_t>(n));
      for (double& v : noise) v = rng.normal();
      const MotifScore s = score_motif_outputs(driven, noise, d);
      EXPECT_EQ(s.dominant_hz, largest(driven, seconds)) << n << " samples, motif " << k;
      EXPECT_EQ(s.quiet_dominant_hz, largest(noise, seconds)) << n << " samples, noise " << k;
    }
  }
}

// Under input 0.5 sin(1 Hz) + 0.3 sin(3 Hz): P_t = 0.125, P = 0.125 + 0.045;
// without input -0.7 + 0.1 cos(2 Hz): Q = 0.005; R = 0.5^2 / 2 = 0.125.
TEST(MotifFitness, HandBuiltSignalsByTheFormula) {
  const std::vector<double> driven =
      sampled([](double t) { return 0.5 * std::sin(2 * kPi * t) + 0.3 * std::sin(6 * kPi * t); });
  // a cosine, so that its peaks fall on samples (t = 0, 0.25 s, ...)
  const std::vector<double> quiet = sampled([](double t) { return -0.7 + 0.1 * std::cos(4 * kPi * t); });
  const MotifScore s = score_motif_outputs(driven, quiet, MotifFitnessDef{});
  EXPECT_TRUE(s.finite);
  EXPECT_NEAR(s.target_power, 0.125, 1e-12);
  EXPECT_NEAR(s.other_power, 0.045, 1e-12);
  EXPECT_DOUBLE_EQ(s.dominant_hz, 1);
  EXPECT_NEAR(s.quiet_power, 0.005, 1e-12);
  EXPECT_DOUBLE_EQ(s.quiet_dominant_hz, 2);
  EXPECT_NEAR(s.quiet_range, 0.2, 1e-12);
  const double oscillation = 0.125 / 0.17;
  const double quiescence = 1 - std::sqrt(0.005 / 0.125);  // 0.8
  EXPECT_NEAR(s.oscillation, oscillation, 1e-12);
  EXPECT_NEAR(s.quiescence, quiescence, 1e-12);
  EXPECT_NEAR(s.fitness, oscillation * quiescence, 1e-12);
}

TEST(MotifFitness, FullSineAndRestScoreOne) {
  const MotifScore s = score_motif_outputs(sine(0.5, 1), sine(0, 1, -0.3), MotifFitnessDef{});
  EXPECT_NEAR(s.fitness, 1, 1e-12);
  // larger, still pure: the share stays 1
  EXPECT_NEAR(score_motif_outputs(sine(0.9, 1), sine(0, 1), MotifFitnessDef{}).fitness, 1, 1e-12);
}

TEST(MotifFitness, FaintSineScoresItsPowerAgainstTheReference) {
  // amplitude 0.25 against the reference 0.5: a quarter of the power
  EXPECT_NEAR(score_motif_outputs(sine(0.25, 1), sine(0, 1), MotifFitnessDef{}).fitness, 0.25, 1e-12);
}

TEST(MotifFitness, ConstantUnderInputScoresZero) {
  const MotifScore s = score_motif_outputs(sine(0, 1, 0.4), sine(0, 1, 0.4), MotifFitnessDef{});
  EXPECT_TRUE(s.finite);
  EXPECT_EQ(s.oscillation, 0);
  EXPECT_EQ(s.fitness, 0);
  EXPECT_EQ(s.dominant_hz, 0);
  EXPECT_EQ(s.quiescence, 1);
}

TEST(MotifFitness, OscillatingWithoutInputScoresBelowQuiescent) {
  const MotifScore both = score_motif_outputs(sine(0.5, 1), sine(0.5, 1), MotifFitnessDef{});
  const MotifScore quiet = score_motif_outputs(sine(0.5, 1), sine(0, 1), MotifFitnessDef{});
  EXPECT_EQ(both.quiescence, 0);
  EXPECT_EQ(both.fitness, 0);
  EXPECT_GT(quiet.fitness, both.fitness);
  // a small wobble costs in proportion to its amplitude: a tenth of 0.5
  EXPECT_NEAR(score_motif_outputs(sine(0.5, 1), sine(0.05, 3), MotifFitnessDef{}).fitness, 0.9, 1e-12);
}

TEST(MotifFitness, NonFiniteScoresTheWorst) {
  std::vector<double> bad = sine(0.5, 1);
  bad[500] = std::numeric_limits<double>::quiet_NaN();
  const MotifScore s = score_motif_outputs(bad, sine(0, 1), MotifFitnessDef{});
  EXPECT_FALSE(s.finite);
  EXPECT_EQ(s.fitness, 0);
  std::vector<double> inf = sine(0, 1);
  inf[3] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(score_motif_outputs(sine(0.5, 1), inf, MotifFitnessDef{}).fitness, 0);

  // a time constant far below dt makes Euler diverge (A grows by 99 times a
  // step) until the output is NaN
  Motif m;
  m.tau = {1, 1, 1e-4};
  m.alpha = {0, 1, 1};
  m.w[2][1] = 1;
  m.input = 0;
  m.output = 2;
  const MotifScore diverged = score_motif(m, MotifFitnessDef{});
  EXPECT_FALSE(diverged.finite);
  EXPECT_EQ(diverged.fitness, 0);
  EXPECT_EQ(motif_fitness(m, MotifFitnessDef{}), 0);
}

TEST(MotifFitness, ZeroMotifScoresZero) {
  // no weights: nothing reaches the output neuron, which sits at tanh(alpha / 2)
  Motif m;
  m.alpha = {1, -2, 0.5};
  m.input = 0;
  m.output = 2;
  const MotifScore s = score_motif(m, MotifFitnessDef{});
  EXPECT_TRUE(s.finite);
  EXPECT_EQ(s.target_power, 0);
  EXPECT_EQ(s.quiet_power, 0);
  EXPECT_EQ(s.fitness, 0);
  // and all-zero genes decode to weights and biases of 0
  const std::vector<double> zero(kMotifGenes, 0.0);
  EXPECT_EQ(motif_fitness(*motif_from_genes(zero, MotifGeneDef{}), MotifFitnessDef{}), 0);
}

TEST(MotifGenes, DecodeInOrderAndRange) {
  ASSERT_EQ(motif_gene_count(), 15);
  std::vector<double> g(kMotifGenes);
  for (std::size_t i = 0; i < g.size(); ++i) g[i] = -1 + static_cast<double>(i) / 7;  // -1 .. 1, all different
  const MotifGeneDef def;
  const Result<Motif> m = motif_from_genes(g, def);
  ASSERT_TRUE(m.ok()) << m.error();
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) EXPECT_DOUBLE_EQ(m->w[i][j], 16 * g[3 * i + j]) << i << ", " << j;
    EXPECT_DOUBLE_EQ(m->tau[i], 0.05 * std::pow(40, (g[9 + i] + 1) / 2)) << i;
    EXPECT_DOUBLE_EQ(m->alpha[i], 16 * g[12 + i]) << i;
  }
  EXPECT_DOUBLE_EQ(m->w[0][0], -16);  // gene 0 at the bottom of the range
  EXPECT_DOUBLE_EQ(m->alpha[2], 16);  // gene 14 at the top
  EXPECT_EQ(m->input, 0);
  EXPECT_EQ(m->output, 2);
  EXPECT_TRUE(check_motif(*m).ok());

  // the ends of the time constants' log scale, and its middle the geometric mean
  const auto tau_of = [](double gene) {
    return motif_from_genes(std::vector<double>(kMotifGenes, gene), MotifGeneDef{})->tau[1];
  };
  EXPECT_DOUBLE_EQ(tau_of(-1), 0.05);
  EXPECT_DOUBLE_EQ(tau_of(1), 2);
  EXPECT_DOUBLE_EQ(tau_of(0), std::sqrt(0.05 * 2));

  // the def's neurons and ranges
  MotifGeneDef other;
  other.input = 1;
  other.output = 1;
  other.weight_max = 4;
  const Result<Motif> o = motif_from_genes(g, other);
  ASSERT_TRUE(o.ok()) << o.error();
  EXPECT_EQ(o->input, 1);
  EXPECT_EQ(o->output, 1);
  EXPECT_DOUBLE_EQ(o->w[1][2], 4 * g[5]);
}

TEST(MotifGenes, ErrorsNameTheCountsGeneAndField) {
  const Result<Motif> short_by_one = motif_from_genes(std::vector<double>(14, 0.0), MotifGeneDef{});
  ASSERT_FALSE(short_by_one.ok());
  EXPECT_EQ(short_by_one.error(), "motif genes: 14 given, 15 expected");
  EXPECT_FALSE(motif_from_genes(std::vector<double>(16, 0.0), MotifGeneDef{}).ok());

  std::vector<double> g(kMotifGenes, 0.0);
  g[4] = 1.5;
  const Result<Motif> out = motif_from_genes(g, MotifGeneDef{});
  ASSERT_FALSE(out.ok());
  EXPECT_NE(out.error().find("gene 4 is 1.5"), std::string::npos) << out.error();
  g[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(motif_from_genes(g, MotifGeneDef{}).ok());

  MotifGeneDef d;
  d.tau_min = 3;
  EXPECT_NE(motif_from_genes(std::vector<double>(15, 0.0), d).error().find("tau_min 3 is above tau_max 2"),
            std::string::npos);
  d = MotifGeneDef{};
  d.output = 3;
  EXPECT_NE(check_motif_gene_def(d).error().find("output is 3"), std::string::npos);
  d = MotifGeneDef{};
  d.weight_max = 0;
  EXPECT_NE(check_motif_gene_def(d).error().find("weight_max is 0"), std::string::npos);
}

// found_motif() (brain/river/found_motif.h): what motif_search_test.cpp's
// search found (seed 20150720, population 1000, 10^6 tournaments of 3;
// fitness 0.899), decoded from its genes and printed to full precision.
TEST(MotifFitness, FoundMotifOscillatesAtOneHertzUnderInputAndRestsWithout) {
  const Motif m = found_motif();
  ASSERT_TRUE(check_motif(m).ok());
  const MotifScore s = score_motif(m, MotifFitnessDef{});
  ASSERT_TRUE(s.finite);
  EXPECT_NEAR(s.dominant_hz, 1, 0.1);
  // a full oscillation: at least the reference's power at 1 Hz, little elsewhere
  EXPECT_GT(s.target_power, 0.11);
  EXPECT_LT(s.other_power, 0.02);
  // without input it rings down from rest to a fixed point: a small range
  // over the whole run, almost none over the last second
  EXPECT_LT(s.quiet_range, 0.1);
  const std::vector<double> quiet = motif_trace(m, 0, 10, 0.01);
  const auto [lo, hi] = std::minmax_element(quiet.end() - 100, quiet.end());
  EXPECT_LT(*hi - *lo, 1e-3);
  EXPECT_GT(s.fitness, 0.85);
  EXPECT_EQ(motif_fitness(m, MotifFitnessDef{}), s.fitness);
}

TEST(MotifFitness, FoundMotifBeatsZeroAndRandomMotifs) {
  const double found = motif_fitness(found_motif(), MotifFitnessDef{});
  Motif zero;
  zero.output = 2;
  EXPECT_GT(found, motif_fitness(zero, MotifFitnessDef{}));
  // the best of 100 random motifs, drawn as the search's first population
  Rng rng(7);
  double best_random = 0;
  for (int r = 0; r < 100; ++r) {
    std::vector<double> g(kMotifGenes);
    for (double& x : g) x = rng.uniform(-1, 1);
    const Motif m = *motif_from_genes(g, MotifGeneDef{});
    const MotifScore s = score_motif(m, MotifFitnessDef{});
    EXPECT_EQ(motif_fitness(m, MotifFitnessDef{}), s.fitness);
    best_random = std::max(best_random, s.fitness);
  }
  EXPECT_GT(found, best_random);
  EXPECT_LT(best_random, 0.1);
}

}  // namespace
}  // namespace bx
