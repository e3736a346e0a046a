// FIGHT OR FLIGHT (lessin2015 V, skill 10): "the creature is either
// confronted with a vulnerable target (a single disc on the ground), which
// the creature should attack, or a dangerous target (a spinning vertical
// stack of three such discs), which will destroy the creature if touched.
// ... At each direction, one evaluation is made with a vulnerable target,
// and one with a dangerous target", and the fitness is
// (f+ + 2n f-) / (2n + 1), f+ and f- the mean over the n directions of the
// larger and the smaller of the two. The paper does not say how a creature
// tells the targets apart, nor their sizes; FightDef's choices are ours
// (docs/config.md, "The fight-or-flight task").
#pragma once

#include <span>
#include <string>
#include <vector>

#include "task/light.h"
#include "task/strike.h"
#include "task/task.h"

namespace bx {

/// The targets. Each carries its light, as the light tasks' (light.*: at
/// light.distance from the creature, at light.height above the ground) over
/// its centre: the targets are "perceived as a point light source", and the
/// skills this one builds on learned the light tasks' lights. Each disc
/// shines with light.strength, so the stack, three discs, shines three
/// times as bright: what the creature can tell them apart by (its eyes
/// read a light's strength over distance; a lone disc at 3 m reads 0.5, the
/// stack reads 1, held there).
struct FightDef {
  /// The light's bearing from the forward when measuring begins, one per
  /// direction (degrees, counterclockwise positive): trials 2k and 2k+1
  /// face headings[k mod n], vulnerable then dangerous, so task.trials must
  /// be a whole multiple of 2n. The paper's count is not given; four, as
  /// its attack's, evenly round.
  std::vector<double> headings = {0, 90, 180, -90};
  /// A disc: an upright cylinder this wide and this tall (m): half the
  /// 1.2 m lessin_crawler's length across, so it can stand on it, and as
  /// thin as a coin, so it cannot trip on it.
  double disc_diameter = 0.5;
  double disc_height = 0.05;
  /// The dangerous stack: this many discs one on another, turning about
  /// the vertical at `spin` rad/s (half a turn a second, plain to see).
  int stack_discs = 3;
  double spin = 3.14159;
  friend bool operator==(const FightDef&, const FightDef&) = default;
};

/// One trial: the vulnerable target is scored as attack (light.goal
/// attack: the share of the way to it come at the first strike, StrikeDef's
/// strike), the dangerous one as retreat (light.goal retreat: the mean
/// distance gained from it over light.distance, halved after an initial
/// move towards it); touching the stack destroys the creature: the trial
/// ends and scores 0. Its phases, light and measures are a LightTask's,
/// which it drives; it places its target (World::add_prop) when the light
/// comes on.
class FightOrFlightTask : public Task {
 public:
  FightOrFlightTask(const FightDef& fight, const LightDef& light, const StrikeDef& strike, double dt, int n_parts,
                    int trial);

  Scenario scenario() const override { return inner_.scenario(); }
  long max_steps() const override { return inner_.max_steps(); }
  void begin(const Observation& o) override { inner_.begin(o); }
  /// The light (the inner task's), then the target under it once it is on.
  void act(const CreatureModel& m, std::span<const double> out, WorldEdits& w, const Observation& o) override;
  void observe(const Observation& o) override;
  bool controller_on() const override { return inner_.controller_on(); }
  /// The inner task is done, or the creature was destroyed.
  bool done() const override { return destroyed_ || inner_.done(); }
  /// Fitness: 0 destroyed, else the inner task's; its metrics with
  /// `dangerous` (1 for the stack) and `destroyed` (1: it touched the stack).
  TaskScore score(const CreatureModel& m) const override;
  std::string note() const override { return inner_.note(); }
  /// "vulnerable target at B degrees" or "dangerous target at B degrees".
  std::string describe() const override;
  /// The inner task's light, and the target as scene props ("target", from
  /// when it appeared; the stack's discs "target 1", "target 2", ...).
  void record(const Observation& o, SceneRecord& out) override;

  bool dangerous() const { return dangerous_; }
  bool destroyed() const { return destroyed_; }
  const LightTask& inner() const { return inner_; }
  double fitness() const { return destroyed_ ? 0 : inner_.fitness(); }
  /// The target's discs, as placed (empty until the light is on).
  const std::vector<Prop>& discs() const { return discs_; }

 private:
  FightDef def_;
  bool dangerous_;
  LightTask inner_;
  std::vector<Prop> discs_;
  std::vector<int> prop_ids_;  // their indices in the world
  double t_on_ = 0;
  bool recorded_ = false;
  bool destroyed_ = false;
};

/// The fight-or-flight fold of an evaluation's trial scores (TaskRow::fold):
/// trials 2k and 2k+1 are one direction's vulnerable and dangerous targets;
/// with n such pairs, f+ and f- the mean of each pair's larger and smaller
/// score, (f+ + 2n f-) / (2n + 1). 0 for no pair; an odd last trial is
/// ignored (the config reader requires pairs).
double fight_fold(std::span<const double> trials);

}  // namespace bx
