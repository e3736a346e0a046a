#include "eval/task_table.h"

#include <string>

#include "eval/evaluate.h"

#include "task/fight_or_flight.h"
#include "task/light.h"
#include "task/locomotion.h"
#include "task/reach.h"
#include "task/river/river_task.h"
#include "task/throwing.h"
#include "task/strike.h"
#include "task/turn.h"

namespace bx {

namespace {

Result<std::unique_ptr<Task>> make_locomotion(const CreatureModel& m, const SimConfig& cfg, std::uint64_t, int) {
  return std::unique_ptr<Task>(new LocomotionTask(cfg.task, cfg.physics.dt, m.n_parts(), cfg.physics.gravity));
}

Result<std::unique_ptr<Task>> make_throwing(const CreatureModel& m, const SimConfig& cfg, std::uint64_t, int) {
  if (m.projectile < 0) return Error{"not a catapult: the throwing task needs a genome with a catapult block"};
  return std::unique_ptr<Task>(new ThrowingTask(cfg.throwing, cfg.physics.dt, m.projectile, m.release_joint));
}

// the river crossing: its quadruped's torso is the agent, its sensor points
// the controller's, and a cell is as wide as the body's unit
Result<std::unique_ptr<Task>> make_river(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed, int) {
  if (cfg.creature != CreatureKind::River)
    return Error{"the river crossing's task needs its quadruped: genotype.kind = \"river\""};
  RiverTaskDef def = cfg.river.task;
  def.cell = cfg.river.body.unit;
  return std::unique_ptr<Task>(
      new RiverTask(def, cfg.physics.dt, seed, kTorso, quadruped_sensor_points(cfg.river.body)));
}

std::vector<SimField> river_fields() {
  return {
      {"river", "seconds", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.river.task.seconds; }, "river crossing: evaluation length (s; the paper: 10 minutes)"},
      {"river", "drop_height", SimField::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.river.task.drop_height; }, "river crossing: gap between the feet and the ground at the start (m)"},
      {"river", "first_level", SimField::Int, 1, 6, {}, [](SimConfig& c) -> void* { return &c.river.task.first_level; }, "river crossing: the level an evaluation starts on (1: food)"},
      {"river", "approach", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.river.task.approach; }, "river crossing: points for getting closer to each level's resource, approach * (1 - d_min / d_0) a level (d the torso centre's distance to the resource cell in cells, d_0 at the level's start, d_min the least since; a completed level gives all of it); 0, the paper's fitness"},
  };
}

// lessin2015's turn in place (skills 2 and 3)
Result<std::unique_ptr<Task>> make_turn(const CreatureModel& m, const SimConfig& cfg, std::uint64_t, int) {
  return std::unique_ptr<Task>(new TurnTask(cfg.turn, cfg.physics.dt, m.n_parts()));
}

std::vector<SimField> turn_fields() {
  return {
      {"turn", "direction", SimField::Choice, 0, 0, {"left", "right"}, [](SimConfig& c) -> void* { return &c.turn.direction; }, "turn: left (counterclockwise seen from above: lessin2015 skill 2) or right (clockwise: skill 3)"},
      {"turn", "seconds", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.turn.seconds; }, "turn: the measured span (s), after the creature settled with its controller off"},
      {"turn", "drop_height", SimField::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.turn.drop_height; }, "turn: gap between the lowest part and the ground at the start (m)"},
      {"turn", "settle_speed", SimField::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.turn.settle.speed; }, "turn: settled when every part moves less than this times the step length in each step (m/s) ..."},
      {"turn", "settle_seconds", SimField::Real, 0, 1e4, {}, [](SimConfig& c) -> void* { return &c.turn.settle.seconds; }, "... for this long without a break (s)"},
      {"turn", "settle_timeout", SimField::Real, 0, 1e4, {}, [](SimConfig& c) -> void* { return &c.turn.settle.timeout; }, "turn: never settled within this (s): fitness 0"},
      {"turn", "windows", SimField::Int, 1, 1000, {}, [](SimConfig& c) -> void* { return &c.turn.windows; }, "turn: the turn that scores is this many times the least turn (in the direction) of any of this many equal spans of the measured time (1: the whole turn; 2 and more: a twist or a fall turns in one span only)"},
      {"turn", "travel_scale", SimField::Real, 1e-6, 1e6, {}, [](SimConfig& c) -> void* { return &c.turn.travel_scale; }, "turn: fitness = max(0, turn rate (rad/s)) / (1 + travel / travel_scale), travel the farthest the centre of mass got on the ground from where it was when measuring began (m): the travel that halves the score"},
      {"turn", "min_level", SimField::Real, 0, 1, {}, [](SimConfig& c) -> void* { return &c.turn.min_level; }, "turn: the heading counts only while the front (task.front: the root's x axis by default), projected on the ground, is at least this long (0.5: within 60 degrees of level); over steeper stretches it is taken up again where the axis comes out, so tipping the root over turns nothing"},
  };
}

// lessin2015's strike (skill 6)
Result<std::unique_ptr<Task>> make_strike(const CreatureModel& m, const SimConfig& cfg, std::uint64_t, int) {
  return std::unique_ptr<Task>(new StrikeTask(cfg.strike, cfg.physics.dt, m.n_parts()));
}

std::vector<SimField> strike_fields() {
  return {
      {"strike", "seconds", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.strike.seconds; }, "strike: the measured span (s), after the creature settled with its controller off"},
      {"strike", "drop_height", SimField::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.strike.drop_height; }, "strike: gap between the lowest part and the ground at the start (m)"},
      {"strike", "settle_speed", SimField::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.strike.settle.speed; }, "strike: settled when every part moves less than this times the step length in each step (m/s) ..."},
      {"strike", "settle_seconds", SimField::Real, 0, 1e4, {}, [](SimConfig& c) -> void* { return &c.strike.settle.seconds; }, "... for this long without a break (s)"},
      {"strike", "settle_timeout", SimField::Real, 0, 1e4, {}, [](SimConfig& c) -> void* { return &c.strike.settle.timeout; }, "strike: never settled within this (s): fitness 0"},
      {"strike", "window", SimField::Real, 1e-4, 10, {}, [](SimConfig& c) -> void* { return &c.strike.window; }, "strike: an impact is the largest rise, within a span of this long (s), from the centre of mass's mean vertical velocity over its first half to that over its second: the speed the ground takes out of the body at once; fitness = the peak impact (m/s)"},
      {"strike", "threshold", SimField::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.strike.threshold; }, "strike: the impact (m/s) that counts as a strike (the first one reaching it: metric strike_time)"},
  };
}

// lessin2015's light tasks (skills 4, 5, 8 and 9): trial k's light at heading k
Result<std::unique_ptr<Task>> make_light(const CreatureModel& m, const SimConfig& cfg, std::uint64_t, int trial) {
  return std::unique_ptr<Task>(new LightTask(cfg.light, cfg.strike, cfg.physics.dt, m.n_parts(), trial));
}

std::vector<SimField> light_fields() {
  return {
      {"light", "goal", SimField::Choice, 0, 0, {"face", "approach", "face_away", "retreat", "attack"}, [](SimConfig& c) -> void* { return &c.light.goal; }, "light: face (turn to face it: lessin2015 skill 4, TURN TO LIGHT), approach (get to it: skill 5, MOVE TO LIGHT), face_away (skill 8, TURN FROM LIGHT), retreat (get away: skill 9, RETREAT) or attack (get to it and strike the ground there, a strike as the strike task's keys measure it: skill 7, ATTACK)"},
      {"light", "headings", SimField::Reals, -360, 360, {}, [](SimConfig& c) -> void* { return &c.light.headings; }, "light: its bearing from the creature's forward (its front, task.front, on the ground) when measuring begins (degrees, counterclockwise positive), trial k taking the (k mod n)-th of these n: task.trials must be a whole multiple of n"},
      {"light", "dark_trials", SimField::Int, 0, 1000, {}, [](SimConfig& c) -> void* { return &c.light.dark_trials; }, "light, attack: after the headings' trials, this many with no light (a strike in one multiplies the fitness by wrong_factor): trial k is dark when k mod (n + dark_trials) >= n"},
      {"light", "distance", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.light.distance; }, "light: placed this far on the ground from the centre of mass (m)"},
      {"light", "height", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.light.height; }, "light: at this height above the ground (m)"},
      {"light", "strength", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.light.strength; }, "light: a photoreceptor facing it from d metres reads strength / (1 + (d / range)^2) ..."},
      {"light", "range", SimField::Real, 1e-6, 1e6, {}, [](SimConfig& c) -> void* { return &c.light.range; }, "... (m: where its reading has halved)"},
      {"light", "seconds", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.light.seconds; }, "light: the measured span (s), after the creature settled with its controller off and in the dark"},
      {"light", "drop_height", SimField::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.light.drop_height; }, "light: gap between the lowest part and the ground at the start (m)"},
      {"light", "settle_speed", SimField::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.light.settle.speed; }, "light: settled when every part moves less than this times the step length in each step (m/s) ..."},
      {"light", "settle_seconds", SimField::Real, 0, 1e4, {}, [](SimConfig& c) -> void* { return &c.light.settle.seconds; }, "... for this long without a break (s)"},
      {"light", "settle_timeout", SimField::Real, 0, 1e4, {}, [](SimConfig& c) -> void* { return &c.light.settle.timeout; }, "light: never settled within this (s): fitness 0"},
      {"light", "score_from", SimField::Real, 0, 1, {}, [](SimConfig& c) -> void* { return &c.light.score_from; }, "light, face and face_away: the fitness is the mean, over the measured steps from this share of the span on, of (1 + cos a) / 2 (face_away: (1 - cos a) / 2), a the angle between the heading and the direction to the light"},
      {"light", "min_level", SimField::Real, 0, 1, {}, [](SimConfig& c) -> void* { return &c.light.min_level; }, "light: a step counts as facing anywhere only while the front (task.front), projected on the ground, is at least this long (0.5: within 60 degrees of level); else it counts 0"},
      {"light", "early_seconds", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.light.early_seconds; }, "light, face_away and retreat: a wrong-direction start is one within this long after measuring begins (s) ..."},
      {"light", "wrong_turn", SimField::Real, 0, 360, {}, [](SimConfig& c) -> void* { return &c.light.wrong_turn; }, "... face_away: the heading turning more than this (degrees) towards the light's side (none for a light dead ahead or behind) ..."},
      {"light", "wrong_move", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.light.wrong_move; }, "... retreat: the centre of mass closing more than this (m) on the light ..."},
      {"light", "wrong_factor", SimField::Real, 0, 1, {}, [](SimConfig& c) -> void* { return &c.light.wrong_factor; }, "... multiplies the trial's fitness by this"},
  };
}

// every heading its trial (and every dark trial its own): as many trials as
// headings (and dark trials), or a whole multiple
Status light_check(const SimConfig& c) {
  const std::size_t n = c.light.headings.size();
  if (n == 0) return Error{"light.headings: needs at least one heading, got []"};
  if (c.light.dark_trials > 0 && c.light.goal != LightGoal::Attack)
    return Error{"light.dark_trials: only the attack goal has dark trials, got " + std::to_string(c.light.dark_trials)};
  const int cycle = static_cast<int>(n) + c.light.dark_trials;
  if (c.trials % cycle != 0)
    return Error{"task.trials: the light task runs trial k with the (k mod n)-th of light.headings' n = " +
                 std::to_string(n) + " headings" +
                 (c.light.dark_trials > 0 ? " (then light.dark_trials = " + std::to_string(c.light.dark_trials) +
                                                " dark ones)"
                                          : std::string()) +
                 ", so task.trials must be a whole multiple of " + std::to_string(cycle) + ", got " +
                 std::to_string(c.trials)};
  return Ok{};
}

// the light task's trials are its headings, which the paper averages
// ("an average over four runs, each with a fixed light source at a
// different heading"), whatever task.trial_score (which still folds the
// elite's repeated evaluations): the least over headings would score a
// creature by its hardest heading alone; attack's fold is its own
double light_fold(const SimConfig& c, std::span<const double> trials) {
  if (c.light.goal == LightGoal::Attack) return attack_fold(c.light, trials);
  return fold_scores(TrialScore::Mean, trials);
}
std::string light_fold_name(const SimConfig& c) {
  if (c.light.goal != LightGoal::Attack) return "mean (the light task averages its headings)";
  return "attack fold (the lit trials' mean times the dark ones' mean of 1, or light.wrong_factor after a strike)";
}

// lessin2015's fight or flight (skill 10): trials 2k and 2k+1 the k-th
// direction's vulnerable and dangerous targets
Result<std::unique_ptr<Task>> make_fight(const CreatureModel& m, const SimConfig& cfg, std::uint64_t, int trial) {
  return std::unique_ptr<Task>(
      new FightOrFlightTask(cfg.fight, cfg.light, cfg.strike, cfg.physics.dt, m.n_parts(), trial));
}

std::vector<SimField> fight_fields() {
  return {
      {"fight", "headings", SimField::Reals, -360, 360, {}, [](SimConfig& c) -> void* { return &c.fight.headings; }, "fight_or_flight: the target's bearing from the creature's forward when measuring begins (degrees, counterclockwise positive), one per direction: trials 2k and 2k+1 take the (k mod n)-th of these n, the vulnerable target then the dangerous one, so task.trials must be a whole multiple of 2n (the target's light, its distance and height, the measured span and settling: the light.* keys; the strike: the strike.* keys)"},
      {"fight", "disc_diameter", SimField::Real, 1e-3, 100, {}, [](SimConfig& c) -> void* { return &c.fight.disc_diameter; }, "fight_or_flight: a target's disc is an upright cylinder this wide (m) ..."},
      {"fight", "disc_height", SimField::Real, 1e-3, 100, {}, [](SimConfig& c) -> void* { return &c.fight.disc_height; }, "... and this tall (m); the vulnerable target is one disc, which the creature should attack"},
      {"fight", "stack_discs", SimField::Int, 1, 100, {}, [](SimConfig& c) -> void* { return &c.fight.stack_discs; }, "fight_or_flight: the dangerous target is this many discs one on another, whose lights add (light.strength each), which destroy the creature if it touches any (the trial ends, scoring 0) ..."},
      {"fight", "spin", SimField::Real, -1e3, 1e3, {}, [](SimConfig& c) -> void* { return &c.fight.spin; }, "... turning about the vertical at this rate (rad/s, counterclockwise seen from above)"},
  };
}

// every direction its pair of trials
Status fight_check(const SimConfig& c) {
  const std::size_t n = c.fight.headings.size();
  if (n == 0) return Error{"fight.headings: needs at least one heading, got []"};
  if (c.trials % static_cast<int>(2 * n) != 0)
    return Error{"task.trials: the fight_or_flight task runs two trials (the vulnerable target, then the dangerous "
                 "one) for each of fight.headings' n = " +
                 std::to_string(n) + " headings, so task.trials must be a whole multiple of " + std::to_string(2 * n) +
                 ", got " + std::to_string(c.trials)};
  return Ok{};
}

double fight_fold_of(const SimConfig&, std::span<const double> trials) { return fight_fold(trials); }
std::string fight_fold_name(const SimConfig&) {
  return "fight-or-flight fold ((f+ + 2n f-) / (2n + 1), f+ and f- the mean larger and smaller score of each "
         "direction's two targets, n directions)";
}

// lessin2015's high reach (VII-B)
Result<std::unique_ptr<Task>> make_reach(const CreatureModel& m, const SimConfig& cfg, std::uint64_t, int) {
  return std::unique_ptr<Task>(new ReachTask(cfg.reach, m, cfg.physics.dt));
}

std::vector<SimField> reach_fields() {
  return {
      {"reach", "seconds", SimField::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.reach.seconds; }, "high_reach: the measured span (s), after the creature settled with its controller off; fitness = the greatest height above the ground any point of the creature reaches in it (m)"},
      {"reach", "drop_height", SimField::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.reach.drop_height; }, "high_reach: gap between the lowest part and the ground at the start (m)"},
      {"reach", "settle_speed", SimField::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.reach.settle.speed; }, "high_reach: settled when every part moves less than this times the step length in each step (m/s) ..."},
      {"reach", "settle_seconds", SimField::Real, 0, 1e4, {}, [](SimConfig& c) -> void* { return &c.reach.settle.seconds; }, "... for this long without a break (s)"},
      {"reach", "settle_timeout", SimField::Real, 0, 1e4, {}, [](SimConfig& c) -> void* { return &c.reach.settle.timeout; }, "high_reach: never settled within this (s): fitness 0"},
  };
}

// doing nothing faces a light half the time (over headings on both sides), and stands as high as it stands
CheckBasis light_basis(const SimConfig& c) {
  return {c.light.goal == LightGoal::Face || c.light.goal == LightGoal::FaceAway, false};
}
CheckBasis reach_basis(const SimConfig&) { return {true, true}; }

double& reach_seconds(SimConfig& c) { return c.reach.seconds; }
double reach_drop(const SimConfig& c) { return c.reach.drop_height; }

double& locomotion_seconds(SimConfig& c) { return c.task.seconds; }
double& strike_seconds(SimConfig& c) { return c.strike.seconds; }
double strike_drop(const SimConfig& c) { return c.strike.drop_height; }
double& throwing_seconds(SimConfig& c) { return c.throwing.seconds; }
double& river_seconds(SimConfig& c) { return c.river.task.seconds; }
double& turn_seconds(SimConfig& c) { return c.turn.seconds; }
double locomotion_drop(const SimConfig& c) { return c.task.drop_height; }
double throwing_drop(const SimConfig& c) { return c.throwing.drop_height; }
double river_drop(const SimConfig& c) { return c.river.task.drop_height; }
double turn_drop(const SimConfig& c) { return c.turn.drop_height; }
double& light_seconds(SimConfig& c) { return c.light.seconds; }
double light_drop(const SimConfig& c) { return c.light.drop_height; }

// one row per TaskKind, in its order
const TaskRow kTasks[] = {
    {TaskKind::Locomotion, "locomotion", make_locomotion, locomotion_seconds, locomotion_drop, "task.seconds",
     "task.drop_height", nullptr},
    {TaskKind::Throwing, "throwing", make_throwing, throwing_seconds, throwing_drop, "throwing.seconds",
     "throwing.drop_height", nullptr},
    {TaskKind::River, "river", make_river, river_seconds, river_drop, "river.seconds", "river.drop_height",
     river_fields},
    {TaskKind::Turn, "turn", make_turn, turn_seconds, turn_drop, "turn.seconds", "turn.drop_height", turn_fields},
    {TaskKind::Strike, "strike", make_strike, strike_seconds, strike_drop, "strike.seconds", "strike.drop_height",
     strike_fields},
    {TaskKind::Light, "light", make_light, light_seconds, light_drop, "light.seconds", "light.drop_height", light_fields,
     light_check, light_fold, light_fold_name, light_basis},
    {TaskKind::Fight, "fight_or_flight", make_fight, light_seconds, light_drop, "light.seconds", "light.drop_height",
     fight_fields, fight_check, fight_fold_of, fight_fold_name},
    {TaskKind::Reach, "high_reach", make_reach, reach_seconds, reach_drop, "reach.seconds", "reach.drop_height",
     reach_fields, nullptr, nullptr, nullptr, reach_basis},
};

}  // namespace

const TaskRow& task_row(TaskKind kind) { return kTasks[static_cast<int>(kind)]; }

double fold_trials(const SimConfig& cfg, std::span<const double> trials) {
  const TaskRow& row = task_row(cfg.task_kind);
  return row.fold ? row.fold(cfg, trials) : fold_scores(cfg.trial_score, trials);
}

std::string trial_fold_name(const SimConfig& cfg) {
  const TaskRow& row = task_row(cfg.task_kind);
  return row.fold_name ? row.fold_name(cfg) : score_name(cfg.trial_score);
}

std::vector<std::string_view> task_kind_names() {
  std::vector<std::string_view> out;
  for (const TaskRow& r : kTasks) out.push_back(r.name);
  return out;
}

std::vector<SimField> task_fields() {
  std::vector<SimField> out;
  for (const TaskRow& r : kTasks)
    if (r.fields)
      for (SimField& f : r.fields()) out.push_back(std::move(f));
  return out;
}

Result<std::unique_ptr<Task>> make_task(const CreatureModel& m, const SimConfig& cfg, std::uint64_t seed, int trial) {
  return task_row(cfg.task_kind).make(m, cfg, seed, trial);
}

Status check_task_keys(const SimConfig& cfg) {
  const TaskRow& row = task_row(cfg.task_kind);
  return row.check ? row.check(cfg) : Status(Ok{});
}

}  // namespace bx
