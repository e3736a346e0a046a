// The dominant frequency of a signal: what `bestiary check` and the viewer
// say of how fast each effector's signal changes (a gait of a few hertz, or a
// buzz at the brain's rate; docs/physics.md cause 27).
#pragma once

#include <span>

namespace bx {

/// The frequency (Hz) of the largest peak of the power spectrum of `samples`,
/// taken `rate` times a second, after removing their mean: the strongest
/// periodic component, to the resolution of rate / (the samples' count padded
/// to a power of two). 0 for a signal that is constant to a thousandth (its
/// standard deviation under 0.001) or has fewer than 4 samples. A signal that flips every
/// sample gives rate / 2; a sine of f Hz gives f within one bin.
double dominant_frequency(std::span<const double> samples, double rate);

}  // namespace bx
