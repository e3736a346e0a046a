// Locomotion scoring: metrics, the measurement window, chaumont2007's
// activation sequence and eq. 1.
#include "task/locomotion.h"

#include <gtest/gtest.h>

#include <cmath>

#include "develop/creature_model.h"

namespace bx {
namespace {

// a one-part creature as a point that moves to a given place each step
struct PointPath {
  PointPath(LocomotionTask& task, double dt, Vec3 start) : task(task), dt(dt), p(start) { task.start(p, {p}); }
  void step(Vec3 to) {
    time += dt;
    p = to;
    task.observe(time, p, {p});
  }
  LocomotionTask& task;
  double dt, time = 0;
  Vec3 p;
};

TEST(Locomotion, MiconiCountsDistanceAlongXAfterTheFirstEighth) {
  LocomotionDef def;
  def.seconds = 8;
  def.metric = DistanceMetric::AlongX;
  def.skip_fraction = 1.0 / 8;
  LocomotionTask t(def, 0.5, 1);
  t.start({0, 0, 0}, {});
  t.observe(0.5, {5, 0, 0}, {});  // falling over in the first second does not count
  t.observe(1.0, {6, 3, 0}, {});
  EXPECT_FALSE(t.done());
  t.observe(8.0, {4, 9, 0}, {});
  EXPECT_TRUE(t.done());
  EXPECT_DOUBLE_EQ(t.distance(), -2.0);
  EXPECT_DOUBLE_EQ(t.measured_seconds(), 7.0);
}

TEST(Locomotion, PlanarDistanceAndSpeed) {
  LocomotionDef def;
  def.seconds = 4;
  def.fitness = LocomotionFitness::Speed;
  LocomotionTask t(def, 1.0, 1);
  t.start({1, 1, 0}, {});
  for (int i = 1; i <= 4; ++i) t.observe(i, {1 + 0.75 * i, 1 + 1.0 * i, 0.3}, {});
  EXPECT_DOUBLE_EQ(t.distance(), 5.0);
  CreatureModel m;
  EXPECT_DOUBLE_EQ(t.fitness(m), 1.25);
}

TEST(Locomotion, ChaumontSequenceGatesTheControllerAndMeasuresOnlyTheLastPhase) {
  LocomotionDef def;
  def.activation = Activation::Chaumont2007;
  def.seconds = 2;
  def.burst_seconds = 1;
  const double dt = 0.1;
  def.settle.seconds = 3 * dt;  // three steps
  def.settle.speed = 0.1;       // 0.01 m per step
  LocomotionTask t(def, dt, 1);
  PointPath path(t, dt, {0, 0, 1});
  Vec3& p = path.p;
  auto step = [&](Vec3 to) { path.step(to); };
  // falling: not settled, controller off
  step({0, 0, 0.5});
  step({0, 0, 0.0});
  EXPECT_EQ(t.phase(), Phase::Settle1);
  EXPECT_FALSE(t.controller_on());
  // three still steps: settled, the burst begins
  for (int i = 0; i < 3; ++i) step(p);
  EXPECT_EQ(t.phase(), Phase::Burst);
  EXPECT_TRUE(t.controller_on());
  // motion during the burst is not counted
  for (int i = 0; i < 10; ++i) step({p.x + 0.5, 0, 0});
  EXPECT_EQ(t.phase(), Phase::Settle2);
  EXPECT_FALSE(t.controller_on());
  for (int i = 0; i < 3; ++i) step(p);
  EXPECT_EQ(t.phase(), Phase::Measure);
  Vec3 start = p;
  for (int i = 0; i < 20; ++i) step({p.x + 0.1, 0, 0});
  EXPECT_TRUE(t.done());
  EXPECT_NEAR(t.distance(), norm(p - start), 1e-12);
  EXPECT_NEAR(t.distance(), 2.0, 1e-9);
}

TEST(Locomotion, SettlingIsASpeedHeldForSettleSecondsWhateverTheStep) {
  // a part creeping at 0.1 m/s is still under settle_speed 0.2 m/s at any
  // step length, and settles after settle_seconds: 0.5 s = 30 steps at
  // 60 Hz, 60 steps at 120 Hz; at 0.3 m/s it never settles
  for (int hz : {60, 120, 240}) {
    const double dt = 1.0 / hz;
    for (double speed : {0.1, 0.3}) {
      LocomotionDef def;
      def.activation = Activation::Chaumont2007;
      LocomotionTask t(def, dt, 1);
      Vec3 p{0, 0, 0};
      t.start(p, {p});
      long steps = 0;
      while (t.phase() == Phase::Settle1 && steps < 10 * hz) {
        p.x += speed * dt;
        t.observe(static_cast<double>(++steps) * dt, p, {p});
      }
      if (speed < def.settle.speed) {
        EXPECT_EQ(t.phase(), Phase::Burst) << hz << " Hz";
        EXPECT_EQ(steps, hz / 2) << hz << " Hz";
      } else {
        EXPECT_TRUE(t.done()) << hz << " Hz";
        EXPECT_EQ(t.note(), "never settled within settle_timeout");
      }
    }
  }
}

TEST(Locomotion, ChaumontFitnessFollowsEquationOne) {
  CreatureModel m;
  PartModel a, b;
  a.size = {1, 2, 3};
  b.size = {2, 2, 2};
  m.parts = {a, b};
  // C_l = mean(6, 6) = 6, C_s = mean(22, 24) = 23, C_v = mean(6, 8) = 7
  EXPECT_NEAR(chaumont_size_factor(m, 1.02), 7.0 / (23.0 * 6.0) * 1.02 * 1.02, 1e-15);
  LocomotionDef def;
  def.seconds = 1;
  def.fitness = LocomotionFitness::Chaumont2007;
  LocomotionTask t(def, 1.0, 2);
  t.start({0, 0, 0}, {});
  t.observe(1.0, {3, 4, 0}, {});
  EXPECT_NEAR(t.fitness(m), 5.0 * chaumont_size_factor(m, 1.02), 1e-15);
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

// an observation of a lone root part turned by R
struct OnePart : Observation {
  Mat3 R;
  Vec3 f{1, 0, 0};
  Vec3 front() const override { return f; }
  double time() const override { return 0; }
  Vec3 centre_of_mass() const override { return {}; }
  int n_parts() const override { return 1; }
  Pose part_pose(int) const override { return {{0, 0, 0}, R}; }
  bool touches_part(int) const override { return false; }
};

TEST(Heading, IsTheRootsXAxisTurnedOnTheGround) {
  OnePart o;
  EXPECT_DOUBLE_EQ(heading(o), 0);
  o.R = Mat3::rotation({0, 0, 1}, 0.5);
  EXPECT_NEAR(heading(o), 0.5, 1e-12);
  o.R = Mat3::rotation({0, 0, 1}, -2.5);
  EXPECT_NEAR(heading(o), -2.5, 1e-12);
  // pitching or rolling does not turn it
  o.R = Mat3::rotation({0, 0, 1}, 0.5) * Mat3::rotation({0, 1, 0}, 0.7) * Mat3::rotation({1, 0, 0}, 0.3);
  EXPECT_NEAR(heading(o), 0.5, 1e-12);
  // nose straight up: no heading
  o.R = Mat3::rotation({0, 1, 0}, -kPi / 2);
  EXPECT_DOUBLE_EQ(heading(o), 0);
  EXPECT_NEAR(root_level(o), 0, 1e-12);
}

// task.front: another axis of the root is the creature's front
TEST(Heading, IsTheFrontAxisTheConfigNames) {
  EXPECT_EQ(axis_vector(RootAxis::PlusX), (Vec3{1, 0, 0}));
  EXPECT_EQ(axis_vector(RootAxis::MinusY), (Vec3{0, -1, 0}));
  EXPECT_EQ(axis_vector(RootAxis::MinusZ), (Vec3{0, 0, -1}));
  OnePart o;
  o.R = Mat3::rotation({0, 0, 1}, 0.5);
  o.f = axis_vector(RootAxis::MinusX);
  EXPECT_NEAR(heading(o), 0.5 - kPi, 1e-12);
  o.f = axis_vector(RootAxis::PlusY);
  EXPECT_NEAR(heading(o), 0.5 + kPi / 2, 1e-12);
  // lying on its side (rolled a quarter turn about x: its -z along +y), turned by 0.5
  o.R = Mat3::rotation({0, 0, 1}, 0.5) * Mat3::rotation({1, 0, 0}, kPi / 2);
  o.f = axis_vector(RootAxis::MinusZ);
  EXPECT_NEAR(heading(o), 0.5 + kPi / 2, 1e-12);
  EXPECT_NEAR(root_level(o), 1, 1e-12);
  o.f = axis_vector(RootAxis::PlusY);  // now vertical: no heading
  EXPECT_NEAR(root_level(o), 0, 1e-12);
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

TEST(Locomotion, SettledStartsWithTheControllerOffAndMeasuresFromRest) {
  LocomotionDef def;
  def.activation = Activation::Settled;
  def.seconds = 1;
  const double dt = 0.1;
  def.settle.seconds = 2 * dt;
  def.settle.speed = 0.1;
  def.settle.timeout = 5;
  LocomotionTask t(def, dt, 1);
  EXPECT_EQ(t.max_steps(), 61);  // (timeout + seconds) / dt, and a step
  PointPath path(t, dt, {0, 0, 1});
  Vec3& p = path.p;
  auto step = [&](Vec3 to) { path.step(to); };
  EXPECT_FALSE(t.controller_on());
  step({1, 0, 0.5});  // toppling out of its built pose: not counted
  step({2, 0, 0});
  step(p);
  step(p);
  EXPECT_EQ(t.phase(), Phase::Measure);
  EXPECT_TRUE(t.controller_on());
  for (int i = 0; i < 10; ++i) step({p.x + 0.05, 0, 0});
  EXPECT_TRUE(t.done());
  EXPECT_NEAR(t.distance(), 0.5, 1e-9);
  EXPECT_NEAR(t.measured_seconds(), 1.0, 1e-9);
}

// the distance that scores with windows: the least span's, times their number
TEST(Locomotion, WindowsScoreOnlyMotionThatLasts) {
  auto scored = [](int windows, const std::vector<double>& x_each_second) {
    LocomotionDef def;
    def.seconds = 4;
    def.windows = windows;
    LocomotionTask t(def, 1.0, 1);
    t.start({0, 0, 0}, {});
    for (std::size_t i = 0; i < x_each_second.size(); ++i)
      t.observe(static_cast<double>(i + 1), {x_each_second[i], 0, 0}, {});
    EXPECT_EQ(t.done(), x_each_second.size() == 4);
    return t.scored_distance();
  };
  const std::vector<double> steady{1, 2, 3, 4}, fall{2, 2, 2, 2}, slowing{1.5, 3, 3.5, 4};
  EXPECT_DOUBLE_EQ(scored(1, steady), 4);
  EXPECT_DOUBLE_EQ(scored(2, steady), 4);
  EXPECT_DOUBLE_EQ(scored(4, steady), 4);
  EXPECT_DOUBLE_EQ(scored(1, fall), 2);
  EXPECT_DOUBLE_EQ(scored(2, fall), 0);  // it fell in the first span and lay still
  EXPECT_DOUBLE_EQ(scored(2, slowing), 2);  // 3 m, then 1 m: twice the second
  EXPECT_DOUBLE_EQ(scored(4, slowing), 2);
  // cut short, the missing span counts 0
  EXPECT_DOUBLE_EQ(scored(2, {1, 2}), 0);
}

// an observation of a point moving along x with a muscle-work meter
struct Meter : Observation {
  double t = 0, x = 0, work = 0;
  double time() const override { return t; }
  Vec3 centre_of_mass() const override { return {x, 0, 0}; }
  int n_parts() const override { return 1; }
  Pose part_pose(int) const override { return {{x, 0, 0}, Mat3::identity()}; }
  bool touches_part(int) const override { return false; }
  double muscle_work() const override { return work; }
};

TEST(Locomotion, Lessin2015FitnessIsTheSpeedStepsPlusTheEfficiency) {
  // 2 kg under g = 10 travel 4 m in 4 s for 80 J of muscle work and
  // 5 W/kg x 2 kg x 4 s = 40 J at rest: a gross cost of transport
  // 120 / (2 x 10 x 4) = 1.5, so efficiency 1 / (1 + 1.5) = 0.4; speed
  // 1 m/s in steps of 0.3 is 3 steps: 0.3 (3 + 0.4) / s_max 2
  CreatureModel m;
  PartModel a, b;
  a.mass = 1.5;
  b.mass = 0.5;
  m.parts = {a, b};
  LocomotionDef def;
  def.seconds = 4;
  def.fitness = LocomotionFitness::Lessin2015;
  def.speed_step = 0.3;
  def.max_speed = 2;
  def.basal_power = 5;
  LocomotionTask t(def, 1.0, 2, -10);
  Meter o;
  o.work = 7;  // before measuring: not counted
  t.begin(o);
  for (int i = 1; i <= 4; ++i) {
    o.t = i;
    o.x = i;
    o.work = 7 + 20 * i;
    t.observe(o);
  }
  EXPECT_TRUE(t.done());
  EXPECT_DOUBLE_EQ(t.measured_work(), 80);
  EXPECT_NEAR(lessin_efficiency(4, 4, 80, 2, 10, 5), 0.4, 1e-15);
  EXPECT_NEAR(t.fitness(m), 0.3 * 3.4 / 2, 1e-12);
  const TaskScore s = t.score(m);
  ASSERT_EQ(s.metrics.size(), 3u);
  EXPECT_EQ(s.metrics[0].name, "speed");
  EXPECT_NEAR(s.metrics[0].value, 1, 1e-12);
  EXPECT_EQ(s.metrics[1].name, "efficiency");
  EXPECT_NEAR(s.metrics[1].value, 0.4, 1e-12);
  EXPECT_EQ(s.metrics[2].name, "muscle_work");
  EXPECT_NEAR(s.metrics[2].value, 80, 1e-12);
}

TEST(Locomotion, Lessin2015EfficiencyFallsToZeroWithTheSpeed) {
  // no distance, no efficiency
  EXPECT_EQ(lessin_efficiency(0, 10, 80, 2, 10, 1), 0);
  // without a resting cost a creature that drifts 0.1 mm for free would be
  // perfectly efficient; with one, its efficiency is at most g s / (g s + b)
  EXPECT_EQ(lessin_efficiency(1e-4, 10, 0, 2, 10, 0), 1);
  const double s = 1e-5, bound = 10 * s / (10 * s + 1);
  EXPECT_NEAR(lessin_efficiency(1e-4, 10, 0, 2, 10, 1), bound, 1e-15);
  EXPECT_LT(bound, 1e-4);
  // faster for the same work: more efficient
  EXPECT_LT(lessin_efficiency(1, 10, 50, 2, 10, 1), lessin_efficiency(2, 10, 50, 2, 10, 1));
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

// a point creature whose root is turned by `h` about +z
struct Walker : Observation {
  double t = 0, h = 0;
  Vec3 com;
  double time() const override { return t; }
  Vec3 centre_of_mass() const override { return com; }
  int n_parts() const override { return 1; }
  Pose part_pose(int) const override { return {com, Mat3::rotation({0, 0, 1}, h)}; }
  bool touches_part(int) const override { return false; }
};

// task.metric = "forward": the displacement along the heading the root had
// when measuring began, whatever it turns to afterwards
TEST(Locomotion, ForwardCountsDisplacementAlongTheHeadingWhenMeasuringBegan) {
  auto walked = [](DistanceMetric metric, double h0, Vec3 step, double turn_to, int windows = 1) {
    LocomotionDef def;
    def.seconds = 4;
    def.metric = metric;
    def.windows = windows;
    LocomotionTask t(def, 1.0, 1);
    Walker o;
    o.h = h0;
    o.com = {1, 2, 0.5};
    t.begin(o);
    for (int i = 1; i <= 4; ++i) {
      o.t = i;
      o.h = turn_to;  // turning away after the start changes nothing
      o.com = o.com + step;
      t.observe(o);
    }
    EXPECT_TRUE(t.done());
    return t.scored_distance();
  };
  const double h = kPi / 6;  // 30 degrees
  const Vec3 along{0.5 * std::cos(h), 0.5 * std::sin(h), 0};
  EXPECT_NEAR(walked(DistanceMetric::Forward, h, along, 2.0), 2, 1e-12);
  EXPECT_NEAR(walked(DistanceMetric::Forward, h, -1.0 * along, 2.0), -2, 1e-12);  // backwards
  // along +x: its share on the heading; square to it: nothing
  EXPECT_NEAR(walked(DistanceMetric::Forward, h, {0.5, 0, 0}, -1.0), 2 * std::cos(h), 1e-12);
  EXPECT_NEAR(walked(DistanceMetric::Forward, h, {-0.5 * std::sin(h), 0.5 * std::cos(h), 0}, 0.0), 0, 1e-12);
  // planar and x for the same walks
  EXPECT_NEAR(walked(DistanceMetric::Planar, h, {-0.5 * std::sin(h), 0.5 * std::cos(h), 0}, 0.0), 2, 1e-12);
  EXPECT_NEAR(walked(DistanceMetric::AlongX, h, along, 0.0), 2 * std::cos(h), 1e-12);
  // windows measure along the same forward
  EXPECT_NEAR(walked(DistanceMetric::Forward, h, along, 2.0, 2), 2, 1e-12);
}

// task.metric = "front": the path travelled front first. A walker that
// goes round a circle nose first scores the circle's path (the chords of
// its steps, each along the heading it started from); backwards, minus
// that; sideways, nothing; "forward" scores the same circle nearly 0.
TEST(Locomotion, FrontCountsThePathTravelledFrontFirst) {
  auto circled = [](DistanceMetric metric, double facing, int windows = 1) {
    LocomotionDef def;
    const int n = 64;  // steps round the circle
    def.seconds = n;
    def.metric = metric;
    def.windows = windows;
    LocomotionTask t(def, 1.0, 1);
    Walker o;
    const double r = 2;
    auto at = [&](int i) {
      const double a = 2 * kPi * i / n;
      o.com = {r * std::cos(a), r * std::sin(a), 0.5};
      o.h = a + kPi / 2 + facing;  // the tangent, turned by `facing`
    };
    at(0);
    t.begin(o);
    for (int i = 1; i <= n; ++i) {
      o.t = i;
      at(i);
      t.observe(o);
    }
    EXPECT_TRUE(t.done());
    return t.scored_distance();
  };
  // each step's chord 2 r sin(pi / n), along a heading half a step behind it
  const double chord = 2 * 2 * std::sin(kPi / 64), along = chord * std::cos(kPi / 64);
  EXPECT_NEAR(circled(DistanceMetric::Front, 0), 64 * along, 1e-9);
  EXPECT_NEAR(64 * along, 2 * kPi * 2, 0.03);  // about the circumference
  EXPECT_NEAR(circled(DistanceMetric::Front, kPi), -64 * along, 1e-9);    // backwards
  // sideways: only each chord's tilt from the side (half a step's turn), 5% of the path
  EXPECT_NEAR(circled(DistanceMetric::Front, kPi / 2), 64 * chord * std::sin(kPi / 64), 1e-9);
  EXPECT_NEAR(circled(DistanceMetric::Forward, 0), 0, 1e-9);              // back where it began
  // windows: the least half, twice
  EXPECT_NEAR(circled(DistanceMetric::Front, 0, 2), 64 * along, 1e-9);
}

// measuring after settling: forward is the heading when settling ended
TEST(Locomotion, ForwardIsTheHeadingWhenSettlingEnded) {
  LocomotionDef def;
  def.activation = Activation::Settled;
  def.metric = DistanceMetric::Forward;
  def.seconds = 1;
  const double dt = 0.125;
  def.settle.seconds = 2 * dt;
  def.settle.speed = 0.1;
  LocomotionTask t(def, dt, 1);
  Walker o;
  o.h = 0.3;
  t.begin(o);
  o.t += dt;
  o.h = 1.0;  // turned while settling (its parts still: a turn in place)
  t.observe(o);
  while (t.phase() != Phase::Measure) {
    o.t += dt;
    t.observe(o);
  }
  while (!t.done()) {
    o.t += dt;
    o.com = o.com + Vec3{0.1, 0, 0};
    t.observe(o);
  }
  EXPECT_NEAR(t.distance(), 0.8 * std::cos(1.0), 1e-12);
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

// The replay's record: the scored span's markers, and the distance as the
// task counts it (here along x, after the first eighth), a counter in metres
// recorded whenever it moved by kDistanceStep and at the end, so a viewer
// shows the distance that scores and where its span lies.
TEST(Locomotion, RecordsTheScoredSpanAndItsDistanceAsItGoes) {
  LocomotionDef def;
  def.seconds = 8;
  def.metric = DistanceMetric::AlongX;
  def.skip_fraction = 1.0 / 8;
  LocomotionTask task(def, 0.5, 1);
  Walker w;
  task.begin(w);
  SceneRecord rec;
  task.record(w, rec);
  for (int k = 1; k <= 16; ++k) {
    w.t = 0.5 * k;
    // 5 m in the first second (a fall: not scored), then 2 mm a step, then 2 cm
    w.com = {k <= 2 ? 2.5 * k : k <= 8 ? 5 + 0.002 * (k - 2) : 5.012 + 0.02 * (k - 8), 0, 0};
    task.observe(w);
    task.record(w, rec);
  }
  task.record(w, rec);  // the loop's last call changes nothing more
  ASSERT_TRUE(task.done());
  EXPECT_EQ(rec.marker(kScoredFrom), 1.0);
  EXPECT_EQ(rec.marker(kScoredTo), 8.0);
  std::vector<std::pair<double, double>> counted;
  for (const SceneEvent& e : rec.events) {
    const auto& c = std::get<SceneCounter>(e.what);
    EXPECT_EQ(c.name, "distance");
    EXPECT_EQ(c.unit, "m");
    counted.push_back({e.t, c.value});
  }
  // 0 when measuring began; 6 mm at 2.5 s and 12 mm at 4 s (steps of 2 mm);
  // then every 2 cm step
  ASSERT_EQ(counted.size(), 3u + 8u);
  EXPECT_EQ(counted[0], (std::pair<double, double>{1.0, 0.0}));
  EXPECT_EQ(counted[1].first, 2.5);
  EXPECT_NEAR(counted[1].second, 0.006, 1e-12);
  EXPECT_EQ(counted[2].first, 4.0);
  EXPECT_NEAR(counted[2].second, 0.012, 1e-12);
  EXPECT_EQ(counted.back().first, 8.0);
  EXPECT_DOUBLE_EQ(counted.back().second, task.distance());
  EXPECT_NEAR(task.distance(), 0.172, 1e-12);
}

}  // namespace
}  // namespace bx
