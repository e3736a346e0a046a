// Config files: strict keys, typed values, ranges, and a lossless round trip.
#include "io/config.h"

#include <gtest/gtest.h>

namespace bx {
namespace {

std::string apply_error(const std::string& toml) {
  SimConfig cfg = default_sim_config(Dialect::Miconi2006);
  Status s = apply_config_toml(cfg, toml, "run.toml");
  return s.ok() ? "" : s.error();
}

TEST(Config, OverlaysValuesOntoTheDialectDefaults) {
  SimConfig cfg = default_sim_config(Dialect::Miconi2006);
  EXPECT_EQ(cfg.physics.erp, 0.015);
  EXPECT_EQ(cfg.motor.model, MotorModel::Servo);
  ASSERT_TRUE(apply_config_toml(cfg, "[physics]\nerp = 0.2\nsolver_iterations = 40\n"
                                     "[motor]\nmodel = \"pd\"\n[task]\nmetric = \"planar\"\nseconds = 3\n",
                                "x.toml"));
  EXPECT_EQ(cfg.physics.erp, 0.2);
  EXPECT_EQ(cfg.physics.solver_iterations, 40);
  EXPECT_EQ(cfg.physics.cfm, 0.01);  // untouched keys keep the dialect's value
  EXPECT_EQ(cfg.motor.model, MotorModel::PD);
  EXPECT_EQ(cfg.task.metric, DistanceMetric::Planar);
  EXPECT_EQ(cfg.task.seconds, 3.0);
}

TEST(Config, BadInputNamesTheKeyAndTheValue) {
  EXPECT_EQ(apply_error("[physics]\nerpp = 0.2\n"), "run.toml: physics.erpp: unknown key");
  EXPECT_EQ(apply_error("[physic]\nerp = 0.2\n"), "run.toml: physic: unknown section");
  EXPECT_EQ(apply_error("[physics]\ndt = \"fast\"\n"),
            "run.toml: physics.dt: expected a number, got \"fast\"");
  EXPECT_EQ(apply_error("[physics]\nerp = 1.5\n"), "run.toml: physics.erp: out of range [0, 1], got 1.5");
  EXPECT_EQ(apply_error("[physics]\nsolver_iterations = 2.5\n"),
            "run.toml: physics.solver_iterations: expected an integer, got 2.5");
  EXPECT_EQ(apply_error("[motor]\nmodel = \"jet\"\n"),
            "run.toml: motor.model: expected one of servo, saturation, torque, pd, got \"jet\"");
  EXPECT_EQ(apply_error("[physics]\nself_collision = 1\n"),
            "run.toml: physics.self_collision: expected true or false, got 1");
  EXPECT_EQ(apply_error("physics = 3\n"), "run.toml: physics: expected a table, got 3");
  EXPECT_EQ(apply_error("[physics\n").substr(0, 11), "run.toml:1:");
}

TEST(Config, BadInputChangesNothing) {
  SimConfig cfg = default_sim_config(Dialect::Sims1994);
  std::string before = config_to_toml(cfg);
  EXPECT_FALSE(apply_config_toml(cfg, "[physics]\nerp = 0.5\ncfm = -1\n", "x.toml"));
  EXPECT_EQ(config_to_toml(cfg), before);
}

TEST(Config, PrintedConfigReadsBackToTheSameConfig) {
  for (Dialect d : {Dialect::Sims1994, Dialect::Miconi2006, Dialect::Chaumont2007}) {
    SimConfig a = default_sim_config(d);
    SimConfig b = default_sim_config(Dialect::Sims1994);
    ASSERT_TRUE(apply_config_toml(b, config_to_toml(a), "printed"));
    EXPECT_EQ(config_to_toml(a), config_to_toml(b));
    EXPECT_EQ(a.physics.dt, b.physics.dt);  // exact: 1/60 survives the text
  }
}

}  // namespace
}  // namespace bx
