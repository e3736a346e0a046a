// Throwing (chaumont2007 4.2): how far a catapult sends its projectile from
// the moment of release to where it comes to rest, and, for the aim task,
// how close the projectile's path passes to a target point.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "task/task.h"

namespace bx {

/// What the fitness is made of.
enum class ThrowFitness {
  Distance,  ///< eq. 2: F_D = D_p
  Aim,       ///< eq. 3 with alpha_p = alpha_t = 1: F_a = D_p - D_t
};

/// When the throw begins.
enum class ThrowStart {
  Drop,     ///< at the drop: the controller runs from the first step (4.1, 4.4)
  Settled,  ///< once the creature, dropped with its joints held, its controller
            ///< and brain off, is still (`settle`); ours (docs/physics.md)
};

/// A throwing task. Defaults are the paper's where it gives them, else ours
/// (docs/config.md).
struct ThrowingDef {
  ThrowFitness fitness = ThrowFitness::Distance;
  /// Longest evaluation (s) from the throw's beginning: a projectile still
  /// moving then is measured where it is. Our choice: 20 s (4.3: "roll for
  /// almost 20 seconds").
  double seconds = 20;
  ThrowStart start = ThrowStart::Drop;
  /// With ThrowStart::Settled: when the creature is still (never: fitness 0).
  SettleDef settle;
  /// After the release the creature may touch its projectile for this long
  /// (s); a later touch ends the throw, the projectile measured where it is
  /// (a push or carry is not a throw). Negative: no limit, the paper's way.
  double touch_seconds = -1;
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
  void begin(const Observation& o) override;
  /// Once the throw has begun the controller drives the motors throughout
  /// (4.4: no activation sequence); before it (settling), the joints are held
  /// and the brain waits.
  bool controller_on() const override { return !settling_; }
  bool brain_on() const override { return !settling_; }
  bool joints_held() const override { return settling_; }
  /// Task output 0 is the release (a graph brain's release effector: 1 once
  /// it has fired, else 0).
  int n_outputs() const override { return 1; }
  /// The release breaks the arm-projectile joint before the first step its
  /// output is at least kFires.
  void act(const CreatureModel& m, std::span<const double> outputs, WorldEdits& w, const Observation& o) override;
  static constexpr double kFires = 0.5;
  void observe(const Observation& o) override;
  /// True once the projectile has come to rest after its release, the
  /// throw's `seconds` are over, or the creature never settled.
  bool done() const override { return done_; }
  TaskScore score(const CreatureModel&) const override;
  std::string note() const override;
  /// The scene (core/scene_record.h): the part "projectile" (scored) and,
  /// for the aim task, the point "target" on the first call; then each
  /// moment once it has happened, at its own time: "begin" (the throw began:
  /// 0 at the drop, or once the creature rested), "release" and "scored
  /// from" with it, "touch end" (a late touch ended the throw), "scored to"
  /// (the throw ended after a release: at rest, a late touch, or its time
  /// up).
  void record(const Observation&, SceneRecord& out) override;
  /// The aim task's metric (TaskScore::metrics): D_t (m), reported once the
  /// projectile was released.
  static constexpr const char* kTargetMiss = "target miss";
  /// The colours a replay draws them in ("#rrggbb").
  static constexpr const char* kProjectileColor = "#ffc61a";
  static constexpr const char* kTargetColor = "#d6336c";
  /// The target's diameter as drawn (m).
  static constexpr double kTargetSize = 0.12;

  /// Call at the step the release fires, with the time and the projectile's centre.
  void release(double t, Vec3 projectile);
  /// Call after every physics step with the projectile's centre and whether
  /// the creature touched it in that step.
  void observe(double t, Vec3 projectile, bool touched = false);

  bool released() const { return released_; }
  /// Whether the creature is still settling (ThrowStart::Settled).
  bool settling() const { return settling_; }
  /// Time of the release (s), or -1.
  double release_time() const { return released_ ? t_release_ : -1; }
  /// When a touch later than touch_seconds after the release ended the throw (s), or -1.
  double late_touch_time() const { return t_touch_end_; }
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
  bool settling_;
  Stillness stillness_;
  std::vector<Vec3> parts_;
  std::string note_;
  double t_touch_end_ = -1;  ///< s: when a late touch ended the throw, or -1
  double t_release_ = 0, t_begin_ = 0;
  Vec3 start_, last_;
  double miss_ = 0;
  long still_steps_ = 0;  ///< consecutive still steps of dt
  // what record() has appended
  bool recorded_items_ = false, recorded_begin_ = false, recorded_release_ = false, recorded_touch_ = false,
       recorded_end_ = false;
  double t_end_ = 0;  ///< s: when the throw ended (done_)
};

/// Least distance from point p to the segment [a, b].
double point_segment_distance(Vec3 p, Vec3 a, Vec3 b);

}  // namespace bx
