#include "task/light.h"

#include <algorithm>
#include <cmath>

#include "core/text.h"

namespace bx {

namespace {

// the scene's light: yellow, a visible 0.2 m across
constexpr const char* kLightColor = "#ffd200";
constexpr double kLightSize = 0.2;

bool towards(LightGoal g) { return g == LightGoal::Face || g == LightGoal::Approach; }

}  // namespace

LightTask::LightTask(const LightDef& def, const StrikeDef& strike, double dt, int n_parts, int trial)
    : SettledTask(def.seconds, def.drop_height, def.settle, dt, n_parts),
      def_(def),
      meter_(strike.window, strike.threshold, dt) {
  const std::size_t n = def_.headings.size(), cycle = n + static_cast<std::size_t>(std::max(0, def_.dark_trials));
  const std::size_t slot = cycle ? static_cast<std::size_t>(std::max(0, trial)) % cycle : 0;
  dark_ = slot >= n;
  bearing_ = dark_ ? 0 : def_.headings[slot];
  // the side the light is on, seen from the forward: none dead ahead or behind
  const double b = std::remainder(bearing_, 360.0);
  side_ = std::abs(b) < 1e-9 || std::abs(b) > 180 - 1e-9 ? 0 : b > 0 ? 1 : -1;
}

std::string LightTask::describe() const { return dark_ ? "no light" : "light at " + g_number(bearing_) + " degrees"; }

void LightTask::begin_measure(const Observation& o) {
  t_start_ = o.time();
  heading_ = heading(o);
  level_ = root_level(o) >= def_.min_level;
  turned_ = 0;
  // the light, `distance` from the centre of mass at the trial's bearing from the forward
  const Vec3 c = o.centre_of_mass();
  const double at = heading_ + bearing_ * kPi / 180;
  light_ = {c.x + def_.distance * std::cos(at), c.y + def_.distance * std::sin(at), def_.height};
  d0_ = d_ = d_min_ = distance_of(o);
  end_bearing_ = bearing_of(o);
  meter_.start(o.time(), c.z);
}

void LightTask::act(const CreatureModel&, std::span<const double>, WorldEdits& w, const Observation&) {
  if (!measuring() || placed_ || dark_) return;
  w.set_lights({Light{light_, def_.strength, def_.range}});
  placed_ = true;
}

double LightTask::distance_of(const Observation& o) const {
  const Vec3 c = o.centre_of_mass();
  return std::hypot(light_.x - c.x, light_.y - c.y);
}

double LightTask::bearing_of(const Observation& o) const {
  const Vec3 c = o.centre_of_mass();
  const double dx = light_.x - c.x, dy = light_.y - c.y;
  if (std::hypot(dx, dy) < 1e-12) return 0;
  return heading_step(heading(o), std::atan2(dy, dx));
}

void LightTask::measure(const Observation& o) {
  const double s = o.time() - t_start_;
  // the heading, unwrapped from one level enough step to the next (as the turn task's)
  const double h = heading(o);
  const bool level = root_level(o) >= def_.min_level;
  if (level && level_) turned_ += heading_step(heading_, h);
  heading_ = h;
  level_ = level;
  d_ = distance_of(o);
  d_min_ = std::min(d_min_, d_);
  gain_sum_ += d_ - d0_;
  ++steps_;
  end_bearing_ = bearing_of(o);
  // the facing, from score_from of the span on; a root not level enough faces nowhere
  if (s >= def_.score_from * def_.seconds - 1e-9) {
    const double c = std::cos(end_bearing_);
    if (level) facing_sum_ += (towards(def_.goal) ? 1 + c : 1 - c) / 2;
    ++facing_steps_;
  }
  // the initial reaction: a turn towards the light's side, a move towards it
  if (s <= def_.early_seconds + 1e-9) {
    wrong_turn_ = std::max(wrong_turn_, side_ * turned_);
    wrong_move_ = std::max(wrong_move_, d0_ - d_);
  }
  if (def_.goal == LightGoal::Attack && !struck()) {
    meter_.observe(o.time(), o.centre_of_mass().z);
    if (meter_.first_strike() >= 0) strike_d_ = d_;
  }
}

std::optional<Light> LightTask::light() const {
  if (!measuring() || dark_) return std::nullopt;
  return Light{light_, def_.strength, def_.range};
}

double LightTask::facing() const {
  return facing_steps_ > 0 ? facing_sum_ / static_cast<double>(facing_steps_) : 0;
}

double LightTask::mean_gain() const { return steps_ > 0 ? gain_sum_ / static_cast<double>(steps_) : 0; }

bool LightTask::penalized() const {
  switch (def_.goal) {
    case LightGoal::FaceAway: return wrong_turn() > def_.wrong_turn;
    case LightGoal::Retreat: return wrong_move_ > def_.wrong_move;
    default: return false;
  }
}

double LightTask::fitness() const {
  if (!measuring()) return 0;
  double f = 0;
  switch (def_.goal) {
    case LightGoal::Face:
    case LightGoal::FaceAway: f = facing(); break;
    case LightGoal::Approach: f = d0_ > 0 ? std::clamp((d0_ - d_min_) / d0_, 0.0, 1.0) : 0; break;
    case LightGoal::Retreat: f = def_.distance > 0 ? std::max(0.0, mean_gain()) / def_.distance : 0; break;
    case LightGoal::Attack:
      if (dark_) return struck() ? 0 : 1;
      f = struck() && d0_ > 0 ? std::max(0.0, 1 - strike_d_ / d0_) : 0;
      break;
  }
  return penalized() ? f * def_.wrong_factor : f;
}

TaskScore LightTask::score(const CreatureModel&) const {
  TaskScore out{fitness(),
                d_,
                {{"bearing", end_bearing_ * 180 / kPi},
                 {"facing", facing()},
                 {"start_distance", d0_},
                 {"end_distance", d_},
                 {"least_distance", d_min_},
                 {"wrong_turn", wrong_turn()},
                 {"wrong_move", wrong_move_},
                 {"muscle_work", phases().measured_work()}}};
  if (def_.goal == LightGoal::Attack) {
    const double t = meter_.first_strike();
    out.metrics.push_back({"strike_time", struck() ? t - t_start_ : -1});
    out.metrics.push_back({"strike_distance", strike_d_});
  }
  return out;
}

double attack_fold(const LightDef& def, std::span<const double> trials) {
  const std::size_t n = def.headings.size(), cycle = n + static_cast<std::size_t>(std::max(0, def.dark_trials));
  double lit = 0, factor = 0;
  long n_lit = 0, n_dark = 0;
  for (std::size_t k = 0; k < trials.size(); ++k) {
    if (cycle == 0 || k % cycle < n) {
      lit += trials[k];
      ++n_lit;
    } else {
      // a dark trial scored 1 without a strike, 0 with one
      factor += trials[k] > 0.5 ? 1 : def.wrong_factor;
      ++n_dark;
    }
  }
  const double mean = n_lit ? lit / static_cast<double>(n_lit) : 0;
  return n_dark ? mean * factor / static_cast<double>(n_dark) : mean;
}

void LightTask::record(const Observation&, SceneRecord& out) {
  // the light holds from when it was placed for the rest of the replay (a
  // scene point holds throughout: the viewer shows it from the start)
  if (!measuring() || recorded_ || dark_) return;
  out.points.push_back({"light", light_, kLightSize, kLightColor});
  out.markers.push_back({"light on", t_start_});
  recorded_ = true;
}

}  // namespace bx
