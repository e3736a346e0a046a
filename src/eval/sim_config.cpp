#include "eval/sim_config.h"

#include "eval/task_table.h"

namespace bx {

SimConfig default_sim_config(Dialect d) {
  SimConfig c;
  switch (d) {
    case Dialect::Miconi2006:
      // Table 1: step 0.01 s, ERP 0.015, CFM 0.01, motors 4 N and 4 rad/s;
      // 10,000 steps per evaluation; distance along x after the first 1/8 (5.2)
      c.physics.dt = 0.01;
      c.brain_hz = 100;  // one brain step per physics step
      // Table 1's ERP 0.015 and CFM 0.01 make every joint and contact a spring
      // of ERP / (dt CFM) = 150 N/m: on our solver, 200 random creatures with
      // constant motors stretch 151 joints past 1 cm, sink 100 past 5 cm and
      // 53 creep more than 2% of their length in 15 s. ODE's usual ERP 0.2 and
      // CFM 1e-5: 1, 4 and 22 (docs/physics.md). Ours: the latter.
      c.physics.erp = 0.2;
      c.physics.cfm = 1e-5;
      // the paper does not say whether a creature's limbs collide with each
      // other (only that limbs must not intersect at birth, 5.2). With them
      // colliding, 4 N m servos wedge 14-33 g limbs into one another and into
      // their joint stops; contact and stop each correct their error, the
      // solver flips the contact's friction every step and evolved creatures
      // with constant motors glide 30-85 m in 100 s (24 of 24 artefact bests
      // of three runs travel; without: all 24 rest). docs/physics.md cause 11
      c.physics.self_collision = false;
      // ODE's joint motor at a stop becomes a plain torque of its full force
      // (a light limb kicked off at many times the motor's speed): each hinge
      // gets a motor of its own beside its stops (docs/physics.md cause 12)
      c.physics.powered_stops = PoweredStops::Separate;
      // a brain's command flipping every 10 ms step hammered limbs into their
      // stops at the step's own rate; a servo lags its command (cause 13; the
      // paper's servo follows at once)
      c.motor.response_time = 0.05;
      c.motor.model = MotorModel::Servo;
      c.motor.max_speed = 4;
      c.motor.max_force = 4;
      c.task.seconds = 100;
      c.task.metric = DistanceMetric::AlongX;
      c.task.skip_fraction = 1.0 / 8;
      break;
    case Dialect::Chaumont2007:
      // 5.4: step 1/60 s; 5.3: motors at saturation, force from the signal;
      // 3.4: joint strength proportional to the larger block's cross-section;
      // 3.5: 20 s evaluations; 3.6: friction "set high" (our value: 2)
      c.physics.dt = 1.0 / 60;
      c.brain_hz = 60;  // one brain step per physics step (4.1: 30 steps = 0.5 s)
      c.physics.friction = 2.0;
      c.motor.model = MotorModel::Saturation;
      // the paper gives neither strength nor target speed: ours let random
      // blocks of 1000 kg/m^3 lift themselves without rewarding vibration
      // (strength 3000 or 10 rad/s evolve buzzing scooters within 20 generations)
      c.motor.max_speed = 4;
      c.motor.strength = 2000;
      // 3.3-3.4: dropped from a safe height, the activation sequence, eq. 1
      c.task.seconds = 20;
      c.task.drop_height = 0.1;
      c.task.activation = Activation::Chaumont2007;
      c.task.fitness = LocomotionFitness::Chaumont2007;
      c.task.kappa = 1.02;
      break;
    case Dialect::Sims1994:
      // Sims (1994): effector torque scaled by cross-section; two brain steps per
      // physics step
      c.physics.dt = 0.01;
      c.brain_hz = 200;
      c.motor.model = MotorModel::Torque;
      c.motor.strength = 1000;
      // a pure torque from rest slammed light parts through their stops in one
      // step (a leg 1 rad past its stop, joints parted by 9.4 cm): the motors
      // push only up to 10 rad/s (1 m/s along sliders), as a real motor's
      // torque falls off towards its no-load speed (docs/physics.md)
      c.motor.torque_max_speed = 10;
      c.motor.torque_max_linear_speed = 1;
      c.task.seconds = 10;
      c.task.fitness = LocomotionFitness::Speed;  // speed of the centre of mass
      break;
    case Dialect::Lessin2015:
      // III: the paper used PhysX and gives no constant; ours. One brain step
      // per physics step (III-C). Measured on 100 random creatures with
      // constant activations (docs/physics.md cause 30): at 1/60 s strong
      // muscles pull 56 joints more than 1 cm apart and 8 explode; at 1/120 s
      // 21 and 2; at 1/240 s 4 and none
      c.physics.dt = 1.0 / 240;
      c.brain_hz = 240;
      // III-B: joints are limited by collisions of adjacent parts (the
      // dialect's joined_parts_collide); every part collides, as PhysX's shapes
      c.physics.self_collision = true;
      c.physics.friction = 1.0;
      // III-E: muscles are the only actuators; the damper keeps a muscle from
      // ringing (lessin2015 gives none): about critical for a 1 kg part on a
      // 100 N/m muscle, well under it for the stronger ones
      c.motor.model = MotorModel::Muscle;
      c.motor.muscle_damping = 20;
      // V, skill 1: forward locomotion scores sigma (floor(s / sigma) + eps) /
      // s_max; the paper gives neither constant nor eps (ours: steps of
      // 1 cm/s, s_max 1 m/s, so the fitness reads as the speed in m/s and
      // efficiency ranks creatures within a step; eps from the gross cost
      // of transport, the muscles' work and 1 W/kg at rest: lessin_efficiency)
      c.task.seconds = 10;
      c.task.fitness = LocomotionFitness::Lessin2015;
      c.task.speed_step = 0.01;
      c.task.max_speed = 1;
      // ours, for honest speeds (the paper is silent): the creature first
      // settles with its muscles slack, so a build that topples or rolls
      // out of its pose scores nothing for it; and the speed that counts is
      // the lesser of the two halves', so a fall or one push when the
      // muscles first pull (which a 12-generation run evolved, 0.9 m and
      // then still) scores nothing either
      c.task.activation = Activation::Settled;
      c.task.settle.speed = 0.02;
      c.task.windows = 2;
      break;
  }
  return c;
}

SimConfig default_sim_config(const Genome& g) {
  SimConfig c = default_sim_config(g.dialect);
  if (g.catapult) c.task_kind = TaskKind::Throwing;
  return c;
}

double& task_seconds(SimConfig& c) { return task_row(c.task_kind).seconds(c); }

double task_drop_height(const SimConfig& c) { return task_row(c.task_kind).drop_height(c); }

std::string_view task_drop_height_key(const SimConfig& c) { return task_row(c.task_kind).drop_height_key; }

}  // namespace bx
