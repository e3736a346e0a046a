// The JSON forms of the evaluator's records (eval/records_json.h).
#include "eval/records_json.h"

#include <cmath>
#include <limits>
#include <stdexcept>


namespace bx {

namespace {

using json = nlohmann::json;

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json nums(const std::vector<double>& v) {
  json a = json::array();
  for (double x : v) a.push_back(num(x));
  return a;
}

// readers that name the field they could not read
const json& field(const json& j, const char* name) {
  if (!j.contains(name)) throw std::runtime_error(std::string("no field ") + name);
  return j.at(name);
}

double read_num(const json& v, const char* name) {
  if (v.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!v.is_number()) throw std::runtime_error(std::string(name) + " is not a number");
  return v.get<double>();
}

double get_num(const json& j, const char* name) { return read_num(field(j, name), name); }

std::vector<double> get_nums(const json& j, const char* name) {
  const json& a = field(j, name);
  if (!a.is_array()) throw std::runtime_error(std::string(name) + " is not an array");
  std::vector<double> v;
  for (const json& x : a) v.push_back(read_num(x, name));
  return v;
}

template <class T>
T get(const json& j, const char* name) {
  try {
    return field(j, name).get<T>();
  } catch (const json::exception&) {
    throw std::runtime_error(std::string(name) + " has the wrong type");
  }
}

// named values (a task's metrics, its markers) as [[name, value], ...]: an
// array keeps the task's order; V is the value's member
template <auto V, class T>
json named_json(const std::vector<T>& named) {
  json a = json::array();
  for (const T& m : named) a.push_back(json::array({m.name, num(m.*V)}));
  return a;
}

template <auto V, class T>
std::vector<T> get_named(const json& j, const char* name) {
  const json& a = field(j, name);
  if (!a.is_array()) throw std::runtime_error(std::string(name) + " is not an array");
  std::vector<T> out;
  for (const json& m : a) {
    if (!m.is_array() || m.size() != 2 || !m[0].is_string())
      throw std::runtime_error(std::string(name) + " holds something other than [name, value]");
    T one;
    one.name = m[0].get<std::string>();
    one.*V = read_num(m[1], name);
    out.push_back(std::move(one));
  }
  return out;
}

}  // namespace

json job_to_json(const EvalJob& job) {
  // the seed as a number: nlohmann keeps 64-bit unsigned integers exact
  json j = {{"seed", job.seed}, {"kind", std::string(job.genotype->kind())}, {"genotype", job.genotype->to_json()}};
  if (job.step_divisor != 1) j["step_divisor"] = job.step_divisor;
  if (job.task != 0) j["task"] = job.task;
  return j;
}

Result<ReadJob> job_from_json(const json& j) {
  try {
    if (!j.is_object()) throw std::runtime_error("not a JSON object");
    const json& seed = field(j, "seed");
    if (!seed.is_number_unsigned()) throw std::runtime_error("seed is not a whole number from 0 to 2^64-1");
    ReadJob job;
    job.seed = seed.get<std::uint64_t>();
    if (j.contains("step_divisor")) {
      if (!j["step_divisor"].is_number_integer()) throw std::runtime_error("step_divisor has the wrong type");
      job.step_divisor = get<int>(j, "step_divisor");
      if (job.step_divisor != 1 && job.step_divisor != 2 && job.step_divisor != 4)
        throw std::runtime_error("step_divisor is " + std::to_string(job.step_divisor) + ", not 1, 2 or 4");
    }
    if (j.contains("task")) {
      if (!j["task"].is_number_integer() || get<int>(j, "task") < 0)
        throw std::runtime_error("task is not a task table index");
      job.task = get<int>(j, "task");
    }
    auto g = read_genotype(get<std::string>(j, "kind"), field(j, "genotype"), "job");
    if (!g) throw std::runtime_error(g.error());
    job.genotype = std::move(*g);
    return job;
  } catch (const std::exception& e) {
    return Error{std::string("evaluation job: ") + e.what()};
  }
}

json outcome_to_json(const EvalOutcome& o) {
  const EvalResult& r = o.result;
  const EvalDiagnostics& d = r.diagnostics;
  return {{"viable", o.viable},
          {"reason", o.reason},
          {"failed", r.failed},
          {"failure", r.failure},
          {"note", r.note},
          {"fitness", num(r.fitness)},
          {"distance", num(r.distance)},
          {"metrics", named_json<&Metric::value>(r.metrics)},
          {"markers", named_json<&SceneMarker::t>(r.markers)},
          {"seconds", num(r.seconds)},
          {"steps", r.steps},
          {"brain_steps", r.brain_steps},
          {"warnings", r.warnings},
          {"trial_fitness", nums(r.trial_fitness)},
          {"trial", r.trial},
          {"setup", r.setup},
          {"diagnostics",
           {{"max_joint_gap", num(d.max_joint_gap)},
            {"worst_joint", d.worst_joint},
            {"max_stop_overshoot", num(d.max_stop_overshoot)},
            {"max_penetration", num(d.max_penetration)},
            {"effector_mean", nums(d.effector_mean)},
            {"effector_sd", nums(d.effector_sd)},
            {"effector_hz", nums(d.effector_hz)}}}};
}

Result<EvalOutcome> outcome_from_json(const json& j) {
  try {
    if (!j.is_object()) throw std::runtime_error("not a JSON object");
    EvalOutcome o;
    o.viable = get<bool>(j, "viable");
    o.reason = get<std::string>(j, "reason");
    EvalResult& r = o.result;
    r.failed = get<bool>(j, "failed");
    r.failure = get<std::string>(j, "failure");
    r.note = get<std::string>(j, "note");
    r.fitness = get_num(j, "fitness");
    r.distance = get_num(j, "distance");
    r.metrics = get_named<&Metric::value, Metric>(j, "metrics");
    r.markers = get_named<&SceneMarker::t, SceneMarker>(j, "markers");
    r.seconds = get_num(j, "seconds");
    r.steps = get<long>(j, "steps");
    r.brain_steps = get<long>(j, "brain_steps");
    r.warnings = get<std::vector<std::string>>(j, "warnings");
    r.trial_fitness = get_nums(j, "trial_fitness");
    r.trial = get<int>(j, "trial");
    r.setup = get<std::string>(j, "setup");
    const json& d = field(j, "diagnostics");
    if (!d.is_object()) throw std::runtime_error("diagnostics is not an object");
    EvalDiagnostics& g = r.diagnostics;
    g.max_joint_gap = get_num(d, "max_joint_gap");
    g.worst_joint = get<int>(d, "worst_joint");
    g.max_stop_overshoot = get_num(d, "max_stop_overshoot");
    g.max_penetration = get_num(d, "max_penetration");
    g.effector_mean = get_nums(d, "effector_mean");
    g.effector_sd = get_nums(d, "effector_sd");
    g.effector_hz = get_nums(d, "effector_hz");
    return o;
  } catch (const std::exception& e) {
    return Error{std::string("evaluation outcome: ") + e.what()};
  }
}

json held_out_to_json(const HeldOut& h) {
  return json{{"id", h.id}, {"by_seed", h.by_seed}, {"fitness", h.fitness}};
}

Result<HeldOut> held_out_from_json(const json& j, const std::string& who, bool with_id) {
  HeldOut h;
  try {
    if (with_id || j.contains("id")) h.id = j.at("id").get<std::int64_t>();
    h.by_seed = j.at("by_seed").get<std::vector<double>>();
    h.fitness = j.at("fitness").get<double>();
  } catch (const json::exception&) {
    return Error{who + ": expected {" + (with_id ? "\"id\": an individual, " : "") +
                 "\"by_seed\": numbers, \"fitness\": a number}, got " + j.dump().substr(0, 60)};
  }
  if (h.by_seed.empty()) return Error{who + ".by_seed: expected at least one number"};
  return h;
}

}  // namespace bx
