// The replay writer's sensors and joint angles: one reading per sensor and one
// position per joint degree of freedom in every frame, the header describing
// each sensor and each joint's stops (and a lessin2015 creature's muscles),
// and recording them changes nothing of the evaluation.
#include "io/replay_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "core/rng.h"
#include "develop/develop.h"
#include "eval/creature.h"
#include "genome/float_vector.h"
#include "io/scene_record_json.h"
#include "genome/genome_json.h"

namespace bx {
namespace {

using nlohmann::json;

// the creature and the config `simulate` gives it (a catapult's: the throwing task)
CreatureModel grow(const std::string& name, SimConfig& cfg, double seconds) {
  auto g = load_genome(std::string(BESTIARY_SOURCE_DIR) + "/creatures/" + name);
  EXPECT_TRUE(g.ok()) << g.error();
  cfg = default_sim_config(*g);
  task_seconds(cfg) = seconds;
  Development d = develop(*g);
  EXPECT_TRUE(d.viable()) << d.reason;
  return *d.model;
}

struct Written {
  CreatureModel m;
  EvalResult res;
  json j;
};

// the creature simulated for `seconds` with a replay, and the replay as JSON
Written simulate(const std::string& name, double seconds) {
  SimConfig cfg;
  Written w{grow(name, cfg, seconds), {}, {}};
  Replay r;
  w.res = evaluate(w.m, cfg, 1, &r);
  w.j = json::parse(replay_to_string(w.m, r, w.res, {name, 1, cfg.physics.dt, cfg.physics.friction}));
  return w;
}

// the least and greatest value of frames[*][field][a][b] (b < 0: [field][a])
std::pair<double, double> extent(const json& frames, const char* field, int a, int b = -1) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& f : frames) {
    double v = b < 0 ? f[field][a].get<double>() : f[field][a][b].get<double>();
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return {lo, hi};
}

TEST(ReplayFile, EveryFrameHoldsEachSensorsReadingAndEachJointDofsPosition) {
  for (const char* name : {"walker.json", "snake.json", "centipede.json", "catapult.json", "pinned.json"}) {
    SCOPED_TRACE(name);
    Written w = simulate(name, 2);
    const json& j = w.j;
    // the header: each sensor as the model has it, each joint's stops
    ASSERT_EQ(j["sensors"].size(), w.m.sensors.size());
    for (std::size_t k = 0; k < w.m.sensors.size(); ++k) {
      const SensorModel& s = w.m.sensors[k];
      const json& h = j["sensors"][k];
      EXPECT_EQ(h["type"], std::string(to_string(s.type)));
      EXPECT_EQ(h["part"], s.part);
      if (s.type == SensorType::JointAngle) {
        EXPECT_EQ(h["joint"], s.joint);
        EXPECT_EQ(h["dof"], s.dof);
        EXPECT_FALSE(h.contains("face"));
      } else {
        EXPECT_EQ(h["face"], std::string(to_string(s.face)));
        EXPECT_FALSE(h.contains("joint"));
      }
    }
    ASSERT_EQ(j["joints"].size(), w.m.joints.size());
    for (std::size_t k = 0; k < w.m.joints.size(); ++k) {
      const json& lim = j["joints"][k]["limits"];
      ASSERT_EQ(lim.size(), w.m.joints[k].limits.size());
      for (std::size_t d = 0; d < lim.size(); ++d) {
        EXPECT_NEAR(lim[d][0].get<double>(), w.m.joints[k].limits[d].lo, 1e-6);
        EXPECT_NEAR(lim[d][1].get<double>(), w.m.joints[k].limits[d].hi, 1e-6);
      }
    }
    // the frames: counts match, sensors read within [-1, 1], values rounded
    for (const auto& f : j["frames"]) {
      ASSERT_EQ(f["sensors"].size(), w.m.sensors.size());
      for (const auto& v : f["sensors"]) {
        double x = v.get<double>();
        EXPECT_GE(x, -1.0);
        EXPECT_LE(x, 1.0);
        EXPECT_NEAR(x * 1e4, std::round(x * 1e4), 1e-6) << "signals to 1e-4";
      }
      ASSERT_EQ(f["joint_angles"].size(), w.m.joints.size());
      for (std::size_t k = 0; k < w.m.joints.size(); ++k) {
        ASSERT_EQ(f["joint_angles"][k].size(), static_cast<std::size_t>(joint_dofs(w.m.joints[k].type)));
        for (const auto& v : f["joint_angles"][k]) {
          double x = v.get<double>();
          EXPECT_TRUE(std::isfinite(x));
          EXPECT_NEAR(x * 1e5, std::round(x * 1e5), 1e-6) << "angles to 1e-5";
        }
      }
    }
    // frame 0 comes before the brain's first step: nothing read yet
    for (const auto& v : j["frames"][0]["sensors"]) EXPECT_EQ(v.get<double>(), 0.0);
  }
}

TEST(ReplayFile, TheWalkersJointsSwingAndItsSensorsFollowThem) {
  Written w = simulate("walker.json", 4);
  const json& frames = w.j["frames"];
  ASSERT_EQ(w.m.joints.size(), 4u);
  // every degree of freedom of its four universal joints moves (rad)
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 2; ++d) {
      auto [lo, hi] = extent(frames, "joint_angles", k, d);
      EXPECT_GT(hi - lo, 0.3) << "joint " << k << " dof " << d;
    }
  // its joint-angle sensors move too, and its contact sensors read +-1
  for (std::size_t k = 0; k < w.m.sensors.size(); ++k) {
    auto [lo, hi] = extent(frames, "sensors", static_cast<int>(k));
    if (w.m.sensors[k].type == SensorType::JointAngle) {
      EXPECT_GT(hi - lo, 0.3) << "sensor " << k;
    } else {
      for (std::size_t i = 1; i < frames.size(); ++i)
        EXPECT_EQ(std::abs(frames[i]["sensors"][k].get<double>()), 1.0) << "sensor " << k;
    }
  }
}

TEST(ReplayFile, ASnakesHingesSwing) {
  Written w = simulate("snake.json", 4);
  for (int k = 0; k < static_cast<int>(w.m.joints.size()); ++k) {
    ASSERT_EQ(w.m.joints[k].type, JointType::Hinge);
    auto [lo, hi] = extent(w.j["frames"], "joint_angles", k, 0);
    EXPECT_GT(hi - lo, 0.1) << "joint " << k;
  }
}

TEST(ReplayFile, APinnedHingeRestsAtItsStopUnderAConstantSignal) {
  // creatures/pinned.json: an effector with bias -1 and no inputs
  // holds its hinge against the stop at -0.5 rad
  Written w = simulate("pinned.json", 3);
  const json& frames = w.j["frames"];
  for (std::size_t i = 1; i < frames.size(); ++i) EXPECT_EQ(frames[i]["effectors"][0], -1.0);
  // from 0.3 s on it stays at the stop, overshooting it a little when jolted
  auto [lo, hi] = extent(json(std::vector<json>(frames.begin() + 10, frames.end())), "joint_angles", 0, 0);
  EXPECT_GT(lo, -0.7);
  EXPECT_LT(hi, -0.45);
  EXPECT_EQ(w.j["joints"][0]["limits"], json::parse("[[-0.5, 0.5]]"));
}

TEST(ReplayFile, RecordingAReplayChangesNothingOfTheEvaluation) {
  for (const char* name : {"walker.json", "catapult.json"}) {
    SimConfig cfg;
    CreatureModel m = grow(name, cfg, 3);
    Replay r;
    EvalResult with = evaluate(m, cfg, 5, &r), without = evaluate(m, cfg, 5);
    EXPECT_EQ(with.fitness, without.fitness) << name;  // bit-identical
    EXPECT_EQ(with.distance, without.distance) << name;
    EXPECT_EQ(with.steps, without.steps) << name;
  }
}

TEST(ReplayFile, ACatapultsSceneNamesItsProjectileAndMarksItsRelease) {
  Written w = simulate("catapult.json", 3);
  const json& rec = w.j["scene"]["record"];
  EXPECT_FALSE(w.j.contains("throw"));  // its fields are the record's now
  // the projectile, whose path the task scores
  EXPECT_EQ(rec["parts"], json::parse(R"([{"name": "projectile", "part": 2, "color": "#ffc61a", "scored": true}])"));
  ASSERT_TRUE(w.res.marker("release"));
  bool release = false, from = false;
  for (const json& m : rec["markers"]) {
    if (m["name"] == "release") {
      release = true;
      EXPECT_NEAR(m["t"].get<double>(), *w.res.marker("release"), 1e-6);
    }
    // the scored span: from the release to the projectile's rest
    if (m["name"] == "scored from") {
      from = true;
      EXPECT_NEAR(m["t"].get<double>(), *w.res.marker("release"), 1e-6);
    }
    if (m["name"] == "scored to") {
      EXPECT_GT(m["t"].get<double>(), *w.res.marker("release"));
    }
  }
  EXPECT_TRUE(release) << rec;
  EXPECT_TRUE(from) << rec;
  EXPECT_FALSE(rec.contains("events"));
  // nor has its result a field of its own: the distance is the task's, D_p
  EXPECT_FALSE(w.j["result"].contains("throw_distance"));
  EXPECT_FALSE(w.j["result"].contains("target_miss"));
  EXPECT_EQ(w.j["result"]["distance"].get<double>(), w.res.distance);
  // a walker's task records only its scored span and its distance: no items, no grid
  const auto walker = simulate("walker.json", 1).j["scene"]["record"];
  EXPECT_EQ(walker["markers"][0]["name"], "scored from") << walker;
  EXPECT_FALSE(walker.contains("parts"));
  EXPECT_FALSE(walker.contains("points"));
  for (const auto& e : walker["events"]) EXPECT_EQ(e["counter"]["name"], "distance") << e;
}

// v rotated by the unit quaternion q = [w, x, y, z] (a replay pose's q)
Vec3 rotate(const json& pose, Vec3 v) {
  const double w = pose[3], x = pose[4], y = pose[5], z = pose[6];
  const Vec3 u{x, y, z}, t = 2.0 * cross(u, v);
  return v + w * t + cross(u, t);
}

// a lessin2015 creature's replay lists its muscles, each end in its own
// part's frame: placed with the parts' poses at development it is the end
// the model has, and with frame 0's poses its length as built; its effectors
// name their muscles, its photoreceptors their directions
TEST(ReplayFile, ALessinCreaturesMusclesComeWithTheirEndsInTheirPartsFrames) {
  Written w = simulate("lessin_pair.json", 1);
  ASSERT_EQ(w.m.muscles.size(), 4u);
  const json& mj = w.j["muscles"];
  ASSERT_EQ(mj.size(), w.m.muscles.size());
  for (std::size_t k = 0; k < w.m.muscles.size(); ++k) {
    SCOPED_TRACE(k);
    const MuscleModel& mm = w.m.muscles[k];
    const json& h = mj[k];
    EXPECT_EQ(h["part_a"], mm.part_a);
    EXPECT_EQ(h["part_b"], mm.part_b);
    EXPECT_NE(mm.part_a, mm.part_b);
    EXPECT_NEAR(h["strength"].get<double>(), mm.strength, 1e-6);
    EXPECT_NEAR(h["rest_length"].get<double>(), mm.rest_length, 1e-6);
    const Vec3 la = {h["anchor_a"][0], h["anchor_a"][1], h["anchor_a"][2]};
    const Vec3 lb = {h["anchor_b"][0], h["anchor_b"][1], h["anchor_b"][2]};
    const Pose &pa = w.m.parts[mm.part_a].pose, &pb = w.m.parts[mm.part_b].pose;
    EXPECT_LT(norm(pa.R * la + pa.p - mm.anchor_a), 2e-6);
    EXPECT_LT(norm(pb.R * lb + pb.p - mm.anchor_b), 2e-6);
    // on its part's surface, not at its centre
    EXPECT_GT(norm(la), 0.04);
    EXPECT_GT(norm(lb), 0.04);
    // frame 0: the creature dropped where the task puts it, as built
    const json& poses = w.j["frames"][0]["poses"];
    const json &qa = poses[mm.part_a], &qb = poses[mm.part_b];
    const Vec3 wa = rotate(qa, la) + Vec3{qa[0], qa[1], qa[2]};
    const Vec3 wb = rotate(qb, lb) + Vec3{qb[0], qb[1], qb[2]};
    EXPECT_NEAR(norm(wb - wa), mm.length, 1e-4);
  }
  // each effector drives its muscle, and names no joint
  ASSERT_EQ(w.j["effectors"].size(), w.m.effectors.size());
  for (std::size_t e = 0; e < w.m.effectors.size(); ++e) {
    const json& h = w.j["effectors"][e];
    ASSERT_GE(w.m.effectors[e].muscle, 0);
    EXPECT_EQ(h["muscle"], w.m.effectors[e].muscle) << e;
    EXPECT_FALSE(h.contains("joint") || h.contains("dof")) << h;
  }
  int eyes = 0;
  for (const json& s : w.j["sensors"])
    if (s["type"] == "photoreceptor") {
      ++eyes;
      EXPECT_EQ(s["direction"].size(), 3u);
    }
  EXPECT_EQ(eyes, 2);
  // a creature of joint motors: no muscles, effectors by joint and dof as before
  const json walker = simulate("walker.json", 1).j;
  EXPECT_FALSE(walker.contains("muscles"));
  for (const json& h : walker["effectors"]) {
    EXPECT_TRUE(h.contains("joint") && h.contains("dof")) << h;
    EXPECT_FALSE(h.contains("muscle")) << h;
  }
}

// a river crossing's replay: the record its task and controller made comes
// back from the file, its field values to the file's 1e-3
TEST(ReplayFile, ARiverSceneRoundTripsThroughTheFile) {
  SimConfig cfg;
  cfg.creature = CreatureKind::River;
  cfg.task_kind = TaskKind::River;
  cfg.physics = river_physics(cfg.river.body);
  cfg.motor = river_motor();
  cfg.river.task.seconds = 3;
  const FloatVectorDef def = creature_kind_row(cfg.creature).float_genes(cfg);
  Rng rng(3);
  std::vector<double> genes(static_cast<std::size_t>(def.length));
  for (double& x : genes) x = rng.uniform(def.lo, def.hi);
  auto c = develop_creature(FloatVector(genes), cfg);
  ASSERT_TRUE(c.ok()) << c.error();
  Replay r;
  const EvalResult res = evaluate(*c, cfg, 42, &r);
  const json j = json::parse(replay_to_string(*c->body, r, res, {"river.json", 42, cfg.physics.dt, 10, "river"}));
  auto back = scene_record_from_json(j["scene"]["record"]);
  ASSERT_TRUE(back.ok()) << back.error();
  ASSERT_EQ(back->events.size(), r.scene.events.size());
  EXPECT_EQ(back->cell_kinds, r.scene.cell_kinds);
  int fields = 0;
  for (std::size_t k = 0; k < r.scene.events.size(); ++k) {
    const SceneEvent &a = r.scene.events[k], &b = back->events[k];
    EXPECT_NEAR(a.t, b.t, 1e-6);
    ASSERT_EQ(a.what.index(), b.what.index()) << k;
    if (const auto* f = std::get_if<SceneField>(&a.what)) {
      ++fields;
      const SceneField& g = std::get<SceneField>(b.what);
      ASSERT_EQ(f->values.size(), g.values.size());
      for (std::size_t i = 0; i < f->values.size(); ++i) ASSERT_NEAR(f->values[i], g.values[i], 5e-4 + 1e-12);
    } else if (const auto* g = std::get_if<SceneGrid>(&a.what)) {
      EXPECT_EQ(g->cells, std::get<SceneGrid>(b.what).cells);
      EXPECT_NEAR(g->origin.x, std::get<SceneGrid>(b.what).origin.x, 1e-6);
    } else {
      EXPECT_EQ(a.what, b.what) << k;
    }
  }
  EXPECT_GE(fields, 1);
  // its quadruped's effectors drive joints, whatever index their `muscle` holds
  EXPECT_FALSE(j.contains("muscles"));
  for (const json& h : j["effectors"]) EXPECT_TRUE(h.contains("joint") && h.contains("dof") && !h.contains("muscle")) << h;
}

}  // namespace
}  // namespace bx
