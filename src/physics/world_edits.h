// What a task may change in the world it acts on (Task::act): break a
// joint, place a prop, set the lights. The evaluation's World does it in
// ODE; `crosscheck`'s replay (io/mujoco_replay.cpp) does the same in MuJoCo,
// so a task scores a creature in either without knowing which.
#pragma once

#include <vector>

#include "core/math.h"
#include "develop/creature_model.h"

namespace bx {

/// A point light (lessin2015 III-D). A photoreceptor facing it from d metres
/// reads strength / (1 + (d / range)^2), times the cosine of the angle
/// between its direction and the light's, 0 behind it or when any body is in
/// the way; several lights add, and the reading is held to [0, 1].
struct Light {
  Vec3 position;
  double strength = 1;
  double range = 1;  ///< m: where its reading has halved
  friend bool operator==(const Light&, const Light&) = default;
};

/// A solid the world holds beside the creature and the ground (lessin2015's
/// targets): shaped as a part is (a cylinder's or capsule's axis along its
/// pose's x axis, length size.x and diameter size.y), fixed where it is
/// placed, or turning about the world's vertical through its centre at
/// `spin` rad/s (counterclockwise seen from above), which nothing the
/// creature does can slow: it is kinematic, of unlimited mass. Parts collide
/// with it (with the world's friction), rays hit it; it touches neither the
/// ground nor other props.
struct Prop {
  Shape shape = Shape::Box;
  Vec3 size{1, 1, 1};
  Pose pose;
  double spin = 0;  ///< rad/s about the vertical
  friend bool operator==(const Prop&, const Prop&) = default;
};

/// The changes a task makes to its world while the creature moves in it.
class WorldEdits {
 public:
  virtual ~WorldEdits() = default;
  /// Breaks joint j for good (a catapult's release, chaumont2007 4.1): its
  /// child part flies free and from then on collides with every part.
  virtual void break_joint(int j) = 0;
  /// Adds a prop and returns its index, from 0 in the order they were added.
  virtual int add_prop(const Prop& p) = 0;
  /// The lights photoreceptors see from now on.
  virtual void set_lights(std::vector<Light> lights) = 0;
};

}  // namespace bx
