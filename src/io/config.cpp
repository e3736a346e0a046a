#include "io/config.h"

#include <toml++/toml.h>

#include <charconv>
#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

#include "core/files.h"

namespace bx {

namespace {

// One config key: where it lives in SimConfig and what it accepts.
struct Field {
  std::string_view section;
  std::string_view key;
  enum Kind { Real, Int, Bool, Choice } kind;
  double lo, hi;                                  // inclusive range (Real, Int)
  std::vector<std::string_view> choices;          // Choice: names, by enum value
  std::function<void*(SimConfig&)> at;            // the field's address
};

template <class E>
E& as_enum(void* p) {
  return *static_cast<E*>(p);
}

const std::vector<Field>& fields() {
  constexpr double inf = 1e300;
  static const std::vector<Field> f = {
      {"physics", "dt", Field::Real, 1e-5, 1, {}, [](SimConfig& c) -> void* { return &c.physics.dt; }},
      {"physics", "gravity", Field::Real, -inf, inf, {}, [](SimConfig& c) -> void* { return &c.physics.gravity; }},
      {"physics", "erp", Field::Real, 0, 1, {}, [](SimConfig& c) -> void* { return &c.physics.erp; }},
      {"physics", "cfm", Field::Real, 0, 1, {}, [](SimConfig& c) -> void* { return &c.physics.cfm; }},
      {"physics", "friction", Field::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.physics.friction; }},
      {"physics", "solver_iterations", Field::Int, 1, 1000, {}, [](SimConfig& c) -> void* { return &c.physics.solver_iterations; }},
      {"physics", "max_contacts", Field::Int, 1, 64, {}, [](SimConfig& c) -> void* { return &c.physics.max_contacts; }},
      {"physics", "self_collision", Field::Bool, 0, 0, {}, [](SimConfig& c) -> void* { return &c.physics.self_collision; }},
      {"physics", "max_speed", Field::Real, 1e-3, inf, {}, [](SimConfig& c) -> void* { return &c.physics.max_speed; }},
      {"physics", "max_step_jump", Field::Real, 1e-6, inf, {}, [](SimConfig& c) -> void* { return &c.physics.max_step_jump; }},
      {"physics", "max_joint_gap", Field::Real, 1e-6, inf, {}, [](SimConfig& c) -> void* { return &c.physics.max_joint_gap; }},
      {"motor", "model", Field::Choice, 0, 0, {"servo", "saturation", "torque", "pd"}, [](SimConfig& c) -> void* { return &c.motor.model; }},
      {"motor", "max_speed", Field::Real, 0, inf, {}, [](SimConfig& c) -> void* { return &c.motor.max_speed; }},
      {"motor", "max_force", Field::Real, 0, inf, {}, [](SimConfig& c) -> void* { return &c.motor.max_force; }},
      {"motor", "strength", Field::Real, 0, inf, {}, [](SimConfig& c) -> void* { return &c.motor.strength; }},
      {"motor", "kp", Field::Real, 0, inf, {}, [](SimConfig& c) -> void* { return &c.motor.kp; }},
      {"motor", "kd", Field::Real, 0, inf, {}, [](SimConfig& c) -> void* { return &c.motor.kd; }},
      {"brain", "steps_per_physics_step", Field::Int, 1, 100, {}, [](SimConfig& c) -> void* { return &c.brain_steps_per_physics_step; }},
      {"develop", "max_parts", Field::Int, 0, 100000, {}, [](SimConfig& c) -> void* { return &c.develop.max_parts; }},
      {"develop", "overlap_margin", Field::Real, 0, 1, {}, [](SimConfig& c) -> void* { return &c.develop.overlap_margin; }},
      {"task", "seconds", Field::Real, 0, 1e6, {}, [](SimConfig& c) -> void* { return &c.task.seconds; }},
      {"task", "drop_height", Field::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.task.drop_height; }},
      {"task", "metric", Field::Choice, 0, 0, {"planar", "x"}, [](SimConfig& c) -> void* { return &c.task.metric; }},
      {"task", "skip_fraction", Field::Real, 0, 1, {}, [](SimConfig& c) -> void* { return &c.task.skip_fraction; }},
      {"task", "fitness", Field::Choice, 0, 0, {"distance", "speed", "chaumont2007"}, [](SimConfig& c) -> void* { return &c.task.fitness; }},
      {"task", "activation", Field::Choice, 0, 0, {"always", "chaumont2007"}, [](SimConfig& c) -> void* { return &c.task.activation; }},
      {"task", "settle_threshold", Field::Real, 0, 1e3, {}, [](SimConfig& c) -> void* { return &c.task.settle_threshold; }},
      {"task", "settle_steps", Field::Int, 1, 1000000, {}, [](SimConfig& c) -> void* { return &c.task.settle_steps; }},
      {"task", "settle_timeout", Field::Real, 0, 1e4, {}, [](SimConfig& c) -> void* { return &c.task.settle_timeout; }},
      {"task", "burst_seconds", Field::Real, 0, 1e4, {}, [](SimConfig& c) -> void* { return &c.task.burst_seconds; }},
      {"task", "kappa", Field::Real, 0, 10, {}, [](SimConfig& c) -> void* { return &c.task.kappa; }},
      {"replay", "fps", Field::Real, 1e-3, 1e4, {}, [](SimConfig& c) -> void* { return &c.replay_fps; }},
  };
  return f;
}

std::string show(const toml::node& n) {
  std::ostringstream ss;
  if (n.is_string())
    ss << '"' << *n.value<std::string>() << '"';
  else if (n.is_table())
    ss << "a table";
  else if (n.is_array())
    ss << "an array";
  else
    n.visit([&](auto&& v) { ss << v; });
  return ss.str();
}

// shortest text that reads back as the same double
std::string num(double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// sets one field from a TOML value, or says what is wrong
Status set_field(const Field& f, SimConfig& cfg, const toml::node& n, const std::string& where) {
  void* p = f.at(cfg);
  auto bad = [&](const std::string& what) { return Status(Error{where + ": " + what + ", got " + show(n)}); };
  switch (f.kind) {
    case Field::Real: {
      std::optional<double> v = n.is_integer() ? std::optional<double>(static_cast<double>(*n.value<std::int64_t>()))
                                               : n.value<double>();
      if (!n.is_number() || !v) return bad("expected a number");
      if (!std::isfinite(*v) || *v < f.lo || *v > f.hi)
        return bad("out of range [" + num(f.lo) + ", " + num(f.hi) + "]");
      *static_cast<double*>(p) = *v;
      return Ok{};
    }
    case Field::Int: {
      if (!n.is_integer()) return bad("expected an integer");
      auto v = *n.value<std::int64_t>();
      if (v < f.lo || v > f.hi) return bad("out of range [" + num(f.lo) + ", " + num(f.hi) + "]");
      *static_cast<int*>(p) = static_cast<int>(v);
      return Ok{};
    }
    case Field::Bool:
      if (!n.is_boolean()) return bad("expected true or false");
      *static_cast<bool*>(p) = *n.value<bool>();
      return Ok{};
    case Field::Choice: {
      std::string names;
      for (auto c : f.choices) names += (names.empty() ? "" : ", ") + std::string(c);
      if (!n.is_string()) return bad("expected one of " + names);
      auto s = *n.value<std::string>();
      for (std::size_t i = 0; i < f.choices.size(); ++i) {
        if (s == f.choices[i]) {
          *static_cast<int*>(p) = static_cast<int>(i);  // enums are int-sized, declared in this order
          return Ok{};
        }
      }
      return bad("expected one of " + names);
    }
  }
  return Ok{};
}

}  // namespace

Status apply_config_toml(SimConfig& cfg, std::string_view text, std::string_view source) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    return Error{std::string(source) + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
                 ": " + std::string(e.description())};
  }
  SimConfig out = cfg;  // apply all or nothing
  for (auto&& [sec_key, sec_node] : root) {
    std::string sec(sec_key.str());
    auto* table = sec_node.as_table();
    bool known = false;
    for (const auto& f : fields()) known |= f.section == sec;
    if (!known) return Error{std::string(source) + ": " + sec + ": unknown section"};
    if (!table) return Error{std::string(source) + ": " + sec + ": expected a table, got " + show(sec_node)};
    for (auto&& [key, node] : *table) {
      std::string where = std::string(source) + ": " + sec + "." + std::string(key.str());
      const Field* field = nullptr;
      for (const auto& f : fields())
        if (f.section == sec && f.key == key.str()) field = &f;
      if (!field) return Error{where + ": unknown key"};
      if (Status s = set_field(*field, out, node, where); !s) return s;
    }
  }
  cfg = out;
  return Ok{};
}

Status apply_config_file(SimConfig& cfg, const std::string& path) {
  auto text = read_file(path);
  if (!text) return Error{text.error()};
  return apply_config_toml(cfg, *text, path);
}

std::string config_to_toml(const SimConfig& cfg_in) {
  SimConfig cfg = cfg_in;
  std::ostringstream ss;
  std::string_view section;
  for (const auto& f : fields()) {
    if (f.section != section) {
      ss << (section.empty() ? "" : "\n") << "[" << f.section << "]\n";
      section = f.section;
    }
    void* p = f.at(cfg);
    ss << f.key << " = ";
    switch (f.kind) {
      case Field::Real: ss << num(*static_cast<double*>(p)); break;
      case Field::Int: ss << *static_cast<int*>(p); break;
      case Field::Bool: ss << (*static_cast<bool*>(p) ? "true" : "false"); break;
      case Field::Choice: ss << '"' << f.choices[*static_cast<int*>(p)] << '"'; break;
    }
    ss << "\n";
  }
  return ss.str();
}

}  // namespace bx
