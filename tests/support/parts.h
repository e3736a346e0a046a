// Parts and motors for physics tests: a creature's part of a shape at a
// position (unrotated), and a torque motor (strength x an effector's
// cross-section = its torque at signal 1).
#pragma once

#include "develop/creature_model.h"
#include "physics/physics_def.h"

namespace bxtest {

inline bx::PartModel part(bx::Shape shape, bx::Vec3 size, double mass, bx::Vec3 pos, int parent = -1) {
  bx::PartModel p;
  p.shape = shape;
  p.size = size;
  p.mass = mass;
  p.pose = {pos, bx::Mat3::identity()};
  p.parent = parent;
  return p;
}

inline bx::PartModel box_part(bx::Vec3 size, double mass, bx::Vec3 pos, int parent = -1) {
  return part(bx::Shape::Box, size, mass, pos, parent);
}

inline bx::MotorDef torque_motor(double strength) {
  bx::MotorDef m;
  m.model = bx::MotorModel::Torque;
  m.strength = strength;
  return m;
}

}  // namespace bxtest
