// A task: what a creature is asked to do, as the one evaluation loop
// (eval/step.h) sees it. A task is a per-evaluation state machine: it says
// where the creature starts (its scenario), whether the controller drives the
// motors, what the controller's actions do to the world, when the
// evaluation ends and what it scored. Locomotion (task/locomotion.h) and
// throwing (task/throwing.h) are its implementations.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/math.h"
#include "core/scene_record.h"

namespace bx {

class WorldEdits;
struct CreatureModel;

/// An axis of the creature's root part's frame: which way is its front
/// (SimConfig::front, the config's task.front).
enum class RootAxis { PlusX, MinusX, PlusY, MinusY, PlusZ, MinusZ };
/// The axis as a unit vector of the root's frame.
Vec3 axis_vector(RootAxis a);

/// What a task may read of the world after a step. The loop's is a view of
/// its world, read when asked (eval/step.cpp); a test's may be a fake.
class Observation {
 public:
  virtual ~Observation() = default;
  /// Simulated time (s).
  virtual double time() const = 0;
  /// Mass-weighted centre of the creature.
  virtual Vec3 centre_of_mass() const = 0;
  virtual int n_parts() const = 0;
  /// Pose of part i (0 is the root).
  virtual Pose part_pose(int i) const = 0;
  /// Whether part i touched another part of the creature in the last step.
  virtual bool touches_part(int i) const = 0;
  /// The work the creature's muscles have done so far (J; World::muscle_work).
  virtual double muscle_work() const { return 0; }
  /// The creature's front: a unit axis of its root part's frame (task.front;
  /// +x unless the config says otherwise), what heading() and root_level() read.
  virtual Vec3 front() const { return {1, 0, 0}; }
  /// Whether any part of the creature touched prop k in the last step
  /// (World::prop_touched; a task knows its props' indices).
  virtual bool touches_prop(int) const { return false; }
};

/// The creature's heading: the angle (rad, from +x towards +y) of its front
/// (Observation::front: its root part's x axis unless the config names
/// another) projected onto the ground; 0 when that axis is vertical.
double heading(const Observation& o);

/// How level the front is: the length of the front axis projected onto
/// the ground (1: level, 0: vertical). A heading means something only while
/// this is not small (TurnDef::min_level, LightDef::min_level).
double root_level(const Observation& o);

/// The heading change (rad) from `from` to `to`, taken the short way round:
/// in [-pi, pi] (unwrapping a heading across +-pi step by step).
double heading_step(double from, double to);

/// Every part's position (part i at out[i]), from an observation.
void part_positions(const Observation& o, std::vector<Vec3>& out);

/// chaumont2007 3.3's stillness, in time: every part moves less than
/// speed * dt over each step of dt, for `seconds` without a break (at
/// dt = 1/60 s, the paper's 1/300 per step for 30 steps); never still
/// within `timeout` (s) -> fitness 0.
struct SettleDef {
  double speed = 0.2;    ///< m/s: (1/300 m) / (1/60 s)
  double seconds = 0.5;  ///< s: 30 steps of 1/60 s
  double timeout = 10;   ///< s
  friend bool operator==(const SettleDef&, const SettleDef&) = default;
};

/// Counts the consecutive still steps (SettleDef) of a creature's parts.
class Stillness {
 public:
  Stillness(const SettleDef& def, double dt) : def_(def), dt_(dt) {}
  /// Call once with every part's position before the first step.
  void start(const std::vector<Vec3>& parts) { prev_ = parts; }
  /// Call after every step with every part's position; true once they have
  /// been still for def.seconds since the start or the last restart().
  bool observe(const std::vector<Vec3>& parts);
  /// Counts from 0 again (a settling phase begins).
  void restart() { still_steps_ = 0; }

 private:
  SettleDef def_;
  double dt_;
  long still_steps_ = 0;
  std::vector<Vec3> prev_;
};

/// Where and how an evaluation starts. (lessin2015's props, lights and
/// targets join this when its tasks arrive.)
struct Scenario {
  double drop_height = 0;  ///< gap between the lowest part and the ground (m)
};

/// A quantity a task measured beside its fitness, by name (the river
/// crossing's levels completed, food eaten): one channel for every task, so
/// a new task's measures need no field of their own in the results.
struct Metric {
  std::string name;
  double value = 0;
  friend bool operator==(const Metric&, const Metric&) = default;
};

/// What an evaluation scored, read once the loop has ended.
struct TaskScore {
  double fitness = 0;
  double distance = 0;       ///< m, by the task's metric (throwing: D_p)
  std::vector<Metric> metrics;  ///< the task's own measures, in the task's order
};

/// One evaluation's task. The loop calls begin() once with the creature in
/// place, then for each physics step: inputs() when the controller is due
/// to think, act() after it thought, the step, observe(); it stops when
/// done() or after max_steps() steps.
class Task {
 public:
  virtual ~Task() = default;

  /// Where the creature starts.
  virtual Scenario scenario() const = 0;
  /// The longest evaluation, in physics steps (the task usually ends sooner).
  virtual long max_steps() const = 0;
  /// Once, before the first step.
  virtual void begin(const Observation&) {}
  /// Inputs it gives the controller beside the body's sensors (a river
  /// crossing's cell under the agent); the controller model must take as many.
  virtual int n_inputs() const { return 0; }
  /// Writes them (n_inputs() values) before each controller step.
  virtual void inputs(const Observation&, std::span<double>) const {}
  /// Outputs it reads of the controller beside the effector signals (a
  /// catapult's release); the controller model must give at least as many.
  virtual int n_outputs() const { return 0; }
  /// Whether the motors follow the controller in the coming step (else the
  /// loop holds them off).
  virtual bool controller_on() const { return true; }
  /// Whether the controller thinks in the coming step (else it stays as it
  /// is, its clock with it: a delay counts from when it thinks again).
  virtual bool brain_on() const { return true; }
  /// Whether every joint is held still with all its motor's force in the
  /// coming step (the creature as one rigid body), whatever the controller.
  virtual bool joints_held() const { return false; }
  /// Before each step: what the controller's task outputs (its last step's,
  /// ControllerState::task_outputs, n_outputs() of them) do to the world
  /// (physics/world_edits.h: ODE's World, or a replay's in MuJoCo).
  virtual void act(const CreatureModel&, std::span<const double> outputs, WorldEdits&, const Observation&) {}
  /// After each step.
  virtual void observe(const Observation& o) = 0;
  /// True once the evaluation is over.
  virtual bool done() const = 0;
  /// The score (unless the evaluation failed).
  virtual TaskScore score(const CreatureModel& m) const = 0;
  /// Why the score is 0 by rule (e.g. never settled), or empty.
  virtual std::string note() const { return {}; }
  /// What this trial sets up, for a viewer's label, where trials differ in
  /// more than their seed ("light at 135 degrees", "no light", "dangerous
  /// target at 90 degrees"); empty when there is nothing to tell.
  virtual std::string describe() const { return {}; }
  /// What a replay shows beside the creature (core/scene_record.h): appends
  /// to `out` what is new since the last call, stamped with the
  /// observation's time (or a moment's own). The loop calls it while it
  /// records a replay, with the creature in place before the first step and
  /// after every step, and once after the last; without a replay,
  /// evaluation calls it once at the end on a fresh record, for the task's
  /// named moments (SceneRecord::markers: a catapult's release).
  virtual void record(const Observation&, SceneRecord& out) {}
};

}  // namespace bx
