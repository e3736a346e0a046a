// The one evaluation loop: any Task drives it (a task written here, on real
// physics), in the order the loop promises, and a blow-up stops it unobserved.
#include "eval/step.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "develop/develop.h"
#include "eval/task_table.h"
#include "genome/genome_json.h"

namespace bx {
namespace {

CreatureModel grow(const std::string& name, SimConfig& cfg) {
  auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name);
  EXPECT_TRUE(g.ok()) << g.error();
  cfg = default_sim_config(g->dialect);
  Development d = develop(*g);
  EXPECT_TRUE(d.viable()) << d.reason;
  return *d.model;
}

// A task that holds the controller off for its first `off` steps, ends after
// `last` observations, and logs what the loop told it.
struct ScriptedTask : Task {
  int off = 10, last = 30;
  double drop = 0.25;
  bool held = false, wait = false;  // while off: joints held, brain waiting
  std::vector<char> log;  // 'b' begin, 'a' act, 'o' observe
  std::vector<double> times;
  double start_z = 0;

  Scenario scenario() const override { return {drop}; }
  long max_steps() const override { return 1000; }
  void begin(const Observation& o) override {
    log.push_back('b');
    start_z = o.part_pose(0).p.z;
    times.push_back(o.time());
  }
  bool controller_on() const override { return observed() >= off; }
  bool joints_held() const override { return held && observed() < off; }
  bool brain_on() const override { return !wait || observed() >= off; }
  void act(const CreatureModel&, std::span<const double>, WorldEdits&, const Observation&) override { log.push_back('a'); }
  void observe(const Observation& o) override {
    log.push_back('o');
    times.push_back(o.time());
  }
  bool done() const override { return observed() >= last; }
  TaskScore score(const CreatureModel&) const override { return {1, 2, {}}; }
  int observed() const { return static_cast<int>(times.size()) - 1; }
};

TEST(Step, ATaskWrittenAnywhereDrivesTheLoopInTheOrderPromised) {
  SimConfig cfg;
  CreatureModel m = grow("walker.json", cfg);
  auto owned = std::make_unique<ScriptedTask>();
  ScriptedTask& task = *owned;
  EvalState s(m, GraphBrain(m.brain), cfg, std::move(owned));
  // placed by the scenario: the lowest point `drop` above the ground (the root at the frame's origin)
  EXPECT_NEAR(task.start_z - (task.drop - m.min_z()), 0, 1e-9);
  ASSERT_EQ(task.log, std::vector<char>{'b'});

  int off_steps = 0, on_steps = 0;
  while (!s.task->done() && step(m, cfg, s)) {
    bool zeros = true, brains = true;
    for (std::size_t e = 0; e < s.signals.size(); ++e) {
      zeros = zeros && s.signals[e] == 0;
      brains = brains && s.signals[e] == s.controller->effectors()[e];
    }
    // held off: the motors get 0; on: the brain's outputs
    if (task.observed() <= task.off) {
      EXPECT_TRUE(zeros) << "step " << s.physics_steps;
      ++off_steps;
    } else {
      EXPECT_TRUE(brains) << "step " << s.physics_steps;
      ++on_steps;
    }
  }
  EXPECT_FALSE(s.failed) << s.failure;
  EXPECT_EQ(s.physics_steps, task.last);
  EXPECT_EQ(off_steps, task.off);
  EXPECT_EQ(on_steps, task.last - task.off);
  // begin, then act before each step and observe after it
  ASSERT_EQ(task.log.size(), 1u + 2u * task.last);
  for (int k = 0; k < task.last; ++k) {
    EXPECT_EQ(task.log[1 + 2 * k], 'a');
    EXPECT_EQ(task.log[2 + 2 * k], 'o');
  }
  for (int k = 0; k <= task.last; ++k) EXPECT_NEAR(task.times[k], k * cfg.physics.dt, 1e-12);
  // the walker's brain ran at brain.rate_hz all along, thinking while held off
  EXPECT_EQ(s.brain_steps, brain_steps_due(task.last, cfg.physics.dt, cfg.brain_hz));
  // the activity counts only the steps the controller drove
  EXPECT_EQ(s.driven_steps, task.last - task.off);
}

// Task::joints_held and Task::brain_on: the walker dropped limp folds its
// joints as it lands; held, it lands as one rigid body; a waiting brain
// takes up its clock where the task turns it on.
TEST(Step, ATaskMayHoldTheJointsAndHaveTheBrainWait) {
  SimConfig cfg;
  CreatureModel m = grow("walker.json", cfg);
  const int n_joints = static_cast<int>(m.joints.size());
  ASSERT_GT(n_joints, 0);
  auto drop = [&](bool held, bool wait, double* brain_steps) {
    auto owned = std::make_unique<ScriptedTask>();
    ScriptedTask& task = *owned;
    task.off = 120;  // 2 s at 60 Hz: it lands and rests
    task.last = 150;
    task.held = held;
    task.wait = wait;
    EvalState s(m, GraphBrain(m.brain), cfg, std::move(owned));
    double most = 0;  // the largest joint excursion while off
    while (!s.task->done() && step(m, cfg, s)) {
      if (task.observed() > task.off) continue;
      for (int j = 0; j < n_joints; ++j)
        for (int d = 0; d < joint_dofs(m.joints[j].type); ++d) most = std::max(most, std::abs(s.world.joint_position(j, d)));
    }
    EXPECT_FALSE(s.failed) << s.failure;
    *brain_steps = static_cast<double>(s.brain_steps - s.brain_waits);
    return most;
  };
  double thought = 0;
  const double limp = drop(false, false, &thought);
  EXPECT_EQ(thought, brain_steps_due(150, cfg.physics.dt, cfg.brain_hz));
  const double held = drop(true, true, &thought);
  EXPECT_GT(limp, 0.1) << "limp joints fold as it lands";
  EXPECT_LT(held, 0.25 * limp) << "held joints barely give";
  // the brain thought only in the 30 steps it was on
  EXPECT_EQ(thought, brain_steps_due(150, cfg.physics.dt, cfg.brain_hz) -
                         brain_steps_due(120, cfg.physics.dt, cfg.brain_hz));
}

TEST(Step, ABlowUpStopsTheLoopAndIsNotObserved) {
  SimConfig cfg;
  CreatureModel m = grow("walker.json", cfg);
  cfg.physics.max_speed = 0.05;  // falling from 1 m is a blow-up by this bound
  auto owned = std::make_unique<ScriptedTask>();
  ScriptedTask& task = *owned;
  task.drop = 1.0;
  task.off = 0;
  task.last = 1000;
  EvalState s(m, GraphBrain(m.brain), cfg, std::move(owned));
  int steps = 0;
  while (step(m, cfg, s)) ++steps;
  EXPECT_TRUE(s.failed);
  EXPECT_NE(s.failure.find("numerical explosion at t="), std::string::npos) << s.failure;
  EXPECT_EQ(s.physics_steps, steps + 1);
  EXPECT_EQ(task.observed(), steps);  // the failing step is not observed
}

TEST(Step, TheThrowingTaskIsRefusedToACreatureWithoutACatapult) {
  SimConfig cfg;
  CreatureModel m = grow("walker.json", cfg);
  cfg.task_kind = TaskKind::Throwing;
  auto t = make_task(m, cfg, 1, 0);
  ASSERT_FALSE(t.ok());
  EXPECT_NE(t.error().find("not a catapult"), std::string::npos) << t.error();
  cfg.task_kind = TaskKind::Locomotion;
  EXPECT_TRUE(make_task(m, cfg, 1, 0).ok());
}

// A controller that is no graph brain: an open-loop oscillator whose
// frequency the task gives it as an input, one signal for every effector, and
// its own clock (s) as its one task output.
struct Oscillator : ControllerModel {
  int sensors = 0, effectors = 0;
  int n_sensors() const override { return sensors; }
  int n_effectors() const override { return effectors; }
  int n_task_inputs() const override { return 1; }
  int n_task_outputs() const override { return 1; }
  struct State : ControllerState {
    std::vector<double> out, seen;
    double t = 0;
    double clock[1] = {0};
    void step(std::span<const double> sensors, std::span<const double> in, double dt) override {
      seen.assign(sensors.begin(), sensors.end());
      t += dt;
      clock[0] = t;
      for (double& o : out) o = std::sin(2 * kPi * in[0] * t);
    }
    std::span<const double> effectors() const override { return out; }
    std::span<const double> task_outputs() const override { return clock; }
    std::span<const double> sensors() const override { return seen; }
    std::span<const double> internals() const override { return {}; }
  };
  std::unique_ptr<ControllerState> make_state() const override {
    auto s = std::make_unique<State>();
    s->out.assign(static_cast<std::size_t>(effectors), 0.0);
    s->seen.assign(static_cast<std::size_t>(sensors), 0.0);
    return s;
  }
};

// a task that gives the controller a frequency (Hz), runs for 4 s and
// keeps, at each act, the controller's task output
struct FrequencyTask : ScriptedTask {
  double hz = 1;
  std::vector<double> outputs;
  int n_inputs() const override { return 1; }
  void inputs(const Observation&, std::span<double> out) const override { out[0] = hz; }
  int n_outputs() const override { return 1; }
  void act(const CreatureModel&, std::span<const double> out, WorldEdits&, const Observation&) override {
    outputs.push_back(out[0]);
  }
};

TEST(Step, AControllerThatIsNoGraphBrainDrivesTheBodyOnTheTasksInputs) {
  SimConfig cfg;
  CreatureModel m = grow("hinged_pair.json", cfg);
  // velocity servos, so the hinge's angle is the signal's integral (the
  // dialect's torque motors flip the light pair over)
  cfg.motor.model = MotorModel::Servo;
  cfg.motor.max_speed = 2;
  cfg.motor.max_force = 50;
  for (double hz : {0.5, 1.0}) {
    Oscillator osc;
    osc.sensors = static_cast<int>(m.sensors.size());
    osc.effectors = static_cast<int>(m.effectors.size());
    ASSERT_GT(osc.effectors, 0);
    auto owned = std::make_unique<FrequencyTask>();
    FrequencyTask& task = *owned;
    task.hz = hz;
    task.off = 0;
    task.last = static_cast<int>(std::lround(4 / cfg.physics.dt));
    EvalState s(m, osc, cfg, std::move(owned));
    // the joint swings both ways, once per period of the task's frequency
    std::vector<double> angle;
    while (!s.task->done() && step(m, cfg, s)) angle.push_back(s.world.joint_position(0, 0));
    const double lo = *std::min_element(angle.begin(), angle.end());
    const double hi = *std::max_element(angle.begin(), angle.end());
    // swings: crossings of the middle, counted with a hysteresis of a fifth of the range
    int crossings = 0, side = 0;
    for (double a : angle) {
      double u = (a - lo) / (hi - lo);
      int now = u > 0.6 ? 1 : u < 0.4 ? -1 : side;
      if (side != 0 && now != side) ++crossings;
      side = now;
    }
    EXPECT_FALSE(s.failed) << s.failure;
    EXPECT_GT(hi - lo, 0.3) << hz << " Hz";
    EXPECT_NEAR(crossings, 2 * 4 * hz, 1) << hz << " Hz";
    // the body's sensors reached it too
    EXPECT_EQ(s.controller->sensors().size(), m.sensors.size());
    // and the task read the controller's output of the step it had just
    // thought: its clock, a brain step ahead of the world's time before the step
    ASSERT_EQ(task.outputs.size(), angle.size());
    const double brain_dt = 1 / cfg.brain_hz;
    for (std::size_t k = 0; k < task.outputs.size(); ++k)
      ASSERT_NEAR(task.outputs[k], brain_dt * static_cast<double>(brain_steps_due(static_cast<long>(k) + 1, cfg.physics.dt, cfg.brain_hz)), 1e-9) << k;
  }
}

}  // namespace
}  // namespace bx
