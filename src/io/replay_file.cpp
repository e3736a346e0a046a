#include "io/replay_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "brain/neuron_set.h"
#include "core/files.h"
#include "core/version.h"
#include "genome/json_text.h"
#include "io/rounding.h"
#include "io/scene_record_json.h"

namespace bx {

namespace {

using nlohmann::json;

// Rounding keeps files small (io/rounding.h): 10 micrometres, 1e-5 of a
// quaternion or a joint angle (rad), 1e-4 of a signal.
json vec_json(Vec3 v, double q) { return json::array({round_to(v.x, q), round_to(v.y, q), round_to(v.z, q)}); }

// a joint's stops per degree of freedom, [lo, hi] each; [] when unlimited
json limits_json(const std::vector<Limit>& limits) {
  json out = json::array();
  for (const Limit& l : limits) out.push_back({round_to(l.lo, 1e-6), round_to(l.hi, 1e-6)});
  return out;
}

// a sensor as the model has it: a joint angle's joint and dof, a contact's
// face, a photoreceptor's direction (in its part's frame), a muscle length's muscle
json sensor_json(const SensorModel& s) {
  json o = {{"type", std::string(to_string(s.type))}, {"part", s.part}};
  switch (s.type) {
    case SensorType::JointAngle:
      o["joint"] = s.joint;
      o["dof"] = s.dof;
      break;
    case SensorType::Contact: o["face"] = std::string(to_string(s.face)); break;
    case SensorType::Photoreceptor:
      o["direction"] = {round_to(s.direction.x, 1e-6), round_to(s.direction.y, 1e-6), round_to(s.direction.z, 1e-6)};
      break;
    case SensorType::MuscleLength: o["muscle"] = s.muscle; break;
  }
  return o;
}

// the wires into neuron (or effector) k: [slot, weight] each, or [slot,
// weight, gate slot] for a gated one (lessin2015's switches); slots are the
// brain's values: sensors first (0 .. sensors - 1), then neurons. A
// positional hole (a wire that reads 0) is left out.
json wires_json(const std::vector<std::uint32_t>& begin, const std::vector<std::int32_t>& src,
                const std::vector<double>& weight, const std::vector<std::int32_t>& gate, std::size_t k) {
  json out = json::array();
  for (std::uint32_t w = begin[k]; w < begin[k + 1]; ++w) {
    if (src[w] < 0) continue;
    json wire = {src[w], round_to(weight[w], 1e-6)};
    if (!gate.empty() && gate[w] >= 0) wire.push_back(gate[w]);
    out.push_back(wire);
  }
  return out;
}

}  // namespace

std::string replay_creature(const SimConfig& cfg) {
  return cfg.creature == CreatureKind::Graph ? std::string() : std::string(creature_kind_row(cfg.creature).name);
}

std::string replay_to_string(const CreatureModel& m, const Replay& r, const EvalResult& res,
                             const ReplayInfo& info) {
  json j;
  j["format"] = "bestiary-replay";
  j["version"] = 1;
  j["bestiary"] = std::string(bestiary_version());
  j["genome"] = info.genome_source;
  if (info.creature.empty())
    j["dialect"] = std::string(to_string(m.dialect));
  else
    j["creature"] = info.creature;
  // a JSON number above 2^53 loses digits in JavaScript (the viewer): such a
  // seed is written as its decimal string
  if (info.seed > (std::uint64_t{1} << 53))
    j["seed"] = std::to_string(info.seed);
  else
    j["seed"] = info.seed;
  j["dt"] = info.dt;
  // the scene: the ground, props drawn from their descriptions (no task
  // writes any now), and what the task and the controller recorded
  j["scene"] = {{"ground", {{"type", "plane"}, {"z", 0.0}, {"friction", info.friction}}},
                {"props", json::array()}};
  if (!r.scene.empty()) j["scene"]["record"] = scene_record_to_json(r.scene);
  // parts and joints at the initial pose
  json parts = json::array();
  for (const auto& p : m.parts)
    parts.push_back({{"shape", std::string(to_string(p.shape))},
                     {"size", vec_json(p.size, 1e-6)},
                     {"mass", p.mass},
                     {"gene", p.gene},
                     {"parent", p.parent},
                     {"mirrored", p.mirrored}});
  j["parts"] = parts;
  // joint anchor and axes in the child part's frame, so a viewer places them
  // with the child's pose in any frame
  json joints = json::array();
  for (const auto& jm : m.joints) {
    const Pose& c = m.parts[jm.child].pose;
    Mat3 Rt = c.R.transposed();
    joints.push_back({{"type", std::string(to_string(jm.type))},
                      {"parent", jm.parent},
                      {"child", jm.child},
                      {"anchor", vec_json(Rt * (jm.anchor - c.p), 1e-6)},
                      {"axis1", vec_json(Rt * jm.axis1, 1e-6)},
                      {"axis2", vec_json(Rt * jm.axis2, 1e-6)},
                      {"limits", limits_json(jm.limits)}});
  }
  j["joints"] = joints;
  // muscles (lessin2015): each end in its own part's frame at the initial
  // pose, so a viewer places it with that part's pose in any frame; left out
  // for a creature without any, whose file stays as it was
  if (!m.muscles.empty()) {
    json muscles = json::array();
    for (const MuscleModel& mm : m.muscles) {
      const Pose& a = m.parts[mm.part_a].pose;
      const Pose& b = m.parts[mm.part_b].pose;
      muscles.push_back({{"part_a", mm.part_a},
                         {"part_b", mm.part_b},
                         {"anchor_a", vec_json(a.R.transposed() * (mm.anchor_a - a.p), 1e-6)},
                         {"anchor_b", vec_json(b.R.transposed() * (mm.anchor_b - b.p), 1e-6)},
                         {"strength", round_to(mm.strength, 1e-6)},
                         {"rest_length", round_to(mm.rest_length, 1e-6)}});
    }
    j["muscles"] = muscles;
  }
  // a graph creature's neurons are its brain's; another kind's controller
  // (or one whose frames hold another count) has signals of its own
  // (a controller may hold none before its first step: its frames are
  // padded with zeros to the most any frame holds, as frame 0 is all zeros)
  json neurons = json::array();
  std::size_t internals = r.frames.empty() ? static_cast<std::size_t>(m.brain.n_neurons()) : 0;
  for (const auto& f : r.frames) internals = std::max(internals, f.neurons.size());
  const bool graph_brain = info.creature.empty() && internals == static_cast<std::size_t>(m.brain.n_neurons());
  if (graph_brain) {
    for (int i = 0; i < m.brain.n_neurons(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      neurons.push_back({{"part", m.brain.neuron_part[k]},
                         {"fn", std::string(all_neuron_fns()[m.brain.fn[k]].name)},
                         {"bias", round_to(m.brain.bias[k], 1e-6)},
                         {"inputs", wires_json(m.brain.input_begin, m.brain.input_src, m.brain.input_weight,
                                               m.brain.input_gate, k)}});
    }
  } else {
    for (std::size_t i = 0; i < internals; ++i) neurons.push_back({{"part", -1}, {"fn", "controller"}});
  }
  j["neurons"] = neurons;
  json effectors = json::array();
  const std::vector<double>& hz = res.diagnostics.effector_hz;
  for (std::size_t e = 0; e < m.effectors.size(); ++e) {
    // a muscle's (lessin2015) names its muscle, a joint's its joint and dof
    const EffectorModel& em = m.effectors[e];
    const bool muscle = em.muscle >= 0;
    json ej = muscle ? json{{"muscle", em.muscle}} : json{{"joint", em.joint}, {"dof", em.dof}};
    // what drives it, as a neuron's inputs (a graph brain's)
    if (graph_brain && e < static_cast<std::size_t>(m.brain.n_effectors())) {
      ej["bias"] = round_to(m.brain.effector_bias[e], 1e-6);
      ej["inputs"] = wires_json(m.brain.effector_input_begin, m.brain.effector_input_src,
                                m.brain.effector_input_weight, m.brain.effector_input_gate, e);
    }
    // its signal's dominant frequency over the driven steps (Hz; 0: constant)
    if (e < hz.size()) ej["hz"] = round_to(hz[e], 1e-3);
    effectors.push_back(ej);
  }
  j["effectors"] = effectors;
  json sensors = json::array();
  for (const auto& s : m.sensors) sensors.push_back(sensor_json(s));
  j["sensors"] = sensors;
  // frames
  json frames = json::array();
  for (const auto& f : r.frames) {
    json poses = json::array();
    for (std::size_t i = 0; i + 6 < f.poses.size(); i += 7)
      poses.push_back({round_to(f.poses[i], 1e-5), round_to(f.poses[i + 1], 1e-5),
                       round_to(f.poses[i + 2], 1e-5), round_to(f.poses[i + 3], 1e-5),
                       round_to(f.poses[i + 4], 1e-5), round_to(f.poses[i + 5], 1e-5),
                       round_to(f.poses[i + 6], 1e-5)});
    json nv = json::array(), ev = json::array(), sv = json::array(), av = json::array();
    for (double v : f.neurons) nv.push_back(round_to(v, 1e-4));
    while (nv.size() < internals) nv.push_back(0.0);
    for (double v : f.effectors) ev.push_back(round_to(v, 1e-4));
    for (double v : f.sensors) sv.push_back(round_to(v, 1e-4));
    // joint angles: one list per joint, one value per degree of freedom
    std::size_t k = 0;
    for (const auto& jm : m.joints) {
      json dofs = json::array();
      for (int d = 0; d < joint_dofs(jm.type) && k < f.joint_angles.size(); ++d)
        dofs.push_back(round_to(f.joint_angles[k++], 1e-5));
      av.push_back(dofs);
    }
    frames.push_back({{"t", round_to(f.t, 1e-6)},
                      {"poses", poses},
                      {"com", vec_json(f.com, 1e-5)},
                      {"neurons", nv},
                      {"effectors", ev},
                      {"sensors", sv},
                      {"joint_angles", av}});
  }
  j["frames"] = frames;
  j["result"] = {{"fitness", res.fitness},   {"distance", res.distance},
                 {"failed", res.failed},     {"failure", res.failure},
                 {"seconds", res.seconds},   {"steps", res.steps},
                 {"warnings", res.warnings}};
  if (!res.trial_fitness.empty()) j["result"]["trial_fitness"] = res.trial_fitness;
  // the frames of a later trial than the first (evaluate_trial): which, from
  // 1; written only then, so every other replay reads as before
  if (res.trial > 0) j["result"]["trial"] = res.trial + 1;
  // the task's own measures by name, when it has any (an aim task's target miss, a
  // river crossing's levels); its moments are the scene record's markers
  if (!res.metrics.empty()) {
    json metrics = json::object();
    for (const Metric& mt : res.metrics) metrics[mt.name] = mt.value;
    j["result"]["metrics"] = metrics;
  }
  return json_text(j) + "\n";
}

Status save_replay(const std::string& path, const CreatureModel& m, const Replay& r,
                   const EvalResult& res, const ReplayInfo& info) {
  return write_file_atomic(path, replay_to_string(m, r, res, info));
}

}  // namespace bx
