// Fitness over generations as a standalone SVG image.
#pragma once

#include <string>
#include <vector>

#include "evolve/evolution.h"

namespace bx {

/// An SVG of best, mean and median fitness per generation, `width` x `height`
/// pixels, titled `title`.
std::string fitness_svg(const std::vector<GenerationStats>& gens, const std::string& title,
                        int width = 800, int height = 500);

}  // namespace bx
