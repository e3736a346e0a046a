#include "io/mjcf.h"

#include <cmath>
#include <string>
#include <vector>

#include "core/text.h"
#include "io/export_common.h"
#include "eval/task_table.h"

namespace bx {

namespace {

using xml::num;
using xml::vec;

std::string quat(const Mat3& R) {
  const Quat q = to_quat(R);
  return num(q.w) + " " + num(q.x) + " " + num(q.y) + " " + num(q.z);
}


// a part's geom in its own body's frame (the part's centre and axes)
std::string geom(const PartModel& p, int i, const std::string& extra) {
  const Vec3 s = p.size;
  std::string g = "<geom name=\"g" + std::to_string(i) + "\" mass=\"" + num(p.mass) + "\" " + extra;
  switch (p.shape) {
    case Shape::Box: g += "type=\"box\" size=\"" + vec(0.5 * s) + "\""; break;
    case Shape::Sphere: g += "type=\"sphere\" size=\"" + num(s.x / 2) + "\""; break;
    case Shape::Capsule: {  // along x: length x overall, diameter y
      const double half = std::max(s.x - s.y, 0.0) / 2;
      g += "type=\"capsule\" size=\"" + num(s.y / 2) + "\" fromto=\"" + num(-half) + " 0 0 " + num(half) + " 0 0\"";
      break;
    }
    case Shape::Cylinder:
      g += "type=\"cylinder\" size=\"" + num(s.y / 2) + "\" fromto=\"" + num(-s.x / 2) + " 0 0 " + num(s.x / 2) +
           " 0 0\"";
      break;
  }
  return g + "/>";
}

}  // namespace

std::string mjcf_joint_name(int joint, int dof) {
  std::string jn = "j";  // built in steps: GCC 12 warns (falsely) on "j" + to_string(...)
  jn += std::to_string(joint);
  jn += '_';
  jn += std::to_string(dof);
  return jn;
}

std::string mjcf_muscle_name(int muscle) {
  std::string mn = "m";  // in steps, as mjcf_joint_name
  mn += std::to_string(muscle);
  return mn;
}

std::string mjcf_prop_body(const Prop& p, int k) {
  PartModel shape;  // geom() writes a part's shape; a mocap body's mass does not count
  shape.shape = p.shape;
  shape.size = p.size;
  shape.mass = 1;
  std::string g = geom(shape, k, "contype=\"4\" conaffinity=\"3\" ");
  g.replace(g.find("name=\"g"), 7, "name=\"q");  // the prop's geom "q<k>", apart from the parts' "g<i>"
  return "    <body name=\"prop" + std::to_string(k) + "\" mocap=\"true\" pos=\"" + vec(p.pose.p) + "\" quat=\"" +
         quat(p.pose.R) + "\">\n      " + g + "\n    </body>\n";
}

std::string mjcf_free_joint_name(int part) {
  if (part == 0) return "root";
  std::string fn = "free";  // in steps, as mjcf_joint_name
  fn += std::to_string(part);
  return fn;
}

std::string creature_mjcf(const CreatureModel& m, const SimConfig& cfg, const std::string& name, MjcfNotes* notes,
                          std::span<const int> broken_joints) {
  MjcfNotes local;
  MjcfNotes& n = notes ? *notes : local;
  const PhysicsDef& ph = cfg.physics;
  const MotorDef& motor = cfg.motor;
  // each part's joint to its parent
  std::vector<int> joint_of(m.parts.size(), -1);
  for (int j = 0; j < static_cast<int>(m.joints.size()); ++j) joint_of[m.joints[j].child] = j;
  // a part whose joint is broken heads a tree of its own, free in the world
  std::vector<bool> freed(m.parts.size(), false);
  for (int j : broken_joints)
    if (j >= 0 && j < static_cast<int>(m.joints.size())) freed[m.joints[j].child] = true;
  std::vector<std::vector<int>> children(m.parts.size());
  for (int i = 1; i < m.n_parts(); ++i) children[m.parts[i].parent].push_back(i);
  bool joined_collide = false;
  for (const JointModel& j : m.joints) joined_collide = joined_collide || j.parts_collide;

  // contacts: every part with the floor; parts with each other as the
  // config says (MuJoCo never lets a body touch its parent unless told)
  const std::string self = ph.self_collision ? "contype=\"1\" conaffinity=\"1\"" : "contype=\"2\" conaffinity=\"1\"";
  std::string x = "<mujoco model=\"" + xml_text(name) + "\">\n";
  x += "  <!-- exported by Bestiary (docs/export.md): lengths m, angles rad, masses kg -->\n";
  x += "  <compiler angle=\"radian\" inertiafromgeom=\"true\"/>\n";
  x += "  <option timestep=\"" + num(ph.dt) + "\" gravity=\"0 0 " + num(ph.gravity) + "\">\n";
  x += std::string("    <flag filterparent=\"") + (joined_collide ? "disable" : "enable") + "\"/>\n  </option>\n";
  x += "  <default>\n    <geom friction=\"" + num(ph.friction) + " 0.005 0.0001\" " + self + "/>\n  </default>\n";
  x += "  <worldbody>\n";
  x += "    <geom name=\"floor\" type=\"plane\" size=\"0 0 1\" contype=\"1\" conaffinity=\"3\"/>\n";
  const double drop = task_row(cfg.task_kind).drop_height(cfg);
  const Vec3 lift{0, 0, drop - m.min_z()};

  // the tree, depth first: each body's frame its part's, given in its parent's
  std::vector<std::string> joint_names(m.joints.size() * 3);
  auto body = [&](auto&& self_fn, int i, const std::string& indent) -> void {
    const PartModel& p = m.parts[i];
    const bool top = p.parent < 0 || freed[i];
    Vec3 pos;
    Mat3 R;
    if (top) {
      pos = p.pose.p + lift;
      R = p.pose.R;
    } else {
      const Pose& q = m.parts[p.parent].pose;
      pos = q.R.transposed() * (p.pose.p - q.p);
      R = q.R.transposed() * p.pose.R;
    }
    x += indent + "<body name=\"p" + std::to_string(i) + "\" pos=\"" + vec(pos) + "\" quat=\"" + quat(R) + "\">\n";
    const std::string in = indent + "  ";
    if (top) x += in + "<freejoint name=\"" + mjcf_free_joint_name(i) + "\"/>\n";
    if (int j = joint_of[i]; j >= 0 && !freed[i]) {
      const JointModel& jm = m.joints[j];
      const Mat3 Rt = p.pose.R.transposed();
      const Vec3 anchor = Rt * (jm.anchor - p.pose.p);
      int k = 0;
      for (const ExportDof& d : export_dofs(jm)) {
        const std::string jn = mjcf_joint_name(j, k);
        joint_names[static_cast<std::size_t>(j) * 3 + k] = jn;
        // ODE's angle is the parent's turn relative to the child: about the negated axis here
        x += in + "<joint name=\"" + jn + "\" type=\"" + (d.slide ? "slide" : "hinge") + "\" pos=\"" + vec(anchor) + "\" axis=\"" +
             vec(-1.0 * (Rt * d.axis)) + "\"";
        if (d.limit && d.limit->hi > d.limit->lo)
          x += " limited=\"true\" range=\"" + num(d.limit->lo) + " " + num(d.limit->hi) + "\"";
        if (motor.model == MotorModel::PD) x += " damping=\"" + num(motor.kd) + "\"";
        x += "/>\n";
        ++k;
      }
    }
    // a freed part collides with every part (World::break_joint)
    x += in + geom(p, i, freed[i] ? "contype=\"3\" conaffinity=\"3\" " : "") + "\n";
    // the ends of the muscles this part holds (lessin2015), in its frame
    for (int k = 0; k < static_cast<int>(m.muscles.size()); ++k) {
      const MuscleModel& mm = m.muscles[k];
      for (int end = 0; end < 2; ++end)
        if ((end == 0 ? mm.part_a : mm.part_b) == i) {
          const Vec3 at = p.pose.R.transposed() * ((end == 0 ? mm.anchor_a : mm.anchor_b) - p.pose.p);
          x += in + "<site name=\"" + mjcf_muscle_name(k) + (end == 0 ? "a" : "b") + "\" pos=\"" + vec(at) + "\"/>\n";
        }
    }
    for (int c : children[i])
      if (!freed[c]) self_fn(self_fn, c, in);
    x += indent + "</body>\n";
  };
  body(body, 0, "    ");
  for (int i = 1; i < m.n_parts(); ++i)
    if (freed[i]) body(body, i, "    ");
  x += "  </worldbody>\n";
  // each muscle a spring between its two ends: a spatial tendon whose
  // stiffness is its activation (0-1) times its strength, 0 at rest (a
  // simulator sets it each step), its damper motor.muscle_damping
  if (!m.muscles.empty()) {
    x += "  <tendon>\n";
    for (int k = 0; k < static_cast<int>(m.muscles.size()); ++k) {
      const std::string mn = mjcf_muscle_name(k);
      x += "    <spatial name=\"" + mn + "\" stiffness=\"0\" damping=\"" + num(motor.muscle_damping) +
           "\" springlength=\"" + num(m.muscles[k].rest_length) + "\">\n      <site site=\"" + mn +
           "a\"/>\n      <site site=\"" + mn + "b\"/>\n    </spatial>\n";
    }
    x += "  </tendon>\n";
  }

  // the actuators: one per effector on its joint's degree of freedom
  std::string acts;
  int muscles = 0;
  for (int e = 0; e < static_cast<int>(m.effectors.size()); ++e) {
    const EffectorModel& em = m.effectors[e];
    if (motor.model == MotorModel::Muscle || em.muscle >= 0) {
      ++muscles;
      continue;
    }
    const std::string& jn = joint_names[static_cast<std::size_t>(em.joint) * 3 + em.dof];
    if (jn.empty()) continue;
    const std::string head = "    <", tail = " name=\"e" + std::to_string(e) + "\" joint=\"" + jn + "\"";
    const double torque = motor.strength * em.cross_section;
    switch (motor.model) {
      case MotorModel::Torque:
      case MotorModel::Saturation:
        acts += head + "motor" + tail + " gear=\"" + num(torque) + "\" ctrllimited=\"true\" ctrlrange=\"-1 1\"/>\n";
        break;
      case MotorModel::Servo:
        acts += head + "velocity" + tail + " kv=\"" + num(motor.max_force) + "\" forcelimited=\"true\" forcerange=\"" +
                num(-motor.max_force) + " " + num(motor.max_force) + "\" ctrllimited=\"true\" ctrlrange=\"" +
                num(-motor.max_speed) + " " + num(motor.max_speed) + "\"/>\n";
        break;
      case MotorModel::PD: {
        const JointModel& jm = m.joints[em.joint];
        const Limit l = em.dof < static_cast<int>(jm.limits.size()) ? jm.limits[em.dof] : Limit{-kPi, kPi};
        acts += head + "position" + tail + " kp=\"" + num(motor.kp) + "\" ctrllimited=\"true\" ctrlrange=\"" +
                num(l.lo) + " " + num(l.hi) + "\"/>\n";
        break;
      }
      case MotorModel::Muscle: break;
    }
  }
  if (!acts.empty()) x += "  <actuator>\n" + acts + "  </actuator>\n";
  x += "</mujoco>\n";

  if (muscles > 0)
    n.lines.push_back(std::to_string(muscles) + " muscles as spatial tendons \"m<k>\" of stiffness 0: a muscle's "
                      "stiffness is its activation (0-1) times its strength (N/m); set tendon_stiffness each step");
  if (motor.model == MotorModel::Servo)
    n.lines.push_back("servo motors as velocity actuators: control = target speed (rad/s), kv = the force cap");
  if (motor.model == MotorModel::Saturation)
    n.lines.push_back("saturation motors as torque motors of their force at signal 1 (MuJoCo has no capped velocity motor)");
  if (motor.response_time > 0)
    n.lines.push_back("the motors' response time (" + num(motor.response_time) + " s) is not in MJCF: filter the controls");
  return x;
}

}  // namespace bx
