#include "io/mujoco_replay.h"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "eval/evaluate.h"
#include "eval/step.h"
#include "eval/task_table.h"
#include "io/mjcf.h"
#include "physics/mechanisms.h"
#include "physics/motor_law.h"

namespace bx {

namespace {

// What the motors did in one ODE step, and where the creature was after it.
struct Recorded {
  EvalState::Motors motors;
  std::vector<double> signals;
  std::vector<double> angles;  // every joint's dofs in turn, over the first kAngleSpan (else empty)
  std::vector<double> outputs;  // the controller's task outputs the task acted on before the step
};

// Where the tracked point was: at [0] the start, then after each step, and
// whether the scored part was down then (on the ground, touching no part).
struct Path {
  std::vector<Vec3> at;
  std::vector<bool> down;
  void add(Vec3 p, bool landed) {
    at.push_back(p);
    down.push_back(landed);
  }
};

// What a path did over a task's scored span [from, to] (s; steps of dt).
struct SpanMeasure {
  Vec3 displacement;
  bool landed = false;
  double landing = 0;  // s: the first step the scored part was down after `from`
  Vec3 flight;         // from `from` to the landing
};
SpanMeasure measure_span(const Path& path, double from, double to, double dt) {
  const long steps = static_cast<long>(path.at.size()) - 1;
  auto index_at = [&](double time) {  // the entry at or after `time` ([0]: the start)
    return std::clamp(static_cast<long>(std::ceil(time / dt - 1e-9)), 0L, steps);
  };
  const auto i_from = static_cast<std::size_t>(index_at(from)), i_to = static_cast<std::size_t>(index_at(to));
  SpanMeasure m;
  m.displacement = path.at[i_to] - path.at[i_from];
  for (std::size_t k = i_from + 1; k <= i_to; ++k)
    if (path.down[k]) {
      m.landed = true;
      m.landing = static_cast<double>(k) * dt;
      m.flight = path.at[k] - path.at[i_from];
      break;
    }
  return m;
}

struct MjDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
  void operator()(mjData* d) const { mj_deleteData(d); }
};

// MuJoCo reports trouble through a global handler: collected per replay
thread_local std::vector<std::string>* g_warnings = nullptr;
void on_warning(const char* msg) {
  if (g_warnings && g_warnings->size() < 8) g_warnings->push_back(msg);
}

// how many times the velocity motors' forces are corrected in a step
constexpr int kCorrections = 4;
// the span (s) over which the joints' angles are compared
constexpr double kAngleSpan = 1.0;

Vec3 horizontal(Vec3 v) { return {v.x, v.y, 0}; }

// How far apart two positions of a degree of freedom are: ODE reads a hinge's
// angle within (-pi, pi], MuJoCo's keeps counting turns
double angle_gap(double a, double b, bool linear) {
  return linear ? std::abs(a - b) : std::abs(std::remainder(a - b, 2 * kPi));
}

// What the ODE evaluation left for the replay.
struct OdeRun {
  SimConfig cfg;  // as evaluated (the seed's motor lag drawn)
  std::uint64_t seed = 0;
  Vec3 front;     // the creature's front in its root's frame
  bool cut = false;  // stopped at a given length, not where the task ends
  double fitness = 0;  // the task's score
  double muscle_work = 0;  // J
  std::vector<Recorded> rec;
  Pose root0;
  std::vector<double> angles0;
  int scored_part = -1;  // the part the task scores (ScenePart::scored), else -1: the centre of mass
  std::string tracked = "centre of mass";
  double from = 0, to = 0;  // the scored span (s)
  SpanMeasure span;         // what the tracked point did over it
};

// How MuJoCo's contacts are set for one replay (docs/export.md).
struct MujocoContacts {
  const char* name;
  bool stiffest = false;  // solref's time constant at 2 steps (default 0.02 s)
  bool elliptic = false;  // the elliptic friction cone (default pyramidal)
};
constexpr MujocoContacts kMujocoContacts[] = {
    {"as exported", false, false},
    {"stiffest", true, false},
    {"elliptic cone", false, true},
    {"stiffest, elliptic cone", true, true},
};

// What one MuJoCo replay did.
struct MujocoRun {
  double fitness = 0;  // the task's score of the replay
  double muscle_work = 0;  // J
  double from = 0, to = 0;  // the scored span its task marked (s)
  SpanMeasure span;         // what the tracked point did over it
  double min_height = 0;
  double first_second_angle_gap = 0;
  std::vector<std::string> warnings;
};

// ODE, closed loop, as evaluate_once runs the first trial: every step's
// motor commands, the joints the task broke, and the scored span
Result<OdeRun> run_ode(const CreatureModel& m, const ControllerModel& controller, const SimConfig& given,
                       std::uint64_t seed, double seconds) {
  OdeRun o;

  reseed_physics(seed);
  const SeedDraw draw = seed_draw(given, seed);
  SimConfig& cfg = o.cfg;
  cfg = given;
  cfg.motor.response_time = draw.response_time;
  auto task = make_task(m, cfg, seed, 0);
  if (!task) return Error{task.error()};
  EvalState s(m, controller, cfg, std::move(*task), {draw.yaw, draw.lift});
  o.seed = seed;
  o.front = s.front;
  o.cut = seconds > 0;
  // the scene as a replay records it: before the first step and after each
  SceneRecord scene;
  record_scene(m, s, scene);
  for (const ScenePart& p : scene.parts)
    if (p.scored && p.part >= 0 && p.part < m.n_parts()) {
      o.scored_part = p.part;
      o.tracked = p.name;
      break;
    }
  auto tracked = [&] { return o.scored_part >= 0 ? s.world.part_pose(o.scored_part).p : s.world.centre_of_mass(); };
  o.root0 = s.world.part_pose(0);
  for (int j = 0; j < static_cast<int>(m.joints.size()); ++j)
    for (int k = 0; k < joint_dofs(m.joints[j].type); ++k) o.angles0.push_back(s.world.joint_position(j, k));
  Path path;
  path.add(tracked(), false);
  const long max_steps =
      seconds > 0 ? static_cast<long>(std::llround(seconds / cfg.physics.dt)) : s.task->max_steps();
  std::vector<Recorded>& rec = o.rec;
  rec.reserve(static_cast<std::size_t>(std::min(max_steps, 1L << 22)));
  while (s.physics_steps < max_steps && (seconds > 0 || !s.task->done())) {
    if (!step(m, cfg, s)) return Error{"it failed in ODE: " + s.failure};
    record_scene(m, s, scene);
    // the joints' angles over the first second, which the replay's are compared with
    std::vector<double> angles;
    if (s.world.time() <= kAngleSpan + 1e-9)
      for (int j = 0; j < static_cast<int>(m.joints.size()); ++j)
        for (int k = 0; k < joint_dofs(m.joints[j].type); ++k) angles.push_back(s.world.joint_position(j, k));
    // touching something, but no part of the creature: the ground
    const bool landed = o.scored_part >= 0 && s.world.contact_mask(o.scored_part) != 0 &&
                        !s.world.touches_part(o.scored_part);
    const std::span<const double> outputs = s.controller->task_outputs();
    rec.push_back({s.motors, std::vector<double>(s.signals.begin(), s.signals.end()), std::move(angles),
                   std::vector<double>(outputs.begin(), outputs.end())});
    path.add(tracked(), landed);
  }
  o.fitness = s.task->score(m).fitness;
  o.muscle_work = s.world.muscle_work();
  // the scored span, as the task marks it
  o.from = scene.marker(kScoredFrom).value_or(0);
  o.to = scene.marker(kScoredTo).value_or(static_cast<double>(rec.size()) * cfg.physics.dt);
  o.span = measure_span(path, o.from, o.to, cfg.physics.dt);
  return o;
}

// The exported body in MuJoCo with the joints broken so far left out, and
// where each effector's, joint's and muscle's state lies in it.
struct MjSim {
  std::unique_ptr<mjModel, MjDeleter> model;
  std::unique_ptr<mjData, MjDeleter> data;
  std::vector<int> dof_of;     // each effector's degree of freedom (-1: a muscle's, or none)
  std::vector<int> qpos_of;    // each joint dof's MuJoCo joint, in the creature's order (-1: none)
  std::vector<int> tendon_of;  // each muscle's tendon
  std::vector<int> body_of;    // each part's body
  std::vector<int> prop_body;  // each prop's (mocap) body
  int tracked_body = -1;       // the scored part's body, else -1
};

// Loads the body with `broken` joints left out, its actuators silenced (the
// motors are ours), its contacts as `contacts` says
Result<MjSim> load_mujoco(const CreatureModel& m, const OdeRun& o, const MujocoContacts& contacts,
                          const std::vector<int>& broken, const std::vector<Prop>& props) {
  const SimConfig& cfg = o.cfg;
  MjSim sim;
  char err[1000] = "";
  std::string xml = creature_mjcf(m, cfg, "creature", nullptr, broken);
  std::string prop_bodies;
  for (std::size_t k = 0; k < props.size(); ++k) prop_bodies += mjcf_prop_body(props[k], static_cast<int>(k));
  xml.insert(xml.rfind("  </worldbody>"), prop_bodies);
  std::unique_ptr<mjVFS> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  const std::string file = "creature.xml";
  mj_makeEmptyFileVFS(vfs.get(), file.c_str(), static_cast<int>(xml.size()));
  std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[vfs->nfile - 1]));
  sim.model.reset(mj_loadXML(file.c_str(), vfs.get(), err, sizeof err));
  mj_deleteVFS(vfs.get());
  if (!sim.model) return Error{std::string("MuJoCo refused the exported body: ") + err};
  mjModel* M = sim.model.get();
  for (int a = 0; a < M->nu; ++a) {
    for (int k = 0; k < mjNGAIN; ++k) M->actuator_gainprm[a * mjNGAIN + k] = 0;
    for (int k = 0; k < mjNBIAS; ++k) M->actuator_biasprm[a * mjNBIAS + k] = 0;
  }
  if (contacts.stiffest)  // the shortest time constant MuJoCo allows (2 steps), nearer ODE's hard contacts
    for (int g = 0; g < M->ngeom; ++g) M->geom_solref[2 * g] = 2 * cfg.physics.dt;
  if (contacts.elliptic) M->opt.cone = mjCONE_ELLIPTIC;
  // implicit in the joints' damping (a PD's damper, as ODE's motor row), and
  // with muscles in the tendons' too (a muscle's damper: ODE's is a soft
  // constraint, implicit)
  M->opt.integrator = m.muscles.empty() ? mjINT_EULER : mjINT_IMPLICIT;
  sim.data.reset(mj_makeData(M));
  sim.dof_of.assign(m.effectors.size(), -1);
  for (int j = 0; j < static_cast<int>(m.joints.size()); ++j)
    for (int k = 0; k < joint_dofs(m.joints[j].type); ++k)
      sim.qpos_of.push_back(mj_name2id(M, mjOBJ_JOINT, mjcf_joint_name(j, k).c_str()));
  for (std::size_t e = 0; e < m.effectors.size(); ++e) {
    const EffectorModel& em = m.effectors[e];
    if (em.muscle >= 0) continue;  // a muscle's tendon
    const int id = mj_name2id(M, mjOBJ_JOINT, mjcf_joint_name(em.joint, em.dof).c_str());
    if (id >= 0) sim.dof_of[e] = M->jnt_dofadr[id];
  }
  sim.tendon_of.assign(m.muscles.size(), -1);
  for (std::size_t k = 0; k < m.muscles.size(); ++k) {
    sim.tendon_of[k] = mj_name2id(M, mjOBJ_TENDON, mjcf_muscle_name(static_cast<int>(k)).c_str());
    if (sim.tendon_of[k] < 0) return Error{"the exported body lacks muscle " + std::to_string(k) + "'s tendon"};
  }
  for (int i = 0; i < m.n_parts(); ++i) {
    sim.body_of.push_back(mj_name2id(M, mjOBJ_BODY, ("p" + std::to_string(i)).c_str()));
    if (sim.body_of.back() < 0) return Error{"the exported body lacks part " + std::to_string(i)};
  }
  if (o.scored_part >= 0) sim.tracked_body = sim.body_of[static_cast<std::size_t>(o.scored_part)];
  for (std::size_t k = 0; k < props.size(); ++k)
    sim.prop_body.push_back(mj_name2id(M, mjOBJ_BODY, ("prop" + std::to_string(k)).c_str()));
  return sim;
}

// Carries the state of `from` into `to`, the same body with more joints
// broken: every joint by its name; a newly freed part's free joint from its
// body's pose and velocity in `from` (MuJoCo's free joint: the position and
// linear velocity in the world's frame, the angular velocity in the body's)
void carry_state(MjSim& from, MjSim& to) {
  const mjModel* A = from.model.get();
  mjData* a = from.data.get();
  mj_forward(A, a);  // its velocities at its positions now (mj_step left those of the step's start)
  const mjModel* B = to.model.get();
  mjData* b = to.data.get();
  b->time = a->time;
  for (int jb = 0; jb < B->njnt; ++jb) {
    const char* name = mj_id2name(B, mjOBJ_JOINT, jb);
    const int ja = name ? mj_name2id(A, mjOBJ_JOINT, name) : -1;
    const int nq = B->jnt_type[jb] == mjJNT_FREE ? 7 : B->jnt_type[jb] == mjJNT_BALL ? 4 : 1;
    const int nv = B->jnt_type[jb] == mjJNT_FREE ? 6 : B->jnt_type[jb] == mjJNT_BALL ? 3 : 1;
    double* qpos = b->qpos + B->jnt_qposadr[jb];
    double* qvel = b->qvel + B->jnt_dofadr[jb];
    if (ja >= 0 && A->jnt_type[ja] == B->jnt_type[jb]) {
      std::copy(a->qpos + A->jnt_qposadr[ja], a->qpos + A->jnt_qposadr[ja] + nq, qpos);
      std::copy(a->qvel + A->jnt_dofadr[ja], a->qvel + A->jnt_dofadr[ja] + nv, qvel);
      std::copy(a->qacc_warmstart + A->jnt_dofadr[ja], a->qacc_warmstart + A->jnt_dofadr[ja] + nv,
                b->qacc_warmstart + B->jnt_dofadr[jb]);
      continue;
    }
    if (B->jnt_type[jb] != mjJNT_FREE) continue;  // none in `from`: left at its reference
    const char* body = mj_id2name(B, mjOBJ_BODY, B->jnt_bodyid[jb]);
    const int ba = body ? mj_name2id(A, mjOBJ_BODY, body) : -1;
    if (ba < 0) continue;
    std::copy(a->xpos + 3 * ba, a->xpos + 3 * ba + 3, qpos);
    std::copy(a->xquat + 4 * ba, a->xquat + 4 * ba + 4, qpos + 3);
    double v[6];  // angular then linear, at the body's origin, in the world's frame
    mj_objectVelocity(A, a, mjOBJ_BODY, ba, v, 0);
    std::copy(v + 3, v + 6, qvel);
    const double* R = a->xmat + 9 * ba;  // row-major: the body's axes as columns
    for (int r = 0; r < 3; ++r) qvel[3 + r] = R[0 + r] * v[0] + R[3 + r] * v[1] + R[6 + r] * v[2];
  }
  mj_forward(B, b);
}

// Whether body `body` touched, in MuJoCo's last step, a body that `other`
// accepts (0: the world's floor)
template <class Other>
bool touches(const MjSim& sim, int body, Other other) {
  const mjModel* M = sim.model.get();
  const mjData* D = sim.data.get();
  for (int k = 0; k < D->ncon; ++k) {
    const int b1 = M->geom_bodyid[D->contact[k].geom1], b2 = M->geom_bodyid[D->contact[k].geom2];
    if ((b1 == body && other(b2)) || (b2 == body && other(b1))) return true;
  }
  return false;
}

// What the task reads of MuJoCo's world (Task's Observation), as
// WorldObservation reads ODE's: the body of each part by its name "p<i>".
class MujocoObservation : public Observation {
 public:
  MujocoObservation(const CreatureModel& m, const MjSim& sim, Vec3 front, const double& muscle_work)
      : m_(m), sim_(sim), front_(front), muscle_work_(muscle_work) {}
  double time() const override { return sim_.data->time; }
  Vec3 centre_of_mass() const override {
    const mjModel* M = sim_.model.get();
    const mjData* D = sim_.data.get();
    Vec3 c;
    double mass = 0;
    for (int b = 1; b < M->nbody; ++b) {
      const double* p = D->xipos + 3 * b;
      c = c + M->body_mass[b] * Vec3{p[0], p[1], p[2]};
      mass += M->body_mass[b];
    }
    return mass > 0 ? (1.0 / mass) * c : c;
  }
  int n_parts() const override { return m_.n_parts(); }
  Pose part_pose(int i) const override {
    const int b = sim_.body_of[static_cast<std::size_t>(i)];
    const double* p = sim_.data->xpos + 3 * b;
    const double* R = sim_.data->xmat + 9 * b;
    Pose pose;
    pose.p = {p[0], p[1], p[2]};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) pose.R.m[r][c] = R[3 * r + c];
    return pose;
  }
  // part i against any other part of the creature in the last step
  bool touches_part(int i) const override {
    const int b = sim_.body_of[static_cast<std::size_t>(i)];
    return touches(sim_, b, [&](int other) { return other != 0 && other != b && !is_prop(other); });
  }
  double muscle_work() const override { return muscle_work_; }
  Vec3 front() const override { return front_; }
  // any part against prop k in the last step
  bool touches_prop(int k) const override {
    if (k < 0 || k >= static_cast<int>(sim_.prop_body.size())) return false;
    return touches(sim_, sim_.prop_body[static_cast<std::size_t>(k)], [](int other) { return other != 0; });
  }

 private:
  bool is_prop(int body) const {
    return std::find(sim_.prop_body.begin(), sim_.prop_body.end(), body) != sim_.prop_body.end();
  }
  const CreatureModel& m_;
  const MjSim& sim_;
  Vec3 front_;
  const double& muscle_work_;
};

// What the task changes in MuJoCo's world: a broken joint or a new prop
// waits for the replay to reload the body with it (each prop's time of
// placing kept for its spin); lights matter to photoreceptors only, which an
// open-loop replay does not read.
class MujocoEdits : public WorldEdits {
 public:
  void break_joint(int j) override {
    if (std::find(broken.begin(), broken.end(), j) == broken.end()) {
      broken.push_back(j);
      pending = true;
    }
  }
  int add_prop(const Prop& p) override {
    props.push_back(p);
    placed.push_back(now);
    pending = true;
    return static_cast<int>(props.size()) - 1;
  }
  void set_lights(std::vector<Light>) override {}
  std::vector<int> broken;
  std::vector<Prop> props;
  std::vector<double> placed;  // s
  double now = 0;              // MuJoCo's time, set before the task acts
  bool pending = false;
};

// MuJoCo, open loop: the exported body, its contacts as `contacts` says,
// ODE's motor commands step by step, and the same task (made from the same
// seed) acting on ODE's task outputs and scoring what MuJoCo does: a joint
// it breaks is left out of a body reloaded then, the state carried over.
// Past ODE's last step, while MuJoCo's task has not ended (a block still
// rolling), the last step's commands go on, up to the task's length.
Result<MujocoRun> run_mujoco(const CreatureModel& m, const OdeRun& o, const MujocoContacts& contacts) {
  const SimConfig& cfg = o.cfg;
  const std::vector<Recorded>& rec = o.rec;
  const long recorded = static_cast<long>(rec.size());
  MujocoRun r;
  MujocoEdits edits;
  auto loaded = load_mujoco(m, o, contacts, edits.broken, edits.props);
  if (!loaded) return Error{loaded.error()};
  MjSim sim = std::move(*loaded);
  {
    mjModel* M = sim.model.get();
    mjData* D = sim.data.get();
    // ODE's start: the root's pose, every joint's position
    const Quat q0 = to_quat(o.root0.R);
    const double start[7] = {o.root0.p.x, o.root0.p.y, o.root0.p.z, q0.w, q0.x, q0.y, q0.z};
    std::copy(start, start + 7, D->qpos);
    for (std::size_t a = 0; a < sim.qpos_of.size(); ++a)
      if (sim.qpos_of[a] >= 0) D->qpos[M->jnt_qposadr[sim.qpos_of[a]]] = o.angles0[a];
  }
  // where a brake holds each muscle (NaN: not held)
  std::vector<double> muscle_hold(m.muscles.size(), std::numeric_limits<double>::quiet_NaN());
  std::vector<std::string> warnings;
  g_warnings = &warnings;
  mju_user_warning = on_warning;
  struct Unhook {
    ~Unhook() {
      g_warnings = nullptr;
      mju_user_warning = nullptr;
    }
  } unhook;
  mj_forward(sim.model.get(), sim.data.get());
  double muscle_work = 0;
  const MujocoObservation obs(m, sim, o.front, muscle_work);
  auto task = make_task(m, cfg, o.seed, 0);
  if (!task) return Error{task.error()};
  Task& t = **task;
  t.begin(obs);
  SceneRecord scene;
  t.record(obs, scene);
  // the tracked point after each step (at [0]: the start)
  auto tracked = [&] { return sim.tracked_body >= 0 ? obs.part_pose(o.scored_part).p : obs.centre_of_mass(); };
  Path path;
  path.add(tracked(), false);
  r.min_height = path.at[0].z;

  const double dt = cfg.physics.dt;
  const double lag = motor_lag_share(dt, cfg.motor.response_time);
  const long longest = o.cut || recorded == 0 ? recorded : std::max(recorded, t.max_steps());
  // the steps ODE's controller drove the motors in: MuJoCo's task decides
  // when its own do (after its own settling), and each takes the next of
  // ODE's, so the gait starts from rest in both
  std::vector<long> driven;
  for (long i = 0; i < recorded; ++i)
    if (rec[static_cast<std::size_t>(i)].motors == EvalState::Motors::Driven) driven.push_back(i);
  std::size_t cursor = 0;
  const std::vector<double> zeros(m.effectors.size(), 0.0);
  std::vector<double> lagged(m.effectors.size(), 0.0);
  std::vector<MotorDemand> drives(m.effectors.size());
  std::vector<int> vel;  // effectors driven as velocity motors this step
  std::vector<double> a_mat, f, v_free, base, probe, f_prev, v_prev;
  for (long i = 0; i < longest && (o.cut || !t.done()); ++i) {
    // the motors as the task has them now (step.cpp: held, off, or driven
    // by ODE's next driven step's signals), and the task outputs then
    const bool on = t.controller_on(), held = t.joints_held();
    const EvalState::Motors mode = held ? EvalState::Motors::Held : on ? EvalState::Motors::Driven
                                                                       : EvalState::Motors::Off;
    const Recorded* from_ode = nullptr;  // the ODE step whose signals drive this one
    if (on && !driven.empty()) {
      from_ode = &rec[static_cast<std::size_t>(driven[std::min(cursor, driven.size() - 1)])];
      ++cursor;
    }
    const Recorded* last = !driven.empty() && cursor > 0
                                ? &rec[static_cast<std::size_t>(driven[std::min(cursor, driven.size()) - 1])]
                                : &rec[0];
    const std::vector<double>& signals = mode == EvalState::Motors::Driven && from_ode ? from_ode->signals : zeros;
    const Recorded* step_rec = i < recorded ? &rec[static_cast<std::size_t>(i)] : nullptr;  // for the angles
    edits.now = sim.data->time;
    t.act(m, last->outputs, edits, obs);
    if (edits.pending) {
      edits.pending = false;
      auto next = load_mujoco(m, o, contacts, edits.broken, edits.props);
      if (!next) return Error{next.error()};
      carry_state(sim, *next);
      sim = std::move(*next);
    }
    mjModel* M = sim.model.get();
    mjData* D = sim.data.get();
    // a spinning prop turned about the vertical by spin x the time since it was placed
    for (std::size_t k = 0; k < edits.props.size(); ++k)
      if (const Prop& p = edits.props[k]; p.spin != 0) {
        const Quat q = to_quat(Mat3::rotation({0, 0, 1}, p.spin * (D->time - edits.placed[k])) * p.pose.R);
        const int id = M->body_mocapid[sim.prop_body[k]];
        const double wxyz[4] = {q.w, q.x, q.y, q.z};
        std::copy(wxyz, wxyz + 4, D->mocap_quat + 4 * id);
      }
    // the motors' laws, after their lag, then any brake (step.cpp's order)
    for (std::size_t e = 0; e < m.effectors.size(); ++e) {
      double sig = signals[e];
      if (lag > 0) sig = lagged[e] += lag * (sig - lagged[e]);
      if (const int k = m.effectors[e].muscle; k >= 0) {
        // a muscle (physics/actuators.cpp's row): a spring of its activation
        // times its strength toward its rest length; braked, held at its
        // length when the brake began with the brake's share of its strength
        const auto ku = static_cast<std::size_t>(k);
        const int t = sim.tendon_of[ku];
        const MuscleModel& mm = m.muscles[ku];
        const double share = mode == EvalState::Motors::Held ? 1
                             : mode == EvalState::Motors::Off ? cfg.motor.off_brake
                                                                          : 0;
        if (share > 0) {
          if (std::isnan(muscle_hold[ku])) muscle_hold[ku] = D->ten_length[t];
          M->tendon_lengthspring[t] = muscle_hold[ku];
          M->tendon_stiffness[t] = share * mm.strength;
        } else {
          muscle_hold[ku] = std::numeric_limits<double>::quiet_NaN();
          M->tendon_lengthspring[t] = mm.rest_length;
          M->tendon_stiffness[t] = std::clamp(sig, 0.0, 1.0) * mm.strength;
        }
        M->tendon_damping[t] = cfg.motor.muscle_damping;
        drives[e] = MotorDemand{};
        continue;
      }
      // a joint's motor by the world's law (physics/motor_law.h); a PD's
      // spring from MuJoCo's angle, its damper the joint's
      const EffectorModel& em = m.effectors[e];
      const int dof = sim.dof_of[e];
      drives[e] = motor_demand(cfg.motor, m.joints[em.joint], em, sig);
      if (drives[e].kind == MotorDemand::Kind::Target && dof >= 0)
        drives[e].torque = cfg.motor.kp * (drives[e].target - D->qpos[M->jnt_qposadr[M->dof_jntid[dof]]]);
      if (mode == EvalState::Motors::Held) drives[e] = brake_demand(cfg.motor, em, 1);
      else if (mode == EvalState::Motors::Off && cfg.motor.off_brake > 0)
        drives[e] = brake_demand(cfg.motor, em, cfg.motor.off_brake);
    }
    // torques first; then the velocity motors' forces, solved together
    // (projected Gauss-Seidel on the effective inverse inertia, as ODE's
    // motor rows are) against the motion everything else would give
    std::fill(D->qfrc_applied, D->qfrc_applied + M->nv, 0.0);
    vel.clear();
    for (std::size_t e = 0; e < m.effectors.size(); ++e) {
      if (sim.dof_of[e] < 0) continue;
      if (drives[e].kind == MotorDemand::Kind::Velocity) vel.push_back(static_cast<int>(e));
      else D->qfrc_applied[sim.dof_of[e]] += drives[e].torque;
    }
    if (!vel.empty()) {
      // the velocity motors' forces, solved together as ODE's motor rows are
      // with its stops and contacts: their response to each motor's force is
      // measured through MuJoCo's constrained forward dynamics (a unit force
      // on each in turn), then projected Gauss-Seidel within the force caps,
      // then a correction round from where those forces take them
      const std::size_t n = vel.size();
      base.assign(D->qfrc_applied, D->qfrc_applied + M->nv);
      f.assign(n, 0.0);
      v_free.assign(n, 0.0);
      a_mat.assign(n * n, 0.0);
      v_prev.assign(n, 0.0);
      auto dof_at = [&](std::size_t c) { return sim.dof_of[static_cast<std::size_t>(vel[c])]; };
      auto forward_with = [&](const std::vector<double>& forces) {
        std::copy(base.begin(), base.end(), D->qfrc_applied);
        for (std::size_t c = 0; c < n; ++c) D->qfrc_applied[dof_at(c)] += forces[c];
        mj_forward(M, D);
      };
      forward_with(f);
      for (std::size_t c = 0; c < n; ++c) v_free[c] = D->qvel[dof_at(c)] + dt * D->qacc[dof_at(c)];
      for (std::size_t c = 0; c < n; ++c) {
        probe.assign(n, 0.0);
        probe[c] = 1;
        forward_with(probe);
        for (std::size_t r2 = 0; r2 < n; ++r2)
          a_mat[r2 * n + c] = D->qvel[dof_at(r2)] + dt * D->qacc[dof_at(r2)] - v_free[r2];
      }
      auto solve = [&] {
        for (int sweep = 0; sweep < 50; ++sweep)
          for (std::size_t c = 0; c < n; ++c) {
            const MotorDemand& dr = drives[static_cast<std::size_t>(vel[c])];
            const double a = a_mat[c * n + c];
            if (!(a > 1e-12)) continue;
            double v = v_free[c];
            for (std::size_t k = 0; k < n; ++k) v += a_mat[c * n + k] * f[k];
            f[c] = std::clamp(f[c] + (dr.speed - v) / a, -dr.force, dr.force);
          }
      };
      solve();
      // corrections: the velocities the forces give, the linear model moved to
      // them, each motor's own response re-measured from the last two rounds
      // (a secant: it grows once a contact's friction gives way, which the
      // unit forces did not show)
      for (int round = 0; round < kCorrections; ++round) {
        forward_with(f);
        for (std::size_t c = 0; c < n; ++c) {
          const double v = D->qvel[dof_at(c)] + dt * D->qacc[dof_at(c)];
          if (round > 0 && std::abs(f[c] - f_prev[c]) > 1e-12) {
            const double slope = (v - v_prev[c]) / (f[c] - f_prev[c]);
            if (slope > a_mat[c * n + c]) a_mat[c * n + c] = slope;
          }
          v_prev[c] = v;
        }
        for (std::size_t c = 0; c < n; ++c) {
          v_free[c] = v_prev[c];
          for (std::size_t k = 0; k < n; ++k) v_free[c] -= a_mat[c * n + k] * f[k];
        }
        f_prev = f;
        solve();
      }
      std::copy(base.begin(), base.end(), D->qfrc_applied);
      for (std::size_t c = 0; c < n; ++c) D->qfrc_applied[dof_at(c)] += f[c];
    }
    mj_step(M, D);
    bool finite = true;
    for (int k = 0; k < M->nq; ++k) finite = finite && std::isfinite(D->qpos[k]);
    if (!finite) return Error{"MuJoCo's simulation blew up at t=" + std::to_string(D->time) + " s"};
    mj_kinematics(M, D);  // the positions after the step
    // the muscles' work (World::muscle_work): each tendon's spring and
    // damper force times its rate, |power| x dt
    if (!sim.tendon_of.empty()) {
      mj_comPos(M, D);
      mj_tendon(M, D);
      mj_transmission(M, D);
      mj_fwdVelocity(M, D);
    }
    for (std::size_t k = 0; k < sim.tendon_of.size(); ++k) {
      const int tn = sim.tendon_of[k];
      const double force = -M->tendon_stiffness[tn] * (D->ten_length[tn] - M->tendon_lengthspring[tn]) -
                           M->tendon_damping[tn] * D->ten_velocity[tn];
      muscle_work += std::abs(force * D->ten_velocity[tn]) * dt;
    }
    if (!t.done()) t.observe(obs);
    t.record(obs, scene);
    const Vec3 c = tracked();
    r.min_height = std::min(r.min_height, c.z);
    // the scored part on the ground and touching no part
    path.add(c, sim.tracked_body >= 0 && !obs.touches_part(o.scored_part) &&
                    touches(sim, sim.tracked_body, [](int other) { return other == 0; }));
    // the joints' angles against ODE's, over the first second
    if (step_rec && !step_rec->angles.empty())
      for (std::size_t k = 0; k < sim.qpos_of.size(); ++k)
        if (const int id = sim.qpos_of[k]; id >= 0)
          r.first_second_angle_gap =
              std::max(r.first_second_angle_gap,
                       angle_gap(D->qpos[M->jnt_qposadr[id]], step_rec->angles[k], M->jnt_type[id] == mjJNT_SLIDE));
  }
  r.fitness = t.score(m).fitness;
  r.muscle_work = muscle_work;
  // the span MuJoCo's task scored, by its own markers, and the flight in it
  r.from = scene.marker(kScoredFrom).value_or(0);
  r.to = scene.marker(kScoredTo).value_or(static_cast<double>(path.at.size() - 1) * dt);
  r.span = measure_span(path, r.from, r.to, dt);
  r.warnings = std::move(warnings);
  return r;
}

}  // namespace

Result<CrossSimReport> crosscheck_mujoco(const CreatureModel& m, const ControllerModel& controller,
                                         const SimConfig& cfg, std::uint64_t seed, double seconds) {
  auto o = run_ode(m, controller, cfg, seed, seconds);
  if (!o) return Error{o.error()};
  CrossSimReport r;
  r.steps = static_cast<long>(o->rec.size());
  r.seconds = static_cast<double>(r.steps) * o->cfg.physics.dt;
  r.from = o->from;
  r.to = o->to;
  r.ode = o->span.displacement;
  r.tracked = o->tracked;
  r.ode_fitness = o->fitness;
  r.ode_muscle_work = o->muscle_work;
  r.has_flight = o->scored_part >= 0 && o->span.landed;
  r.ode_flight = o->span.flight;
  r.landing = o->span.landing;
  // MuJoCo's horizontal displacement against ODE's: the angle between them, and the length ratio
  auto compare = [](Vec3 ode, Vec3 mj, double& heading, double& ratio) {
    const Vec3 a = horizontal(ode), b = horizontal(mj);
    const double la = norm(a), lb = norm(b);
    ratio = la > 0 ? lb / la : 0;
    heading = la > 0 && lb > 0 ? std::acos(std::clamp(dot(a, b) / (la * lb), -1.0, 1.0)) : 0;
  };
  std::vector<double> headings, ratios, flight_headings, flight_ratios, fitnesses;
  for (const MujocoContacts& contacts : kMujocoContacts) {
    auto run = run_mujoco(m, *o, contacts);
    if (!run) return Error{std::string(contacts.name) + ": " + run.error()};
    CrossSimVariant v;
    v.name = contacts.name;
    v.displacement = run->span.displacement;
    v.fitness = run->fitness;
    v.muscle_work = run->muscle_work;
    v.from = run->from;
    v.to = run->to;
    fitnesses.push_back(v.fitness);
    v.min_height = run->min_height;
    v.first_second_angle_gap = run->first_second_angle_gap;
    v.warnings = std::move(run->warnings);
    compare(r.ode, v.displacement, v.heading_difference, v.distance_ratio);
    headings.push_back(v.heading_difference);
    ratios.push_back(v.distance_ratio);
    if (r.has_flight) {
      // one that never came down within the span flew all of it
      v.flight = run->span.landed ? run->span.flight : run->span.displacement;
      compare(r.ode_flight, v.flight, v.flight_heading_difference, v.flight_ratio);
      flight_headings.push_back(v.flight_heading_difference);
      flight_ratios.push_back(v.flight_ratio);
    }
    r.variants.push_back(std::move(v));
  }
  auto median = [](std::vector<double> x) {
    if (x.empty()) return 0.0;
    std::sort(x.begin(), x.end());
    const std::size_t n = x.size();
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
  };
  r.heading_difference = median(headings);
  r.mujoco_fitness = median(fitnesses);
  r.flight_heading_difference = median(flight_headings);
  r.flight_ratio = median(flight_ratios);
  r.distance_ratio = median(ratios);
  return r;
}

}  // namespace bx
