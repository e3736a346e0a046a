// Locomotion on flat ground: how far, or how fast, the creature's centre of
// mass travels, with chaumont2007's activation sequence as an option.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "task/task.h"

namespace bx {

struct CreatureModel;

/// Which displacement counts as distance.
enum class DistanceMetric {
  Planar,  ///< horizontal distance (x, y) of the centre of mass
  AlongX,  ///< signed displacement along +x (miconi2006 5.2)
  /// signed displacement along the creature's forward when measuring began:
  /// its heading (task.h's heading(), its front on the ground), the
  /// forward lessin2015's light tasks aim (task/light.h)
  Forward,
  /// the path travelled front first: each step's horizontal displacement
  /// projected on the heading the creature had at the step's start, summed.
  /// A gait that curves scores its whole path, one that backs or sidles
  /// none of it: locomotion along the creature's own front, which a skill
  /// that steers it (lessin2015's turn to light) can then aim.
  Front,
};

/// What the fitness is made of.
enum class LocomotionFitness {
  Distance,      ///< the distance (miconi2006)
  Speed,         ///< distance over the measured time (sims1994)
  Chaumont2007,  ///< eq. 1: D_w * (C_v / (C_s C_l)) * kappa^N
  /// lessin2015 V, skill 1: sigma (floor(s / sigma) + eps) / s_max, s the
  /// speed, sigma the speed step, eps the efficiency (lessin_efficiency)
  Lessin2015,
};

/// When the controller drives the motors.
enum class Activation {
  Always,        ///< from the first step
  Chaumont2007,  ///< 3.3: settle (off), 1 s on, settle (off), then on and measured
  /// settle (off), then on and measured: a creature that topples or rolls
  /// out of its built pose has come to rest before its speed counts
  Settled,
};

/// A locomotion task.
struct LocomotionDef {
  /// Evaluation length (s). With the chaumont2007 sequence: the measured
  /// last phase; the settling and first burst come before it.
  double seconds = 10;
  double drop_height = 0.0;   ///< gap between the lowest part and the ground at the start (m)
  DistanceMetric metric = DistanceMetric::Planar;
  /// Distance is measured from this fraction of the evaluation on
  /// (miconi2006 5.2: 1/8, so falling over does not count).
  double skip_fraction = 0.0;
  LocomotionFitness fitness = LocomotionFitness::Distance;
  Activation activation = Activation::Always;
  /// chaumont2007 3.3's settling phases: when the creature is still.
  SettleDef settle;
  double burst_seconds = 1.0;  ///< the first controller activation (s)
  double kappa = 1.02;         ///< eq. 1's reward per block
  /// The distance that scores is `windows` times the least distance the
  /// centre of mass travels in any of that many equal spans of the measured
  /// time (1: the whole distance). From 2 on, a creature must keep moving
  /// to score: a fall or one push out of its pose travels in one span only.
  int windows = 1;
  /// lessin2015's efficiency: the resting cost beside the muscles' work (W per kg)
  double basal_power = 1;
  double speed_step = 0.05;    ///< lessin2015's sigma: speed counts in steps of this (m/s)
  double max_speed = 1;        ///< lessin2015's s_max: the speed that scores 1 (m/s)
  friend bool operator==(const LocomotionDef&, const LocomotionDef&) = default;
};

/// The phases of an evaluation.
enum class Phase { Settle1, Burst, Settle2, Measure, Done };

/// A locomotion task: says when the controller is on and when the
/// evaluation ends, and scores it. The Task overrides read the observation;
/// start() and observe(t, com, parts) take the values themselves.
class LocomotionTask : public Task {
 public:
  /// `gravity` (m/s^2, its size counts) prices lessin2015's efficiency.
  LocomotionTask(const LocomotionDef& def, double dt, int n_parts, double gravity = 9.81);

  Scenario scenario() const override { return {def_.drop_height}; }
  /// The whole sequence at its longest (every settling phase timing out), and a step.
  long max_steps() const override;
  void begin(const Observation& o) override;
  void observe(const Observation& o) override;
  /// True when the motors follow the brain this step.
  bool controller_on() const override { return phase_ == Phase::Burst || phase_ == Phase::Measure; }
  /// True once the evaluation is over.
  bool done() const override { return phase_ == Phase::Done; }
  /// lessin2015's fitness adds its speed, efficiency and muscle work as metrics.
  TaskScore score(const CreatureModel& m) const override;
  std::string note() const override { return note_; }
  /// The scored span's markers (kScoredFrom, kScoredTo) and its distance so
  /// far as the counter "distance" (m), recorded each time it moved by
  /// kDistanceStep and at the end: what a viewer shows as the distance.
  void record(const Observation& o, SceneRecord& out) override;
  static constexpr double kDistanceStep = 0.005;
  Phase phase() const { return phase_; }

  /// Call at the start with the centre of mass and every part's position.
  /// (These two take no heading: with DistanceMetric::Forward, forward is
  /// the last heading the Observation overrides read, +x if none did.)
  void start(Vec3 com, const std::vector<Vec3>& parts);
  /// Call after every physics step.
  void observe(double t, Vec3 com, const std::vector<Vec3>& parts);

  /// Distance travelled while measured (0 if measuring never started).
  double distance() const;
  /// The distance that scores: distance(), or with LocomotionDef::windows
  /// above 1, windows x the least distance of one window (a window the
  /// evaluation did not reach counts 0).
  double scored_distance() const;
  /// Seconds measured.
  double measured_seconds() const { return measured_ ? t_ - t_start_ : 0; }
  /// The muscles' work while measured (J).
  double measured_work() const { return measured_ ? work_ - work_start_ : 0; }
  /// lessin2015's speed (scored_distance over the measured time) and efficiency.
  double speed() const;
  double efficiency(const CreatureModel& m) const;
  /// The fitness of the evaluation, given the creature (for eq. 1's block terms).
  double fitness(const CreatureModel& m) const;
  /// Whether the part positions are needed by observe() (else pass an empty vector).
  bool needs_parts() const { return def_.activation != Activation::Always; }

 private:
  void settle(double t, bool still, Phase next);
  // every part's position, from an observation (when needs_parts())
  const std::vector<Vec3>& parts_of(const Observation& o);
  void begin_measure(double t, Vec3 com);
  double displacement(Vec3 from, Vec3 to) const;

  LocomotionDef def_;
  double dt_;
  Phase phase_ = Phase::Measure;
  bool measured_ = false;
  Vec3 start_, last_;
  double heading_ = 0;        // the root's heading at the last observation (DistanceMetric::Forward, Front)
  double step_heading_ = 0;   // ... at the one before: the heading a step starts from (DistanceMetric::Front)
  double path_ = 0;           // the path travelled front first while measured (DistanceMetric::Front)
  std::vector<double> path_marks_;  // path_ where each window began (and the last ended)
  Vec3 forward_{1, 0, 0};     // the unit forward on the ground when measuring began (DistanceMetric::Forward)
  std::vector<Vec3> marks_;  // the centre of mass where each window began (and the last ended)
  double window_ = 0;        // s: each window's length
  double t_ = 0, t_start_ = 0, phase_start_ = 0;
  double gravity_;
  double work_ = 0, work_start_ = 0;  // the muscles' work (J): now, and when measuring began
  Stillness stillness_;
  bool recorded_from_ = false, recorded_to_ = false;
  double recorded_distance_ = 0;
  std::vector<Vec3> parts_;
  std::string note_;
};

/// The phases of a task that, as lessin2015's locomotion (activation
/// "settled"), settles its creature with the controller off and then
/// measures it for `seconds`: a LocomotionTask of this def drives them (the
/// turn, strike and light tasks).
LocomotionDef settled_phases(double seconds, double drop_height, const SettleDef& settle);

/// lessin2015's efficiency eps in [0, 1] of travelling `distance` (m) in
/// `seconds` with `work` (J) of muscle work, for a creature of `mass` (kg)
/// under `gravity`, at a resting cost of `basal_power` (W per kg):
/// 1 / (1 + E / (m g d)) with E = W + basal_power m seconds, E / (m g d)
/// being the gross cost of transport (0 for no distance). The resting cost
/// keeps a creature that does nothing from being perfectly efficient: its
/// eps falls to 0 with its speed (at most g s / (g s + basal_power)).
/// lessin2015 asks for an efficiency and does not define one; this is ours.
double lessin_efficiency(double distance, double seconds, double work, double mass, double gravity,
                         double basal_power);

/// chaumont2007 eq. 1's size factor C_v / (C_s C_l) * kappa^N of a creature's blocks.
double chaumont_size_factor(const CreatureModel& m, double kappa);

}  // namespace bx
