// Config files: strict keys, typed values, ranges, and a lossless round trip.
#include "io/config.h"

#include "core/files.h"
#include "io/syllabus.h"

#include <gtest/gtest.h>

namespace bx {
namespace {

std::string apply_error(const std::string& toml) {
  RunConfig cfg = default_run_config(Dialect::Miconi2006);
  Status s = apply_config_toml(cfg, toml, "run.toml");
  return s.ok() ? "" : s.error();
}

TEST(Config, OverlaysValuesOntoTheDialectDefaults) {
  RunConfig cfg = default_run_config(Dialect::Miconi2006);
  EXPECT_EQ(cfg.sim.physics.erp, 0.2);  // not Table 1's 0.015 (docs/physics.md)
  EXPECT_EQ(cfg.sim.motor.model, MotorModel::Servo);
  ASSERT_TRUE(apply_config_toml(cfg, "[physics]\nerp = 0.5\nsolver_iterations = 40\n"
                                     "[motor]\nmodel = \"pd\"\n[task]\nmetric = \"planar\"\nseconds = 3\n",
                                "x.toml"));
  EXPECT_EQ(cfg.sim.physics.erp, 0.5);
  EXPECT_EQ(cfg.sim.physics.solver_iterations, 40);
  EXPECT_EQ(cfg.sim.physics.cfm, 1e-5);  // untouched keys keep the dialect's value
  EXPECT_EQ(cfg.sim.motor.model, MotorModel::PD);
  EXPECT_EQ(cfg.sim.task.metric, DistanceMetric::Planar);
  EXPECT_EQ(cfg.sim.task.seconds, 3.0);
}

TEST(Config, BadInputNamesTheKeyAndTheValue) {
  EXPECT_EQ(apply_error("[physics]\nerpp = 0.2\n"), "run.toml: physics.erpp: unknown key (did you mean \"erp\"?)");
  EXPECT_EQ(apply_error("[physic]\nerp = 0.2\n"), "run.toml: physic: unknown section (did you mean \"physics\"?)");
  EXPECT_EQ(apply_error("[physics]\ndt = \"fast\"\n"),
            "run.toml: physics.dt: expected a number, got \"fast\"");
  EXPECT_EQ(apply_error("[physics]\nerp = 1.5\n"), "run.toml: physics.erp: out of range [0, 1], got 1.5");
  EXPECT_EQ(apply_error("[physics]\nsolver_iterations = 2.5\n"),
            "run.toml: physics.solver_iterations: expected an integer, got 2.5");
  EXPECT_EQ(apply_error("[motor]\nmodel = \"jet\"\n"),
            "run.toml: motor.model: expected one of servo, saturation, torque, pd, muscle, got \"jet\"");
  EXPECT_EQ(apply_error("[physics]\nself_collision = 1\n"),
            "run.toml: physics.self_collision: expected true or false, got 1");
  EXPECT_EQ(apply_error("physics = 3\n"), "run.toml: physics: expected a table, got 3");
  EXPECT_EQ(apply_error("[physics\n").substr(0, 11), "run.toml:1:");
  EXPECT_EQ(apply_error("[evolution]\npopulation = 2\n"),
            "run.toml: evolution.population: out of range [3, 1000000], got 2");
  EXPECT_EQ(apply_error("[evolution]\nalgorithm = \"generational\"\np_asexual = 0.5\np_crossover = 0.3\n"
                        "p_graft = 0.4\n"),
            "run.toml: evolution.p_asexual + p_crossover + p_graft: must sum to 1, got 1.2");
  EXPECT_EQ(apply_error("[evolution]\nelite_evaluations = 0\n"),
            "run.toml: evolution.elite_evaluations: out of range [1, 1000], got 0");
}

// the keys that counted physics steps are gone: an old config fails on the
// first of them, naming the key in seconds (or per second) to use
TEST(Config, KeysCountedInPhysicsStepsAreRefusedNamingTheirReplacement) {
  EXPECT_EQ(apply_error("[brain]\nsteps_per_physics_step = 2\n"),
            "run.toml: brain.steps_per_physics_step: replaced by brain.rate_hz (brain steps per "
            "simulated second), got 2");
  EXPECT_EQ(apply_error("[task]\nsettle_threshold = 0.005\n"),
            "run.toml: task.settle_threshold: replaced by task.settle_speed (m/s), got 0.005");
  EXPECT_EQ(apply_error("[task]\nsettle_steps = 30\n"),
            "run.toml: task.settle_steps: replaced by task.settle_seconds (s), got 30");
  EXPECT_EQ(apply_error("[throwing]\nrest_steps = 30\n"),
            "run.toml: throwing.rest_steps: replaced by throwing.rest_seconds (s), got 30");
  EXPECT_EQ(read_run_config("", "r.toml", {"task.settle_steps=10"}).error(),
            "--set task.settle_steps=10: task.settle_steps: replaced by task.settle_seconds (s), got 10");
  // the new keys are read, in range
  auto c = read_run_config("[genome]\ndialect = \"chaumont2007\"\n[brain]\nrate_hz = 120\n", "r.toml",
                           {"task.settle_speed=0.1", "task.settle_seconds=0.25", "throwing.rest_seconds=1"});
  ASSERT_TRUE(c.ok()) << c.error();
  EXPECT_EQ(c->sim.brain_hz, 120.0);
  EXPECT_EQ(c->sim.task.settle.speed, 0.1);
  EXPECT_EQ(c->sim.task.settle.seconds, 0.25);
  EXPECT_EQ(c->sim.throwing.rest_seconds, 1.0);
  EXPECT_EQ(apply_error("[brain]\nrate_hz = 0\n"), "run.toml: brain.rate_hz: out of range [0.1, 100000], got 0");
  EXPECT_EQ(apply_error("[task]\nsettle_seconds = -1\n"),
            "run.toml: task.settle_seconds: out of range [0, 10000], got -1");
}

TEST(Config, RunConfigTakesTheDialectsDefaultsThenTheTextThenTheOverrides) {
  auto c = read_run_config("[genome]\ndialect = \"miconi2006\"\n[evolution]\npopulation = 50\n", "r.toml",
                           {"evolution.population=60", "motor.model=pd", "task.seconds=5"});
  ASSERT_TRUE(c.ok()) << c.error();
  EXPECT_EQ(c->dialect, Dialect::Miconi2006);
  EXPECT_EQ(c->sim.motor.max_force, 4);  // miconi2006's default
  EXPECT_EQ(c->evolution.population, 60);
  EXPECT_EQ(c->sim.motor.model, MotorModel::PD);
  EXPECT_EQ(c->sim.task.seconds, 5.0);
  auto bad = read_run_config("", "r.toml", {"evolution.populaton=3"});
  EXPECT_EQ(bad.error(), "--set evolution.populaton=3: evolution.populaton: unknown key (did you mean \"population\"?)");
  EXPECT_EQ(read_run_config("", "r.toml", {"population=3"}).error(),
            "--set: expected section.key=value, got \"population=3\"");
  EXPECT_EQ(read_run_config("[genome]\ndialect = \"sims\"\n", "r.toml").error(),
            "r.toml: genome.dialect: expected one of sims1994, miconi2006, chaumont2007, lessin2015, got \"sims\"");
}

// A --set is one key: the value was spliced into TOML text, so a newline in
// it could start a line that set any other key (issue 13)
TEST(Config, AnOverrideSetsItsKeyAndNoOther) {
  EXPECT_EQ(read_run_config("", "r.toml", {"task.seconds=1\nphysics.gravity=5"}).error(),
            "--set: a control character (newline, tab, ...) in \"task.seconds=1\\nphysics.gravity=5\" "
            "(one section.key=value per --set)");
  EXPECT_FALSE(read_run_config("", "r.toml", {"task.seconds=1\r\n[physics]\ngravity=5"}).ok());
  EXPECT_FALSE(read_run_config("", "r.toml", {"task.seconds\n=1"}).ok());
  // a key is section.key, nothing more
  EXPECT_EQ(read_run_config("", "r.toml", {"physics.gravity.x=1"}).error(),
            "--set: expected section.key=value, got \"physics.gravity.x=1\"");
  EXPECT_EQ(read_run_config("", "r.toml", {"physics.\"gravity\"=1"}).error(),
            "--set: expected section.key=value, got \"physics.\"gravity\"=1\"");
  // quotes and backslashes in a bare-word value stay inside the string
  EXPECT_EQ(read_run_config("", "r.toml", {"genome.dialect=sims\"1994"}).error(),
            "--set genome.dialect=sims\"1994: genome.dialect: expected one of sims1994, miconi2006, "
            "chaumont2007, lessin2015, got \"sims\"1994\"");
  EXPECT_EQ(read_run_config("", "r.toml", {"genome.dialect=a\\"}).error(),
            "--set genome.dialect=a\\: genome.dialect: expected one of sims1994, miconi2006, chaumont2007, lessin2015, got \"a\\\"");
  // spaces around the key and the value are fine, as before
  auto c = read_run_config("", "r.toml", {" physics.gravity = -3.5"});
  ASSERT_TRUE(c.ok()) << c.error();
  EXPECT_EQ(c->sim.physics.gravity, -3.5);
}

// A string a config holds is quoted on one line in errors: a message is one line
TEST(Config, QuotedStringsStayOnOneLine) {
  RunConfig cfg = default_run_config(Dialect::Sims1994);
  Status s = apply_config_toml(cfg, "[motor]\nmodel = \"a\\nb\"\n", "x.toml");
  EXPECT_EQ(s.error(), "x.toml: motor.model: expected one of servo, saturation, torque, pd, muscle, got \"a\\nb\"");
  // toml++ quotes the text it stopped at, a newline included (found by fuzz_config)
  s = apply_config_toml(cfg, "metric = [t\n", "x.toml");
  EXPECT_EQ(s.error(), "x.toml:1:12: Error while parsing boolean: expected 'true', saw 't\\n'");
  s = apply_config_toml(cfg, "[motor]\n\"mo\\ndel\" = 1\n", "x.toml");
  EXPECT_EQ(s.error(), "x.toml: motor.mo\\ndel: unknown key (did you mean \"model\"?)");
}

// A number a double (or a 64-bit integer) cannot hold is refused as written,
// never rounded: 1e-400 read as 0 would make motor.torque_max_linear_speed
// "no limit" (issue 37).
TEST(Config, ANumberThatUnderflowsOrOverflowsIsRefusedWithTheKeyAndTheValueAsWritten) {
  const std::string under =
      ": underflows: below 2.2e-308 a number reads as 0 or loses digits (write 0, or a larger number), got ";
  EXPECT_EQ(apply_error("[motor]\ntorque_max_linear_speed = 1e-400\n"),
            "run.toml: motor.torque_max_linear_speed" + under + "1e-400");
  EXPECT_EQ(apply_error("[motor]\ntorque_max_linear_speed = -1.5e-400\n"),
            "run.toml: motor.torque_max_linear_speed" + under + "-1.5e-400");
  // below the least normal double it keeps only some of its digits
  EXPECT_EQ(apply_error("[motor]\ntorque_max_linear_speed = 1e-320\n"),
            "run.toml: motor.torque_max_linear_speed" + under + "1e-320");
  EXPECT_EQ(apply_error("[catapult]\nprojectile_size = [0.1, 1e-400, 0.1]\n"),
            "run.toml: catapult.projectile_size[1]" + under + "1e-400");
  // 0 however written is 0, and the least normal double is kept
  EXPECT_EQ(apply_error("[motor]\ntorque_max_linear_speed = 0.0e-400\n"), "");
  EXPECT_EQ(apply_error("[motor]\ntorque_max_linear_speed = 2.3e-308\n"), "");
  // too large: toml++ refuses it naming the value, the error names its key too
  EXPECT_EQ(apply_error("[motor]\ntorque_max_linear_speed = 1e400\n"),
            "run.toml:2:32: motor.torque_max_linear_speed: overflows: a number holds at most 1.8e308 in magnitude, "
            "got 1e400");
  EXPECT_EQ(apply_error("[evolution]\n  population = 99999999999999999999 # many\n"),
            "run.toml:2:36: evolution.population: overflows: an integer holds at most 9223372036854775807 in "
            "magnitude, got 99999999999999999999");
  // from --set, and in a stage of a run of several, whose tables are written
  // out again (1e-400 as 0.0) before their keys are read
  auto set = read_run_config("", "run.toml", {"motor.torque_max_linear_speed=1e-400"});
  ASSERT_FALSE(set);
  EXPECT_EQ(set.error(), "--set motor.torque_max_linear_speed=1e-400: motor.torque_max_linear_speed" + under + "1e-400");
  auto staged = read_syllabus("[[stage]]\nname = \"a\"\n[stage.motor]\ntorque_max_linear_speed = 1e-400\n", "run.toml");
  ASSERT_FALSE(staged);
  EXPECT_EQ(staged.error(), "run.toml: stage[0].motor.torque_max_linear_speed" + under + "1e-400");
}

TEST(Config, BadInputChangesNothing) {
  RunConfig cfg = default_run_config(Dialect::Sims1994);
  std::string before = config_to_toml(cfg);
  EXPECT_FALSE(apply_config_toml(cfg, "[physics]\nerp = 0.5\ncfm = -1\n", "x.toml"));
  EXPECT_EQ(config_to_toml(cfg), before);
}

// Every field, not only the printed text: a field the TOML form forgot would
// keep another default and differ here.
TEST(Config, PrintedConfigReadsBackFieldForField) {
  const Dialect all[] = {Dialect::Sims1994, Dialect::Miconi2006, Dialect::Chaumont2007};
  for (Dialect from : all) {
    RunConfig a = default_run_config(from);
    if (from == Dialect::Chaumont2007) {
      // and values no dialect has by default
      a.operators.catapult.enabled = true;
      a.sim.task_kind = TaskKind::Throwing;
      a.sim.throwing.target = {1.25, -2.5, 0.125};
      a.check.converge_seeds = 3;
      a.evolution.report_every = 17;
    }
    // read as a run reads its config.toml: the dialect's defaults, then the text
    auto back = read_run_config(config_to_toml(a), "printed");
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_TRUE(*back == a) << to_string(from);
    // overlaid on another dialect's defaults, every section but the operators'
    // constants, which are not keys (the dialect picks them; only [catapult] is)
    for (Dialect onto : all) {
      RunConfig b = default_run_config(onto);
      ASSERT_TRUE(apply_config_toml(b, config_to_toml(a), "printed"));
      const std::string pair = std::string(to_string(from)) + " onto " + std::string(to_string(onto));
      EXPECT_TRUE(a.dialect == b.dialect && a.sim == b.sim && a.evolution == b.evolution && a.check == b.check)
          << pair;
      EXPECT_TRUE(a.operators.catapult == b.operators.catapult) << pair;
    }
  }
}

TEST(Config, PrintedConfigReadsBackToTheSameConfig) {
  for (Dialect d : {Dialect::Sims1994, Dialect::Miconi2006, Dialect::Chaumont2007}) {
    RunConfig a = default_run_config(d);
    RunConfig b = default_run_config(Dialect::Sims1994);
    ASSERT_TRUE(apply_config_toml(b, config_to_toml(a), "printed"));
    EXPECT_EQ(config_to_toml(a), config_to_toml(b));
    EXPECT_EQ(a.sim.physics.dt, b.sim.physics.dt);  // exact: 1/60 survives the text
  }
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

TEST(Config, TheReferenceDocListsEveryKeyAsTheCodeHasIt) {
  auto doc = read_file(std::string(BESTIARY_SOURCE_DIR) + "/docs/config.md");
  ASSERT_TRUE(doc.ok()) << doc.error();
  EXPECT_NE(doc->find(config_reference_markdown()), std::string::npos)
      << "docs/config.md is stale: paste the output of `bestiary config --reference` into it";
}

}  // namespace
}  // namespace bx

namespace bx {
namespace {

TEST(Config, CatapultAndThrowingKeys) {
  auto c = read_run_config("[genome]\ndialect = \"chaumont2007\"\n[catapult]\nenabled = true\n"
                           "projectile_size = [0.3, 0.2, 0.05]\n[task]\nkind = \"throwing\"\n"
                           "[throwing]\nfitness = \"aim\"\ntarget = [4, -1, 0.1]\n",
                           "c.toml", {"throwing.rest_seconds=0.25", "catapult.mutate_projectile=true"});
  ASSERT_TRUE(c.ok()) << c.error();
  EXPECT_EQ(c->sim.task_kind, TaskKind::Throwing);
  EXPECT_EQ(c->sim.throwing.fitness, ThrowFitness::Aim);
  EXPECT_EQ(c->sim.throwing.target, (Vec3{4, -1, 0.1}));
  EXPECT_EQ(c->sim.throwing.rest_seconds, 0.25);
  EXPECT_TRUE(c->operators.catapult.enabled);
  EXPECT_TRUE(c->operators.catapult.mutate_projectile);
  EXPECT_EQ(c->operators.catapult.projectile_size, (Vec3{0.3, 0.2, 0.05}));
  // printed and read back: the same
  RunConfig back = default_run_config(Dialect::Sims1994);
  ASSERT_TRUE(apply_config_toml(back, config_to_toml(*c), "printed"));
  EXPECT_EQ(config_to_toml(back), config_to_toml(*c));
  // --set takes a vector too
  auto v = read_run_config("", "r.toml", {"throwing.target=[1, 2, 3]"});
  ASSERT_TRUE(v.ok()) << v.error();
  EXPECT_EQ(v->sim.throwing.target, (Vec3{1, 2, 3}));
}

TEST(Config, BadCatapultInputNamesTheKeyAndTheValue) {
  EXPECT_EQ(apply_error("[throwing]\ntarget = [1, 2]\n"),
            "run.toml: throwing.target: expected an array of 3 numbers, got [1, 2]");
  EXPECT_EQ(apply_error("[throwing]\ntarget = 3\n"),
            "run.toml: throwing.target: expected an array of 3 numbers, got 3");
  EXPECT_EQ(apply_error("[catapult]\nprojectile_size = [0.1, 0, 0.1]\n"),
            "run.toml: catapult.projectile_size: each out of range [0.001, 100], got [0.1, 0, 0.1]");
  EXPECT_EQ(apply_error("[catapult]\nrelease_delay_steps = 1\n"),
            "run.toml: catapult.release_delay_steps: out of range [2, 1001], got 1");
  EXPECT_EQ(apply_error("[task]\nkind = \"fly\"\n"),
            "run.toml: task.kind: expected one of locomotion, throwing, river, turn, strike, light, fight_or_flight, high_reach, got \"fly\"");
  // keys that must agree
  EXPECT_EQ(read_run_config("[task]\nkind = \"throwing\"\n[genome]\ndialect = \"chaumont2007\"\n", "r.toml").error(),
            "r.toml: task.kind: \"throwing\" needs catapult.enabled = true");
  EXPECT_EQ(read_run_config("[catapult]\nenabled = true\n", "r.toml").error(),
            "r.toml: catapult.enabled: catapults need genome.dialect = \"chaumont2007\", got \"sims1994\"");
}

TEST(Config, ADropJitteredBelowTheGroundIsRefused) {
  // miconi2006 starts on the ground (drop_height 0): jitter needs a drop above it
  EXPECT_EQ(read_run_config("[genome]\ndialect = \"miconi2006\"\n[task]\nstart_drop_jitter = 0.005\n", "r.toml").error(),
            "r.toml: task.start_drop_jitter: 0.005 m is more than task.drop_height (0 m): a lowered drop would start "
            "the creature inside the ground");
  EXPECT_TRUE(read_run_config("[genome]\ndialect = \"miconi2006\"\n[task]\ndrop_height = 0.01\nstart_drop_jitter = 0.005\n",
                              "r.toml")
                  .ok());
}

// A creature kind brings its defaults as a dialect does: the river crossing's
// kind alone gives the paper's body physics, PD motors and its task; the
// config's own keys and overrides still win
TEST(Config, ACreatureKindBringsItsDefaultsBeforeTheConfigsKeys) {
  auto c = read_run_config("[genotype]\nkind = \"river\"\n", "r.toml");
  ASSERT_TRUE(c.ok()) << c.error();
  EXPECT_EQ(c->sim.creature, CreatureKind::River);
  EXPECT_EQ(c->sim.task_kind, TaskKind::River);
  EXPECT_EQ(c->sim.motor.model, MotorModel::PD);
  EXPECT_EQ(c->sim.motor.kp, 0.25);
  EXPECT_EQ(c->sim.motor.kd, 0.175);
  EXPECT_EQ(c->sim.physics.friction, 10);
  EXPECT_EQ(c->sim.physics.cfm, 5e-5);
  EXPECT_EQ(c->sim.physics.powered_stops, PoweredStops::Separate);
  EXPECT_DOUBLE_EQ(c->sim.physics.max_joint_gap, 0.05);  // per 1 m cell
  EXPECT_EQ(c->sim.brain_hz, 100);  // the pattern generator's Euler step: the paper's 0.01 s
  auto mine = read_run_config("[genotype]\nkind = \"river\"\n[physics]\nfriction = 2\n", "r.toml",
                              {"motor.kd=0.2"});
  ASSERT_TRUE(mine.ok()) << mine.error();
  EXPECT_EQ(mine->sim.physics.friction, 2);
  EXPECT_EQ(mine->sim.motor.kd, 0.2);
  EXPECT_EQ(mine->sim.motor.model, MotorModel::PD);
  // an override may name the kind too
  auto set = read_run_config("", "r.toml", {"genotype.kind=\"river\""});
  ASSERT_TRUE(set.ok()) << set.error();
  EXPECT_EQ(set->sim.physics.friction, 10);
  // a graph creature keeps its dialect's
  EXPECT_EQ(read_run_config("[genotype]\nkind = \"graph\"\n", "r.toml")->sim.physics.friction, 1);
}

// tournament_evaluates = "all" has tournaments to evaluate only in a steady state
TEST(Config, TournamentsThatEvaluateAllNeedASteadyState) {
  EXPECT_EQ(read_run_config("[evolution]\nalgorithm = \"generational\"\ntournament_evaluates = \"all\"\n", "r.toml")
                .error(),
            "r.toml: evolution.tournament_evaluates: \"all\" needs evolution.algorithm = \"steady_state\", got "
            "\"generational\"");
  EXPECT_TRUE(read_run_config("[evolution]\nalgorithm = \"steady_state\"\ntournament_evaluates = \"all\"\n", "r.toml")
                  .ok());
}

}  // namespace
}  // namespace bx
