// bench_muscle: a muscle's spring integrated implicitly (ODE's soft distance
// constraint, as World does it: MotorModel::Muscle) against explicitly
// (spring-damper forces added each step), measured on the one system with a
// closed form (docs/physics.md, "Muscles: implicit soft constraint or
// explicit forces"; docs/benchmarks.md).
//
// The system: a free 1 kg cube tethered by a muscle to a free 100 kg cube
// (reduced mass mu = 100/101 kg), no gravity, no contacts, started at rest
// stretched by x0 = 0.05 m beyond the rest length L0 = 0.5 m along the line
// between their centres (the anchors). The stretch x = L - L0 is then the
// damped oscillator mu x'' + c x' + k x = 0, omega = sqrt(k / mu), c = 2 zeta
// sqrt(k mu), omega_d = omega sqrt(1 - zeta^2).
//
//   implicit   bx::World with MotorModel::Muscle at activation 1 (strength
//              k, muscle_damping c), apply_effectors and step each step:
//              the product's own code path (a DBall joint whose ERP and CFM
//              are the spring and damper at the step)
//   explicit   raw ODE bodies with World's settings; each step F = -k (L -
//              L0) - c dL/dt along the line between the anchors, from the
//              state at the step's start, added with dBodyAddForceAtPos on
//              both anchors; then the step World takes (dWorldStep for the
//              exact solver, dWorldQuickStep for QuickStep)
//
// Per grid point (zeta, k h^2 / mu), measured at each step h, for each way:
// whether the stretch stays bounded (explodes: |x| > 100 x0, not finite, or
// the anchors within L0 / 10 of each other, within 4 closed-form periods
// plus 2000 steps); the period (from the first 7 zero crossings) against
// 2 pi / omega_d; the amplitude at the 3rd period (the sampled peak between
// crossings 6 and 7, refined by a parabola through its neighbours) against
// the closed form's envelope x0 exp(-zeta omega t) at that time (for zeta 0
// the integrator's own numerical damping); the largest |x - x_closed(t)| /
// x0 over 3 closed-form periods; and the static force error: the free cube
// hung from a cube of its own mass fixed to the world, under a gravity of
// k x0 / m, settled (zeta 0.5), its stretch x_eq against x0 (the spring's
// force k x_eq against the load m g = k x0). "5%": period and amplitude
// within 5% of the closed form (zeta < 1), the trajectory within 5% of x0
// (zeta 1). A row prints the first step's figures, the largest static error
// over the steps, and how far the steps' figures differ.
//
// Cost: CPU time per step (thread CPU time) of each way at k h^2 / mu = 0.1,
// zeta 0.1, the ways interleaved in each repetition; printed as ratios
// against the implicit way in World, min / median / max over the
// repetitions. A third way, ODE's DBall set up by hand as a plain ODE
// program would (same bodies as the explicit way), separates World's own
// cost (collision pass, effector table) from the soft constraint's; its
// trajectory must end bit-identical to World's (the check line).
//
// Exit code 0; 2 on a bad argument.
#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "args.h"
#include "develop/creature_model.h"
#include "geometry/ode.h"
#include "physics/physics_def.h"
#include "physics/world.h"
#include "raw_ode.h"  // cpu_seconds, median

namespace {

using namespace bx;
using namespace bx::bench;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ---------------------------------------------------------------------------
// The system

struct Spring {
  double h = 0.01;     ///< step (s)
  double m = 1;        ///< the free cube (kg)
  double M = 100;      ///< the other cube (kg): heavy; the static test's fixed one: m
  double L0 = 0.5;     ///< rest length (m)
  double x0 = 0.05;    ///< initial stretch (m)
  double k = 0, c = 0; ///< spring (N/m), damper (N s/m)
  double zeta = 0;
  bool hang = false;   ///< the static test: the other cube fixed, gravity k x0 / m along -z
  Solver solver = Solver::Exact;
  int iterations = 20;

  double mu() const { return hang ? m : m * M / (m + M); }
  double omega() const { return std::sqrt(k / mu()); }
  double omega_d() const { return omega() * std::sqrt(std::max(0.0, 1 - zeta * zeta)); }
  double gravity() const { return hang ? -k * x0 / m : 0.0; }
  // the cubes' centres at the start: along x stretched by x0, or (hanging)
  // along -z at the rest length
  Vec3 pos_a() const { return {0, 0, 2}; }
  Vec3 pos_b() const { return hang ? Vec3{0, 0, 2 - L0} : Vec3{L0 + x0, 0, 2}; }

  /// The closed form's stretch at time t (zeta < 1 or zeta = 1).
  double closed(double t) const {
    const double w = omega();
    if (zeta >= 1) return x0 * (1 + w * t) * std::exp(-w * t);
    const double wd = omega_d();
    return x0 * std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
  }
};

/// A spring of `kn` = k h^2 / mu and damping ratio zeta at step h.
Spring make_spring(double h, double kn, double zeta, Solver solver, int iterations) {
  Spring s;
  s.h = h;
  s.zeta = zeta;
  s.solver = solver;
  s.iterations = iterations;
  s.k = kn * s.mu() / (h * h);
  s.c = 2 * zeta * std::sqrt(s.k * s.mu());
  return s;
}

PhysicsDef physics_of(const Spring& s) {
  PhysicsDef def;
  def.dt = s.h;
  def.gravity = s.gravity();
  def.solver = s.solver;
  def.solver_iterations = s.iterations;
  return def;
}

// ---------------------------------------------------------------------------
// The implicit way: World, MotorModel::Muscle

PartModel cube(double mass, Vec3 pos, int parent) {
  PartModel p;
  p.shape = Shape::Box;
  p.size = {0.1, 0.1, 0.1};
  p.mass = mass;
  p.pose = {pos, Mat3::identity()};
  p.parent = parent;
  return p;
}

class ImplicitWorld {
 public:
  explicit ImplicitWorld(const Spring& s) : s_(s), w_(physics_of(s)) {
    cm_.parts = {cube(s.M, s.pos_a(), -1), cube(s.m, s.pos_b(), 0)};
    cm_.muscles.push_back({0, 1, s.pos_a(), s.pos_b(), s.k, s.L0});
    EffectorModel e;
    e.muscle = 0;
    cm_.effectors.push_back(e);
    motor_.model = MotorModel::Muscle;
    motor_.muscle_damping = s.c;
    w_.add_creature(cm_, {{0, 0, 0}, Mat3::identity()});
    if (s.hang) w_.fix_part_to_world(0);
  }
  /// One step at full activation; the stretch after it.
  double step() {
    const double full[1] = {1};
    w_.apply_effectors(cm_, motor_, full);
    w_.step();
    return stretch();
  }
  double stretch() const { return norm(w_.part_pose(1).p - w_.part_pose(0).p) - s_.L0; }
  Vec3 position(int i) const { return w_.part_pose(i).p; }

 private:
  Spring s_;
  World w_;
  CreatureModel cm_;
  MotorDef motor_;
};

// ---------------------------------------------------------------------------
// Raw ODE: the same bodies with World's world settings; the spring either as
// forces (the explicit way) or as a DBall set up by hand (the plain ODE
// program's implicit way: the timing's and the check's third way)

class Raw {
 public:
  Raw(const Spring& s, bool dball) : s_(s) {
    const PhysicsDef def = softness_at_step(physics_of(s));
    world_ = dWorldCreate();
    dWorldSetGravity(world_, 0, 0, def.gravity);
    dWorldSetERP(world_, def.erp);
    dWorldSetCFM(world_, def.cfm);
    dWorldSetQuickStepNumIterations(world_, def.solver_iterations);
    dWorldSetAutoDisableFlag(world_, 0);
    threading_ = dThreadingAllocateSelfThreadedImplementation();
    dWorldSetStepThreadingImplementation(world_, dThreadingImplementationGetFunctions(threading_), threading_);
    a_ = body(s.M, s.pos_a());
    b_ = body(s.m, s.pos_b());
    if (s.hang) {
      dJointID f = dJointCreateFixed(world_, nullptr);
      dJointAttach(f, a_, nullptr);
      dJointSetFixed(f);
    }
    if (dball) {
      const Vec3 pa = s.pos_a(), pb = s.pos_b();
      dball_ = dJointCreateDBall(world_, nullptr);
      dJointAttach(dball_, a_, b_);
      dJointSetDBallAnchor1(dball_, pa.x, pa.y, pa.z);
      dJointSetDBallAnchor2(dball_, pb.x, pb.y, pb.z);
      dJointSetDBallDistance(dball_, s.L0);
    }
  }
  ~Raw() {
    dWorldDestroy(world_);
    dThreadingFreeImplementation(threading_);
  }
  Raw(const Raw&) = delete;
  Raw& operator=(const Raw&) = delete;

  double step() {
    if (dball_) {
      // as a muscle whose activation may change: its ERP and CFM each step
      const double both = s_.h * s_.k + s_.c;
      dJointEnable(dball_);
      dJointSetDBallParam(dball_, dParamERP, s_.h * s_.k / both);
      dJointSetDBallParam(dball_, dParamCFM, 1 / both);
    } else {
      // the anchors (the centres), the line between them and its rate
      const dReal* pa = dBodyGetPosition(a_);
      const dReal* pb = dBodyGetPosition(b_);
      const dReal* va = dBodyGetLinearVel(a_);
      const dReal* vb = dBodyGetLinearVel(b_);
      double d[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
      const double L = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      for (double& di : d) di /= L;
      const double rate = d[0] * (vb[0] - va[0]) + d[1] * (vb[1] - va[1]) + d[2] * (vb[2] - va[2]);
      const double f = -s_.k * (L - s_.L0) - s_.c * rate;  // along a -> b, on b
      dBodyAddForceAtPos(b_, f * d[0], f * d[1], f * d[2], pb[0], pb[1], pb[2]);
      dBodyAddForceAtPos(a_, -f * d[0], -f * d[1], -f * d[2], pa[0], pa[1], pa[2]);
    }
    if (s_.solver == Solver::Exact)
      dWorldStep(world_, s_.h);
    else
      dWorldQuickStep(world_, s_.h);
    return stretch();
  }
  double stretch() const {
    const dReal* pa = dBodyGetPosition(a_);
    const dReal* pb = dBodyGetPosition(b_);
    return std::sqrt((pb[0] - pa[0]) * (pb[0] - pa[0]) + (pb[1] - pa[1]) * (pb[1] - pa[1]) +
                     (pb[2] - pa[2]) * (pb[2] - pa[2])) -
           s_.L0;
  }
  Vec3 position(int i) const {
    const dReal* p = dBodyGetPosition(i == 0 ? a_ : b_);
    return {p[0], p[1], p[2]};
  }

 private:
  dBodyID body(double mass, Vec3 pos) {
    dBodyID b = dBodyCreate(world_);
    dMass ms;
    dMassSetBoxTotal(&ms, mass, 0.1, 0.1, 0.1);
    dBodySetMass(b, &ms);
    dBodySetPosition(b, pos.x, pos.y, pos.z);
    return b;
  }
  Spring s_;
  dWorldID world_ = nullptr;
  dThreadingImplementationID threading_ = nullptr;
  dBodyID a_ = nullptr, b_ = nullptr;
  dJointID dball_ = nullptr;
};

// ---------------------------------------------------------------------------
// Measurement

struct Measured {
  bool bounded = true;
  double period = kNaN;  ///< measured / 2 pi / omega_d
  double amp = kNaN;     ///< measured peak at the 3rd period / x0 exp(-zeta omega t)
  double traj = kNaN;    ///< max |x - x_closed| / x0 over 3 closed-form periods
  double stat = kNaN;    ///< x_eq / x0 - 1 hung under a load of k x0
  bool ok5 = false;
};

/// Whether a stretch means the spring has exploded: not finite, beyond
/// 100 x0, or the anchors within L0 / 10 of each other (an unstable spring
/// that throws its cubes through each other: L >= 0 bounds x from below).
bool exploded(double x, const Spring& s) {
  return !std::isfinite(x) || std::abs(x) > 100 * s.x0 || x < -0.9 * s.L0;
}

/// Steps a way from the start and measures its trajectory.
template <class Way>
Measured measure_dynamic(const Spring& s) {
  Way way(s);
  const double h = s.h, x0 = s.x0;
  const double T = 2 * kPi / (s.zeta < 1 ? s.omega_d() : s.omega());  // the closed form's period
  const long n = static_cast<long>(std::ceil(4 * T / h)) + 2000;
  std::vector<double> x{x0};
  x.reserve(static_cast<std::size_t>(n) + 1);
  Measured r;
  for (long i = 0; i < n; ++i) {
    const double xi = way.step();
    if (exploded(xi, s)) {
      r.bounded = false;
      return r;
    }
    x.push_back(xi);
  }
  // trajectory error over 3 closed-form periods
  r.traj = 0;
  for (std::size_t i = 0; i < x.size() && i * h <= 3 * T; ++i)
    r.traj = std::max(r.traj, std::abs(x[i] - s.closed(static_cast<double>(i) * h)) / x0);
  if (s.zeta >= 1) {
    r.ok5 = r.traj <= 0.05;
    return r;
  }
  // zero crossings, linearly interpolated
  std::vector<double> tc;
  std::vector<std::size_t> ic;  // the step before each crossing
  for (std::size_t i = 0; i + 1 < x.size() && tc.size() < 7; ++i) {
    if ((x[i] > 0 && x[i + 1] <= 0) || (x[i] < 0 && x[i + 1] >= 0)) {
      if (x[i + 1] == 0 && i + 2 < x.size() && (x[i + 2] > 0) == (x[i] > 0)) continue;  // touched 0
      tc.push_back(h * (static_cast<double>(i) + x[i] / (x[i] - x[i + 1])));
      ic.push_back(i);
    }
  }
  const double w = s.omega();
  if (tc.size() == 7) {
    r.period = (tc[6] - tc[0]) / 3 / T;
    // the 6th extremum: the largest |x| between crossings 6 and 7
    std::size_t j = ic[5] + 1;
    for (std::size_t i = ic[5] + 1; i <= ic[6]; ++i)
      if (std::abs(x[i]) > std::abs(x[j])) j = i;
    double peak = std::abs(x[j]), tp = h * static_cast<double>(j);
    const double sg = x[j] > 0 ? 1 : -1;
    const double ym = sg * x[j - 1], y0 = sg * x[j], yp = sg * x[j + 1];
    const double den = ym - 2 * y0 + yp;
    if (den < 0) {
      const double off = 0.5 * (ym - yp) / den;
      if (std::abs(off) <= 1) {
        peak = y0 - 0.25 * (ym - yp) * off;
        tp += off * h;
      }
    }
    r.amp = peak / (x0 * std::exp(-s.zeta * w * tp));
  } else {
    // no 7 crossings (damped out, or stuck at 0): the largest |x| around the
    // closed form's 3rd period against its envelope there
    double peak = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double t = h * static_cast<double>(i);
      if (t >= 2.75 * T && t <= 3.25 * T) peak = std::max(peak, std::abs(x[i]));
    }
    r.amp = peak / (x0 * std::exp(-s.zeta * w * 3 * T));
  }
  r.ok5 = std::isfinite(r.period) && std::abs(r.period - 1) <= 0.05 && std::abs(r.amp - 1) <= 0.05;
  return r;
}

/// The free cube hung from a cube of its own mass fixed to the world, under
/// a load of k x0, settled at zeta 0.5: x_eq / x0 - 1 (NaN if it exploded or
/// did not settle: its last 100 steps more than 1e-6 x0 apart).
template <class Way>
double measure_static(const Spring& dyn) {
  Spring s = dyn;
  s.hang = true;
  // its weight loads the fixed joint (ERP 0.2, CFM 1e-5): kept light, the cubes stay clear of the ground
  s.M = s.m;
  s.zeta = 0.5;
  s.k = dyn.k * s.mu() / dyn.mu();  // the same k h^2 / mu with mu = m
  s.c = 2 * s.zeta * std::sqrt(s.k * s.mu());
  Way way(s);
  const long n = std::min(200000L, std::max(2000L, static_cast<long>(60 / (s.zeta * s.omega() * s.h))));
  double x = 0, lo = 1e300, hi = -1e300;
  for (long i = 0; i < n; ++i) {
    x = way.step();
    if (exploded(x, s)) return kNaN;
    if (i >= n - 100) lo = std::min(lo, x), hi = std::max(hi, x);
  }
  if (hi - lo > 1e-6 * s.x0) return kNaN;  // not settled
  return x / s.x0 - 1;
}

struct ExplicitRaw : Raw {
  explicit ExplicitRaw(const Spring& s) : Raw(s, false) {}
};
struct ImplicitRaw : Raw {
  explicit ImplicitRaw(const Spring& s) : Raw(s, true) {}
};

/// One grid point's measurements at each step h.
struct Row {
  double zeta = 0, kn = 0;
  std::vector<Measured> imp, exp;
};

// ---------------------------------------------------------------------------
// Output

std::string fmt(double v, const char* f = "%.3f") {
  if (!std::isfinite(v)) return "-";
  char b[32];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

std::string step_name(double h) {
  char b[32];
  std::snprintf(b, sizeof b, "1/%.0f", 1 / h);
  return b;
}

/// The largest |x_eq / x0 - 1| over the steps, NaN if any step's is.
double worst_static(const std::vector<Measured>& ms) {
  double w = 0;
  for (const Measured& m : ms) {
    if (!std::isfinite(m.stat)) return kNaN;
    w = std::max(w, std::abs(m.stat));
  }
  return w;
}

/// How far the steps' figures of one way differ: "same" if bit for bit,
/// "DIFFER" if their verdicts (bounded, 5%) do, else the largest difference.
struct Spread {
  bool verdicts_differ = false;
  double most = 0;
  void add(const std::vector<Measured>& ms) {
    for (const Measured& m : ms) {
      const Measured& a = ms.front();
      if (m.bounded != a.bounded || m.ok5 != a.ok5) verdicts_differ = true;
      for (auto [p, q] : {std::pair{m.period, a.period}, std::pair{m.amp, a.amp}, std::pair{m.traj, a.traj}}) {
        if (std::isfinite(p) != std::isfinite(q)) verdicts_differ = true;
        else if (std::isfinite(p)) most = std::max(most, std::abs(p - q));
      }
    }
  }
  std::string str() const { return verdicts_differ ? "DIFFER" : most == 0 ? "same" : fmt(most, "%.1e"); }
};

void print_way(const std::vector<Measured>& ms) {
  const Measured& m = ms.front();
  const std::string st = fmt(worst_static(ms), "%.0e");
  if (!m.bounded) {
    std::printf(" | %-8s %6s %6s %8s %6s %3s", "EXPLODES", "-", "-", "-", st.c_str(), "no");
    return;
  }
  std::printf(" | %-8s %6s %6s %8s %6s %3s", "bounded", fmt(m.period).c_str(), fmt(m.amp).c_str(),
              fmt(m.traj, "%.2e").c_str(), st.c_str(), m.ok5 ? "yes" : "no");
}

/// Where one way holds at one zeta, over the grid from its smallest point:
/// the last point bounded (at every step h) and the first not; the last
/// within 5% and the first not. NaN: none.
struct Reach {
  double bounded = kNaN, first_unbounded = kNaN, ok5 = kNaN, first_not_ok5 = kNaN;
};
Reach reach(const std::vector<Row>& rows, double zeta, bool imp) {
  Reach r;
  bool b = true, k = true;
  for (const Row& row : rows) {
    if (row.zeta != zeta) continue;
    bool all_b = true, all_k = true;
    for (const Measured& m : imp ? row.imp : row.exp) {
      all_b = all_b && m.bounded;
      all_k = all_k && m.ok5;
    }
    if (b && all_b) r.bounded = row.kn;
    if (b && !all_b) r.first_unbounded = row.kn, b = false;
    if (k && all_k) r.ok5 = row.kn;
    if (k && !all_k) r.first_not_ok5 = row.kn, k = false;
  }
  return r;
}

int usage(const char* msg) {
  if (msg) std::fprintf(stderr, "bench_muscle: %s\n", msg);
  std::fprintf(stderr,
               "usage: bench_muscle [--quick] [--reps R] [--steps N] [--solver exact|quickstep] [--iterations I]\n"
               "  a muscle's spring integrated implicitly (World's soft DBall constraint) and explicitly\n"
               "  (forces each step) against the damped oscillator's closed form, and the CPU time of each\n"
               "  --quick         3 grid points, zeta 0 and 1, h 1/60, 3 timed repetitions of 2000 steps (smoke)\n"
               "  --reps R        timed repetitions (default 9)\n"
               "  --steps N       steps per timed repetition (default 20000)\n"
               "  --solver S      exact (default, PhysicsDef's) or quickstep\n"
               "  --iterations I  QuickStep iterations (default 20)\n");
  return msg ? 2 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  int reps = 9;
  long steps = 20000;
  Solver solver = Solver::Exact;
  int iterations = 20;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&](const char* name) {
      return bxbench::number_after(i, argc, argv, name, usage, [](double v) { return v >= 1; }, "a number >= 1");
    };
    if (a == "--quick") quick = true;
    else if (a == "--reps") reps = static_cast<int>(value("--reps"));
    else if (a == "--steps") steps = static_cast<long>(value("--steps"));
    else if (a == "--iterations") iterations = static_cast<int>(value("--iterations"));
    else if (a == "--solver") {
      if (i + 1 >= argc) return usage("--solver: missing value");
      std::string v = argv[++i];
      if (v == "exact") solver = Solver::Exact;
      else if (v == "quickstep") solver = Solver::QuickStep;
      else return usage(("--solver: unknown solver \"" + v + "\"").c_str());
    } else if (a == "-h" || a == "--help") return usage(nullptr);
    else return usage(("unknown argument \"" + a + "\"").c_str());
  }
  if (quick) {
    reps = 3;
    steps = 2000;
  }
  ensure_ode_initialized();

  const std::vector<double> hs =
      quick ? std::vector<double>{1.0 / 60} : std::vector<double>{1.0 / 60, 1.0 / 120, 1.0 / 240};
  const std::vector<double> zetas = quick ? std::vector<double>{0, 1} : std::vector<double>{0, 0.1, 1};
  const std::vector<double> grid =
      quick ? std::vector<double>{0.01, 1, 10}
            : std::vector<double>{1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3, 0.01, 0.03, 0.1, 0.3,
                                  0.6,  0.8,  1,    2,    3,    3.9,  4.1,  10,   30,  100};
  std::string solver_name = solver == Solver::Exact ? "dWorldStep (exact, PhysicsDef's default)"
                                                    : "dWorldQuickStep, " + std::to_string(iterations) + " iterations";
  std::string steps_names;
  for (double h : hs) steps_names += (steps_names.empty() ? "" : ", ") + step_name(h);

  std::printf("muscle spring: a free 1 kg cube tethered to a free 100 kg cube (mu = %.4f kg), no gravity, no "
              "contacts,\nstarted at rest stretched x0 = 0.05 m beyond its rest length L0 = 0.5 m; solver %s\n",
              100.0 / 101, solver_name.c_str());
  std::printf("implicit: World, MotorModel::Muscle (ODE's soft DBall constraint, ERP and CFM from k and c at h);\n"
              "explicit: raw ODE, F = -k (L - L0) - c dL/dt from the step's start, dBodyAddForceAtPos on both "
              "anchors\n");
  std::printf("per way: bounded (|x| <= 100 x0, anchors not within L0/10, over 4 periods + 2000 steps);\n"
              "T/Td: period / (2 pi / omega_d); A/Acf: peak at the 3rd period / x0 exp(-zeta omega t) (zeta 0: "
              "the\nintegrator's own damping); traj: max |x - x_closed| / x0 over 3 periods; static: |x_eq / x0 - "
              "1|\nhung from a fixed cube under a load k x0, settled at zeta 0.5 (-: did not settle), the largest "
              "over h;\n5%%: period and amplitude within 5%% (zeta < 1), trajectory within 5%% of x0 (zeta 1);\n"
              "steps h = %s: each row is measured at every h; 'over h' is the largest difference of\nT/Td, A/Acf "
              "and traj between them ('same': bit for bit; DIFFER: bounded or 5%% differ)\n\n",
              steps_names.c_str());
  std::printf("%4s %7s | %-8s %6s %6s %8s %6s %3s | %-8s %6s %6s %8s %6s %3s | %s\n", "", "", "implicit", "", "",
              "", "", "", "explicit", "", "", "", "", "", "over h");
  std::printf("%4s %7s | %-8s %6s %6s %8s %6s %3s | %-8s %6s %6s %8s %6s %3s |\n", "zeta", "kh^2/mu", "", "T/Td",
              "A/Acf", "traj", "static", "5%", "", "T/Td", "A/Acf", "traj", "static", "5%");

  std::vector<Row> rows;
  for (double zeta : zetas) {
    for (double kn : grid) {
      Row r{zeta, kn, {}, {}};
      for (double h : hs) {
        const Spring s = make_spring(h, kn, zeta, solver, iterations);
        Measured imp = measure_dynamic<ImplicitWorld>(s), exp = measure_dynamic<ExplicitRaw>(s);
        imp.stat = measure_static<ImplicitWorld>(s);
        exp.stat = measure_static<ExplicitRaw>(s);
        r.imp.push_back(imp);
        r.exp.push_back(exp);
      }
      Spread spread;
      spread.add(r.imp);
      spread.add(r.exp);
      std::printf("%4g %7g", zeta, kn);
      print_way(r.imp);
      print_way(r.exp);
      std::printf(" | %s\n", spread.str().c_str());
      std::fflush(stdout);
      rows.push_back(r);
    }
  }

  // where each way is bounded and within 5%, per zeta
  std::printf("\nfrom the smallest kh^2/mu up (at every h):\n");
  std::vector<Reach> imp_reach, exp_reach;
  for (double zeta : zetas) {
    imp_reach.push_back(reach(rows, zeta, true));
    exp_reach.push_back(reach(rows, zeta, false));
    const Reach &ri = imp_reach.back(), &re = exp_reach.back();
    std::printf("zeta %-3g implicit: bounded up to %s (first unbounded %s), within 5%% up to %s (first not %s)\n",
                zeta, fmt(ri.bounded, "%g").c_str(), fmt(ri.first_unbounded, "%g").c_str(), fmt(ri.ok5, "%g").c_str(),
                fmt(ri.first_not_ok5, "%g").c_str());
    std::printf("zeta %-3g explicit: bounded up to %s (first unbounded %s), within 5%% up to %s (first not %s)\n",
                zeta, fmt(re.bounded, "%g").c_str(), fmt(re.first_unbounded, "%g").c_str(), fmt(re.ok5, "%g").c_str(),
                fmt(re.first_not_ok5, "%g").c_str());
  }
  double static_imp = 0, static_exp = 0;  // the largest static error where each settled
  for (const Row& r : rows)
    for (std::size_t i = 0; i < r.imp.size(); ++i) {
      if (std::isfinite(r.imp[i].stat)) static_imp = std::max(static_imp, std::abs(r.imp[i].stat));
      if (std::isfinite(r.exp[i].stat)) static_exp = std::max(static_exp, std::abs(r.exp[i].stat));
    }
  std::printf("static force: the largest |k x_eq / (m g) - 1| where it settled: implicit %.1e, explicit %.1e\n",
              static_imp, static_exp);

  // the check: World's muscle is ODE's DBall and nothing else
  {
    const Spring s = make_spring(hs.back(), 0.1, 0.1, solver, iterations);
    ImplicitWorld w(s);
    ImplicitRaw raw(s);
    for (int i = 0; i < 2000; ++i) {
      w.step();
      raw.step();
    }
    double dev = 0;
    for (int i = 0; i < 2; ++i) dev = std::max(dev, norm(w.position(i) - raw.position(i)));
    std::printf("\ncheck: 2000 steps at kh^2/mu 0.1, zeta 0.1, h %s: a DBall set up by hand ends %s World's "
                "muscle (max part deviation %.3g m)\n",
                step_name(s.h).c_str(), dev == 0 ? "bit-identical to" : "DIFFERENT from", dev);
  }

  // cost: CPU time per step, the ways interleaved in each repetition
  std::printf("\nCPU time per step at kh^2/mu 0.1, zeta 0.1 (%d repetitions of %ld steps, thread CPU time; "
              "ratios per repetition, min / median / max)\n",
              reps, steps);
  std::vector<double> all_ratio;
  auto mmm = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    char b[64];
    std::snprintf(b, sizeof b, "%.3f / %.3f / %.3f", v.front(), median(v), v.back());
    return std::string(b);
  };
  for (double h : hs) {
    const Spring s = make_spring(h, 0.1, 0.1, solver, iterations);
    std::vector<double> t_world, t_exp, t_raw, r_exp, r_raw, r_exp_raw;
    for (int rep = 0; rep < reps; ++rep) {
      bool finite = true;
      auto timed = [&](auto& way) {
        double sink = 0;
        const double t0 = cpu_seconds();
        for (long i = 0; i < steps; ++i) sink += way.step();
        const double t = (cpu_seconds() - t0) / static_cast<double>(steps);
        finite = finite && std::isfinite(sink);
        return t;
      };
      ImplicitWorld w(s);
      ExplicitRaw e(s);
      ImplicitRaw d(s);
      const double tw = timed(w), te = timed(e), td = timed(d);
      if (!finite) std::printf("(a timed run went non-finite)\n");
      t_world.push_back(tw);
      t_exp.push_back(te);
      t_raw.push_back(td);
      r_exp.push_back(te / tw);
      r_raw.push_back(td / tw);
      r_exp_raw.push_back(te / td);
    }
    std::printf("h %s: implicit (World) %.2f us/step, explicit (raw forces) %.2f us/step, implicit (raw DBall) "
                "%.2f us/step (medians)\n",
                step_name(h).c_str(), 1e6 * median(t_world), 1e6 * median(t_exp), 1e6 * median(t_raw));
    std::printf("  explicit / implicit (World):     %s\n", mmm(r_exp).c_str());
    std::printf("  explicit / implicit (raw DBall): %s\n", mmm(r_exp_raw).c_str());
    std::printf("  raw DBall / World:               %s\n", mmm(r_raw).c_str());
    all_ratio.insert(all_ratio.end(), r_exp.begin(), r_exp.end());
  }
  std::printf("cpu_ratio_explicit_vs_implicit: %.3f (median of all %zu repetitions; min / median / max %s)\n", median(all_ratio),
              all_ratio.size(), mmm(all_ratio).c_str());

  // verdict
  auto per_zeta = [&](const std::vector<Reach>& rs, double Reach::*f) {
    std::string out;
    for (std::size_t i = 0; i < rs.size(); ++i) out += (i ? " / " : "") + fmt(rs[i].*f, "%g");
    return out;
  };
  std::string zeta_names;
  for (std::size_t i = 0; i < zetas.size(); ++i) zeta_names += (i ? " / " : "") + fmt(zetas[i], "%g");
  bool imp_all_bounded = true;
  for (const Reach& r : imp_reach) imp_all_bounded = imp_all_bounded && !std::isfinite(r.first_unbounded);
  std::printf("\nverdict (zeta %s): implicit bounded up to kh^2/mu %s%s, within 5%% up to %s; explicit bounded up "
              "to %s (explodes from %s), within 5%% up to %s; static force error implicit %.0e, explicit %.0e; "
              "CPU explicit/implicit %.2f. %s\n",
              zeta_names.c_str(), per_zeta(imp_reach, &Reach::bounded).c_str(),
              imp_all_bounded ? " (all the grid)" : "", per_zeta(imp_reach, &Reach::ok5).c_str(),
              per_zeta(exp_reach, &Reach::bounded).c_str(), per_zeta(exp_reach, &Reach::first_unbounded).c_str(),
              per_zeta(exp_reach, &Reach::ok5).c_str(), static_imp, static_exp, median(all_ratio),
              imp_all_bounded ? "Muscles stay implicit: bounded at any stiffness, at the price of numerical damping"
                              : "The implicit way did not stay bounded: see the table");
  return 0;
}
