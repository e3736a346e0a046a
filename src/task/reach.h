// Reaching high (lessin2015 VII-B, the high-reach task: "reaching for a high
// target", where Fast ESP's creatures "jump as high as possible, or reach
// one limb up by tipping over onto the other limb", and General ESP's grow
// new segments or limbs to reach higher). The paper gives no formula (its
// best fitnesses are 0.164 to 0.314); ReachDef's is ours (docs/config.md,
// "The high-reach task").
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "task/locomotion.h"
#include "task/settled.h"
#include "task/task.h"

namespace bx {

struct CreatureModel;
struct PartModel;

/// A high-reach task. As lessin2015's other skills, the creature first
/// settles with its controller off, then is measured for `seconds` with it
/// on; fitness = the greatest height (m) above the ground that any point of
/// the creature reaches while measured (its top: each part's highest point
/// as its shape and pose give it, part_top()). A jump's peak counts, as the
/// paper's jumpers' did; so does the height the creature stands at before
/// it moves: a taller body reaches higher, which is what General ESP's new
/// segments bought.
struct ReachDef {
  /// The measured span (s), after settling: lessin2015's locomotion's 10 s.
  double seconds = 10;
  double drop_height = 0;  ///< gap between the lowest part and the ground at the start (m)
  /// When the creature is still: lessin2015's locomotion's, 2 cm/s for 0.5 s within 10 s.
  SettleDef settle{0.02, 0.5, 10};
  friend bool operator==(const ReachDef&, const ReachDef&) = default;
};

/// The height of the highest point of a part of the given shape and size
/// (a part's: capsules and cylinders along their x axis, size.x their
/// length, size.y their diameter; a sphere's diameter size.x) at `pose`.
double part_top(const PartModel& part, const Pose& pose);

/// The high-reach task: a SettledTask that follows the creature's top
/// while measured.
class ReachTask : public SettledTask {
 public:
  /// For creature `m` (its parts' shapes and sizes).
  ReachTask(const ReachDef& def, const CreatureModel& m, double dt);

  /// Fitness: the reach (m; 0 without settling); distance: the centre of
  /// mass's travel on the ground while measured; metrics: reach (m),
  /// start_top (m: the top when measuring began), reach_time (s into the
  /// measured span) and muscle_work (J).
  TaskScore score(const CreatureModel& m) const override;
  /// The creature's top now (m).
  double top(const Observation& o) const;
  double reach() const { return measuring() ? reach_ : 0; }

 private:
  void begin_measure(const Observation& o) override;
  void measure(const Observation& o) override;

  ReachDef def_;
  std::vector<PartModel> parts_;
  double t_start_ = 0, start_top_ = 0, reach_ = 0, reach_t_ = 0;
};

}  // namespace bx
