// A creature exported as URDF (io/urdf.h, docs/export.md) loads in MuJoCo
// (Debian's libmujoco reads URDF too) with its parts' masses and every
// degree of freedom a joint, and its kinematics are the MJCF export's: the
// same joint angles put every part in the same place relative to the root
// (so the URDF's frames, axes and signs agree with the MJCF's, whose knee
// sign a test of its own pins to our world's).
#include "io/urdf.h"

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
#include "io/mjcf.h"
#include "support/creatures.h"
#include "task/river/quadruped.h"

namespace bx {
namespace {

namespace fs = std::filesystem;

mjModel* load(const std::string& text, const char* ext, std::string& error) {
  const fs::path f = fs::temp_directory_path() / ("bx_urdf_" + std::to_string(::getpid()) + ext);
  std::ofstream(f) << text;
  char err[1000] = "";
  mjModel* m = mj_loadXML(f.c_str(), nullptr, err, sizeof err);
  error = err;
  fs::remove(f);
  return m;
}

// part i's centre relative to the root part (in the root's frame), in a
// model whose first geom of body "p<i>" is centred on the part and whose
// body "p0" has the root part's frame
Vec3 centre_in_root(const mjModel* m, const mjData* d, int i) {
  auto geom_at = [&](int part) {
    const int b = mj_name2id(m, mjOBJ_BODY, ("p" + std::to_string(part)).c_str());
    EXPECT_GE(b, 0) << part;
    const int g = m->body_geomadr[b];
    return Vec3{d->geom_xpos[3 * g], d->geom_xpos[3 * g + 1], d->geom_xpos[3 * g + 2]};
  };
  // the root body's frame is the root part's in both (a geom's frame need not
  // be: MuJoCo turns a cylinder's as it likes about its axis)
  const int b0 = mj_name2id(m, mjOBJ_BODY, "p0");
  Mat3 R;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) R.m[r][c] = d->xmat[9 * b0 + 3 * r + c];
  return R.transposed() * (geom_at(i) - Vec3{d->xpos[3 * b0], d->xpos[3 * b0 + 1], d->xpos[3 * b0 + 2]});
}

void compare(const CreatureModel& cm, const SimConfig& sim, const std::string& name) {
  std::vector<std::string> notes;
  std::string err;
  // MuJoCo fuses a URDF's root link, fixed where it stands, into the world
  // unless told not to (its own extension element, which URDF readers skip)
  std::string urdf = creature_urdf(cm, sim, name, &notes);
  urdf.insert(urdf.find('>', urdf.find("<robot")) + 1, "<mujoco><compiler fusestatic=\"false\"/></mujoco>");
  mjModel* u = load(urdf, ".urdf", err);
  ASSERT_NE(u, nullptr) << err;
  mjModel* x = load(creature_mjcf(cm, sim, name), ".xml", err);
  ASSERT_NE(x, nullptr) << err;
  EXPECT_FALSE(notes.empty());
  // masses: the parts', and the massless links of joints of several degrees of freedom
  int dofs = 0, extra = 0;
  for (const JointModel& j : cm.joints) {
    dofs += joint_dofs(j.type);
    extra += std::max(joint_dofs(j.type) - 1, 0);
  }
  double mass = 0;
  for (int b = 1; b < u->nbody; ++b) mass += u->body_mass[b];
  EXPECT_NEAR(mass, cm.total_mass() + extra * kUrdfDofLinkMass, 1e-9 * cm.total_mass());
  EXPECT_EQ(u->njnt, dofs);  // no free root: URDF's root link is where it stands
  // each joint's angles set alike in both (0.3 rad, alternating in sign;
  // the MJCF's after its free root): the parts stand alike about the root
  mjData* du = mj_makeData(u);
  mjData* dx = mj_makeData(x);
  mj_forward(x, dx);
  for (int j = 0; j < u->njnt; ++j) {
    const char* jn = mj_id2name(u, mjOBJ_JOINT, j);
    const int k = mj_name2id(x, mjOBJ_JOINT, jn);
    ASSERT_GE(k, 0) << jn;
    const double q = j % 2 ? -0.3 : 0.3;
    du->qpos[u->jnt_qposadr[j]] = q;
    dx->qpos[x->jnt_qposadr[k]] = q;
  }
  mj_kinematics(u, du);
  mj_kinematics(x, dx);
  for (int i = 1; i < cm.n_parts(); ++i) {
    const Vec3 a = centre_in_root(u, du, i), b = centre_in_root(x, dx, i);
    EXPECT_LT(norm(a - b), 1e-9) << name << " part " << i << ": " << a.x << " " << a.y << " " << a.z << " vs " << b.x
                                 << " " << b.y << " " << b.z;
  }
  mj_deleteData(du);
  mj_deleteData(dx);
  mj_deleteModel(u);
  mj_deleteModel(x);
}

class UrdfCreature : public ::testing::TestWithParam<const char*> {};

TEST_P(UrdfCreature, LoadsWithItsMassAndJointsAndMovesAsTheMjcfExport) {
  const bxtest::DevelopedCreature c = bxtest::develop_creature(GetParam());
  ASSERT_TRUE(c.dev.viable());
  compare(*c.dev.model, c.cfg.sim, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Canonical, UrdfCreature,
                         ::testing::Values("hinged_pair", "snake", "walker", "centipede", "rocker", "lessin_crawler"));

TEST(Urdf, TheRiverQuadrupedLoadsAndMovesAsTheMjcfExport) {
  auto cfg = read_run_config("[genotype]\nkind = \"river\"\n", "test");
  ASSERT_TRUE(cfg.ok()) << cfg.error();
  compare(make_quadruped(QuadrupedDef{}), cfg->sim, "quadruped");
}

}  // namespace
}  // namespace bx
