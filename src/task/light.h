// The light tasks (lessin2015 V, skills 4, 5, 8 and 9): TURN TO LIGHT, "its
// ability to orient itself to a target (which is perceived as a point light
// source) ... an average over four runs, each with a fixed light source at a
// different heading"; MOVE TO LIGHT, "its ability to navigate to a light
// source ... averaged over ... five [runs], again with a fixed light source
// at a different relative angle each time"; TURN FROM LIGHT, "turn away from
// a light source" with "a fitness term to discourage an initial
// wrong-direction turn" and thirteen directions "particularly near the
// front"; RETREAT, "maximize its average distance from a light target" with
// "penalties for initial wrong-direction moves"; ATTACK, "an average across
// four directions of distance from the target when the first sufficiently
// strong ground impact occurs (with a penalty for producing such an impact
// when the scene contains no light)". The paper gives no formula; LightDef's
// are ours (docs/config.md, "The light tasks").
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/math.h"
#include "physics/world_edits.h"
#include "task/locomotion.h"
#include "task/settled.h"
#include "task/strike.h"
#include "task/task.h"

namespace bx {

struct CreatureModel;

/// What the creature is asked to do about the light.
enum class LightGoal {
  Face,      ///< turn to face it (skill 4, TURN TO LIGHT)
  Approach,  ///< get to it (skill 5, MOVE TO LIGHT)
  FaceAway,  ///< turn to face away from it (skill 8, TURN FROM LIGHT)
  Retreat,   ///< get away from it (skill 9, RETREAT)
  Attack,    ///< get to it and strike the ground there (skill 7, ATTACK)
};

/// A light task. As lessin2015's forward locomotion (the dialect's
/// task.activation = "settled") and the turn task, the creature first
/// settles with its controller off and in the dark, then is measured for
/// `seconds` with its controller on and one point light (World::set_lights)
/// placed, when measuring begins, `distance` metres on the ground from its
/// centre of mass at `height` above the ground, at `headings[trial %
/// headings.size()]` degrees from its forward (the root's heading,
/// task.h's heading(), counterclockwise positive). Below, a is the angle
/// between the root's heading and the horizontal direction from the centre
/// of mass to the light, d the centre of mass's horizontal distance from
/// the light, d0 its d when measuring began, and each goal's score per trial
/// (evaluate() folds the trials, task.trial_score):
///   face:      the mean over the measured steps from `score_from` of the
///              span on of (1 + cos a) / 2, a step whose root is not level
///              (min_level) counting 0: 1 facing the light all along, 0
///              facing away;
///   face_away: the same of (1 - cos a) / 2, times `wrong_factor` when the
///              heading turned towards the light's side by more than
///              `wrong_turn` degrees within the first `early_seconds`;
///   approach:  (d0 - least d) / d0, in [0, 1];
///   retreat:   max(0, mean of d - d0 over the measured steps) / distance,
///              times `wrong_factor` when d fell below d0 by more than
///              `wrong_move` within the first `early_seconds`;
///   attack:    max(0, 1 - ds / d0), ds the d at the first strike (an
///              impact reaching strike.threshold, measured as the strike
///              task measures it: StrikeDef, ImpactMeter), which ends the
///              trial; 0 without a strike. A dark trial (below) scores 1
///              without a strike and 0 with one, and attack_fold() folds
///              the trials: the lit ones' mean times the dark ones' mean
///              of 1 (no strike) or wrong_factor (a strike).
/// Never settling scores 0.
struct LightDef {
  LightGoal goal = LightGoal::Face;
  /// The light's bearing from the creature's forward when measuring begins
  /// (degrees, counterclockwise positive), trial k taking headings[k % n]:
  /// task.trials must be a whole multiple of their count. Ours, for face:
  /// four (the paper's count) at +-45 and +-135, two on each side so no
  /// turning direction is favoured, and none at 0, where a creature doing
  /// nothing would already face the light. Approach should set five (0,
  /// +-72, +-144), face_away and retreat thirteen (0, +-10, +-20, +-30,
  /// +-45, +-90, +-135: seven within 30 degrees of the front), docs/config.md.
  std::vector<double> headings = {45, 135, -135, -45};
  /// attack: after the headings, this many trials with no light at all
  /// (the paper's penalty "for producing such an impact when the scene
  /// contains no light"): trial k is dark when k mod (n + dark_trials) >= n,
  /// n the headings' count. Only for attack.
  int dark_trials = 0;
  /// From the centre of mass, on the ground (m): two and a half lengths of
  /// the 1.2 m lessin_crawler, so a creature must travel to reach it and
  /// can turn without touching it.
  double distance = 3;
  /// Above the ground (m): an eye looking level sees it from 3 m within 8
  /// degrees of its axis, and the ground never hides it.
  double height = 0.5;
  /// Light::strength and Light::range (m): a receptor facing the light at
  /// `distance` reads half its strength (range = distance), nearing it up
  /// to 1 and at twice the distance a fifth.
  double strength = 1;
  double range = 3;
  /// The measured span (s), after settling: twice the locomotion's and the
  /// turn's 10 s, so a creature turning at 0.3 rad/s faces a light at 135
  /// degrees within the first half, and one crawling at 0.2 m/s covers the
  /// 3 m in 15 s.
  double seconds = 20;
  double drop_height = 0;  ///< gap between the lowest part and the ground at the start (m)
  /// When the creature is still (task.settle_* of locomotion): the turn
  /// task's, lessin2015's locomotion's (2 cm/s for 0.5 s within 10 s).
  SettleDef settle{0.02, 0.5, 10};
  /// face and face_away: the facing counts from this share of the measured
  /// span on (0.5: its second half), so the creature has the first half to
  /// turn and must then hold its aim (a spinning creature averages 0.5).
  double score_from = 0.5;
  /// The heading counts only while the front (task.front) lies within 60
  /// degrees of the ground (its projection at least this long), as the turn
  /// task's turn.min_level: a root tipped up has no heading to aim.
  double min_level = 0.5;
  /// face_away and retreat: how long after measuring begins a move counts
  /// as initial (s): a tenth of the span, the time of a first reaction.
  double early_seconds = 2;
  /// face_away: the largest turn (degrees) towards the light's side in the
  /// early span that goes unpunished: over the 6 degrees lessin_crawler
  /// twists on its muscles' first pull, under the gap to the 20-degree
  /// headings. A light dead ahead or dead behind has no wrong side.
  double wrong_turn = 15;
  /// retreat: the most the centre of mass may close on the light in the
  /// early span unpunished (m): over a first pull's pose change (0.09 m for
  /// lessin_crawler), under a tenth of a body length of travel towards it.
  double wrong_move = 0.1;
  /// What a wrong-direction start multiplies the score by: a half, so a
  /// creature that recovers still beats one that does nothing, but not one
  /// that reacts the right way at once.
  double wrong_factor = 0.5;
  friend bool operator==(const LightDef&, const LightDef&) = default;
};

/// attack's fold of an evaluation's trial scores (TaskRow::fold): the mean
/// of the lit trials' times the mean over the dark trials of 1 (no strike)
/// or wrong_factor (a strike); trial k lit or dark as LightTask's.
double attack_fold(const LightDef& def, std::span<const double> trials);

/// The light task of one trial: a SettledTask that places the light (act():
/// World::set_lights) before the first measured step and follows the
/// heading and the centre of mass while measured.
class LightTask : public SettledTask {
 public:
  /// Trial `trial` (0-based) of an evaluation: its light at
  /// def.headings[trial % (n + def.dark_trials)] (0 degrees if there is
  /// none), or none (a dark trial); `strike` measures attack's strikes.
  LightTask(const LightDef& def, const StrikeDef& strike, double dt, int n_parts, int trial);

  /// Places the light once measuring has begun (dark until then).
  void act(const CreatureModel&, std::span<const double>, WorldEdits& w, const Observation&) override;
  /// The measured span is over, or (attack) the first strike came.
  bool done() const override { return SettledTask::done() || (def_.goal == LightGoal::Attack && struck()); }
  /// Fitness (LightDef); distance: the end's d (m); metrics: bearing (deg,
  /// the light from the heading at the end, counterclockwise positive),
  /// facing (the goal's facing score, before any penalty: the light for
  /// face and approach, away from it for face_away and retreat),
  /// start_distance, end_distance, least_distance (m), wrong_turn (deg),
  /// wrong_move (m) and muscle_work (J, while measured); attack adds
  /// strike_time (s into the measured span, -1: none) and strike_distance
  /// (m, the d at the strike; -1: none).
  TaskScore score(const CreatureModel& m) const override;
  /// "light at B degrees" (B the trial's bearing), or "no light" (a dark trial).
  std::string describe() const override;
  /// The light, as a ScenePoint "light", and the moment it came on ("light on").
  void record(const Observation& o, SceneRecord& out) override;

  /// This trial's bearing (degrees).
  double bearing() const { return bearing_; }
  /// Whether this trial has no light (attack's dark trials).
  bool dark() const { return dark_; }
  /// attack: whether the first strike has come (while measured), and d then (m).
  bool struck() const { return strike_d_ >= 0; }
  double strike_distance() const { return strike_d_; }
  /// The light, once measuring has begun.
  std::optional<Light> light() const;
  /// The goal's facing score (face: (1 + cos a) / 2; face_away: (1 - cos
  /// a) / 2; the others likewise towards and away from the light), averaged
  /// over the counted steps (0 if none).
  double facing() const;
  /// The light's bearing from the heading at the last observation (rad,
  /// counterclockwise positive, in [-pi, pi]).
  double end_bearing() const { return end_bearing_; }
  /// d when measuring began, at the end, and the least (m).
  double start_distance() const { return d0_; }
  double end_distance() const { return d_; }
  double least_distance() const { return d_min_; }
  /// The mean of d - d0 over the measured steps (m).
  double mean_gain() const;
  /// The most the heading turned towards the light's side within the early
  /// span (degrees; 0 with no side), and the most d fell below d0 (m).
  double wrong_turn() const { return wrong_turn_ * 180 / kPi; }
  double wrong_move() const { return wrong_move_; }
  /// Whether the goal's wrong-direction penalty applies.
  bool penalized() const;
  double fitness() const;

 private:
  void begin_measure(const Observation& o) override;
  void measure(const Observation& o) override;
  // the horizontal distance from the centre of mass to the light, and the
  // light's bearing from the heading (rad)
  double distance_of(const Observation& o) const;
  double bearing_of(const Observation& o) const;

  LightDef def_;
  ImpactMeter meter_;
  bool dark_ = false;
  double strike_d_ = -1;  // d at the first strike (attack), -1 before
  double bearing_ = 0;       // deg
  double side_ = 0;          // +1 light on the left, -1 on the right, 0 ahead or behind
  Vec3 light_;               // where the light is, once measuring
  bool placed_ = false;      // in the world
  bool recorded_ = false;    // in the scene record
  double t_start_ = 0;
  double heading_ = 0;       // the last counted step's heading (rad)
  bool level_ = true;
  double turned_ = 0;        // rad, counterclockwise, while measured
  double facing_sum_ = 0;
  long facing_steps_ = 0;
  double d0_ = 0, d_ = 0, d_min_ = 0, gain_sum_ = 0;
  long steps_ = 0;
  double end_bearing_ = 0;
  double wrong_turn_ = 0, wrong_move_ = 0;
};

}  // namespace bx
