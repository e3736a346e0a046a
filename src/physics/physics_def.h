// Definitions of the physics world and the motors, with their defaults in one
// place (docs/design.md: definition structs). Config files map onto these; presets
// and dialects override them.
#pragma once

namespace bx {

/// How ODE solves the constraints of one step.
enum class Solver {
  QuickStep,  ///< dWorldQuickStep: iterative (solver_iterations), O(n) per step
  Exact,      ///< dWorldStep: the exact LCP solve (Dantzig), O(n^3) per step
};

/// How the friction of a contact is bounded by its normal force.
enum class FrictionBound {
  /// A contact that persists with a steady normal force (changed by at most
  /// 30% between the last two steps) is bounded by mu times the lesser of
  /// those two forces; others by ODE's pyramid. On the exact solver ODE's
  /// pyramid alone left resting creatures gliding over frictionless ground
  /// (docs/physics.md).
  Lagged,
  /// ODE's friction pyramid (dContactApprox1): mu times the normal force as
  /// the solver has it when it reaches the friction row
  Ode,
};

/// How a velocity motor (servo, saturation, speed-limited torque) meets its
/// joint's stops.
enum class PoweredStops {
  /// ODE's joint motor: at a stop it gives up its constraint row and pushes
  /// with a plain torque of its full force into the stop, or fudge_factor
  /// times it away from the stop, whatever the target speed: a light limb
  /// kicked off its stop leaves it far faster than the motor's speed, and a
  /// signal flipping every brain step hammers the stop (docs/physics.md
  /// cause 12)
  Ode,
  /// hinges and universal joints: the motor is its own constraint (an ODE
  /// angular motor on the joint's axes) beside the stops, so a motor at a
  /// stop is solved with it: no more than its force, no faster than its
  /// speed. Sliders, pistons and ball joints keep ODE's joint motor.
  /// MotorModel::PD needs it: its implicit damper is this motor's row, with
  /// no force limit.
  Separate,
};

/// The physics world. Defaults are ODE's usual values; each dialect sets its
/// paper's constants (see io/config.cpp).
struct PhysicsDef {
  double dt = 0.01;              ///< step length (s)
  double gravity = -9.81;        ///< along z (m/s^2)
  double erp = 0.2;              ///< ODE error reduction parameter
  double cfm = 1e-5;             ///< ODE constraint force mixing
  double friction = 1.0;         ///< Coulomb coefficient, ground and part-part contacts
  FrictionBound friction_bound = FrictionBound::Lagged;
  Solver solver = Solver::Exact;
  int solver_iterations = 20;    ///< QuickStep iterations
  /// ERP and CFM of contacts and of joint stops (negative: the world's erp
  /// and cfm, ODE's default behaviour).
  double contact_erp = -1;
  double contact_cfm = -1;
  double stop_erp = -1;
  double stop_cfm = -1;
  /// The step (s) at which the ERP and CFM above are given; 0: at whatever
  /// step, ODE's way. Each ERP, CFM pair makes every constraint a spring of
  /// ERP/(dt CFM) and a damper of (1 - ERP)/CFM, so fixed values stiffen
  /// contacts and joints as the step shrinks, and a change of `dt` changes
  /// the physics, not only its integration (docs/physics.md, cause 18). Set,
  /// the pairs are recomputed at `dt` to keep the spring and damper they make
  /// at this step (softness_at_step).
  double erp_cfm_dt = 0;
  /// dParamFudgeFactor of every joint stop: how much of a motor's force may
  /// act at a stop (ODE: 1; smaller damps "jumping" at powered stops).
  double fudge_factor = 1;
  PoweredStops powered_stops = PoweredStops::Ode;
  /// Fastest speed at which contacts push interpenetrating parts apart
  /// (m/s; 0: no bound, ODE's default) and the depth they may sink before
  /// that starts (m; ODE's surface layer, default 0).
  double contact_max_correcting_vel = 0;
  double contact_surface_layer = 0;
  /// Rolling resistance of round parts (spheres, capsules, cylinders) on
  /// whatever they touch: the lever arm (m) of the torque that resists
  /// rolling, as a share of the contact's normal force (ODE's rho). Without
  /// it a cylinder carrying an offset weight rocks for ever, as nothing
  /// rigid dissipates rolling energy (docs/physics.md). 0: none.
  double rolling_friction = 0.005;
  int max_contacts = 4;          ///< contact points per colliding pair
  bool self_collision = true;    ///< non-adjacent parts collide with each other
  // numerical-explosion tests (chaumont2007 5.4): exceeding any ends the evaluation
  double max_speed = 50;         ///< a part's linear speed (m/s)
  double max_step_jump = 0.5;    ///< a part's displacement in one step (m)
  /// How far a joint may come apart (m): the distance between the points
  /// that the joint holds together on its two parts (its anchor; a hinge's
  /// axis; a slider's line and its stops; a fixed joint's whole pose).
  /// 5 cm: on the exact solver sound creatures stay within about 1 cm, and
  /// evolved walkers that gained fitness from torn joints parted 0.18-0.4 m
  /// (docs/physics.md).
  double max_joint_gap = 0.05;
  friend bool operator==(const PhysicsDef&, const PhysicsDef&) = default;
};

/// `def` with its ERP and CFM pairs (world, contacts, stops) restated at
/// def.dt from def.erp_cfm_dt (keeping the spring kp = ERP/(h CFM) and the
/// damper kd = (1 - ERP)/CFM they make at step h = erp_cfm_dt: ERP' =
/// dt kp/(dt kp + kd), CFM' = 1/(dt kp + kd)); as given when erp_cfm_dt is 0
/// or equal to dt.
PhysicsDef softness_at_step(PhysicsDef def);

/// How effector signals in [-1,1] move joints.
enum class MotorModel {
  Servo,       ///< miconi2006: target velocity max_speed*s, force capped at max_force
  Saturation,  ///< chaumont2007 5.3: target velocity sign(s)*max_speed, force cap
               ///< |s|*strength*cross-section of the larger part (3.4)
  Torque,      ///< sims1994: torque s*strength*cross-section of the larger part
  /// rivercrossing: T = kp(theta_d - theta) - kd*dtheta, theta_d from s. The
  /// damper is implicit (dtheta at the end of the step, through a joint motor
  /// row of CFM 1/kd: stable for any limb inertia), so it needs
  /// PoweredStops::Separate (World::apply_effectors; docs/physics.md cause 28)
  PD,
  /// lessin2015 III-E: each effector activates a muscle (EffectorModel::
  /// muscle): its stiffness is the signal, held to [0, 1], times its strength,
  /// with the damper muscle_damping. Integrated implicitly as ODE's soft
  /// distance constraint (a DBall joint whose ERP and CFM are the spring and
  /// damper at the step), stable at any stiffness.
  Muscle,
};

/// Whether a motor model drives through each hinge's and universal joint's
/// motor row of its own, beside the stops, and so needs
/// PoweredStops::Separate (PD: its implicit damper; docs/physics.md cause 28).
/// Its row of the actuator table says (src/physics/actuators.cpp).
bool needs_own_motor_row(MotorModel m);

/// The motors of every effector of a creature.
struct MotorDef {
  MotorModel model = MotorModel::Servo;
  double max_speed = 4;   ///< Servo, Saturation: rad/s (or m/s for sliders)
  double max_force = 4;   ///< Servo: N m (or N)
  double strength = 50;   ///< Torque, Saturation: N m per m^2 of cross-section
  /// Torque: the joint speed at which a motor stops pushing (its no-load
  /// speed; rad/s, and m/s for a linear degree of freedom): the motor gives
  /// its torque up to that speed and none beyond, so a light part is not
  /// slammed through its stop in one step (docs/physics.md). 0: no limit, a
  /// pure torque.
  double torque_max_speed = 0;
  double torque_max_linear_speed = 0;
  /// Every model: the time constant (s) of a first-order lag between the
  /// effector signal and the motor, which follows it from 0 (a motor's
  /// inductance and rotor cannot follow a command that flips every brain
  /// step; docs/physics.md cause 13). 0: the motor takes each signal at once.
  double response_time = 0;
  /// Each physics seed draws the motors' response time uniformly within
  /// +-this share of response_time (0.5: 0.02 s becomes 0.01-0.03 s): no
  /// real actuator's lag is known exactly, and a gait tuned to one lag
  /// (docs/physics.md cause 27) earns its score only under that seed. 0: no
  /// draw (runs made before it draw as ever).
  double response_time_jitter = 0;
  /// While a task holds the controller off (chaumont2007's settling), each
  /// motor brakes its joint with this share of its full force (Servo:
  /// max_force; Saturation, Torque: strength x cross-section), against any
  /// motion: a joint's friction. 0: limp, frictionless joints (the papers'
  /// ODE), where a limb left swinging never stops (docs/physics.md cause 15).
  double off_brake = 0;
  double kp = 0.25;       ///< PD gain
  double kd = 0.175;      ///< PD damping
  double muscle_damping = 0;  ///< Muscle: N s/m along its line, whatever its activation
  friend bool operator==(const MotorDef&, const MotorDef&) = default;
};

}  // namespace bx
