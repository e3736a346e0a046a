// A law of physics as a test (docs/physics.md): a creature whose joints are
// bounded, driven by constant effector signals, comes to rest. A motor held
// at one command does no net work over a bounded joint's excursion, gravity
// is conservative and contacts dissipate, so any sustained travel would be
// paid for by constraint error: a simulator artefact that evolution finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/rng.h"
#include "develop/develop.h"
#include "eval/check.h"
#include "eval/evaluate.h"
#include "genome/dialect.h"
#include "genome/genome_json.h"
#include "io/config.h"

namespace bx {
namespace {

// settle this long, then measure this long (s)
constexpr double kSettle = 5, kMeasure = 15;
// after settling, the centre of mass travels less than this share of the body
// length in 15 s (measured: docs/physics.md); `check` forgives a clamped
// creature whose distance was a transient by the same bound
constexpr double kMostTravel = kRestTravel;
// joints stay within this (m) at every moment, the canonical creatures' within
// 4.6 mm (docs/physics.md); no contact sinks deeper than this (m)
constexpr double kMostGap = 0.01, kMostDepth = 0.05;


// the dialect's physics and motors, the brain bypassed: every effector at
// `signal` from the first step, distance counted after the settling time
SimConfig clamped(Dialect d, double signal) {
  SimConfig c = default_run_config(d).sim;
  c.task.activation = Activation::Always;
  c.task.fitness = LocomotionFitness::Distance;
  c.task.metric = DistanceMetric::Planar;
  c.task.seconds = kSettle + kMeasure;
  c.task.skip_fraction = kSettle / (kSettle + kMeasure);
  c.effector_clamp = {signal};
  return c;
}

// every driven degree of freedom has stops (an unbounded joint driven at a
// constant is a wheel, and may roll for real)
bool bounded(const CreatureModel& m) {
  for (const auto& e : m.effectors) {
    if (e.muscle >= 0) continue;  // a spring: it pulls towards its rest length
    const JointModel& j = m.joints[e.joint];
    if (e.dof >= static_cast<int>(j.limits.size())) return false;
    if (!(j.limits[e.dof].hi - j.limits[e.dof].lo < 2 * kPi - 1e-9)) return false;
  }
  return true;
}

struct Outcome {
  double travel = 0;  // share of the body length
  double gap = 0, depth = 0;
  std::string failure;
};

// the creature evaluated under `c` (the rest law's clamped config, or a variant)
Outcome rest(const CreatureModel& m, const SimConfig& c, std::uint64_t seed) {
  EvalResult r = evaluate(m, c, seed);
  return {std::abs(r.distance) / m.body_length(), r.diagnostics.max_joint_gap,
          r.diagnostics.max_penetration, r.failed ? r.failure : ""};
}

Outcome rest(const CreatureModel& m, Dialect d, double signal, std::uint64_t seed) {
  return rest(m, clamped(d, signal), seed);
}

const double kSignals[] = {-1, -0.3, 0.3, 1};

TEST(RestLaw, CanonicalCreaturesWithConstantSignalsComeToRest) {
  for (const char* name : {"hinged_pair.json", "snake.json", "centipede.json", "walker.json"}) {
    auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name);
    ASSERT_TRUE(g.ok()) << g.error();
    Development dev = develop(*g, default_run_config(g->dialect).sim.develop);
    ASSERT_TRUE(dev.viable()) << name;
    ASSERT_TRUE(bounded(*dev.model)) << name;
    for (double s : kSignals) {
      Outcome o = rest(*dev.model, g->dialect, s, 1);
      EXPECT_EQ(o.failure, "") << name << " at " << s;
      EXPECT_LT(o.travel, kMostTravel) << name << " at " << s;
      EXPECT_LT(o.gap, kMostGap) << name << " at " << s;
      EXPECT_LT(o.depth, kMostDepth) << name << " at " << s;
    }
  }
}

// A creature from creatures/, developed with its dialect's defaults.
CreatureModel canonical(const std::string& name, Dialect* dialect = nullptr) {
  auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name);
  EXPECT_TRUE(g.ok()) << g.error();
  Development dev = develop(*g, default_run_config(g->dialect).sim.develop);
  EXPECT_TRUE(dev.viable()) << name;
  if (dialect) *dialect = g->dialect;
  return *dev.model;
}

TEST(FrictionBound, ACreatureThatGlidedOnOdesFrictionPyramidRests) {
  // glider.json (the random miconi2006 creature 56 of RestLawRandom): its
  // motors press its three 40-120 g limbs together and the ground holds it
  // at the edge of friction. ODE's exact solver bounds a friction row by
  // the normal force as it stands when the solver reaches that row (0 here)
  // and left it gliding on frictionless ground at 0.16 m/s, its pose frozen
  Dialect d;
  CreatureModel m = canonical("glider.json", &d);
  SimConfig c = clamped(d, 1);
  // as it was found, before causes 11-13
  c.physics.self_collision = true;
  c.physics.powered_stops = PoweredStops::Ode;
  c.motor.response_time = 0;
  c.physics.friction_bound = FrictionBound::Ode;
  Outcome ode = rest(m, c, 56);
  EXPECT_EQ(ode.failure, "");
  EXPECT_GT(ode.travel, 1.0);
  // the lagged bound of a steady contact: mu times its last normal forces
  c.physics.friction_bound = FrictionBound::Lagged;
  Outcome lagged = rest(m, c, 56);
  EXPECT_EQ(lagged.failure, "");
  EXPECT_LT(lagged.travel, kMostTravel);
}

TEST(JointFriction, ALimbLeftSwingingAfterTheBurstStopsWhenMotorsBrake) {
  // swinger.json: the best of `run chaumont2007-walker-small --seed 1`
  // (33 parts). With frictionless limp joints, as in the paper's ODE, at
  // 1/480 s its 80 g limb 11 swings stop to stop after the 1 s burst and never
  // stops, so the activation sequence scores it 0; at its own 1/240 s it came
  // to rest (docs/physics.md cause 15)
  Dialect d;
  CreatureModel m = canonical("swinger.json", &d);
  SimConfig c = default_run_config(d).sim;
  ASSERT_EQ(c.task.activation, Activation::Chaumont2007);
  c.task.seconds = 1;
  const std::uint64_t seed = 2213218683792410103ULL;  // its evaluation seed in that run
  c.physics.dt = 1.0 / 480;
  EXPECT_EQ(evaluate(m, c, seed).note, "never settled within settle_timeout");
  // a motor that brakes with 1% of its force while the controller is off:
  // the limb stops, at every step
  c.motor.off_brake = 0.01;
  for (double dt : {1.0 / 240, 1.0 / 480, 1.0 / 960}) {
    c.physics.dt = dt;
    EvalResult r = evaluate(m, c, seed);
    EXPECT_EQ(r.note, "") << "dt " << dt;
    EXPECT_FALSE(r.failed) << r.failure;
    // settled twice and measured: the measured second ends before 5 s
    EXPECT_LT(r.seconds, 5) << "dt " << dt;
  }
}

TEST(SelfCollision, Miconi2006LimbsWedgedIntoEachOtherNoLongerCarryTheCreature) {
  // wedger.json: the best of `run miconi2006-small --seed 1` on self-colliding
  // limbs (84.7 m in 100 s). Its servos press a 33 g foot 24 mm deep into
  // its 14 g upper leg and its joints into their stops; contact and stops
  // each correct their error, the solver flips the contact's friction every
  // step and the creature glides with a frozen pose (docs/physics.md cause 11)
  Dialect d;
  CreatureModel m = canonical("wedger.json", &d);
  SimConfig c = clamped(d, 0);
  c.effector_clamp = {0.98, 0.48, -0.86, 0.98, 0.48, -0.86};  // its evolved commands
  c.physics.self_collision = true;
  Outcome wedged = rest(m, c, 1);
  EXPECT_EQ(wedged.failure, "");
  EXPECT_GT(wedged.travel, 1.0);
  // the dialect's default: limbs pass through each other, joints rest at their stops
  c.physics.self_collision = default_sim_config(d).physics.self_collision;
  Outcome free = rest(m, c, 1);
  EXPECT_EQ(free.failure, "");
  EXPECT_LT(free.travel, kMostTravel);
}

TEST(RollingFriction, ACylinderCarryingAnOffsetBlockStopsRocking) {
  // rocker.json (random sims1994 creature 107): a cylinder with a block on a
  // universal joint; nothing rigid dissipates rolling, so without rolling
  // resistance it rocks back and forth for ever (about 0.3 m either way)
  Dialect d;
  CreatureModel m = canonical("rocker.json", &d);
  SimConfig c = clamped(d, 0.3);
  c.physics.rolling_friction = 0;
  EXPECT_GT(rest(m, c, 107).travel, 0.1);
  c.physics.rolling_friction = default_sim_config(d).physics.rolling_friction;
  EXPECT_LT(rest(m, c, 107).travel, kMostTravel);
}

TEST(TorqueMotor, FullTorqueDoesNotSlamALightLegThroughItsStop) {
  // sims1994's torque motors scale with the larger part's cross-section: a
  // pure torque from rest threw the walker's light legs a radian past their
  // stops and parted its universal joints by 5-9 cm; pushing only up to
  // 10 rad/s, they stay within 5 mm
  Dialect d;
  CreatureModel m = canonical("walker.json", &d);
  SimConfig c = clamped(d, -1);
  c.motor.torque_max_speed = 0;
  c.motor.torque_max_linear_speed = 0;
  c.physics.max_joint_gap = 1;
  EXPECT_GT(rest(m, c, 1).gap, 0.04);
  Outcome bounded = rest(m, clamped(d, -1), 1);
  EXPECT_EQ(bounded.failure, "");
  EXPECT_LT(bounded.gap, 0.005);
}

TEST(Solver, AContactPointTheColliderRepeatsIsKeptOnceSoTheStepIsSolved) {
  // lcp_failure.json (random sims1994 creature 91): at 0.74 s ODE's exact
  // solver reported "LCP internal error, s <= 0" and left the rows it did not
  // reach at zero force, so its evaluation failed (cause 9). The cause was a
  // contact point ODE's collider gave twice for one pair: two identical rows
  // make the LCP singular. Kept once (cause 30), the step is solved and the
  // creature comes to rest
  Dialect d;
  CreatureModel m = canonical("lcp_failure.json", &d);
  Outcome o = rest(m, clamped(d, 0.3), 91);
  EXPECT_EQ(o.failure, "");
  EXPECT_LT(o.travel, kMostTravel);
  EXPECT_LT(o.gap, kMostGap);
}

// Today's counts, out of 200 random creatures per dialect, of those that
// break the law: travel more than 2% of their length in the 15 s after
// settling, a joint more than 1 cm apart at any moment, a contact deeper
// than 5 cm, or a numerical explosion (measured on the exact solver with each
// dialect's defaults; docs/physics.md says which causes remain). A ratchet,
// not the law yet (issue 11 stays open): a change that raises any count
// fails; lower them here as causes are removed.
struct Allowed {
  int travel, gap, depth, failed;
};

Allowed allowed(Dialect d) {
  switch (d) {
    case Dialect::Sims1994: return {8, 27, 2, 0};  // 4 steps ODE could not solve, until repeated contacts went (cause 30)
    // causes 11-13 (no self-collision, motors beside the stops, a 0.05 s
    // motor lag): 7 -> 1 travel and 2 -> 1 deep, but 1 -> 3 joints part by
    // 1.1-1.6 cm for a moment in the first second (the landing, a limb's
    // first swing into its stop), then close again
    case Dialect::Miconi2006: return {1, 3, 1, 0};
    case Dialect::Chaumont2007: return {11, 9, 7, 0};
    // muscles at rest fraction 0.5 pulling joints whose parts collide, at
    // 1/240 s (at 1/60 s: 56 of 100 joints part, docs/physics.md cause 30)
    // Since slides are limited (DevelopDef::slide_range; unlimited, a slider
    // let its child drift off), 5 more: strong muscles slam a slider or a
    // cylinder's slide into its stop, which ODE meets a step late, 1.2-2.2
    // cm past it (about one step's travel at 1/240 s); travel 7 -> 6
    case Dialect::Lessin2015: return {6, 12, 0, 0};
  }
  return {};
}

class RestLawRandom : public ::testing::TestWithParam<Dialect> {};

TEST_P(RestLawRandom, TwoHundredRandomCreaturesWithConstantSignalsComeToRestBarTodaysKnownCount) {
  const Dialect d = GetParam();
  RunConfig run = default_run_config(d);
  Rng rng(stream_seed({2026, static_cast<std::uint64_t>(d)}));
  int tested = 0, unbounded = 0, tries = 0;
  Allowed seen{0, 0, 0, 0};
  std::string travellers;
  while (tested < 200 && tries < 20000) {
    ++tries;
    Genome g = random_genome(d, run.operators, rng);
    if (!validate(g).ok()) continue;
    Development dev = develop(g, run.sim.develop);
    if (!dev.viable() || dev.model->effectors.empty()) continue;
    if (!bounded(*dev.model)) {
      ++unbounded;
      continue;
    }
    // each creature under one of the constants, in turn
    double s = kSignals[tested % 4];
    Outcome o = rest(*dev.model, d, s, static_cast<std::uint64_t>(tested + 1));
    ++tested;
    if (o.travel >= kMostTravel) {
      ++seen.travel;
      char buf[64];
      std::snprintf(buf, sizeof buf, " %d@%.1f:%.3f", tested, s, o.travel);
      travellers += buf;
    }
    seen.gap += o.gap >= kMostGap;
    seen.depth += o.depth >= kMostDepth;
    seen.failed += !o.failure.empty();
  }
  ASSERT_EQ(tested, 200) << unbounded << " unbounded of " << tries;
  const Allowed a = allowed(d);
  EXPECT_LE(seen.travel, a.travel) << "creatures that travelled (index@signal:body lengths):" << travellers;
  EXPECT_LE(seen.gap, a.gap);
  EXPECT_LE(seen.depth, a.depth);
  EXPECT_LE(seen.failed, a.failed);
  std::printf("%s: of 200, %d travel, %d joint gaps, %d deep contacts, %d explosions (%d unbounded skipped)\n",
              std::string(to_string(d)).c_str(), seen.travel, seen.gap, seen.depth, seen.failed, unbounded);
}

INSTANTIATE_TEST_SUITE_P(EveryDialect, RestLawRandom,
                         ::testing::Values(Dialect::Sims1994, Dialect::Miconi2006, Dialect::Chaumont2007, Dialect::Lessin2015),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace bx
