// Throwing (chaumont2007 4.2): how far a catapult sends its projectile from
// the moment of release to where it comes to rest, and, for the aim task,
// how close the projectile's path passes to a target point.
#pragma once

#include <string>

#include "core/math.h"
#include "task/task.h"

namespace bx {

/// What the fitness is made of.
enum class ThrowFitness {
  Distance,  ///< eq. 2: F_D = D_p
  Aim,       ///< eq. 3 with alpha_p = alpha_t = 1: F_a = D_p - D_t
};

/// A throwing task. Defaults are the paper's where it gives them, else ours
/// (docs/config.md).
struct ThrowingDef {
  ThrowFitness fitness = ThrowFitness::Distance;
  /// Longest evaluation (s): a projectile still moving then is measured
  /// where it is. Our choice: 20 s (4.3: "roll for almost 20 seconds").
  double seconds = 20;
  /// Gap between the lowest part and the ground at the start (m).
  double drop_height = 0.1;
  /// At rest: the projectile's centre moves less than rest_speed * dt over
  /// each step of dt, for rest_seconds without a break after the release
  /// (30 steps at 60 Hz). Our choice.
  double rest_speed = 0.05;   ///< m/s
  double rest_seconds = 0.5;  ///< s
  /// The aim task's target point (m). Our choice: 3 m ahead along +x, at the
  /// height of a 15 cm projectile's centre lying on the ground.
  Vec3 target{3, 0, 0.075};
  friend bool operator==(const ThrowingDef&, const ThrowingDef&) = default;
};

/// Scores one throw. As a Task, it breaks the catapult's release joint when
/// the controller's release fires and follows the projectile part; release()
/// and observe(t, projectile) take the values themselves.
class ThrowingTask : public Task {
 public:
  /// `projectile` and `release_joint`: the catapult's (CreatureModel), or -1
  /// when only the value methods are used.
  ThrowingTask(const ThrowingDef& def, double dt, int projectile = -1, int release_joint = -1);

  Scenario scenario() const override { return {def_.drop_height}; }
  long max_steps() const override;
  /// The controller drives the motors throughout (4.4: no activation sequence).
  /// The release breaks the arm-projectile joint before the step.
  void act(const CreatureModel& m, const Actions& a, World& w, const Observation& o) override;
  void observe(const Observation& o) override;
  /// True once the projectile has come to rest after its release.
  bool done() const override { return done_; }
  TaskScore score(const CreatureModel&) const override;
  std::string note() const override;
  TaskScene scene(const CreatureModel&) const override;

  /// Call at the step the release fires, with the time and the projectile's centre.
  void release(double t, Vec3 projectile);
  /// Call after every physics step with the projectile's centre.
  void observe(double t, Vec3 projectile);

  bool released() const { return released_; }
  /// Time of the release (s), or -1.
  double release_time() const { return released_ ? t_release_ : -1; }
  /// D_p: horizontal distance from the release point to the last observed
  /// position (the resting point once done()); 0 before the release.
  double distance() const;
  /// D_t: least distance from the target to the projectile's path since the
  /// release (the path is the polyline through every observed position);
  /// -1 before the release.
  double target_miss() const { return released_ ? miss_ : -1; }
  /// The fitness by def.fitness (0 if never released).
  double fitness() const;

 private:
  ThrowingDef def_;
  double dt_;
  int projectile_, release_joint_;
  bool released_ = false, done_ = false;
  double t_release_ = 0;
  Vec3 start_, last_;
  double miss_ = 0;
  long still_steps_ = 0;  ///< consecutive still steps of dt
};

/// Least distance from point p to the segment [a, b].
double point_segment_distance(Vec3 p, Vec3 a, Vec3 b);

}  // namespace bx
