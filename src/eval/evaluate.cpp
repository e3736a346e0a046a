#include "eval/evaluate.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "core/rng.h"
#include "geometry/ode.h"  // PhysicsFault
#include "eval/step.h"
#include "eval/task_table.h"
#include "physics/world.h"

namespace bx {

namespace {

// the stream of start poses (evolution.cpp's streams are 1-4, trials' 5, checks' 6)
constexpr std::uint64_t kStartStream = 7;

// Records the replay: a frame at the start and the first step at or after
// each k / fps; `signals` are what the motors were given (the brain's
// outputs, 0 while the task holds the motors off, or the diagnostic clamp).
class ReplayRecorder {
 public:
  ReplayRecorder(const SimConfig& cfg, Replay& r) : fps_(cfg.replay_fps), r_(r) {}

  void observe(const CreatureModel& m, EvalState& s) {
    // the scene's changes, at every step; the frames at the replay's rate
    record_scene(m, s, r_.scene);
    if (frames_ > 0 && s.world.time() < frames_ / fps_ - 1e-9) return;
    ++frames_;
    const World& w = s.world;
    ReplayFrame f;
    f.t = w.time();
    f.poses.reserve(7 * m.parts.size());
    for (int i = 0; i < m.n_parts(); ++i) {
      Pose p = w.part_pose(i);
      Quat q = to_quat(p.R);
      f.poses.insert(f.poses.end(), {p.p.x, p.p.y, p.p.z, q.w, q.x, q.y, q.z});
    }
    std::span<const double> internals = s.controller->internals(), sensors = s.controller->sensors();
    f.neurons.assign(internals.begin(), internals.end());
    f.effectors.assign(s.signals.begin(), s.signals.end());
    // the readings the controller took before its last step (0 before its first)
    f.sensors.assign(sensors.begin(), sensors.end());
    for (int j = 0; j < static_cast<int>(m.joints.size()); ++j)
      for (int d = 0; d < joint_dofs(m.joints[j].type); ++d) f.joint_angles.push_back(w.joint_position(j, d));
    f.com = w.centre_of_mass();
    r_.frames.push_back(std::move(f));
  }

  /// What the scene still holds at the end (the step that blew up, a
  /// moment the task names once it is over).
  void finish(const CreatureModel& m, EvalState& s) { record_scene(m, s, r_.scene); }

  const SceneRecord& scene() const { return r_.scene; }

 private:
  double fps_;
  Replay& r_;
  long frames_ = 0;
};

// What an evaluation reports of its state once its loop has ended; `scene`
// is the replay's scene record, or null when none was recorded.
void report(const CreatureModel& m, EvalState& s, EvalResult& res, const SceneRecord* scene) {
  res.steps = s.physics_steps;
  res.brain_steps = s.brain_steps - s.brain_waits;
  res.seconds = s.world.time();
  res.note = s.task->note();
  res.diagnostics = diagnostics(s);
  // the task's moments, as its scene names them
  SceneRecord own;
  if (!scene) {
    s.task->record(WorldObservation(m, s.world, s.front), own);
    scene = &own;
  }
  res.markers = scene->markers;
  if (s.failed) {
    res.failed = true;
    res.failure = s.failure;
    return;
  }
  TaskScore score = s.task->score(m);
  res.fitness = score.fitness;
  res.distance = score.distance;
  res.metrics = std::move(score.metrics);
}

// One trial: trial `trial` (0-based) of an evaluation, under its physics seed
// `seed` (its task made for that trial: TaskRow::make).
EvalResult evaluate_once(const CreatureModel& m, const ControllerModel& controller, const SimConfig& given,
                         std::uint64_t seed, int trial, Replay* replay) {
  EvalResult res;
  res.warnings = m.warnings;
  reseed_physics(seed);
  const SeedDraw d = seed_draw(given, seed);
  const StartPose start{d.yaw, d.lift};
  // the seed's motors, when it draws their lag
  std::optional<SimConfig> drawn;
  if (d.response_time != given.motor.response_time) {
    drawn.emplace(given);
    drawn->motor.response_time = d.response_time;
  }
  const SimConfig& cfg = drawn ? *drawn : given;
  res.trial = trial;
  auto task = make_task(m, cfg, seed, trial);
  if (!task) {
    res.note = task.error();
    return res;
  }
  res.setup = (*task)->describe();
  std::optional<EvalState> s;
  std::optional<ReplayRecorder> recorder;
  if (replay) recorder.emplace(cfg, *replay);
  try {
    s.emplace(m, controller, cfg, std::move(*task), start);
    if (recorder) s->record_signals = true;  // the replay says each effector's frequency
    if (recorder) recorder->observe(m, *s);
    const long max_steps = s->task->max_steps();
    while (s->physics_steps < max_steps && !s->task->done() && step(m, cfg, *s))
      if (recorder) recorder->observe(m, *s);
  } catch (const PhysicsFault& e) {
    // ODE gave up inside a step: a failed evaluation, as an explosion is;
    // the replay keeps its frames
    if (!s) {
      res.failed = true;
      res.failure = e.what();
      return res;
    }
    s->failed = true;
    s->failure = e.what();
  }
  if (recorder) recorder->finish(m, *s);
  report(m, *s, res, recorder ? &recorder->scene() : nullptr);
  return res;
}

// Every trial of an evaluation, as evaluate() runs them: trial k under
// trial_seed(seed, k), recording into replays[k] when there is one.
std::vector<EvalResult> run_trials(const CreatureModel& m, const ControllerModel& controller, const SimConfig& cfg,
                                   std::uint64_t seed, std::span<Replay* const> replays) {
  const int n = std::max(1, cfg.trials);
  std::vector<EvalResult> out;
  out.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k)
    out.push_back(evaluate_once(m, controller, cfg, trial_seed(seed, k), k,
                                k < static_cast<int>(replays.size()) ? replays[k] : nullptr));
  return out;
}

// The evaluation of these trials seen through trial `shown`: its own fields,
// with the whole evaluation's fitness, steps and failure.
EvalResult shown_trial(std::span<const EvalResult> trials, int shown, const SimConfig& cfg) {
  EvalResult res = trials[static_cast<std::size_t>(shown)];
  if (trials.size() <= 1) return res;
  res.trial_fitness.clear();
  res.steps = res.brain_steps = 0;
  res.failed = false;
  res.failure.clear();
  const int n = static_cast<int>(trials.size());
  for (int k = 0; k < n; ++k) {
    const EvalResult& t = trials[static_cast<std::size_t>(k)];
    res.trial_fitness.push_back(t.fitness);
    res.steps += t.steps;
    res.brain_steps += t.brain_steps;
    if (t.failed && !res.failed) {
      res.failed = true;
      // the shown trial's own failure needs no saying which
      res.failure = k == shown ? t.failure
                               : "trial " + std::to_string(k + 1) + " of " + std::to_string(n) + ": " + t.failure;
    }
  }
  // a creature that blows up in any trial is discarded (5.4), as in one
  res.fitness = res.failed ? 0 : fold_trials(cfg, res.trial_fitness);
  return res;
}

}  // namespace

SeedDraw seed_draw(const SimConfig& cfg, std::uint64_t seed) {
  // a turn within +-start_yaw_jitter degrees, a drop height within
  // +-start_drop_jitter and the motors' lag within +-response_time_jitter of
  // it, the last two drawn only when set, so that runs without them draw as
  // before
  Rng draw(stream_seed({seed, kStartStream}));
  SeedDraw d;
  d.yaw = draw.uniform(-1, 1) * cfg.start_yaw_jitter * kPi / 180;
  if (cfg.start_drop_jitter > 0) d.lift = draw.uniform(-1, 1) * cfg.start_drop_jitter;
  d.response_time = cfg.motor.response_time;
  if (cfg.motor.response_time_jitter > 0 && cfg.motor.response_time > 0)
    d.response_time *= 1 + draw.uniform(-1, 1) * cfg.motor.response_time_jitter;
  return d;
}

long brain_steps_due(long physics_steps, double dt, double brain_hz) {
  // the count of k >= 0 with k < physics_steps * dt * brain_hz, less a millionth
  return static_cast<long>(std::ceil(static_cast<double>(physics_steps) * dt * brain_hz - 1e-6));
}

std::optional<double> EvalResult::metric(std::string_view name) const {
  for (const Metric& m : metrics)
    if (m.name == name) return m.value;
  return std::nullopt;
}

std::optional<double> EvalResult::marker(std::string_view name) const {
  for (const SceneMarker& m : markers)
    if (m.name == name) return m.t;
  return std::nullopt;
}

// the stream of trial seeds (evolution.cpp's streams are 1-4)
constexpr std::uint64_t kTrialStream = 5;

std::uint64_t trial_seed(std::uint64_t seed, int trial) {
  return trial == 0 ? seed : stream_seed({seed, kTrialStream, static_cast<std::uint64_t>(trial)});
}

// the stream of repeated evaluations' seeds (check's is 6, the start's 7)
constexpr std::uint64_t kRepeatStream = 8;

std::uint64_t repeat_seed(std::uint64_t seed, int k) {
  return k == 0 ? seed : stream_seed({seed, kRepeatStream, static_cast<std::uint64_t>(k)});
}

const char* score_name(TrialScore how) { return how == TrialScore::Min ? "least" : "mean"; }

double fold_score(TrialScore how, double so_far, int n, double next) {
  return how == TrialScore::Min ? std::min(so_far, next) : so_far + (next - so_far) / (n + 1);
}

double fold_scores(TrialScore how, std::span<const double> scores) {
  if (scores.empty()) return 0;
  if (how == TrialScore::Min) return *std::min_element(scores.begin(), scores.end());
  double sum = 0;
  for (double s : scores) sum += s;
  return sum / static_cast<double>(scores.size());
}

SimConfig divided_step_config(const SimConfig& cfg, int divisor) {
  SimConfig c = cfg;
  c.physics.dt /= divisor;
  return c;
}

int repeat_step_divisor(const Repeats& r, int k) {
  int cycle[3] = {1, 0, 0}, n = 1;
  if (r.half_step) cycle[n++] = 2;
  if (r.quarter_step) cycle[n++] = 4;
  return cycle[k % n];
}

std::string finer_step_text(const Repeats& r) {
  std::string out;
  for (int divisor : {2, 4}) {
    std::vector<std::string> which;
    for (int k = 1; k < r.evaluations; ++k)
      if (repeat_step_divisor(r, k) == divisor) which.push_back(std::to_string(k + 1));
    if (which.empty()) continue;
    std::string s = out.empty() ? (which.size() == 1 ? "evaluation " : "evaluations ") : ", ";
    for (std::size_t i = 0; i < which.size(); ++i)
      s += (i == 0 ? "" : i + 1 == which.size() ? " and " : ", ") + which[i];
    out += s + (divisor == 2 ? " at half the step" : out.empty() ? " at a quarter of the step" : " at a quarter of it");
  }
  return out;
}

double repeated_fitness(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed, const Repeats& r,
                        const EvalResult& first, std::vector<double>* each) {
  return repeated_fitness(m, GraphBrain(m.brain), cfg, seed, r, first, each);
}

double repeated_fitness(const CreatureModel& m, const ControllerModel& controller, const SimConfig& cfg,
                        std::uint64_t seed, const Repeats& r, const EvalResult& first, std::vector<double>* each) {
  auto scored = [&](const EvalResult& e) { return e.failed ? r.failed_fitness : e.fitness; };
  const DividedSteps steps(cfg);
  double score = scored(first);
  if (each) each->assign(1, score);
  for (int k = 1; k < r.evaluations; ++k) {
    const double f = scored(evaluate(m, controller, steps.at(repeat_step_divisor(r, k)), repeat_seed(seed, k)));
    if (each) each->push_back(f);
    score = fold_score(cfg.trial_score, score, k, f);
  }
  return score;
}

EvalResult evaluate(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed, Replay* replay) {
  return evaluate(m, GraphBrain(m.brain), cfg, seed, replay);
}

EvalResult evaluate(const CreatureModel& m, const ControllerModel& controller, const SimConfig& cfg,
                    std::uint64_t seed, Replay* replay) {
  // the first trial is the one a replay shows and the one distance, release
  // and target miss describe; the others only score
  return evaluate_trial(m, controller, cfg, seed, 0, replay);
}

EvalResult evaluate_trial(const CreatureModel& m, const ControllerModel& controller, const SimConfig& cfg,
                          std::uint64_t seed, int trial, Replay* replay) {
  if (trial < 0 || trial >= std::max(1, cfg.trials))
    throw std::logic_error("evaluate_trial: trial " + std::to_string(trial) + " of an evaluation of " +
                           std::to_string(std::max(1, cfg.trials)) + " trials");
  // a single trial is the evaluation (every run's usual case: no vectors on the way)
  if (cfg.trials <= 1) return evaluate_once(m, controller, cfg, seed, 0, replay);
  std::vector<Replay*> replays(static_cast<std::size_t>(trial) + 1, nullptr);
  replays.back() = replay;
  const std::vector<EvalResult> trials = run_trials(m, controller, cfg, seed, replays);
  return shown_trial(trials, trial, cfg);
}

std::vector<EvalResult> evaluate_trials(const CreatureModel& m, const ControllerModel& controller,
                                        const SimConfig& cfg, std::uint64_t seed, std::span<Replay> replays) {
  if (replays.empty() || replays.size() > static_cast<std::size_t>(std::max(1, cfg.trials)))
    throw std::logic_error("evaluate_trials: " + std::to_string(replays.size()) + " replays of an evaluation of " +
                           std::to_string(std::max(1, cfg.trials)) + " trials");
  std::vector<Replay*> each;
  for (Replay& r : replays) each.push_back(&r);
  const std::vector<EvalResult> trials = run_trials(m, controller, cfg, seed, each);
  std::vector<EvalResult> out;
  for (int k = 0; k < static_cast<int>(replays.size()); ++k) out.push_back(shown_trial(trials, k, cfg));
  return out;
}

}  // namespace bx
