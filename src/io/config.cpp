#include "io/config.h"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

#include "core/text.h"
#include "core/files.h"
#include "eval/creature.h"
#include "eval/task_table.h"
#include "genome/dialect.h"
#include "io/toml_numbers.h"

namespace bx {

namespace {

// One config key: where it lives in RunConfig and what it accepts.
struct Field {
  std::string_view section;
  std::string_view key;
  // Triple: std::array<double, 3>; Text: std::string; Reals: std::vector<double>
  enum Kind { Real, Int, Long, Bool, Choice, Vec, Triple, Text, Reals } kind;
  double lo, hi;                                  // inclusive range (Real, Int, each of Vec's or Reals')
  std::vector<std::string_view> choices;          // Choice: names, by enum value
  std::function<void*(RunConfig&)> at;            // the field's address
  std::string_view doc;                           // one line for docs/config.md
};

Vec3 triple(void* p) {
  const auto& a = *static_cast<std::array<double, 3>*>(p);
  return {a[0], a[1], a[2]};
}

template <class E>
E& as_enum(void* p) {
  return *static_cast<E*>(p);
}

// the reader's own keys, then those the task and creature tables bring
// (eval/task_table.h, eval/creature.h), each table's sections together
std::vector<Field> with_table_fields(std::vector<Field> own) {
  std::vector<SimField> table = task_fields();
  for (SimField& f : creature_fields()) table.push_back(std::move(f));
  // sections in the order they first appear, each with all its keys (a
  // section written twice would not be valid TOML)
  std::vector<std::string_view> sections;
  for (const SimField& f : table)
    if (std::find(sections.begin(), sections.end(), f.section) == sections.end()) sections.push_back(f.section);
  static constexpr Field::Kind kinds[] = {Field::Real, Field::Int, Field::Choice, Field::Triple, Field::Text,
                                          Field::Reals};
  for (std::string_view sec : sections)
    for (const SimField& f : table)
      if (f.section == sec)
        own.push_back({f.section, f.key, kinds[f.kind], f.lo, f.hi, f.choices,
                       [at = f.at](RunConfig& c) -> void* { return at(c.sim); }, f.doc});
  return own;
}

const std::vector<Field>& fields() {
  constexpr double inf = 1e300;
  static const std::vector<Field> f = with_table_fields({
      {"physics", "dt", Field::Real, 1e-5, 1, {}, [](RunConfig& c) -> void* { return &c.sim.physics.dt; }, "physics step (s)"},
      {"physics", "gravity", Field::Real, -inf, inf, {}, [](RunConfig& c) -> void* { return &c.sim.physics.gravity; }, "gravity along z (m/s^2)"},
      {"physics", "erp", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.sim.physics.erp; }, "ODE error reduction parameter"},
      {"physics", "cfm", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.sim.physics.cfm; }, "ODE constraint force mixing"},
      {"physics", "friction", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.sim.physics.friction; }, "Coulomb friction of every contact (friction pyramid)"},
      {"physics", "powered_stops", Field::Choice, 0, 0, {"ode", "separate"}, [](RunConfig& c) -> void* { return &c.sim.physics.powered_stops; }, "ode: a joint motor at its stop becomes a plain torque (fudge_factor); separate: hinge and universal motors are their own constraint beside the stops"},
      {"physics", "friction_bound", Field::Choice, 0, 0, {"lagged", "ode"}, [](RunConfig& c) -> void* { return &c.sim.physics.friction_bound; }, "lagged: a steady contact's friction up to mu times its normal force of the last steps, others ODE's pyramid; ode: ODE's pyramid"},
      {"physics", "solver_iterations", Field::Int, 1, 1000, {}, [](RunConfig& c) -> void* { return &c.sim.physics.solver_iterations; }, "QuickStep iterations"},
      {"physics", "rolling_friction", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.sim.physics.rolling_friction; }, "rolling resistance of spheres, capsules and cylinders: lever arm per unit normal force (m; 0: none)"},
      {"physics", "max_contacts", Field::Int, 1, 64, {}, [](RunConfig& c) -> void* { return &c.sim.physics.max_contacts; }, "contact points per colliding pair of geoms"},
      {"physics", "self_collision", Field::Bool, 0, 0, {}, [](RunConfig& c) -> void* { return &c.sim.physics.self_collision; }, "parts not joined to each other collide"},
      {"physics", "max_speed", Field::Real, 1e-3, inf, {}, [](RunConfig& c) -> void* { return &c.sim.physics.max_speed; }, "explosion test: a part faster than this (m/s) ends the evaluation"},
      {"physics", "max_step_jump", Field::Real, 1e-6, inf, {}, [](RunConfig& c) -> void* { return &c.sim.physics.max_step_jump; }, "explosion test: a part moving farther than this in one step (m)"},
      {"physics", "max_joint_gap", Field::Real, 1e-6, inf, {}, [](RunConfig& c) -> void* { return &c.sim.physics.max_joint_gap; }, "explosion test: joint anchors drifting apart farther than this (m)"},
      {"physics", "solver", Field::Choice, 0, 0, {"quickstep", "exact"}, [](RunConfig& c) -> void* { return &c.sim.physics.solver; }, "quickstep (iterative, solver_iterations) or exact (ODE's dWorldStep)"},
      {"physics", "contact_erp", Field::Real, -1, 1, {}, [](RunConfig& c) -> void* { return &c.sim.physics.contact_erp; }, "ERP of contacts (negative: physics.erp)"},
      {"physics", "contact_cfm", Field::Real, -1, 1, {}, [](RunConfig& c) -> void* { return &c.sim.physics.contact_cfm; }, "CFM of contacts (negative: physics.cfm)"},
      {"physics", "stop_erp", Field::Real, -1, 1, {}, [](RunConfig& c) -> void* { return &c.sim.physics.stop_erp; }, "ERP of joint stops (negative: physics.erp)"},
      {"physics", "stop_cfm", Field::Real, -1, 1, {}, [](RunConfig& c) -> void* { return &c.sim.physics.stop_cfm; }, "CFM of joint stops (negative: physics.cfm)"},
      {"physics", "erp_cfm_dt", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.sim.physics.erp_cfm_dt; }, "the step (s) at which the erp and cfm keys are given: at another physics.dt they are restated to keep the spring and damper they make there (0: per step, ODE's way; docs/physics.md cause 18)"},
      {"physics", "fudge_factor", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.sim.physics.fudge_factor; }, "share of a motor's force allowed at a joint stop (ODE's dParamFudgeFactor)"},
      {"physics", "contact_max_correcting_vel", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.sim.physics.contact_max_correcting_vel; }, "fastest depenetration of contacts (m/s; 0: unbounded)"},
      {"physics", "contact_surface_layer", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.sim.physics.contact_surface_layer; }, "depth contacts may sink before they push back (m)"},
      {"motor", "model", Field::Choice, 0, 0, {"servo", "saturation", "torque", "pd", "muscle"}, [](RunConfig& c) -> void* { return &c.sim.motor.model; }, "servo (miconi2006), saturation (chaumont2007 5.3), torque (sims1994), pd (a spring and damper towards a target angle: kp, kd), muscle (lessin2015 III-E: each effector a muscle's activation; the lessin2015 dialect's, and only it)"},
      {"motor", "muscle_damping", Field::Real, 0, 1e9, {}, [](RunConfig& c) -> void* { return &c.sim.motor.muscle_damping; }, "muscle: damper along each muscle's line, whatever its activation (N s/m)"},
      {"motor", "max_speed", Field::Real, 0, inf, {}, [](RunConfig& c) -> void* { return &c.sim.motor.max_speed; }, "servo: target speed at signal 1; saturation: the fixed high target speed (rad/s or m/s)"},
      {"motor", "max_force", Field::Real, 0, inf, {}, [](RunConfig& c) -> void* { return &c.sim.motor.max_force; }, "servo: torque cap (N m or N)"},
      {"motor", "off_brake", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.sim.motor.off_brake; }, "while the task holds the controller off (settling), each motor brakes its joint with this share of its full force (a joint's friction; 0: limp, frictionless)"},
      {"motor", "response_time", Field::Real, 0, 1e3, {}, [](RunConfig& c) -> void* { return &c.sim.motor.response_time; }, "every model: time constant of a first-order lag from effector signal to motor, from 0 (s; 0: none)"},
      {"motor", "response_time_jitter", Field::Real, 0, 0.99, {}, [](RunConfig& c) -> void* { return &c.sim.motor.response_time_jitter; }, "each physics seed draws motor.response_time within +-this share of it (a lag not known exactly; 0: none)"},
      {"motor", "strength", Field::Real, 0, inf, {}, [](RunConfig& c) -> void* { return &c.sim.motor.strength; }, "torque and saturation: N m per m^2 of the larger part's cross-section"},
      {"motor", "torque_max_speed", Field::Real, 0, inf, {}, [](RunConfig& c) -> void* { return &c.sim.motor.torque_max_speed; }, "torque: joint speed beyond which the motor stops pushing (rad/s; 0: no limit)"},
      {"motor", "torque_max_linear_speed", Field::Real, 0, inf, {}, [](RunConfig& c) -> void* { return &c.sim.motor.torque_max_linear_speed; }, "torque: the same for sliding degrees of freedom (m/s; 0: no limit)"},
      {"motor", "kp", Field::Real, 0, inf, {}, [](RunConfig& c) -> void* { return &c.sim.motor.kp; }, "pd: proportional gain"},
      {"motor", "kd", Field::Real, 0, inf, {}, [](RunConfig& c) -> void* { return &c.sim.motor.kd; }, "pd: damping gain"},
      {"brain", "rate_hz", Field::Real, 0.1, 1e5, {}, [](RunConfig& c) -> void* { return &c.sim.brain_hz; }, "brain steps per simulated second, whatever physics.dt (genome delays count these steps)"},
      {"brain", "skill", Field::Text, 0, 0, {}, [](RunConfig& c) -> void* { return &c.sim.develop.skill; }, "lessin2015 ESP: an encapsulated skill run alone (its switch at 1, the skill being learned cut off, so only the skills it drives act); empty: the switches follow the brain"},
      {"develop", "max_parts", Field::Int, 0, 100000, {}, [](RunConfig& c) -> void* { return &c.sim.develop.max_parts; }, "most parts after development (0: the dialect's limit)"},
      {"develop", "max_body_length", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.sim.develop.max_body_length; }, "largest extent of the starting pose (m): longer creatures are not viable (0: no limit)"},
      {"develop", "overlap_margin", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.sim.develop.overlap_margin; }, "self-intersection test shrinks parts by this much (m)"},
      {"develop", "collide_gap", Field::Real, 0, 10, {}, [](RunConfig& c) -> void* { return &c.sim.develop.collide_gap; }, "lessin2015 (joined parts collide): a child starts this share of its half-thickness off its parent (1: a box child turns 45 degrees about its thinner side before meeting it)"},
      {"develop", "muscle_rest_fraction", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.sim.develop.muscle_rest_fraction; }, "lessin2015: a muscle's rest length as a share of its built length (below 1 an active muscle contracts)"},
      {"develop", "slide_range", Field::Real, 0, 100, {}, [](RunConfig& c) -> void* { return &c.sim.develop.slide_range; }, "lessin2015 (joined parts collide): a prismatic or cylindrical joint without limits in its gene slides at most this share of its child's half-thickness either way (collisions stop only a slide into the parent)"},
      {"task", "seconds", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.sim.task.seconds; }, "evaluation length (s); with the chaumont2007 sequence, the measured phase"},
      {"task", "drop_height", Field::Real, 0, 1e3, {}, [](RunConfig& c) -> void* { return &c.sim.task.drop_height; }, "gap between the lowest part and the ground at the start (m)"},
      {"task", "metric", Field::Choice, 0, 0, {"planar", "x", "forward", "front"}, [](RunConfig& c) -> void* { return &c.sim.task.metric; }, "planar: horizontal distance of the centre of mass; x: displacement along +x; forward: displacement along the creature's heading (its front, task.front, on the ground) when measuring began; front: the path travelled front first (each step's displacement along the heading it started from, summed: a curving gait scores its path, backing or sidling none)"},
      {"task", "skip_fraction", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.sim.task.skip_fraction; }, "distance counts from this fraction of the evaluation on"},
      {"task", "fitness", Field::Choice, 0, 0, {"distance", "speed", "chaumont2007", "lessin2015"}, [](RunConfig& c) -> void* { return &c.sim.task.fitness; }, "distance, speed (distance / measured time), chaumont2007 (eq. 1) or lessin2015 (V, skill 1: speed_step (floor(speed / speed_step) + efficiency) / max_speed)"},
      {"task", "activation", Field::Choice, 0, 0, {"always", "chaumont2007", "settled"}, [](RunConfig& c) -> void* { return &c.sim.task.activation; }, "always, chaumont2007 (settle, 1 s burst, settle, measure) or settled (settle with the controller off, then measure)"},
      {"task", "settle_speed", Field::Real, 0, 1e3, {}, [](RunConfig& c) -> void* { return &c.sim.task.settle.speed; }, "settled: every part moves less than this times the step length in each step (m/s) ..."},
      {"task", "settle_seconds", Field::Real, 0, 1e4, {}, [](RunConfig& c) -> void* { return &c.sim.task.settle.seconds; }, "... for this long without a break (s)"},
      {"task", "settle_timeout", Field::Real, 0, 1e4, {}, [](RunConfig& c) -> void* { return &c.sim.task.settle.timeout; }, "never settled within this (s): fitness 0"},
      {"task", "burst_seconds", Field::Real, 0, 1e4, {}, [](RunConfig& c) -> void* { return &c.sim.task.burst_seconds; }, "the first controller activation (s)"},
      {"task", "kappa", Field::Real, 0, 10, {}, [](RunConfig& c) -> void* { return &c.sim.task.kappa; }, "eq. 1's reward per block"},
      {"task", "windows", Field::Int, 1, 1000, {}, [](RunConfig& c) -> void* { return &c.sim.task.windows; }, "the distance that scores is this many times the least distance travelled in any of this many equal spans of the measured time (1: the whole distance; 2 and more: a fall or one push out of the start pose travels in one span only)"},
      {"task", "basal_power", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.sim.task.basal_power; }, "lessin2015 fitness: the resting cost counted beside the muscles' work in the efficiency 1 / (1 + (work + basal_power x mass x seconds) / (mass g distance)) (W per kg; keeps a creature that does nothing from being perfectly efficient)"},
      {"task", "speed_step", Field::Real, 1e-6, 1e6, {}, [](RunConfig& c) -> void* { return &c.sim.task.speed_step; }, "lessin2015 fitness: sigma, the step in which speed counts (m/s); efficiency ranks creatures within one step"},
      {"task", "max_speed", Field::Real, 1e-6, 1e6, {}, [](RunConfig& c) -> void* { return &c.sim.task.max_speed; }, "lessin2015 fitness: s_max, the speed that scores 1 (m/s)"},
      {"task", "kind", Field::Choice, 0, 0, task_kind_names(), [](RunConfig& c) -> void* { return &c.sim.task_kind; }, "locomotion (the [task] keys), throwing (the [throwing] keys; needs catapults), or a task with keys of its own (docs/config.md)"},
      {"task", "front", Field::Choice, 0, 0, {"+x", "-x", "+y", "-y", "+z", "-z"}, [](RunConfig& c) -> void* { return &c.sim.front; }, "the creature's front: this axis of its root part's frame, projected on the ground, is its heading for every task that has one (turn, light, fight_or_flight, task.metric = forward); a creature lying on its side names the axis it moves along"},
      {"task", "trials", Field::Int, 1, 1000, {}, [](RunConfig& c) -> void* { return &c.sim.trials; }, "evaluations per creature under different physics seeds; fitness is their mean (task.trial_score)"},
      {"task", "trial_score", Field::Choice, 0, 0, {"mean", "min"}, [](RunConfig& c) -> void* { return &c.sim.trial_score; }, "how trials make the fitness: their mean, or the least of them (robust to luck); an elite's repeated evaluations (evolution.elite_evaluations) fold the same way"},
      {"task", "start_yaw_jitter", Field::Real, 0, 180, {}, [](RunConfig& c) -> void* { return &c.sim.start_yaw_jitter; }, "each physics seed turns the start by up to this (degrees) about the vertical"},
      {"task", "start_drop_jitter", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.sim.start_drop_jitter; }, "each physics seed raises or lowers the drop by up to this (m), which samples a chaotic outcome where a turn cannot (docs/physics.md cause 17)"},
      {"throwing", "fitness", Field::Choice, 0, 0, {"distance", "aim"}, [](RunConfig& c) -> void* { return &c.sim.throwing.fitness; }, "distance (chaumont2007 eq. 2: D_p) or aim (eq. 3: D_p - D_t)"},
      {"throwing", "seconds", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.sim.throwing.seconds; }, "longest throw (s, from its beginning); it ends earlier once the projectile rests"},
      {"throwing", "drop_height", Field::Real, 0, 1e3, {}, [](RunConfig& c) -> void* { return &c.sim.throwing.drop_height; }, "gap between the lowest part and the ground at the start (m)"},
      {"throwing", "rest_speed", Field::Real, 0, 1e3, {}, [](RunConfig& c) -> void* { return &c.sim.throwing.rest_speed; }, "at rest: the projectile moves slower than this (m/s) ..."},
      {"throwing", "rest_seconds", Field::Real, 0, 1e4, {}, [](RunConfig& c) -> void* { return &c.sim.throwing.rest_seconds; }, "... for this long without a break (s)"},
      {"throwing", "target", Field::Vec, -1e6, 1e6, {}, [](RunConfig& c) -> void* { return &c.sim.throwing.target; }, "aim: the target point [x, y, z] (m)"},
      {"throwing", "start", Field::Choice, 0, 0, {"drop", "settled"}, [](RunConfig& c) -> void* { return &c.sim.throwing.start; }, "drop: the controller runs from the drop (chaumont2007 4.1); settled: the throw begins once the creature, its joints held and its controller off, is still (the settle keys)"},
      {"throwing", "settle_speed", Field::Real, 0, 1e3, {}, [](RunConfig& c) -> void* { return &c.sim.throwing.settle.speed; }, "start = settled: every part moves less than this times the step length in each step (m/s) ..."},
      {"throwing", "settle_seconds", Field::Real, 0, 1e4, {}, [](RunConfig& c) -> void* { return &c.sim.throwing.settle.seconds; }, "... for this long without a break (s)"},
      {"throwing", "touch_seconds", Field::Real, -1, 1e4, {}, [](RunConfig& c) -> void* { return &c.sim.throwing.touch_seconds; }, "after the release the creature may touch its projectile for this long (s); a later touch ends the throw where the projectile is (negative: no limit)"},
      {"throwing", "settle_timeout", Field::Real, 0, 1e4, {}, [](RunConfig& c) -> void* { return &c.sim.throwing.settle.timeout; }, "never settled within this (s): fitness 0"},
      {"replay", "fps", Field::Real, 1e-3, 1e4, {}, [](RunConfig& c) -> void* { return &c.sim.replay_fps; }, "replay frames per simulated second"},
      {"genotype", "kind", Field::Choice, 0, 0, creature_kind_names(), [](RunConfig& c) -> void* { return &c.sim.creature; }, "what a genotype develops into, body and controller: graph (Sims' graph genome, of genome.dialect: it grows its body and brain), or a kind with a fixed body and keys of its own (docs/config.md)"},
      {"genome", "dialect", Field::Choice, 0, 0, {"sims1994", "miconi2006", "chaumont2007", "lessin2015"}, [](RunConfig& c) -> void* { return &c.dialect; }, "sims1994, miconi2006, chaumont2007 or lessin2015: picks every default"},
      {"evolution", "algorithm", Field::Choice, 0, 0, {"generational", "steady_state"}, [](RunConfig& c) -> void* { return &c.evolution.algorithm; }, "generational (chaumont2007) or steady_state (miconi2006)"},
      {"evolution", "population", Field::Int, 3, 1000000, {}, [](RunConfig& c) -> void* { return &c.evolution.population; }, "individuals in the population"},
      {"evolution", "generations", Field::Int, 1, 1000000, {}, [](RunConfig& c) -> void* { return &c.evolution.generations; }, "generational: generations, the random one included"},
      {"evolution", "elite_fraction", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.evolution.elite_fraction; }, "generational: fraction of the best that survive (steady state: that elite_evaluations evaluates again)"},
      {"evolution", "selection", Field::Choice, 0, 0, {"rank", "proportionate", "uniform"}, [](RunConfig& c) -> void* { return &c.evolution.selection; }, "generational: rank, proportionate or uniform choice of parents among survivors"},
      {"evolution", "p_asexual", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.evolution.p_asexual; }, "share of children by mutation alone (steady state: asexual_mutations of the tournament's best)"},
      {"evolution", "p_crossover", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.evolution.p_crossover; }, "share of children by crossover (steady state: then mutated at mutation_rate)"},
      {"evolution", "p_graft", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.evolution.p_graft; }, "share of children by grafting (steady state: then mutated at mutation_rate)"},
      {"evolution", "asexual_rate", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.evolution.asexual_rate; }, "generational: per-parameter mutation probability of asexual children"},
      {"evolution", "sexual_mutation_chance", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.evolution.sexual_mutation_chance; }, "generational: chance that a crossover/graft child is mutated"},
      {"evolution", "sexual_rate", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.evolution.sexual_rate; }, "generational: ... at this per-site probability"},
      {"evolution", "evaluations", Field::Long, 0, 1e12, {}, [](RunConfig& c) -> void* { return &c.evolution.evaluations; }, "steady state: tournaments after the initial population (elites evaluated again come on top)"},
      {"evolution", "mutation_rate", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.evolution.mutation_rate; }, "steady state: P_mut of the mutation operator"},
      {"evolution", "asexual_mutations", Field::Int, 1, 1000, {}, [](RunConfig& c) -> void* { return &c.evolution.asexual_mutations; }, "steady state: mutations applied to make an asexual child"},
      {"evolution", "batch", Field::Int, 1, 100000, {}, [](RunConfig& c) -> void* { return &c.evolution.batch; }, "steady state: tournaments evaluated together (disjoint triples); 1 = strictly sequential"},
      {"evolution", "tournament_evaluates", Field::Choice, 0, 0, {"child", "all"}, [](RunConfig& c) -> void* { return &c.evolution.tournament_evaluates; }, "steady state: child (miconi2006: each child evaluated once, at birth; the three compete on the fitness they keep) or all (stanton2015: each tournament evaluates its three in fresh worlds and ranks them by these evaluations; fitness is the mean of all a creature had)"},
      {"evolution", "islands", Field::Int, 1, 100000, {}, [](RunConfig& c) -> void* { return &c.evolution.islands; }, "steady state: islands the population is split into (each population / islands members, its own tournaments); a batch holds `batch` tournaments on every island, so islands x batch evaluations run at once (1: one population, the papers)"},
      {"evolution", "migration_every", Field::Long, 1, 1e12, {}, [](RunConfig& c) -> void* { return &c.evolution.migration_every; }, "steady state with islands: creatures born on each island between migrations, when each island's best, copied under a new id (operator migrant), replaces the worst evaluated member of the next island in the ring"},
      {"evolution", "elite_evaluations", Field::Int, 1, 1000, {}, [](RunConfig& c) -> void* { return &c.evolution.elite_evaluations; }, "the elite (elite_fraction) is evaluated again under fresh seeds after each generation (steady state: report interval) until each fitness is the mean of this many (task.trial_score = min: the least) (1: once)"},
      {"evolution", "best_evaluations", Field::Int, 0, 1000, {}, [](RunConfig& c) -> void* { return &c.evolution.best_evaluations; }, "the elite's best is evaluated again until its fitness is the mean (task.trial_score = min: the least) of this many, and so is each that takes its place, so the best is not the luckiest of near-equal creatures (0: as elite_evaluations)"},
      {"evolution", "best_evaluations_doubling", Field::Bool, 0, 0, {}, [](RunConfig& c) -> void* { return &c.evolution.best_evaluations_doubling; }, "the best's further evaluations in rounds that double its count (2, 4, 8, ... up to best_evaluations), each followed by a new ranking, so a lucky start drops out after a few; false: all at once"},
      {"evolution", "held_out_evaluations", Field::Int, 0, 10000, {}, [](RunConfig& c) -> void* { return &c.evolution.held_out_evaluations; }, "once the run ends, its best is evaluated this many times under seeds no evaluation of the run used, an estimate of its fitness that selection never saw (stored in the run; `best` and `check` use it) (0: none)"},
      {"evolution", "elite_half_step", Field::Bool, 0, 0, {}, [](RunConfig& c) -> void* { return &c.evolution.elite_half_step; }, "the elite's and the best's 2nd, 4th, ... evaluations (with tournament_evaluates = all, every creature's) step at half physics.dt, so that a gait only the step makes loses its score (all of it with task.trial_score = min, half with the mean)"},
      {"evolution", "elite_quarter_step", Field::Bool, 0, 0, {}, [](RunConfig& c) -> void* { return &c.evolution.elite_quarter_step; }, "the evaluations that elite_half_step names cycle through physics.dt, dt/2 (with elite_half_step) and dt/4, so that a score the step makes at dt/4 is lost too"},
      {"evolution", "max_regenerations", Field::Int, 0, 1000000, {}, [](RunConfig& c) -> void* { return &c.evolution.max_regenerations; }, "non-viable children redrawn at most this often, then a random genome"},
      {"evolution", "max_random_redraws", Field::Int, 1, 1e9, {}, [](RunConfig& c) -> void* { return &c.evolution.max_random_redraws; }, "random genotypes drawn in a row, none of them viable, before the run stops saying why (no creature is viable under its config)"},
      {"evolution", "distinct_children", Field::Bool, 0, 0, {}, [](RunConfig& c) -> void* { return &c.evolution.distinct_children; }, "a child whose genotype equals a parent's is made again (up to max_regenerations times), so a stage of mostly locked genomes (Fast ESP) does not spend its evaluations on copies"},
      {"evolution", "evaluation_timeout", Field::Real, 0.1, 1e6, {}, [](RunConfig& c) -> void* { return &c.evolution.evaluation_timeout; }, "seconds before a worker's evaluation is abandoned as failed"},
      {"evolution", "failed_fitness", Field::Real, -1e12, 1e12, {}, [](RunConfig& c) -> void* { return &c.evolution.failed_fitness; }, "fitness of an evaluation that blew up, crashed or timed out (below any real score)"},
      {"evolution", "report_every", Field::Long, 0, 1e12, {}, [](RunConfig& c) -> void* { return &c.evolution.report_every; }, "steady state: evaluations per statistics row and checkpoint (0: the population)"},
      {"catapult", "enabled", Field::Bool, 0, 0, {}, [](RunConfig& c) -> void* { return &c.operators.catapult.enabled; }, "random genomes are catapults (chaumont2007 section 4)"},
      {"catapult", "projectile_size", Field::Vec, 1e-3, 100, {}, [](RunConfig& c) -> void* { return &c.operators.catapult.projectile_size; }, "the projectile of a random catapult: box extents [x, y, z] (m)"},
      {"catapult", "projectile_density", Field::Real, 1, 1e6, {}, [](RunConfig& c) -> void* { return &c.operators.catapult.projectile_density; }, "... and density (kg/m^3)"},
      {"catapult", "mutate_projectile", Field::Bool, 0, 0, {}, [](RunConfig& c) -> void* { return &c.operators.catapult.mutate_projectile; }, "random catapults' projectiles come without a body lock, so mutation changes their size (4.2: \"in some experiments\")"},
      {"catapult", "release_delay_steps", Field::Int, 2, 1001, {}, [](RunConfig& c) -> void* { return &c.operators.catapult.release_delay_steps; }, "brain steps (at brain.rate_hz) until the mechanism releases at the latest (4.1: 30 = 0.5 s at 60 Hz)"},
      {"operators", "add_input", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.operators.structure.add_input; }, "per mutation, the chance of a random input for a random weighted-sum neuron or effector that no lock holds whole (lessin2015 IV-B: a new skill wires into the shared muscles and the switches of the skills it uses); 0: never (no draw)"},
      {"operators", "remove_input", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.operators.structure.remove_input; }, "per mutation, the chance that such a unit loses a random input that is not gated; 0: never (no draw)"},
      {"operators", "wired_neurons", Field::Real, 0, 1, {}, [](RunConfig& c) -> void* { return &c.operators.p_wired_neuron; }, "the chance that the add_neuron mutation puts its neuron in front of a random unit that may take an input (as add_input draws them), which reads it: on a frozen genome (ESP) an unread neuron changes nothing; 0: never (no draw)"},
      {"check", "other_seeds", Field::Int, 0, 1000, {}, [](RunConfig& c) -> void* { return &c.check.other_seeds; }, "check: physics seeds tried besides the scored one"},
      {"check", "other_seeds_statistic", Field::Choice, 0, 0, {"median", "mean"}, [](RunConfig& c) -> void* { return &c.check.other_seeds_statistic; }, "check: how the other seeds combine: their median (one lucky or unlucky seed does not decide) or their mean (a task whose rare large score, such as a level reached in a third of its layouts, a mean fitness counts: with enough other_seeds); under the mean the converge_seeds variants compare means too, and each gate on a mean widens by two standard errors of the difference"},
      {"check", "min_other_seeds", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.check.min_other_seeds; }, "check: their median (mean) fitness must keep this share of the scored one"},
      {"check", "min_converged", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.check.min_converged; }, "check: dt/2, dt/4 and twice the solver iterations each keep this share"},
      {"check", "max_converged", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.check.max_converged; }, "check: dt/2, dt/4 and twice the solver iterations each keep at most this share (a fitness that grows as the step shrinks is not converged)"},
      {"check", "motor_lag", Field::Real, 0, 10, {}, [](RunConfig& c) -> void* { return &c.check.motor_lag; }, "check: the motor-lag variant lengthens motor.response_time by this (s); 0: no such variant"},
      {"check", "min_motor_lag", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.check.min_motor_lag; }, "check: under that lag the fitness keeps at least this share, or the creature is a buzzer"},
      {"check", "min_half_rate", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.check.min_half_rate; }, "check: with the brain at half its rate the fitness keeps at least this share, or the creature is a buzzer; 0: no such variant"},
      {"check", "min_sustained", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.check.min_sustained; }, "check, locomotion: in a run twice as long the last third's travel keeps at least this share of the first third's; 0: no such gate"},
      {"check", "max_clamped", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.check.max_clamped; }, "check: with every effector held at its mean, at most this share"},
      {"check", "max_held", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.check.max_held; }, "check: with every joint held still by its motor (a catapult still releasing), at most this share"},
      {"check", "rest_seconds", Field::Real, 0, 1e6, {}, [](RunConfig& c) -> void* { return &c.check.rest_seconds; }, "check: clamped effectors may keep more than max_clamped if the creature is then at rest over its last this many seconds (a transient: a stroke or a topple, named in a note); 0: never"},
      {"check", "converge_seeds", Field::Int, 1, 100, {}, [](RunConfig& c) -> void* { return &c.check.converge_seeds; }, "check: dt/2, dt/4, 2x iterations, the motor lag and the half rate each as the median over this many seeds, against the median at dt (for chaotic tasks)"},
  });
  return f;
}

// Keys of older configs that counted in physics steps, and the keys in seconds
// (or per second) that replaced them: refused with a pointer to the new key.
struct OldKey {
  std::string_view section, key, use;
};

const std::vector<OldKey>& old_keys() {
  static const std::vector<OldKey> k = {
      {"brain", "steps_per_physics_step", "brain.rate_hz (brain steps per simulated second)"},
      {"task", "settle_threshold", "task.settle_speed (m/s)"},
      {"task", "settle_steps", "task.settle_seconds (s)"},
      {"throwing", "rest_steps", "throwing.rest_seconds (s)"},
  };
  return k;
}

std::string num(double v);

std::string show(const toml::node& n) {
  std::ostringstream ss;
  if (n.is_floating_point())
    ss << num(*n.value<double>());
  else if (n.is_string())
    ss << '"' << one_line(*n.value<std::string>(), 200) << '"';
  else if (n.is_table())
    ss << "a table";
  else if (const toml::array* a = n.as_array()) {
    ss << '[';
    for (std::size_t i = 0; i < a->size(); ++i) ss << (i ? ", " : "") << show(*a->get(i));
    ss << ']';
  }
  else
    n.visit([&](auto&& v) { ss << v; });
  return ss.str();
}

// shortest text that reads back as the same double
std::string num(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// an array of numbers as TOML: [a, b, c]
std::string reals_text(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s.append(i ? ", " : "").append(num(v[i]));
  return s + "]";
}

std::string vec_text(Vec3 v) {
  // appended piecewise: GCC 12 at -O3 warns falsely (-Wrestrict) on "[" + string&&
  std::string s = "[";
  s.append(num(v.x)).append(", ").append(num(v.y)).append(", ").append(num(v.z)).append("]");
  return s;
}

// sets one field from a TOML value, or says what is wrong
Status set_field(const Field& f, RunConfig& cfg, const toml::node& n, const std::string& where) {
  void* p = f.at(cfg);
  auto bad = [&](const std::string& what) { return Status(Error{where + ": " + what + ", got " + show(n)}); };
  switch (f.kind) {
    case Field::Real: {
      std::optional<double> v = n.is_integer() ? std::optional<double>(static_cast<double>(*n.value<std::int64_t>()))
                                               : n.value<double>();
      if (!n.is_number() || !v) return bad("expected a number");
      if (!std::isfinite(*v) || *v < f.lo || *v > f.hi)
        return bad("out of range [" + num(f.lo) + ", " + num(f.hi) + "]");
      *static_cast<double*>(p) = *v;
      return Ok{};
    }
    case Field::Int:
    case Field::Long: {
      if (!n.is_integer()) return bad("expected an integer");
      auto v = *n.value<std::int64_t>();
      if (v < f.lo || v > f.hi) return bad("out of range [" + num(f.lo) + ", " + num(f.hi) + "]");
      if (f.kind == Field::Int)
        *static_cast<int*>(p) = static_cast<int>(v);
      else
        *static_cast<long*>(p) = static_cast<long>(v);
      return Ok{};
    }
    case Field::Bool:
      if (!n.is_boolean()) return bad("expected true or false");
      *static_cast<bool*>(p) = *n.value<bool>();
      return Ok{};
    case Field::Vec:
    case Field::Triple: {
      const toml::array* a = n.as_array();
      if (!a || a->size() != 3) return bad("expected an array of 3 numbers");
      Vec3 v;
      for (std::size_t i = 0; i < 3; ++i) {
        const toml::node& e = *a->get(i);
        std::optional<double> x = e.is_integer() ? std::optional<double>(static_cast<double>(*e.value<std::int64_t>()))
                                                 : e.value<double>();
        if (!e.is_number() || !x) return bad("expected an array of 3 numbers");
        if (!std::isfinite(*x) || *x < f.lo || *x > f.hi)
          return bad("each out of range [" + num(f.lo) + ", " + num(f.hi) + "]");
        v[static_cast<int>(i)] = *x;
      }
      if (f.kind == Field::Vec)
        *static_cast<Vec3*>(p) = v;
      else
        *static_cast<std::array<double, 3>*>(p) = {v.x, v.y, v.z};
      return Ok{};
    }
    case Field::Reals: {
      const toml::array* a = n.as_array();
      if (!a) return bad("expected an array of numbers");
      std::vector<double> v;
      for (const toml::node& e : *a) {
        std::optional<double> x = e.is_integer() ? std::optional<double>(static_cast<double>(*e.value<std::int64_t>()))
                                                 : e.value<double>();
        if (!e.is_number() || !x) return bad("expected an array of numbers");
        if (!std::isfinite(*x) || *x < f.lo || *x > f.hi)
          return bad("each out of range [" + num(f.lo) + ", " + num(f.hi) + "]");
        v.push_back(*x);
      }
      *static_cast<std::vector<double>*>(p) = std::move(v);
      return Ok{};
    }
    case Field::Text: {
      if (!n.is_string()) return bad("expected text in quotes");
      auto text = *n.value<std::string>();
      for (unsigned char c : text)
        if (c < 0x20 || c == 0x7f) return bad("expected one line of text without control characters");
      *static_cast<std::string*>(p) = std::move(text);
      return Ok{};
    }
    case Field::Choice: {
      std::string names;
      for (auto c : f.choices) names += (names.empty() ? "" : ", ") + std::string(c);
      if (!n.is_string()) return bad("expected one of " + names);
      auto s = *n.value<std::string>();
      for (std::size_t i = 0; i < f.choices.size(); ++i) {
        if (s == f.choices[i]) {
          *static_cast<int*>(p) = static_cast<int>(i);  // enums are int-sized, declared in this order
          return Ok{};
        }
      }
      return bad("expected one of " + names);
    }
  }
  return Ok{};
}

// a TOML basic string: "text" with quotes and backslashes escaped (control
// characters are refused before)
std::string toml_quote(std::string_view text) {
  std::string q = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

// One `--set section.key=value` as a line of TOML that sets that key and no
// other: the key is a bare section.key, the value one line of TOML (a bare
// word is a string). A newline in the value could otherwise start a new line
// that sets any key.
Result<std::string> override_toml(const std::string& o) {
  std::string shown = "\"";  // appended piecewise: GCC 12 warns falsely (-Wrestrict) on "x" + string&&
  shown.append(one_line(o, 200)).append("\"");
  for (unsigned char c : o)
    if (c < 0x20 || c == 0x7f)
      return Error{"--set: a control character (newline, tab, ...) in " + shown +
                   " (one section.key=value per --set)"};
  auto eq = o.find('=');
  std::string key = eq == std::string::npos ? o : o.substr(0, eq);
  while (!key.empty() && key.back() == ' ') key.pop_back();
  while (!key.empty() && key.front() == ' ') key.erase(0, 1);
  auto dot = key.find('.');
  bool key_ok = eq != std::string::npos && dot != std::string::npos && dot > 0 && dot + 1 < key.size();
  for (std::size_t i = 0; key_ok && i < key.size(); ++i) key_ok = i == dot || name_char(key[i]);
  if (!key_ok) return Error{"--set: expected section.key=value, got " + shown};
  std::string section = key.substr(0, dot), name = key.substr(dot + 1), value = o.substr(eq + 1);
  // a bare word is a string; anything else is read as TOML
  std::string line = key + " = " + value;
  toml::table parsed;
  try {
    parsed = toml::parse(line);
  } catch (const toml::parse_error&) {
    line = key + " = " + toml_quote(value);
    try {
      parsed = toml::parse(line);
    } catch (const toml::parse_error& e) {
      return Error{"--set " + one_line(o, 200) + ": " + one_line(e.description(), 200)};
    }
  }
  // exactly the one key, whatever the value held
  const toml::table* sec = parsed[section].as_table();
  if (parsed.size() != 1 || !sec || sec->size() != 1 || !sec->contains(name))
    return Error{"--set: " + shown + " sets more than " + key};
  return line;
}

}  // namespace

std::string evolved_name(const RunConfig& cfg) {
  if (cfg.sim.creature == CreatureKind::Graph) return std::string(to_string(cfg.dialect));
  return std::string(creature_kind_row(cfg.sim.creature).name);
}

RunConfig default_run_config(Dialect d) {
  RunConfig c;
  c.dialect = d;
  c.sim = default_sim_config(d);
  c.evolution = default_evolution(d);
  c.operators = default_operators(d);
  return c;
}

Status apply_config_toml(RunConfig& cfg, std::string_view text, std::string_view source) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    return Error{toml_error_text(e, text, source)};
  }
  // a number that would read as 0 (or lose digits) is refused, not rounded
  if (Status s = check_number_range(root, text, source); !s) return s;
  RunConfig out = cfg;  // apply all or nothing
  std::vector<std::string> set;  // the keys this layer sets, section.key
  for (auto&& [sec_key, sec_node] : root) {
    std::string sec = one_line(sec_key.str(), 100);  // as messages quote it
    auto* table = sec_node.as_table();
    bool known = false;
    for (const auto& f : fields()) known |= f.section == sec;
    if (!known) {
      std::vector<std::string> sections;
      for (const auto& f : fields()) sections.emplace_back(f.section);
      return Error{std::string(source) + ": " + sec + ": unknown section" + did_you_mean(sec, sections)};
    }
    if (!table) return Error{std::string(source) + ": " + sec + ": expected a table, got " + show(sec_node)};
    for (auto&& [key, node] : *table) {
      std::string where = std::string(source) + ": " + sec + "." + one_line(key.str(), 100);
      const Field* field = nullptr;
      for (const auto& f : fields())
        if (f.section == sec && f.key == key.str()) field = &f;
      if (!field) {
        for (const auto& o : old_keys())
          if (o.section == sec && o.key == key.str())
            return Error{where + ": replaced by " + std::string(o.use) +
                         ", got " + show(node)};
        std::vector<std::string> keys;
        for (const auto& f : fields())
          if (f.section == sec) keys.emplace_back(f.key);
        return Error{where + ": unknown key" + did_you_mean(one_line(key.str(), 100), keys)};
      }
      if (Status s = set_field(*field, out, node, where); !s) return s;
      set.push_back(std::string(field->section) + "." + std::string(field->key));
    }
  }
  // what setting them does besides (a key that names a file reads it)
  for (const CreatureKindRow& row : creature_kind_rows())
    if (row.resolve)
      if (Status s = row.resolve(out.sim, set); !s) return Error{std::string(source) + ": " + s.error()};
  // keys that must agree with each other (both algorithms breed in these shares)
  const EvolutionDef& e = out.evolution;
  if (std::abs(e.p_asexual + e.p_crossover + e.p_graft - 1) > 1e-9)
    return Error{std::string(source) + ": evolution.p_asexual + p_crossover + p_graft: must sum to 1, got " +
                 num(std::round((e.p_asexual + e.p_crossover + e.p_graft) * 1e9) / 1e9)};
  cfg = out;
  return Ok{};
}

Result<RunConfig> read_run_config(std::string_view text, std::string_view source,
                                  const std::vector<std::string>& overrides) {
  return read_run_config({{std::string(text), std::string(source)}}, overrides);
}

Result<RunConfig> read_run_config(std::vector<ConfigLayer> layers, const std::vector<std::string>& overrides) {
  if (layers.empty()) return Error{"no config"};
  const std::string source = layers.front().source;  // the config's name in messages about the whole
  for (const auto& o : overrides) {
    auto line = override_toml(o);
    if (!line) return Error{line.error()};
    layers.push_back({*line, "--set " + o});
  }
  // the dialect and the creature kind decide the defaults, so they are read first
  Dialect d = Dialect::Sims1994;
  std::optional<CreatureKind> kind;
  for (const auto& [t, src] : layers) {
    try {
      toml::table root = toml::parse(t, src);
      if (auto name = root["genome"]["dialect"].value<std::string>()) {
        auto parsed = parse_dialect(*name);
        if (!parsed)
          return Error{src + ": genome.dialect: expected one of sims1994, miconi2006, chaumont2007, lessin2015, got \"" +
                       *name + "\""};
        d = *parsed;
      }
      if (auto name = root["genotype"]["kind"].value<std::string>()) {
        const auto names = creature_kind_names();
        for (std::size_t i = 0; i < names.size(); ++i)
          if (*name == names[i]) kind = static_cast<CreatureKind>(i);
        // an unknown name is reported by apply_config_toml below
      }
    } catch (const toml::parse_error&) {
      // reported with its position by apply_config_toml below
    }
  }
  RunConfig cfg = default_run_config(d);
  if (kind) apply_creature_kind(cfg.sim, *kind);
  for (const auto& [t, src] : layers)
    if (Status s = apply_config_toml(cfg, t, src); !s) return Error{s.error()};
  // the creature kinds' own rules between their keys
  for (const CreatureKindRow& row : creature_kind_rows())
    if (row.check)
      if (Status s = row.check(cfg.sim); !s) return Error{source + ": " + s.error()};
  // the task's own rules between its keys
  if (Status s = check_task_keys(cfg.sim); !s) return Error{source + ": " + s.error()};
  // catapults are chaumont2007's, and a throwing run needs them
  if (cfg.operators.catapult.enabled && cfg.dialect != Dialect::Chaumont2007)
    return Error{std::string(source) + ": catapult.enabled: catapults need genome.dialect = \"chaumont2007\", got \"" +
                 std::string(to_string(cfg.dialect)) + "\""};
  if (cfg.sim.task_kind == TaskKind::Throwing && !cfg.operators.catapult.enabled)
    return Error{std::string(source) + ": task.kind: \"throwing\" needs catapult.enabled = true"};
  // muscles are the muscle dialect's effectors, and its effectors are muscles
  if (cfg.sim.creature == CreatureKind::Graph &&
      (cfg.sim.motor.model == MotorModel::Muscle) != dialect_rules(cfg.dialect).muscle_effectors)
    return Error{std::string(source) + ": motor.model: " +
                 (dialect_rules(cfg.dialect).muscle_effectors
                      ? "genome.dialect \"" + std::string(to_string(cfg.dialect)) + "\" actuates by muscles only and needs \"muscle\", got another model"
                      : std::string("\"muscle\" needs a dialect whose effectors are muscles (lessin2015), got genome.dialect \"") +
                            std::string(to_string(cfg.dialect)) + "\"")};
  // a PD motor's damper is a motor row of its own (docs/physics.md cause 28):
  // ODE's joint motor at a stop would turn its unlimited force into a torque
  if (needs_own_motor_row(cfg.sim.motor.model) && cfg.sim.physics.powered_stops != PoweredStops::Separate)
    return Error{std::string(source) + ": motor.model: \"pd\" needs physics.powered_stops = \"separate\", got \"ode\""};
  // a generational GA has no tournaments
  if (cfg.evolution.tournament_evaluates == TournamentEvaluates::All && cfg.evolution.algorithm != Algorithm::SteadyState)
    return Error{std::string(source) + ": evolution.tournament_evaluates: \"all\" needs evolution.algorithm = "
                 "\"steady_state\", got \"generational\""};
  // islands hold tournaments: of at least three members each, all alike
  if (cfg.evolution.islands > 1) {
    const EvolutionDef& e = cfg.evolution;
    if (e.algorithm != Algorithm::SteadyState)
      return Error{std::string(source) + ": evolution.islands: " + std::to_string(e.islands) +
                   " needs evolution.algorithm = \"steady_state\" (a generational run evaluates its whole population at once)"};
    if (e.population % e.islands != 0 || e.population / e.islands < 3)
      return Error{std::string(source) + ": evolution.islands: " + std::to_string(e.islands) +
                   " must divide evolution.population (" + std::to_string(e.population) +
                   ") into islands of at least 3 members"};
  }
  // a drop jittered lower than the ground would start the creature inside it
  if (cfg.sim.start_drop_jitter > task_drop_height(cfg.sim))
    return Error{std::string(source) + ": task.start_drop_jitter: " + num(cfg.sim.start_drop_jitter) +
                 " m is more than " + std::string(task_drop_height_key(cfg.sim)) + " (" + num(task_drop_height(cfg.sim)) +
                 " m): a lowered drop would start the creature inside the ground"};
  return cfg;
}

Status apply_config_file(SimConfig& cfg, const std::string& path) {
  auto text = read_file(path);
  if (!text) return Error{text.error()};
  // a run config works too: its sim sections apply, the rest is checked and ignored
  RunConfig rc;
  rc.sim = cfg;
  if (Status s = apply_config_toml(rc, *text, path); !s) return s;
  cfg = rc.sim;
  return Ok{};
}

std::string config_to_toml(const RunConfig& cfg_in, bool sim_only) {
  RunConfig cfg = cfg_in;
  std::ostringstream ss;
  std::string_view section;
  for (const auto& f : fields()) {
    bool sim_section = f.section != "genome" && f.section != "evolution" && f.section != "catapult";
    if (sim_only && !sim_section) continue;
    if (f.section != section) {
      ss << (section.empty() ? "" : "\n") << "[" << f.section << "]\n";
      section = f.section;
    }
    void* p = f.at(cfg);
    ss << f.key << " = ";
    switch (f.kind) {
      case Field::Real: ss << num(*static_cast<double*>(p)); break;
      case Field::Int: ss << *static_cast<int*>(p); break;
      case Field::Long: ss << *static_cast<long*>(p); break;
      case Field::Bool: ss << (*static_cast<bool*>(p) ? "true" : "false"); break;
      case Field::Choice: ss << '"' << f.choices[*static_cast<int*>(p)] << '"'; break;
      case Field::Vec: ss << vec_text(*static_cast<Vec3*>(p)); break;
      case Field::Triple: ss << vec_text(triple(p)); break;
      case Field::Text: ss << toml_quote(*static_cast<std::string*>(p)); break;
      case Field::Reals: ss << reals_text(*static_cast<std::vector<double>*>(p)); break;
    }
    ss << "\n";
  }
  return ss.str();
}

std::string config_reference_markdown() {
  // one row per key: the dialects' defaults side by side
  RunConfig d[4] = {default_run_config(Dialect::Sims1994), default_run_config(Dialect::Miconi2006),
                    default_run_config(Dialect::Chaumont2007), default_run_config(Dialect::Lessin2015)};
  std::ostringstream ss;
  ss << "| key | sims1994 | miconi2006 | chaumont2007 | lessin2015 | meaning |\n|---|---|---|---|---|---|\n";
  for (const auto& f : fields()) {
    ss << "| `" << f.section << "." << f.key << "` |";
    for (auto& c : d) {
      void* p = f.at(c);
      switch (f.kind) {
        case Field::Real: ss << " " << num(*static_cast<double*>(p)) << " |"; break;
        case Field::Int: ss << " " << *static_cast<int*>(p) << " |"; break;
        case Field::Long: ss << " " << *static_cast<long*>(p) << " |"; break;
        case Field::Bool: ss << " " << (*static_cast<bool*>(p) ? "true" : "false") << " |"; break;
        case Field::Choice: ss << " " << f.choices[*static_cast<int*>(p)] << " |"; break;
        case Field::Vec: ss << " " << vec_text(*static_cast<Vec3*>(p)) << " |"; break;
        case Field::Triple: ss << " " << vec_text(triple(p)) << " |"; break;
        case Field::Text: ss << " " << toml_quote(*static_cast<std::string*>(p)) << " |"; break;
        case Field::Reals: ss << " " << reals_text(*static_cast<std::vector<double>*>(p)) << " |"; break;
      }
    }
    ss << " " << f.doc << " |\n";
  }
  return ss.str();
}

std::string config_to_toml(const SimConfig& cfg) {
  RunConfig rc;
  rc.sim = cfg;
  return config_to_toml(rc, true);
}

}  // namespace bx
