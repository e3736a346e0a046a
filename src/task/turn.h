// Turning in place (lessin2015 V, skills 2 and 3, LEFT TURN and RIGHT TURN:
// "the ability to rotate counterclockwise while largely maintaining
// position", and clockwise "in the same way"): how fast the creature's
// heading turns the wanted way while its centre of mass stays near where it
// was. The paper gives no formula; TurnDef's is ours (docs/config.md, "The
// turn task").
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "task/locomotion.h"
#include "task/settled.h"
#include "task/task.h"

namespace bx {

struct CreatureModel;

/// Which way the creature is asked to turn, seen from above (+z up).
enum class TurnDirection {
  Left,   ///< counterclockwise: heading() grows (skill 2)
  Right,  ///< clockwise: heading() falls (skill 3)
};

/// A turning task. As lessin2015's forward locomotion (the dialect's
/// task.activation = "settled"), the creature first settles with its
/// controller off, then is measured for `seconds` with it on. Over that span
/// the heading (heading(): the front, task.front, on the ground) is unwrapped
/// step by step, and
///   fitness = max(0, rate) / (1 + travel / travel_scale),
/// rate being the turn in `direction` (rad/s; windows below) and travel the
/// farthest the centre of mass got, on the ground, from where it was when
/// measuring began (m). Not discretized as skill 1's speed (its step and
/// efficiency tie-break): the paper names only the turn and staying in
/// place, and the factor already ranks equal turns by how well they stay.
struct TurnDef {
  TurnDirection direction = TurnDirection::Left;
  /// The measured span (s), after settling: lessin2015's locomotion's 10 s.
  double seconds = 10;
  double drop_height = 0;  ///< gap between the lowest part and the ground at the start (m)
  /// When the creature is still (task.settle_* of locomotion): lessin2015's
  /// locomotion's, 2 cm/s for 0.5 s within 10 s, so both skills start a
  /// creature alike.
  SettleDef settle{0.02, 0.5, 10};
  /// The turn that scores is `windows` times the least turn (in
  /// `direction`) of any of that many equal spans of the measured time, as
  /// task.windows does for distance: 2 (lessin2015's locomotion's), so a
  /// twist when the muscles first pull, or a fall that swings the heading,
  /// turns in one span only and scores nothing.
  int windows = 2;
  /// The travel (m) that halves the score: a quarter metre, a fifth of the
  /// 1.2 m lessin_crawler, so a pivot shuffling a few centimetres keeps
  /// 80-90% while walking off at 0.5 m/s (5 m in 10 s) keeps under 5%.
  double travel_scale = 0.25;
  /// The heading counts only while the front (task.front) lies within 60 degrees
  /// of the ground (its projection on the ground at least this long: 0.5);
  /// over a steeper stretch it is taken up again where the axis comes out,
  /// so a root tipped over the vertical (its heading flipping by pi) or
  /// wobbling about it (its heading noise) turns nothing. Our choice: 0.5
  /// keeps every turn of a creature whose root stays within 60 degrees of
  /// level, as lessin_crawler's does.
  double min_level = 0.5;
  friend bool operator==(const TurnDef&, const TurnDef&) = default;
};

/// The turn task: a SettledTask that follows the heading and the centre of
/// mass while measured.
class TurnTask : public SettledTask {
 public:
  TurnTask(const TurnDef& def, double dt, int n_parts);

  /// Fitness (TurnDef); distance: travel(); metrics: turn_rate (rad/s, the
  /// rate that scores, negative when the least window turned the wrong
  /// way), turned (rad, the whole span's turn in `direction`), travel (m)
  /// and muscle_work (J, while measured).
  TaskScore score(const CreatureModel& m) const override;

  /// The unwrapped heading change while measured (rad, counterclockwise
  /// positive; 0 before measuring).
  double turned() const { return turned_; }
  /// The turn that scores (rad, in `direction`): windows x the least
  /// window's (a window the evaluation did not reach counts 0).
  double scored_turn() const;
  /// scored_turn over the measured time (rad/s; 0 if nothing was measured).
  double turn_rate() const;
  /// The farthest horizontal distance of the centre of mass from where it
  /// was when measuring began (m).
  double travel() const { return travel_; }
  double fitness() const;

 private:
  void begin_measure(const Observation& o) override;
  void measure(const Observation& o) override;

  TurnDef def_;
  double sign_;              // +1 left, -1 right
  double heading_ = 0;       // the last counted step's heading (rad)
  bool level_ = true;        // whether the last step's root was level enough (TurnDef::min_level)
  double turned_ = 0;        // rad, counterclockwise
  Vec3 start_;               // the centre of mass when measuring began
  double travel_ = 0;
  double t_start_ = 0, window_ = 0;
  std::vector<double> marks_;  // turned_ where each window began (and the last ended)
};

}  // namespace bx
