// Striking the ground (lessin2015 V, skill 6, STRIKE: "the creature must
// first learn to deliver a strike to the ground underneath it. For this
// creature, that goal is accomplished with a vertical jump"; ATTACK later
// scores where "the first sufficiently strong ground impact occurs"). The
// paper gives no measure of an impact; StrikeDef's is ours (docs/config.md,
// "The strike task").
#pragma once

#include <string>
#include <vector>

#include "task/locomotion.h"
#include "task/settled.h"
#include "task/task.h"

namespace bx {

struct CreatureModel;

/// A strike task. As lessin2015's forward locomotion (task.activation =
/// "settled"), the creature first settles with its controller off, then is
/// measured for `seconds` with it on. An impact is how much the ground
/// stops the creature's fall: gravity being the only other force on it, the
/// ground's vertical impulse over a span T is M (dv + g T), dv the rise of
/// the centre of mass's vertical velocity over T; standing still it is
/// M g T, so
///   impact = the largest rise, over any span of `window` seconds, from the
///            centre of mass's mean vertical velocity over the span's first
///            half to that over its second half (m/s),
/// the speed the ground takes out of the body at once (a jump's landing: its
/// falling speed). Only the centre of mass is read, its velocity as a mean
/// over half the window, so neither a contact force (which depends on the
/// solver) nor a step's jitter on the ground enters. fitness = impact (m/s).
struct StrikeDef {
  /// The measured span (s), after settling: long enough for a jump and its landing.
  double seconds = 5;
  double drop_height = 0;  ///< gap between the lowest part and the ground at the start (m)
  /// When the creature is still: lessin2015's locomotion's, 2 cm/s for 0.5 s
  /// within 10 s, as the turn task's.
  SettleDef settle{0.02, 0.5, 10};
  /// The span (s) over which an impact stops the body: 0.1 s, so each half's
  /// mean velocity spans several steps (a contact's step-to-step jitter of a
  /// millimetre moves it by a few cm/s, not a rigid body's held still by 1.3
  /// m/s as velocities from single steps did on lessin_crawler), and short
  /// enough that pushing off slowly (a rise, not a strike) counts little.
  double window = 0.1;
  /// ATTACK's "sufficiently strong" impact (m/s): the first impact reaching
  /// it is the strike (StrikeTask::first_strike). 0.5 m/s: a fall from 1.3 cm.
  double threshold = 0.5;
  friend bool operator==(const StrikeDef&, const StrikeDef&) = default;
};

/// Follows a body's centre of mass step by step and measures its impacts
/// (StrikeDef): shared by every task that scores a strike.
class ImpactMeter {
 public:
  ImpactMeter(double window, double threshold, double dt);
  /// From here on (measuring began at time t with the centre at z).
  void start(double t, double z);
  /// After each step of `dt`.
  void observe(double t, double z);
  /// The largest impact so far (m/s; 0 before any).
  double peak() const { return peak_; }
  /// When (s, the observation's time) the peak was reached.
  double peak_time() const { return peak_t_; }
  /// When the first impact reaching the threshold came, or -1.
  double first_strike() const { return first_; }

 private:
  double threshold_, dt_;
  int half_;                 // half the window, in steps
  std::vector<double> z_;    // the last 2 half_ + 1 heights of the centre of mass, oldest first
  double peak_ = 0, peak_t_ = 0, first_ = -1;
};

/// The strike task: a SettledTask that meters the impacts while measured.
class StrikeTask : public SettledTask {
 public:
  StrikeTask(const StrikeDef& def, double dt, int n_parts);

  /// Fitness: the peak impact (m/s); distance: the centre of mass's travel
  /// on the ground while measured; metrics: impact (m/s), impact_time (s
  /// into the measured span), strike_time (s into it of the first impact
  /// reaching the threshold, -1: none), muscle_work (J).
  TaskScore score(const CreatureModel& m) const override;
  const ImpactMeter& meter() const { return meter_; }

 private:
  void begin_measure(const Observation& o) override;
  void measure(const Observation& o) override;

  StrikeDef def_;
  ImpactMeter meter_;
  double t_start_ = 0;
};

}  // namespace bx
