// A creature exported as MJCF (io/mjcf.h, docs/export.md) loads in MuJoCo
// (Debian's libmujoco) with the body's parts, masses, joints and actuators;
// dropped with its controls at 0 it comes to rest; and a joint's angle has
// ODE's sign (the river quadruped's positive knee angle lowers its foot, as
// in our world).
#include "io/mjcf.h"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "develop/develop.h"
#include "genome/genome_json.h"
#include "io/config.h"
#include "physics/world.h"
#include "support/creatures.h"
#include "task/river/quadruped.h"

namespace bx {
namespace {

namespace fs = std::filesystem;

struct Loaded {
  mjModel* m = nullptr;
  std::string error;
  ~Loaded() {
    if (m) mj_deleteModel(m);
  }
};

void load(const std::string& xml, Loaded& out) {
  const fs::path f = fs::temp_directory_path() / ("bx_mjcf_" + std::to_string(::getpid()) + ".xml");
  std::ofstream(f) << xml;
  char err[1000] = "";
  out.m = mj_loadXML(f.c_str(), nullptr, err, sizeof err);
  out.error = err;
  fs::remove(f);
}

// the degrees of freedom of a model's joints, as MJCF joints count them
int dof_joints(const CreatureModel& m) {
  int n = 0;
  for (const JointModel& j : m.joints) n += joint_dofs(j.type);
  return n;
}

class MjcfCreature : public ::testing::TestWithParam<const char*> {};

TEST_P(MjcfCreature, LoadsWithItsPartsMassJointsAndActuatorsAndComesToRest) {
  const std::string name = GetParam();
  const bxtest::DevelopedCreature c = bxtest::develop_creature(name);
  ASSERT_TRUE(c.dev.viable());
  const CreatureModel& cm = *c.dev.model;
  const auto* cfg = &c.cfg;
  MjcfNotes notes;
  Loaded l;
  load(creature_mjcf(cm, cfg->sim, name, &notes), l);
  ASSERT_NE(l.m, nullptr) << l.error;
  EXPECT_EQ(l.m->nbody, cm.n_parts() + 1);  // and the world
  double mass = 0;
  for (int b = 1; b < l.m->nbody; ++b) mass += l.m->body_mass[b];
  EXPECT_NEAR(mass, cm.total_mass(), 1e-9 * cm.total_mass());
  EXPECT_EQ(l.m->njnt, 1 + dof_joints(cm));  // the free root and every degree of freedom
  int drivable = 0;
  for (const EffectorModel& e : cm.effectors) drivable += e.muscle < 0 && cfg->sim.motor.model != MotorModel::Muscle;
  EXPECT_EQ(l.m->nu, drivable);
  EXPECT_EQ(notes.lines.empty(), drivable == static_cast<int>(cm.effectors.size()) &&
                                     cfg->sim.motor.model != MotorModel::Servo &&
                                     cfg->sim.motor.model != MotorModel::Saturation && !(cfg->sim.motor.response_time > 0));
  // dropped with every control at 0: after 10 s it rests (the root's speed
  // below 1 cm/s and 0.05 rad/s), without a warning from MuJoCo
  mjData* d = mj_makeData(l.m);
  const int steps = static_cast<int>(std::lround(10 / l.m->opt.timestep));
  for (int i = 0; i < steps; ++i) mj_step(l.m, d);
  for (int k = 0; k < l.m->nv; ++k) ASSERT_TRUE(std::isfinite(d->qvel[k])) << k;
  EXPECT_LT(std::hypot(d->qvel[0], d->qvel[1], d->qvel[2]), 0.01);
  EXPECT_LT(std::hypot(d->qvel[3], d->qvel[4], d->qvel[5]), 0.05);
  for (int w = 0; w < mjNWARNING; ++w) EXPECT_EQ(d->warning[w].number, 0) << "MuJoCo warning " << w;
  mj_deleteData(d);
}

INSTANTIATE_TEST_SUITE_P(Canonical, MjcfCreature,
                         ::testing::Values("hinged_pair", "snake", "walker", "centipede", "rocker", "lessin_crawler"));

TEST(Mjcf, AJointsAngleHasOdesSign) {
  // the river quadruped: a positive knee angle lowers the lower limb (docs/rivercrossing.md,
  // "Joints"), in our world by the PD motor and in MuJoCo by setting the angle
  const QuadrupedDef def;
  const CreatureModel cm = make_quadruped(def);
  auto cfg = read_run_config("[genotype]\nkind = \"river\"\n", "test");
  ASSERT_TRUE(cfg.ok()) << cfg.error();
  Loaded l;
  load(creature_mjcf(cm, cfg->sim, "quadruped"), l);
  ASSERT_NE(l.m, nullptr) << l.error;
  mjData* d = mj_makeData(l.m);
  mj_forward(l.m, d);
  const int lower = mj_name2id(l.m, mjOBJ_BODY, "p2");  // leg 0's lower limb
  const int knee = mj_name2id(l.m, mjOBJ_JOINT, "j1_0");
  ASSERT_GE(lower, 0);
  ASSERT_GE(knee, 0);
  const double z0 = d->xpos[3 * lower + 2];
  d->qpos[l.m->jnt_qposadr[knee]] = 0.3;
  mj_forward(l.m, d);
  const double z1 = d->xpos[3 * lower + 2];
  EXPECT_LT(z1, z0 - 1e-3) << "a positive knee angle must lower the limb";
  mj_deleteData(d);
  // and in our world: the knee's angle read back after a positive target is positive
  PhysicsDef physics = river_physics(def);
  physics.gravity = 0;
  World w(physics);
  w.add_creature(cm, {{0, 0, 1}, Mat3::identity()});
  std::vector<double> s(kQuadrupedEffectors, 0.0);
  s[2] = 0.5;  // leg 0's knee
  for (int i = 0; i < 300; ++i) {
    w.apply_effectors(cm, river_motor(), s);
    w.step();
  }
  EXPECT_GT(w.joint_position(1, 0), 0.05);
}

// A broken joint (a catapult's release) is left out: its child heads a free
// body of its own at the top level, at its place, colliding with every part;
// the rest of the body is as before.
TEST(Mjcf, ABrokenJointsChildIsAFreeBodyOfItsOwn) {
  const bxtest::DevelopedCreature c = bxtest::develop_creature("catapult");
  ASSERT_TRUE(c.dev.viable());
  const CreatureModel& cm = *c.dev.model;
  ASSERT_GE(cm.release_joint, 0);
  const int projectile = cm.joints[cm.release_joint].child;
  const int broken[] = {cm.release_joint};
  Loaded whole, freed;
  load(creature_mjcf(cm, c.cfg.sim, "catapult"), whole);
  load(creature_mjcf(cm, c.cfg.sim, "catapult", nullptr, broken), freed);
  ASSERT_NE(whole.m, nullptr) << whole.error;
  ASSERT_NE(freed.m, nullptr) << freed.error;
  EXPECT_EQ(freed.m->nbody, whole.m->nbody);
  EXPECT_EQ(freed.m->njnt, whole.m->njnt + 1);  // its free joint
  const int b = mj_name2id(freed.m, mjOBJ_BODY, ("p" + std::to_string(projectile)).c_str());
  ASSERT_GE(b, 0);
  EXPECT_EQ(freed.m->body_parentid[b], 0);  // the world's
  const int j = mj_name2id(freed.m, mjOBJ_JOINT, mjcf_free_joint_name(projectile).c_str());
  ASSERT_GE(j, 0);
  EXPECT_EQ(freed.m->jnt_type[j], mjJNT_FREE);
  EXPECT_EQ(freed.m->jnt_bodyid[j], b);
  // it collides with every part, whatever self_collision says
  const int g = freed.m->body_geomadr[b];
  EXPECT_EQ(freed.m->geom_contype[g] & 1, 1);
  EXPECT_EQ(freed.m->geom_conaffinity[g] & 2, 2);
  // at its place: where the whole body has it
  mjData* dw = mj_makeData(whole.m);
  mjData* df = mj_makeData(freed.m);
  mj_forward(whole.m, dw);
  mj_forward(freed.m, df);
  const int bw = mj_name2id(whole.m, mjOBJ_BODY, ("p" + std::to_string(projectile)).c_str());
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(df->xpos[3 * b + k], dw->xpos[3 * bw + k], 1e-9) << k;
  mj_deleteData(dw);
  mj_deleteData(df);
}

// A prop (a lessin2015 target) as a mocap body: the creature lands on it and
// rests there; it never touches the floor it stands in.
TEST(Mjcf, APropIsAKinematicBodyThePartsLandOn) {
  const bxtest::DevelopedCreature c = bxtest::develop_creature("hinged_pair");
  ASSERT_TRUE(c.dev.viable());
  const CreatureModel& cm = *c.dev.model;
  Prop slab;  // 0.3 m thick, 4 m across, standing on the floor under the creature
  slab.size = {4, 4, 0.3};
  slab.pose.p = {0, 0, 0.15};
  auto rest_height = [&](bool with_slab) {
    std::string xml = creature_mjcf(cm, c.cfg.sim, "pair");
    if (with_slab) xml.insert(xml.rfind("  </worldbody>"), mjcf_prop_body(slab, 0));
    Loaded l;
    load(xml, l);
    EXPECT_NE(l.m, nullptr) << l.error;
    if (!l.m) return 0.0;
    mjData* d = mj_makeData(l.m);
    d->qpos[2] += 0.5;  // dropped from above the slab's top
    for (int i = 0; i < static_cast<int>(std::lround(2 / l.m->opt.timestep)); ++i) mj_step(l.m, d);
    const int prop = mj_name2id(l.m, mjOBJ_BODY, "prop0");
    for (int k = 0; k < d->ncon; ++k) {
      const int b1 = l.m->geom_bodyid[d->contact[k].geom1], b2 = l.m->geom_bodyid[d->contact[k].geom2];
      EXPECT_FALSE((b1 == prop && b2 == 0) || (b1 == 0 && b2 == prop)) << "the prop touches the floor";
    }
    const double z = d->qpos[2];
    mj_deleteData(d);
    return z;
  };
  const double on_floor = rest_height(false), on_slab = rest_height(true);
  EXPECT_NEAR(on_slab - on_floor, 0.3, 0.02);  // it rests on the slab's top
}

}  // namespace
}  // namespace bx
