// A second simulator's opinion (issue 36): a creature's evaluation in ODE,
// closed loop, then the effector signals it recorded replayed open loop into
// the same body exported to MuJoCo (io/mjcf.h), with the same motor laws.
// Whether the creature moves the same way there (direction and distance of
// its centre of mass over the task's scored span) is evidence that what it
// does is not an artefact of ODE's contacts, joints or solver.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "brain/controller.h"
#include "core/math.h"
#include "core/result.h"
#include "develop/creature_model.h"
#include "eval/sim_config.h"

namespace bx {

/// One MuJoCo replay, under one setting of its contacts.
struct CrossSimVariant {
  std::string name;   ///< "as exported", "stiffest", "elliptic cone", "stiffest, elliptic cone"
  /// The task's score of what the creature did in MuJoCo (the same task,
  /// made from the same seed, reading MuJoCo's world), and the span it
  /// scored there (s: its own markers, else the whole replay).
  double fitness = 0, from = 0, to = 0;
  /// The work its muscles did (J, as World::muscle_work: |power| x dt of
  /// each tendon's spring and damper), which lessin2015's efficiency prices.
  double muscle_work = 0;
  Vec3 displacement;  ///< the tracked point's over the span (m): CrossSimReport::tracked
  /// Against ODE's horizontal displacement: the angle (rad, 0..pi) and the
  /// length ratio (0 when ODE's is 0).
  double heading_difference = 0, distance_ratio = 0;
  double min_height = 0;  ///< the tracked point's lowest (m)
  /// The largest difference of any joint's angle (rad or m) from ODE's over
  /// the first second: whether the motors drive the joints alike before the
  /// two paths part.
  double first_second_angle_gap = 0;
  std::vector<std::string> warnings;  ///< what MuJoCo warned of, if anything
  /// With CrossSimReport::has_flight: the scored part's flight here, from
  /// the span's start to its first touch of anything (the whole span if it
  /// never touched), and its angle and ratio against ODE's flight.
  Vec3 flight;
  double flight_heading_difference = 0, flight_ratio = 0;
};

/// What the two simulators did with the same motor commands.
struct CrossSimReport {
  double from = 0, to = 0;  ///< ODE's span compared (s): the task's scored span, else the whole run
  double seconds = 0;       ///< simulated in ODE
  long steps = 0;           ///< physics steps in ODE (MuJoCo steps at the same dt)
  /// What is compared: the part the task scores (ScenePart::scored: a
  /// thrown "projectile"), else the creature's "centre of mass".
  std::string tracked;
  Vec3 ode;                 ///< ODE's displacement of it over the span (m)
  /// The task's score in ODE (its first trial's), and the median of its
  /// scores in MuJoCo (CrossSimVariant::fitness).
  double ode_fitness = 0, mujoco_fitness = 0;
  double ode_muscle_work = 0;  ///< J, in ODE (World::muscle_work)
  /// MuJoCo under each contact setting: as the MJCF export writes them
  /// (MuJoCo's defaults: a soft 0.02 s time constant, the pyramidal cone),
  /// the stiffest time constant it allows (2 steps), the elliptic cone, and both.
  std::vector<CrossSimVariant> variants;
  /// The medians over the variants: open-loop replays diverge, and which
  /// contact model is nearer ODE's is not settled, so no one of them decides.
  double heading_difference = 0, distance_ratio = 0;
  /// A scored part's flight (a throw's): from the span's start to its
  /// landing in ODE (`landing`, s: the first step it touches the ground and
  /// no part), when it lands; apart from the roll after it, which soft and
  /// hard contacts treat differently.
  bool has_flight = false;
  Vec3 ode_flight;
  double landing = 0;
  double flight_heading_difference = 0, flight_ratio = 0;  ///< medians over the variants
};

/// Evaluates the creature in ODE as `evaluate` does its first trial (the same
/// seed, start, task and controller), recording at every physics step what
/// its motors did (driven by which signals, braked or held), then replays
/// those steps open loop in MuJoCo: the body as `creature_mjcf` writes it,
/// started in ODE's start pose, each step's motor computed by ODE's laws
/// (motor.model, its lag, brakes) from MuJoCo's joint state: a velocity
/// motor with a force cap (servo, saturation, a torque's no-load speed, a
/// brake) as the force that reaches its speed in one step, capped, solved
/// for all motors together; a torque as itself; a PD's spring explicit, its
/// damper the joint's (implicit in MuJoCo's Euler step); a muscle its
/// exported tendon, a spring of its activation times its strength (implicit
/// integration); once under each of four contact settings
/// (CrossSimReport::variants). The same task, made from the same seed,
/// scores each replay, reading MuJoCo's world and acting on ODE's task
/// outputs; it holds or drives the motors by its own rules (a settling),
/// each driven step taking ODE's next driven step's commands. A joint it
/// breaks (a catapult's release) is left out of a body reloaded then
/// (io/mjcf.h's broken joints), the state carried over, the freed part
/// flying free; a prop it places (a target) is a mocap body there, turned
/// each step as it spins. `seconds` > 0 replaces the task's length.
Result<CrossSimReport> crosscheck_mujoco(const CreatureModel& m, const ControllerModel& controller,
                                         const SimConfig& cfg, std::uint64_t seed, double seconds = 0);

}  // namespace bx
