// A run's curves as standalone SVG images: fitness over generations, and a
// task's metrics over them (line_chart.h draws both).
#pragma once

#include <string>
#include <vector>

#include "evolve/evolution.h"

namespace bx {

/// An SVG of best, mean and median fitness per generation, `width` x `height`
/// pixels, titled `title`.
std::string fitness_svg(const std::vector<GenerationStats>& gens, const std::string& title,
                        int width = 800, int height = 500);

/// One run of a comparison: the condition it belongs to (its label in the
/// legend) and its generations.
struct PlottedRun {
  std::string condition;
  std::vector<GenerationStats> gens;
};

/// An SVG comparing runs: for each condition (runs with the same label, in
/// order of first appearance) the median over its runs of the best fitness
/// (solid) and of the mean (dashed) per generation, and, with more than one
/// run, the interquartile range of the best as a shaded band. x is the
/// generation, or with `per_evaluation` the evaluations done by its end (a
/// steady state's x: the median over the runs).
std::string compare_svg(const std::vector<PlottedRun>& runs, bool per_evaluation, const std::string& title,
                        int width = 800, int height = 500);

/// An SVG of the share (%) of each generation's evaluations in which each
/// named metric was not 0 (GenerationStats::metrics), e.g. the river
/// crossing's "level k completed" (Stanton & Channon 2015, Fig. 5), when
/// every one drawn is 0 or 1 in every evaluation (its mean is that share);
/// else of each one's mean over the generation's evaluations (a motif's
/// "oscillation"). x is the generation times `per_generation` (a steady
/// state's tournaments per report).
std::string metric_svg(const std::vector<GenerationStats>& gens, const std::vector<std::string>& names,
                       double per_generation, const std::string& x_label, const std::string& title,
                       int width = 800, int height = 500);

/// metric_svg for several runs: for each condition (as compare_svg) and each
/// named metric, the median over its runs per report (share or mean, as
/// metric_svg decides over every run), with the interquartile band when the
/// condition has more than one run. x is the generation times
/// `per_generation` (the median over the runs that have it).
std::string compare_metric_svg(const std::vector<PlottedRun>& runs, const std::vector<std::string>& names,
                               double per_generation, const std::string& x_label, const std::string& title,
                               int width = 800, int height = 500);

}  // namespace bx
