// bench_step: steps per second of a full evaluation (brain, sensors, motors,
// contacts, explosion checks, task) against raw ODE stepping the same bodies
// and joints in the same process (docs/benchmarks.md).
//
//   ours     bx::evaluate() itself, the production code, over N steps
//   raw ODE  the same bodies, geoms, joints, ground, contact rules and solver
//            settings built with direct ODE calls, stepped with dSpaceCollide
//            + dWorldQuickStep + dJointGroupEmpty, its motors replaying the
//            joint torques our run applied (recorded once, untimed) so that
//            both do identical physics work; no brain, sensors or checks
//
// Output: one line per creature, then `ratio_vs_raw_ode: X` (the smaller
// ratio). Checks (does raw reproduce our trajectory bit for bit?) go to stderr.
#include <ode/ode.h>

#include <dlfcn.h>
#include <time.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "develop/develop.h"
#include "eval/evaluate.h"
#include "eval/sim_config.h"
#include "genome/genome_json.h"
#include "physics/world.h"

#ifndef BESTIARY_SOURCE_DIR
#define BESTIARY_SOURCE_DIR "."
#endif

// ---------------------------------------------------------------------------
// Contact counter. This definition takes the place of ODE's for every call in
// this executable (ours in bx_sim and raw below alike): it counts, then calls
// ODE's own. One increment and one indirect call per contact, on both sides.

namespace {
using CreateContactFn = dJointID (*)(dWorldID, dJointGroupID, const dContact*);
CreateContactFn g_real_create_contact = nullptr;
long g_contacts = 0;
}  // namespace

extern "C" dJointID dJointCreateContact(dWorldID w, dJointGroupID g, const dContact* c) {
  ++g_contacts;
  return g_real_create_contact(w, g, c);
}

namespace {

using namespace bx;

// thread CPU time (s): the work itself, not time the scheduler gave others on
// a shared machine
double cpu_seconds() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// ---------------------------------------------------------------------------
// Raw ODE: the creature built and stepped by hand, as a plain ODE program
// would, with World's settings and call order (so ODE does the same work).

void to_ode(const Mat3& R, dMatrix3 out) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out[i * 4 + j] = R.m[i][j];
    out[i * 4 + 3] = 0;
  }
}

// one motor-driven joint and its torques, per step, from the recorded run
struct Drive {
  int joint = 0;
  JointType type = JointType::Hinge;
};

struct RawWorld {
  PhysicsDef def;
  dWorldID world = nullptr;
  dSpaceID space = nullptr;
  dJointGroupID contact_group = nullptr;
  dThreadingImplementationID threading = nullptr;
  std::vector<dBodyID> bodies;
  std::vector<dJointID> joints;
  std::vector<dJointID> amotors;
  std::vector<dContact> contact_buf;

  static void near_callback(void* data, dGeomID a, dGeomID b) {
    auto& w = *static_cast<RawWorld*>(data);
    dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
    if (ba && bb && (!w.def.self_collision || dAreConnectedExcluding(ba, bb, dJointTypeContact)))
      return;
    int n = dCollide(a, b, w.def.max_contacts, &w.contact_buf[0].geom, sizeof(dContact));
    for (int i = 0; i < n; ++i) {
      dContact& c = w.contact_buf[i];
      c.surface.mode = dContactApprox1;
      c.surface.mu = w.def.friction;
      dJointAttach(dJointCreateContact(w.world, w.contact_group, &c), ba, bb);
    }
  }

  RawWorld(const CreatureModel& m, const PhysicsDef& d, const Pose& placement) : def(d) {
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, def.gravity);
    dWorldSetERP(world, def.erp);
    dWorldSetCFM(world, def.cfm);
    dWorldSetQuickStepNumIterations(world, def.solver_iterations);
    dWorldSetAutoDisableFlag(world, 0);
    threading = dThreadingAllocateSelfThreadedImplementation();
    dWorldSetStepThreadingImplementation(world, dThreadingImplementationGetFunctions(threading),
                                         threading);
    space = dSimpleSpaceCreate(nullptr);
    contact_group = dJointGroupCreate(0);
    dCreatePlane(space, 0, 0, 1, 0);
    contact_buf.resize(std::max(def.max_contacts, 1));

    // bodies: mass, inertia, pose, geom
    const Mat3 z_to_x = Mat3::rotation({0, 1, 0}, kPi / 2);
    for (const PartModel& part : m.parts) {
      Pose pose{placement.apply(part.pose.p), placement.R * part.pose.R};
      dBodyID b = dBodyCreate(world);
      dMass mass;
      const Vec3& s = part.size;
      dGeomID g = nullptr;
      switch (part.shape) {
        case Shape::Box:
          dMassSetBoxTotal(&mass, part.mass, s.x, s.y, s.z);
          g = dCreateBox(space, s.x, s.y, s.z);
          break;
        case Shape::Sphere:
          dMassSetSphereTotal(&mass, part.mass, s.x / 2);
          g = dCreateSphere(space, s.x / 2);
          break;
        case Shape::Capsule:
          dMassSetCapsuleTotal(&mass, part.mass, 1, s.y / 2, std::max(s.x - s.y, 0.0));
          g = dCreateCapsule(space, s.y / 2, std::max(s.x - s.y, 0.0));
          break;
        case Shape::Cylinder:
          dMassSetCylinderTotal(&mass, part.mass, 1, s.y / 2, s.x);
          g = dCreateCylinder(space, s.y / 2, s.x);
          break;
      }
      dBodySetMass(b, &mass);
      dBodySetPosition(b, pose.p.x, pose.p.y, pose.p.z);
      dMatrix3 R;
      to_ode(pose.R, R);
      dBodySetRotation(b, R);
      dGeomSetBody(g, b);
      if (part.shape == Shape::Capsule || part.shape == Shape::Cylinder) {
        dMatrix3 off;
        to_ode(z_to_x, off);
        dGeomSetOffsetRotation(g, off);
      }
      bodies.push_back(b);
    }

    // joints: type, anchor, axes, limits
    for (const JointModel& jm : m.joints) {
      Vec3 an = placement.apply(jm.anchor);
      Vec3 a1 = placement.R * jm.axis1, a2 = placement.R * jm.axis2;
      dBodyID b1 = bodies[jm.parent], b2 = bodies[jm.child];
      dJointID j = nullptr, am = nullptr;
      switch (jm.type) {
        case JointType::Fixed:
          j = dJointCreateFixed(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetFixed(j);
          break;
        case JointType::Hinge:
          j = dJointCreateHinge(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetHingeAnchor(j, an.x, an.y, an.z);
          dJointSetHingeAxis(j, a1.x, a1.y, a1.z);
          break;
        case JointType::Universal:
          j = dJointCreateUniversal(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetUniversalAnchor(j, an.x, an.y, an.z);
          dJointSetUniversalAxis1(j, a1.x, a1.y, a1.z);
          dJointSetUniversalAxis2(j, a2.x, a2.y, a2.z);
          break;
        case JointType::Slider:
          j = dJointCreateSlider(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetSliderAxis(j, a1.x, a1.y, a1.z);
          break;
        case JointType::Cylindrical:
          j = dJointCreatePiston(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetPistonAnchor(j, an.x, an.y, an.z);
          dJointSetPistonAxis(j, a1.x, a1.y, a1.z);
          break;
        case JointType::Spherical:
          j = dJointCreateBall(world, nullptr);
          dJointAttach(j, b1, b2);
          dJointSetBallAnchor(j, an.x, an.y, an.z);
          am = dJointCreateAMotor(world, nullptr);
          dJointAttach(am, b1, b2);
          dJointSetAMotorMode(am, dAMotorEuler);
          dJointSetAMotorAxis(am, 0, 1, a1.x, a1.y, a1.z);
          dJointSetAMotorAxis(am, 2, 2, a2.x, a2.y, a2.z);
          break;
      }
      for (std::size_t d = 0; d < jm.limits.size(); ++d) {
        int g = static_cast<int>(d) * dParamGroup;
        for (auto [param, v] : {std::pair{dParamLoStop, jm.limits[d].lo},
                                std::pair{dParamHiStop, jm.limits[d].hi}}) {
          switch (jm.type) {
            case JointType::Hinge: dJointSetHingeParam(j, param, v); break;
            case JointType::Universal: dJointSetUniversalParam(j, param + g, v); break;
            case JointType::Slider: dJointSetSliderParam(j, param, v); break;
            case JointType::Cylindrical: dJointSetPistonParam(j, param + g, v); break;
            case JointType::Spherical: dJointSetAMotorParam(am, param + g, v); break;
            case JointType::Fixed: break;
          }
        }
      }
      joints.push_back(j);
      amotors.push_back(am);
    }
  }

  ~RawWorld() {
    dJointGroupDestroy(contact_group);
    dSpaceDestroy(space);
    dWorldDestroy(world);
    dThreadingFreeImplementation(threading);
  }

  // adds one recorded joint torque (per degree of freedom)
  void add_torque(const Drive& d, const double* tq) {
    dJointID j = joints[d.joint];
    switch (d.type) {
      case JointType::Hinge: dJointAddHingeTorque(j, tq[0]); break;
      case JointType::Universal: dJointAddUniversalTorques(j, tq[0], tq[1]); break;
      case JointType::Slider: dJointAddSliderForce(j, tq[0]); break;
      case JointType::Cylindrical: {
        dJointAddPistonForce(j, tq[0]);
        dVector3 a;
        dJointGetPistonAxis(j, a);
        dBodyAddTorque(dJointGetBody(j, 0), tq[1] * a[0], tq[1] * a[1], tq[1] * a[2]);
        dBodyAddTorque(dJointGetBody(j, 1), -tq[1] * a[0], -tq[1] * a[1], -tq[1] * a[2]);
        break;
      }
      case JointType::Spherical: dJointAddAMotorTorques(amotors[d.joint], tq[0], tq[1], tq[2]); break;
      case JointType::Fixed: break;
    }
  }

  void step() {
    dSpaceCollide(space, this, &near_callback);
    dWorldQuickStep(world, def.dt);
    dJointGroupEmpty(contact_group);
  }
};

// The joint torques of every step of one of our runs, as World applied them.
struct TorqueTape {
  std::vector<Drive> drives;
  std::vector<double> tq;  // steps x drives x 3
  long steps = 0;
};

TorqueTape record_torques(const CreatureModel& m, const SimConfig& cfg, const Replay& replay,
                          long steps) {
  TorqueTape tape;
  tape.steps = steps;
  std::vector<int> drive_of(m.joints.size(), -1);
  for (const EffectorModel& e : m.effectors) {
    if (drive_of[e.joint] >= 0) continue;
    drive_of[e.joint] = static_cast<int>(tape.drives.size());
    tape.drives.push_back({e.joint, m.joints[e.joint].type});
  }
  // drives in joint order, as World adds torques
  std::sort(tape.drives.begin(), tape.drives.end(),
            [](const Drive& a, const Drive& b) { return a.joint < b.joint; });
  for (std::size_t k = 0; k < tape.drives.size(); ++k) drive_of[tape.drives[k].joint] = int(k);
  const std::size_t nd = tape.drives.size();
  tape.tq.assign(static_cast<std::size_t>(steps) * nd * 3, 0.0);
  // frame 0 is the initial state; frame k+1 holds the signals of step k
  for (long s = 0; s < steps; ++s) {
    const std::vector<double>& sig = replay.frames[s + 1].effectors;
    double* row = &tape.tq[static_cast<std::size_t>(s) * nd * 3];
    for (std::size_t e = 0; e < m.effectors.size(); ++e) {
      const EffectorModel& em = m.effectors[e];
      row[drive_of[em.joint] * 3 + em.dof] += sig[e] * cfg.motor.strength * em.cross_section;
    }
  }
  return tape;
}

// One raw run: build, step `tape.steps` steps replaying the torques, destroy.
// Returns the final body positions for the trajectory check.
std::vector<Vec3> run_raw(const CreatureModel& m, const SimConfig& cfg, const Pose& placement,
                          const TorqueTape& tape, std::uint64_t seed) {
  dRandSetSeed(static_cast<unsigned long>(seed & 0xffffffffULL));
  RawWorld w(m, cfg.physics, placement);
  const std::size_t nd = tape.drives.size();
  const double* tq = tape.tq.data();
  for (long s = 0; s < tape.steps; ++s) {
    for (std::size_t k = 0; k < nd; ++k, tq += 3) w.add_torque(tape.drives[k], tq);
    w.step();
  }
  std::vector<Vec3> pos;
  for (dBodyID b : w.bodies) {
    const dReal* p = dBodyGetPosition(b);
    pos.push_back({p[0], p[1], p[2]});
  }
  return pos;
}

struct Figures {
  double ours_sps = 0, raw_sps = 0;
  double ours_contacts = 0, raw_contacts = 0;
};

Figures bench_creature(const char* label, const std::string& path, long steps, int reps,
                       std::uint64_t seed) {
  auto genome = load_genome(path);
  if (!genome) {
    std::fprintf(stderr, "bench_step: %s\n", genome.error().c_str());
    std::exit(2);
  }
  SimConfig cfg = default_sim_config(genome->dialect);
  if (cfg.motor.model != MotorModel::Torque) {
    std::fprintf(stderr, "bench_step: %s: raw replay supports the Torque motor model only\n",
                 path.c_str());
    std::exit(2);
  }
  Development dev = develop(*genome, cfg.develop);
  if (!dev.viable()) {
    std::fprintf(stderr, "bench_step: %s: not viable: %s\n", path.c_str(), dev.reason.c_str());
    std::exit(2);
  }
  const CreatureModel& m = *dev.model;
  cfg.task.seconds = static_cast<double>(steps) * cfg.physics.dt;
  const Pose placement{{0, 0, cfg.task.drop_height - m.min_z()}, Mat3::identity()};

  // untimed: our run with a frame every step, to record the effector signals
  // (recording only reads the world, so the physics is that of the timed runs)
  SimConfig rec_cfg = cfg;
  rec_cfg.replay_fps = 1.0 / cfg.physics.dt;
  Replay replay;
  EvalResult rec = evaluate(m, rec_cfg, seed, &replay);
  if (rec.failed) {
    std::fprintf(stderr, "bench_step: %s: %s (the benchmark needs a full-length run)\n", label,
                 rec.failure.c_str());
    std::exit(2);
  }
  const long n = rec.steps;
  if (static_cast<long>(replay.frames.size()) != n + 1) {
    std::fprintf(stderr, "bench_step: %s: expected %ld replay frames, got %zu\n", label, n + 1,
                 replay.frames.size());
    std::exit(2);
  }
  TorqueTape tape = record_torques(m, cfg, replay, n);

  // check: raw ODE reproduces our trajectory (same physics work)
  std::vector<Vec3> raw_end = run_raw(m, cfg, placement, tape, seed);
  double max_dev = 0;
  const std::vector<double>& ours_end = replay.frames.back().poses;
  for (int i = 0; i < m.n_parts(); ++i) {
    Vec3 o{ours_end[7 * i], ours_end[7 * i + 1], ours_end[7 * i + 2]};
    max_dev = std::max(max_dev, norm(o - raw_end[i]));
  }
  std::fprintf(stderr, "check %s: %ld steps, raw ODE replay ends %s (max part deviation %.3g m)\n",
               label, n, max_dev == 0 ? "bit-identical to ours" : "DIFFERENT from ours", max_dev);

  // warm up, then alternate timed repetitions
  evaluate(m, cfg, seed);
  run_raw(m, cfg, placement, tape, seed);
  std::vector<double> ours_t, raw_t;
  Figures f;
  for (int r = 0; r < reps; ++r) {
    long c0 = g_contacts;
    double t0 = cpu_seconds();
    EvalResult res = evaluate(m, cfg, seed);
    double t1 = cpu_seconds();
    long c1 = g_contacts;
    run_raw(m, cfg, placement, tape, seed);
    double t2 = cpu_seconds();
    long c2 = g_contacts;
    if (res.steps != n) {
      std::fprintf(stderr, "bench_step: %s: run %d took %ld steps, expected %ld\n", label, r,
                   res.steps, n);
      std::exit(2);
    }
    ours_t.push_back(t1 - t0);
    raw_t.push_back(t2 - t1);
    f.ours_contacts = static_cast<double>(c1 - c0) / static_cast<double>(n);
    f.raw_contacts = static_cast<double>(c2 - c1) / static_cast<double>(n);
  }
  f.ours_sps = static_cast<double>(n) / median(ours_t);
  f.raw_sps = static_cast<double>(n) / median(raw_t);
  return f;
}

int usage(const char* msg) {
  if (msg) std::fprintf(stderr, "bench_step: %s\n", msg);
  std::fprintf(stderr,
               "usage: bench_step [--quick] [--steps N] [--reps R] [--seed S] [--only NAME]\n"
               "  steps per second of our evaluation vs raw ODE, 6- and 12-part creatures\n"
               "  --quick   500 steps x 3 repetitions (smoke test)\n"
               "  --only    one creature: snake or centipede (for profiling)\n"
               "  defaults: 5000 steps x 9 repetitions, seed 1\n");
  return msg ? 2 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  long steps = 5000;
  int reps = 9;
  std::uint64_t seed = 1;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](const char* name) -> long {
      if (i + 1 >= argc) std::exit(usage((std::string(name) + ": missing value").c_str()));
      char* end = nullptr;
      long v = std::strtol(argv[++i], &end, 10);
      if (*end || v < 1) std::exit(usage((std::string(name) + ": expected a positive integer, got \"" +
                                          argv[i] + "\"").c_str()));
      return v;
    };
    if (a == "--quick") {
      steps = 500;
      reps = 3;
    } else if (a == "--steps") {
      steps = value("--steps");
    } else if (a == "--reps") {
      reps = static_cast<int>(value("--reps"));
    } else if (a == "--seed") {
      seed = static_cast<std::uint64_t>(value("--seed"));
    } else if (a == "--only" && i + 1 < argc) {
      only = argv[++i];
      if (only != "snake" && only != "centipede")
        return usage(("--only: expected snake or centipede, got \"" + only + "\"").c_str());
    } else if (a == "-h" || a == "--help") {
      return usage(nullptr);
    } else {
      return usage(("unknown argument \"" + a + "\"").c_str());
    }
  }

  g_real_create_contact =
      reinterpret_cast<CreateContactFn>(dlsym(RTLD_NEXT, "dJointCreateContact"));
  if (!g_real_create_contact) {
    std::fprintf(stderr, "bench_step: cannot find ODE's dJointCreateContact\n");
    return 2;
  }
  bx::ensure_ode_initialized();

  // creature files: $BESTIARY_SOURCE_DIR, else the source tree this was built from
  const char* env = std::getenv("BESTIARY_SOURCE_DIR");
  std::string dir = std::string(env && *env ? env : BESTIARY_SOURCE_DIR) + "/tests/creatures/";
  struct Case {
    const char* label;
    const char* file;
    const char* name;
  };
  double worst = 1e300;
  for (Case c : {Case{"snake (6 parts)", "snake.json", "snake"},
                 Case{"centipede (12 parts)", "centipede.json", "centipede"}}) {
    if (!only.empty() && only != c.name) continue;
    Figures f = bench_creature(c.label, dir + c.file, steps, reps, seed);
    double ratio = f.ours_sps / f.raw_sps;
    worst = std::min(worst, ratio);
    std::printf("%s: ours %.0f steps/s, raw ODE %.0f steps/s, ratio %.3f, contacts/step ours %.1f raw %.1f\n",
                c.label, f.ours_sps, f.raw_sps, ratio, f.ours_contacts, f.raw_contacts);
    std::fflush(stdout);
  }
  std::printf("ratio_vs_raw_ode: %.3f\n", worst);
  return 0;
}
