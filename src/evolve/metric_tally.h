// A task's named metrics (TaskScore::metrics) summed over the evaluations of
// one generation (steady state: report interval), so a run records how often
// its evaluations did what the task counts: the river crossing's share of
// evaluations that complete each level (Stanton & Channon 2015, Fig. 5).
#pragma once

#include <string>
#include <vector>

#include "task/task.h"

namespace bx {

/// One metric over a generation's evaluations.
struct MetricStat {
  std::string name;
  double mean = 0;     ///< its mean over the evaluations (0 where an evaluation lacked it)
  double nonzero = 0;  ///< the share of the evaluations where it was not 0
  friend bool operator==(const MetricStat&, const MetricStat&) = default;
};

/// Sums metrics evaluation by evaluation, by name in the order first seen.
class MetricTally {
 public:
  /// One evaluation's metrics (none for one that failed: it counts, as zeros).
  void add(const std::vector<Metric>& metrics) {
    ++n_;
    for (const Metric& m : metrics) {
      std::size_t i = 0;
      while (i < stats_.size() && stats_[i].name != m.name) ++i;
      if (i == stats_.size()) stats_.push_back({m.name, 0, 0});
      stats_[i].mean += m.value;
      stats_[i].nonzero += m.value != 0 ? 1 : 0;
    }
  }
  /// Each metric's mean and nonzero share over the evaluations added.
  std::vector<MetricStat> stats() const {
    std::vector<MetricStat> out = stats_;
    for (MetricStat& s : out) {
      s.mean /= static_cast<double>(n_);
      s.nonzero /= static_cast<double>(n_);
    }
    return out;
  }
  long evaluations() const { return n_; }

 private:
  std::vector<MetricStat> stats_;  // sums until stats()
  long n_ = 0;
};

}  // namespace bx
