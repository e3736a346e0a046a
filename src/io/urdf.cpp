#include "io/urdf.h"

#include <algorithm>
#include <cmath>

#include "core/text.h"
#include "io/export_common.h"

namespace bx {

namespace {

using xml::num;
using xml::vec;

// URDF's rpy (fixed axes x, y, z: R = Rz(yaw) Ry(pitch) Rx(roll)) of a rotation
std::string rpy(const Mat3& R) {
  const auto& m = R.m;
  const double pitch = std::asin(std::clamp(-m[2][0], -1.0, 1.0));
  double roll, yaw;
  if (std::abs(m[2][0]) < 1 - 1e-12) {
    roll = std::atan2(m[2][1], m[2][2]);
    yaw = std::atan2(m[1][0], m[0][0]);
  } else {  // gimbal lock: the roll folds into the yaw
    roll = 0;
    yaw = std::atan2(-m[0][1], m[1][1]);
  }
  return num(roll) + " " + num(pitch) + " " + num(yaw);
}

std::string origin(Vec3 xyz, const std::string& angles = "0 0 0") {
  return "<origin xyz=\"" + vec(xyz) + "\" rpy=\"" + angles + "\"/>";
}

// the principal moments of a uniform solid about its centre, in its frame
// (ODE's dMassSet*: shapes along x as ours are)
Vec3 moments(const PartModel& p) {
  const Vec3 s = p.size;
  const double m = p.mass;
  switch (p.shape) {
    case Shape::Box:
      return {m * (s.y * s.y + s.z * s.z) / 12, m * (s.x * s.x + s.z * s.z) / 12, m * (s.x * s.x + s.y * s.y) / 12};
    case Shape::Sphere: return Vec3{1, 1, 1} * (0.4 * m * (s.x / 2) * (s.x / 2));
    case Shape::Cylinder: {
      const double r = s.y / 2, l = s.x;
      return {m * r * r / 2, m * (3 * r * r + l * l) / 12, m * (3 * r * r + l * l) / 12};
    }
    case Shape::Capsule: {  // a cylinder of length x - y and two half balls, by volume
      const double r = s.y / 2, l = std::max(s.x - s.y, 0.0);
      const double vc = kPi * r * r * l, vs = 4.0 / 3 * kPi * r * r * r;
      const double mc = m * vc / (vc + vs), ms = m * vs / (vc + vs);
      const double along = (0.5 * mc + 0.4 * ms) * r * r;
      const double across = mc * (0.25 * r * r + l * l / 12) + ms * (0.4 * r * r + 0.375 * r * l + 0.25 * l * l);
      return {along, across, across};
    }
  }
  return {};
}

// a part's shape as URDF geometry, at `centre` in its link's frame
std::vector<std::string> shapes(const PartModel& p, Vec3 centre) {
  const Vec3 s = p.size;
  const std::string along_x = "0 " + num(kPi / 2) + " 0";  // URDF's cylinder lies along z
  switch (p.shape) {
    case Shape::Box: return {origin(centre) + "<geometry><box size=\"" + vec(s) + "\"/></geometry>"};
    case Shape::Sphere: return {origin(centre) + "<geometry><sphere radius=\"" + num(s.x / 2) + "\"/></geometry>"};
    case Shape::Cylinder:
      return {origin(centre, along_x) + "<geometry><cylinder radius=\"" + num(s.y / 2) + "\" length=\"" + num(s.x) +
              "\"/></geometry>"};
    case Shape::Capsule: {
      const double r = s.y / 2, l = std::max(s.x - s.y, 0.0);
      const std::string ball = "<geometry><sphere radius=\"" + num(r) + "\"/></geometry>";
      // the part's x axis in the link's frame is the link's x (the link turns as the part)
      return {origin(centre, along_x) + "<geometry><cylinder radius=\"" + num(r) + "\" length=\"" + num(l) +
                  "\"/></geometry>",
              origin(centre + Vec3{l / 2, 0, 0}) + ball, origin(centre - Vec3{l / 2, 0, 0}) + ball};
    }
  }
  return {};
}

}  // namespace

std::string creature_urdf(const CreatureModel& m, const SimConfig& cfg, const std::string& name,
                          std::vector<std::string>* notes) {
  const MotorDef& motor = cfg.motor;
  std::vector<int> joint_of(m.parts.size(), -1);
  for (int j = 0; j < static_cast<int>(m.joints.size()); ++j) joint_of[m.joints[j].child] = j;
  // each link's frame in the creature frame: at the anchor (the root: its centre), turned as its part
  auto frame_origin = [&](int i) { return joint_of[i] >= 0 ? m.joints[joint_of[i]].anchor : m.parts[i].pose.p; };
  // the largest push an effector gives each joint's degree of freedom
  std::vector<std::vector<double>> effort(m.joints.size(), std::vector<double>(3, 0.0));
  int muscles = 0;
  for (const EffectorModel& e : m.effectors) {
    if (motor.model == MotorModel::Muscle || e.muscle >= 0) {
      ++muscles;
      continue;
    }
    // a PD motor's push has no cap of its own (kp times the error): left 0
    const double push = motor.model == MotorModel::Servo ? motor.max_force
                        : motor.model == MotorModel::PD  ? 0
                                                         : motor.strength * e.cross_section;
    double& slot = effort[static_cast<std::size_t>(e.joint)][static_cast<std::size_t>(std::clamp(e.dof, 0, 2))];
    slot = std::max(slot, push);
  }

  std::string x = "<?xml version=\"1.0\"?>\n<robot name=\"" + xml_text(name) + "\">\n";
  x += "  <!-- exported by Bestiary (docs/export.md): lengths m, angles rad, masses kg; the pose as built -->\n";
  for (int i = 0; i < m.n_parts(); ++i) {
    const PartModel& p = m.parts[i];
    const Vec3 centre = p.pose.R.transposed() * (p.pose.p - frame_origin(i));
    const Vec3 I = moments(p);
    x += "  <link name=\"p" + std::to_string(i) + "\">\n";
    x += "    <inertial>" + origin(centre) + "<mass value=\"" + num(p.mass) + "\"/><inertia ixx=\"" + num(I.x) +
         "\" ixy=\"0\" ixz=\"0\" iyy=\"" + num(I.y) + "\" iyz=\"0\" izz=\"" + num(I.z) + "\"/></inertial>\n";
    for (const std::string& g : shapes(p, centre)) {
      x += "    <visual>" + g + "</visual>\n";
      x += "    <collision>" + g + "</collision>\n";
    }
    x += "  </link>\n";
  }
  const std::string tiny = num(kUrdfDofLinkMass), tiny_i = num(kUrdfDofLinkMass * 1e-3);
  for (int j = 0; j < static_cast<int>(m.joints.size()); ++j) {
    const JointModel& jm = m.joints[j];
    const Pose& parent = m.parts[jm.parent].pose;
    const Mat3 Rt = m.parts[jm.child].pose.R.transposed();
    const Vec3 at = parent.R.transposed() * (jm.anchor - frame_origin(jm.parent));
    const std::string turn = rpy(parent.R.transposed() * m.parts[jm.child].pose.R);
    const std::vector<ExportDof> dofs = export_dofs(jm);
    // (appended, not "p" + ...: gcc 12's -Wrestrict misreads that concatenation here)
    std::string child = "p", parent_link = "p";
    child += std::to_string(jm.child);
    parent_link += std::to_string(jm.parent);
    if (dofs.empty()) {
      x += "  <joint name=\"j" + std::to_string(j) + "\" type=\"fixed\"><parent link=\"";
      x += parent_link + "\"/><child link=\"" + child + "\"/>" + origin(at, turn) + "</joint>\n";
      continue;
    }
    std::string from = parent_link;
    for (std::size_t k = 0; k < dofs.size(); ++k) {
      const ExportDof& d = dofs[k];
      const bool last = k + 1 == dofs.size();
      const std::string to = last ? child : child + "_dof" + std::to_string(k);
      if (!last)
        x += "  <link name=\"" + to + "\"><inertial><mass value=\"" + tiny + "\"/><inertia ixx=\"" + tiny_i +
             "\" ixy=\"0\" ixz=\"0\" iyy=\"" + tiny_i + "\" iyz=\"0\" izz=\"" + tiny_i + "\"/></inertial></link>\n";
      const bool limited = d.limit && d.limit->hi > d.limit->lo;
      const char* type = d.slide ? "prismatic" : limited ? "revolute" : "continuous";
      x += "  <joint name=\"j" + std::to_string(j) + "_" + std::to_string(k) + "\" type=\"" + type +
           "\"><parent link=\"" + from + "\"/><child link=\"" + to + "\"/>" +
           (k == 0 ? origin(at, turn) : origin({0, 0, 0})) + "<axis xyz=\"" + vec(-1.0 * (Rt * d.axis)) + "\"/>";
      const double lo = limited ? d.limit->lo : d.slide ? -1e3 : 0, hi = limited ? d.limit->hi : d.slide ? 1e3 : 0;
      const std::string push = num(effort[static_cast<std::size_t>(j)][std::min<std::size_t>(k, 2)]);
      x += limited || d.slide
               ? "<limit lower=\"" + num(lo) + "\" upper=\"" + num(hi) + "\" effort=\"" + push + "\" velocity=\"" +
                     num(motor.max_speed) + "\"/>"
               : "<limit effort=\"" + push + "\" velocity=\"" + num(motor.max_speed) + "\"/>";
      x += "</joint>\n";
      from = to;
    }
  }
  x += "</robot>\n";
  if (notes) {
    notes->push_back("URDF has no actuators: each joint's effort is the largest push of its effectors (motor." +
                     std::string(motor.model == MotorModel::Servo ? "max_force" : "strength") +
                     "); the motor model, its response time, the step and friction are not in it (--mjcf has them)");
    if (muscles > 0) notes->push_back(std::to_string(muscles) + " muscle effectors not exported (URDF has no muscles)");
  }
  return x;
}

}  // namespace bx
