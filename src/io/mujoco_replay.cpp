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
  Vec3 com;
  std::vector<double> angles;  // every joint's dofs in turn, over the first kAngleSpan (else empty)
};

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
  std::vector<Recorded> rec;
  Pose root0;
  std::vector<double> angles0;
  Vec3 com0;
  double from = 0, to = 0;  // the scored span (s)
  long i_from = -1, i_to = -1;  // the steps at its ends (-1: the start)
  Vec3 displacement;
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
  Vec3 displacement;  // of the centre of mass over the scored span
  double min_height = 0;
  double first_second_angle_gap = 0;
  std::vector<std::string> warnings;
};

// ODE, closed loop, as evaluate_once runs the first trial: every step's
// motor commands, and the scored span
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
  o.root0 = s.world.part_pose(0);
  for (int j = 0; j < static_cast<int>(m.joints.size()); ++j)
    for (int k = 0; k < joint_dofs(m.joints[j].type); ++k) o.angles0.push_back(s.world.joint_position(j, k));
  o.com0 = s.world.centre_of_mass();
  const long max_steps =
      seconds > 0 ? static_cast<long>(std::llround(seconds / cfg.physics.dt)) : s.task->max_steps();
  std::vector<Recorded>& rec = o.rec;
  rec.reserve(static_cast<std::size_t>(std::min(max_steps, 1L << 22)));
  while (s.physics_steps < max_steps && (seconds > 0 || !s.task->done())) {
    if (!step(m, cfg, s)) return Error{"it failed in ODE: " + s.failure};
    // the joints' angles over the first second, which the replay's are compared with
    std::vector<double> angles;
    if (s.world.time() <= kAngleSpan + 1e-9)
      for (int j = 0; j < static_cast<int>(m.joints.size()); ++j)
        for (int k = 0; k < joint_dofs(m.joints[j].type); ++k) angles.push_back(s.world.joint_position(j, k));
    rec.push_back({s.motors, std::vector<double>(s.signals.begin(), s.signals.end()), s.world.centre_of_mass(),
                   std::move(angles)});
  }
  if (s.world.n_props() > 0) return Error{"its task places props in the world (a target, a projectile), which MJCF does not carry"};
  for (int j = 0; j < static_cast<int>(m.joints.size()); ++j)
    if (s.world.joint_broken(j)) return Error{"its task broke a joint (a catapult's release), which the replay cannot"};
  // the scored span, as the task marks it
  SceneRecord scene;
  s.task->record(WorldObservation(m, s.world, s.front), scene);
  const long steps = static_cast<long>(rec.size());
  o.from = 0;
  o.to = static_cast<double>(steps) * cfg.physics.dt;
  for (const SceneMarker& mk : scene.markers) {
    if (mk.name == kScoredFrom) o.from = mk.t;
    if (mk.name == kScoredTo) o.to = mk.t;
  }
  auto index_at = [&](double t) {  // the step whose end is at or after t (-1: the start)
    const long k = static_cast<long>(std::ceil(t / cfg.physics.dt - 1e-9)) - 1;
    return std::clamp(k, -1L, steps - 1);
  };
  o.i_from = index_at(o.from);
  o.i_to = index_at(o.to);
  auto ode_com = [&](long i) { return i < 0 ? o.com0 : rec[static_cast<std::size_t>(i)].com; };
  o.displacement = ode_com(o.i_to) - ode_com(o.i_from);
  return o;
}


// MuJoCo, open loop: the exported body, its actuators silenced (the motors
// are ours), its contacts as `contacts` says
Result<MujocoRun> run_mujoco(const CreatureModel& m, const OdeRun& o, const MujocoContacts& contacts) {
  const SimConfig& cfg = o.cfg;
  const std::vector<Recorded>& rec = o.rec;
  const long steps = static_cast<long>(rec.size());
  MujocoRun r;
  char err[1000] = "";
  std::string xml = creature_mjcf(m, cfg, "creature");
  std::unique_ptr<mjVFS> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  const std::string file = "creature.xml";
  mj_makeEmptyFileVFS(vfs.get(), file.c_str(), static_cast<int>(xml.size()));
  std::copy(xml.begin(), xml.end(), static_cast<char*>(vfs->filedata[vfs->nfile - 1]));
  std::unique_ptr<mjModel, MjDeleter> mm(mj_loadXML(file.c_str(), vfs.get(), err, sizeof err));
  mj_deleteVFS(vfs.get());
  if (!mm) return Error{std::string("MuJoCo refused the exported body: ") + err};
  mjModel* M = mm.get();
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
  std::unique_ptr<mjData, MjDeleter> dd(mj_makeData(M));
  mjData* D = dd.get();
  // ODE's start: the root's pose, every joint's position
  const Quat q0 = to_quat(o.root0.R);
  const double start[7] = {o.root0.p.x, o.root0.p.y, o.root0.p.z, q0.w, q0.x, q0.y, q0.z};
  std::copy(start, start + 7, D->qpos);
  // each effector's degree of freedom in MuJoCo, and each joint dof's
  std::vector<int> dof_of(m.effectors.size(), -1), qpos_of;
  {
    std::size_t a = 0;
    for (int j = 0; j < static_cast<int>(m.joints.size()); ++j)
      for (int k = 0; k < joint_dofs(m.joints[j].type); ++k, ++a) {
        const int id = mj_name2id(M, mjOBJ_JOINT, mjcf_joint_name(j, k).c_str());
        qpos_of.push_back(id);
        if (id >= 0) D->qpos[M->jnt_qposadr[id]] = o.angles0[a];
      }
    for (std::size_t e = 0; e < m.effectors.size(); ++e) {
      const EffectorModel& em = m.effectors[e];
      if (em.muscle >= 0) continue;  // a muscle's tendon, below
      const int id = mj_name2id(M, mjOBJ_JOINT, mjcf_joint_name(em.joint, em.dof).c_str());
      if (id >= 0) dof_of[e] = M->jnt_dofadr[id];
    }
  }
  // each muscle's tendon, and where a brake holds it (NaN: not held)
  std::vector<int> tendon_of(m.muscles.size(), -1);
  for (std::size_t k = 0; k < m.muscles.size(); ++k) {
    tendon_of[k] = mj_name2id(M, mjOBJ_TENDON, mjcf_muscle_name(static_cast<int>(k)).c_str());
    if (tendon_of[k] < 0) return Error{"the exported body lacks muscle " + std::to_string(k) + "'s tendon"};
  }
  std::vector<double> muscle_hold(m.muscles.size(), std::numeric_limits<double>::quiet_NaN());
  std::vector<std::string> warnings;
  g_warnings = &warnings;
  mju_user_warning = on_warning;
  mj_forward(M, D);
  auto mj_com = [&] { return Vec3{D->subtree_com[3], D->subtree_com[4], D->subtree_com[5]}; };
  const Vec3 mj_com0 = mj_com();
  Vec3 mj_from = mj_com0, mj_to = mj_com0;
  r.min_height = mj_com0.z;

  const double dt = cfg.physics.dt;
  const double lag = motor_lag_share(dt, cfg.motor.response_time);
  std::vector<double> lagged(m.effectors.size(), 0.0);
  std::vector<MotorDemand> drives(m.effectors.size());
  std::vector<int> vel;  // effectors driven as velocity motors this step
  std::vector<double> a_mat, f, v_free, base, probe, f_prev, v_prev;
  for (long i = 0; i < steps; ++i) {
    const Recorded& step_rec = rec[static_cast<std::size_t>(i)];
    // the motors' laws, after their lag, then any brake (step.cpp's order)
    for (std::size_t e = 0; e < m.effectors.size(); ++e) {
      double sig = step_rec.signals[e];
      if (lag > 0) sig = lagged[e] += lag * (sig - lagged[e]);
      if (const int k = m.effectors[e].muscle; k >= 0) {
        // a muscle (physics/actuators.cpp's row): a spring of its activation
        // times its strength toward its rest length; braked, held at its
        // length when the brake began with the brake's share of its strength
        const auto ku = static_cast<std::size_t>(k);
        const int t = tendon_of[ku];
        const MuscleModel& mm = m.muscles[ku];
        const double share = step_rec.motors == EvalState::Motors::Held ? 1
                             : step_rec.motors == EvalState::Motors::Off ? cfg.motor.off_brake
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
      drives[e] = motor_demand(cfg.motor, m.joints[em.joint], em, sig);
      if (drives[e].kind == MotorDemand::Kind::Target && dof_of[e] >= 0)
        drives[e].torque = cfg.motor.kp * (drives[e].target - D->qpos[M->jnt_qposadr[M->dof_jntid[dof_of[e]]]]);
      if (step_rec.motors == EvalState::Motors::Held) drives[e] = brake_demand(cfg.motor, em, 1);
      else if (step_rec.motors == EvalState::Motors::Off && cfg.motor.off_brake > 0)
        drives[e] = brake_demand(cfg.motor, em, cfg.motor.off_brake);
    }
    // torques first; then the velocity motors' forces, solved together
    // (projected Gauss-Seidel on the effective inverse inertia, as ODE's
    // motor rows are) against the motion everything else would give
    std::fill(D->qfrc_applied, D->qfrc_applied + M->nv, 0.0);
    vel.clear();
    for (std::size_t e = 0; e < m.effectors.size(); ++e) {
      if (dof_of[e] < 0) continue;
      if (drives[e].kind == MotorDemand::Kind::Velocity) vel.push_back(static_cast<int>(e));
      else D->qfrc_applied[dof_of[e]] += drives[e].torque;
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
      auto dof_at = [&](std::size_t c) { return dof_of[static_cast<std::size_t>(vel[c])]; };
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
    if (!finite) {
      g_warnings = nullptr;
      return Error{"MuJoCo's simulation blew up at t=" + std::to_string(D->time) + " s"};
    }
    mj_kinematics(M, D);  // subtree_com of the state after the step
    mj_comPos(M, D);
    const Vec3 c = mj_com();
    r.min_height = std::min(r.min_height, c.z);
    // the joints' angles against ODE's, over the first second
    if (!step_rec.angles.empty())
      for (std::size_t k = 0; k < qpos_of.size(); ++k)
        if (qpos_of[k] >= 0)
          r.first_second_angle_gap = std::max(r.first_second_angle_gap,
                                              angle_gap(D->qpos[M->jnt_qposadr[qpos_of[k]]], step_rec.angles[k],
                                                        M->jnt_type[qpos_of[k]] == mjJNT_SLIDE));
    if (i == o.i_from) mj_from = c;
    if (i == o.i_to) mj_to = c;
  }
  g_warnings = nullptr;
  mju_user_warning = nullptr;
  r.warnings = std::move(warnings);
  r.displacement = mj_to - mj_from;
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
  r.ode = o->displacement;
  const Vec3 a = horizontal(r.ode);
  const double la = norm(a);
  std::vector<double> headings, ratios;
  for (const MujocoContacts& contacts : kMujocoContacts) {
    auto run = run_mujoco(m, *o, contacts);
    if (!run) return Error{std::string(contacts.name) + ": " + run.error()};
    CrossSimVariant v;
    v.name = contacts.name;
    v.displacement = run->displacement;
    v.min_height = run->min_height;
    v.first_second_angle_gap = run->first_second_angle_gap;
    v.warnings = std::move(run->warnings);
    const Vec3 b = horizontal(v.displacement);
    const double lb = norm(b);
    v.distance_ratio = la > 0 ? lb / la : 0;
    v.heading_difference = la > 0 && lb > 0 ? std::acos(std::clamp(dot(a, b) / (la * lb), -1.0, 1.0)) : 0;
    headings.push_back(v.heading_difference);
    ratios.push_back(v.distance_ratio);
    r.variants.push_back(std::move(v));
  }
  auto median = [](std::vector<double> x) {
    std::sort(x.begin(), x.end());
    const std::size_t n = x.size();
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
  };
  r.heading_difference = median(headings);
  r.distance_ratio = median(ratios);
  return r;
}

}  // namespace bx
