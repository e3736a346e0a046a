// Genome helpers: degrees of freedom per joint type and the names used in
// genome files and messages.
#include "genome/genome.h"

namespace bx {

int joint_dofs(JointType t) {
  switch (t) {
    case JointType::Fixed: return 0;
    case JointType::Hinge: return 1;
    case JointType::Universal: return 2;
    case JointType::Spherical: return 3;
    case JointType::Slider: return 1;
    case JointType::Cylindrical: return 2;
  }
  return 0;
}

std::string_view to_string(Dialect d) {
  switch (d) {
    case Dialect::Sims1994: return "sims1994";
    case Dialect::Miconi2006: return "miconi2006";
    case Dialect::Chaumont2007: return "chaumont2007";
    case Dialect::Lessin2015: return "lessin2015";
  }
  return "?";
}

std::string_view to_string(Shape s) {
  switch (s) {
    case Shape::Box: return "box";
    case Shape::Sphere: return "sphere";
    case Shape::Capsule: return "capsule";
    case Shape::Cylinder: return "cylinder";
  }
  return "?";
}

std::string_view to_string(JointType t) {
  switch (t) {
    case JointType::Fixed: return "fixed";
    case JointType::Hinge: return "hinge";
    case JointType::Universal: return "universal";
    case JointType::Spherical: return "spherical";
    case JointType::Slider: return "slider";
    case JointType::Cylindrical: return "cylindrical";
  }
  return "?";
}

std::string_view to_string(Face f) {
  switch (f) {
    case Face::PosX: return "+x";
    case Face::NegX: return "-x";
    case Face::PosY: return "+y";
    case Face::NegY: return "-y";
    case Face::PosZ: return "+z";
    case Face::NegZ: return "-z";
  }
  return "?";
}

std::string_view to_string(SourcePlace p) {
  switch (p) {
    case SourcePlace::Self: return "self";
    case SourcePlace::Parent: return "parent";
    case SourcePlace::Child: return "child";
    case SourcePlace::Root: return "root";
    case SourcePlace::Global: return "global";
  }
  return "?";
}

std::string_view to_string(SensorType t) {
  switch (t) {
    case SensorType::JointAngle: return "joint_angle";
    case SensorType::Contact: return "contact";
    case SensorType::Photoreceptor: return "photoreceptor";
    case SensorType::MuscleLength: return "muscle_length";
  }
  return "?";
}

}  // namespace bx
