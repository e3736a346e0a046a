// Everything an evaluation needs besides the creature and the seed, with
// each dialect's paper constants as defaults.
#pragma once

#include <string_view>
#include <vector>

#include "brain/river/found_motif.h"
#include "brain/river/motif_def.h"
#include "develop/develop.h"
#include "genome/genome.h"
#include "physics/physics_def.h"
#include "task/fight_or_flight.h"
#include "task/light.h"
#include "task/locomotion.h"
#include "task/reach.h"
#include "task/river/river_def.h"
#include "task/throwing.h"
#include "task/strike.h"
#include "task/turn.h"

namespace bx {

/// Which task an evaluation runs.
enum class TaskKind {
  Locomotion,  ///< SimConfig::task
  Throwing,    ///< SimConfig::throwing (catapults, chaumont2007 section 4)
  River,       ///< SimConfig::river's task (the river crossing; its quadruped only)
  Turn,        ///< SimConfig::turn (lessin2015 V, skills 2 and 3: turning in place)
  Strike,      ///< SimConfig::strike (lessin2015 V, skill 6: an impact on the ground)
  Light,       ///< SimConfig::light (lessin2015 V, skills 4, 5, 7, 8 and 9: a point light's tasks)
  Fight,       ///< SimConfig::fight with light and strike (lessin2015 V, skill 10: FIGHT OR FLIGHT)
  Reach,       ///< SimConfig::reach (lessin2015 VII-B: the high-reach task)
};

/// What a genotype develops into: a body and its controller (eval/creature.h,
/// whose table says each kind's genotype and development).
enum class CreatureKind {
  Graph,  ///< Sims' graph genome: it grows its body and compiles its own brain
  River,  ///< a float vector: the river crossing's controller weights, driving its quadruped
  Motif,  ///< a float vector: a CTRNN motif's 15 genes, scored without a body (no physics world)
};

/// How several trials' fitnesses combine (SimConfig::trial_score).
enum class TrialScore { Mean, Min };

/// The settings of one simulation. Config files (io/config.h) map onto these
/// fields one to one, section by section.
struct SimConfig {
  PhysicsDef physics;
  MotorDef motor;
  /// Brain steps per simulated second, independent of physics.dt: brain step
  /// k runs at time k / brain_hz, each one brain step long (1 / brain_hz s).
  double brain_hz = 100;
  DevelopDef develop;
  /// What the genotypes develop into (genotype.kind).
  CreatureKind creature = CreatureKind::Graph;
  TaskKind task_kind = TaskKind::Locomotion;
  LocomotionDef task;
  ThrowingDef throwing;
  RiverDef river;  ///< the river crossing's creature and task
  TurnDef turn;    ///< the turn task (task.kind = "turn": the [turn] keys)
  StrikeDef strike;  ///< the strike task (task.kind = "strike": the [strike] keys)
  LightDef light;  ///< the light tasks (task.kind = "light": the [light] keys)
  /// Fight or flight's targets (task.kind = "fight_or_flight": the [fight]
  /// keys; its lights and strikes those of [light] and [strike]).
  FightDef fight;
  ReachDef reach;  ///< the high-reach task (task.kind = "high_reach": the [reach] keys)
  /// The pre-evolved CTRNN motif every copy in the river crossing's pattern
  /// generator shares (the [motif] keys), and the file it came from.
  Motif motif = found_motif();
  MotifSource motif_source;
  /// How genotype.kind = "motif" scores and breeds motifs ([motif_fitness]).
  MotifKindDef motif_kind;
  /// The creature's front, an axis of its root part's frame: what every
  /// task's heading is (turn, light, fight_or_flight, task.metric =
  /// "forward"). +x by default; a creature that lies on its side and moves
  /// along another axis of its root names it (lessin_crawler: -z).
  RootAxis front = RootAxis::PlusX;
  /// Evaluations per creature under different physics seeds; its fitness is
  /// their mean (QuickStep's randomised solver makes a chaotic motion, such
  /// as a throw, depend on the seed).
  int trials = 1;
  /// How the trials' fitnesses make the creature's: their mean, or the
  /// least of them (a creature is scored by its worst trial, so a lucky
  /// chaotic event under one physics seed earns nothing; docs/physics.md).
  TrialScore trial_score = TrialScore::Mean;
  /// Each physics seed turns the creature's starting pose about the vertical
  /// by a uniform angle within +-this (degrees), so that seeds vary an
  /// evaluation under the exact solver too, which, unlike QuickStep, draws
  /// no random numbers (docs/physics.md). 0: every seed starts alike.
  double start_yaw_jitter = 0.5;
  /// Each physics seed also raises or lowers the drop by a uniform height
  /// within +-this (m). A turn about the vertical is a symmetry of flat
  /// ground, so under it seeds barely vary a throw, while a tenth of a
  /// millimetre of drop can switch it between outcomes (docs/physics.md,
  /// cause 17). 0: no draw (the default: runs made before it draw as ever).
  double start_drop_jitter = 0;
  double replay_fps = 30;  ///< frames per simulated second in replays
  /// Diagnostics (`bestiary check`, the rest tests), not a config key: when
  /// non-empty the brain is bypassed and effector e holds effector_clamp[e]
  /// (one value: every effector holds it) whenever the controller is on.
  std::vector<double> effector_clamp;
  /// Diagnostics (`bestiary check`'s "held"), not a config key: whenever the
  /// controller is on, every effector's motor holds its joint still (target
  /// speed 0 at its full force) instead of following its signal, while the
  /// controller still takes the task's actions (a catapult's release): what
  /// is left of a throw then is a fall, not a swing.
  bool hold_joints = false;
  /// Diagnostics (`bestiary check`), not a config key: record every effector
  /// signal while the controller drives the motors, for each one's dominant
  /// frequency (EvalDiagnostics::effector_hz). A replay records them too.
  bool effector_spectrum = false;
  friend bool operator==(const SimConfig&, const SimConfig&) = default;
};

/// The defaults of a dialect (its paper's constants; docs/config.md lists them).
SimConfig default_sim_config(Dialect d);

/// The defaults for a genome: its dialect's, with the throwing task for a
/// catapult.
SimConfig default_sim_config(const Genome& g);

/// The active task's evaluation length (s): task.seconds or throwing.seconds.
double& task_seconds(SimConfig& c);
/// The active task's drop height (m) and its key: task.drop_height or
/// throwing.drop_height.
double task_drop_height(const SimConfig& c);
std::string_view task_drop_height_key(const SimConfig& c);

}  // namespace bx
