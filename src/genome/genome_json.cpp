// Genome <-> JSON. Parsing checks the form (types, names, required and
// unknown fields) and maps parameters by name; validate() then checks values
// and the dialect's rules, so both paths report through the same messages.
#include "genome/genome_json.h"

#include "core/files.h"
#include "core/text.h"

#include <unistd.h>

#include <array>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <sstream>

#include "genome/dialect.h"
#include "genome/locks.h"
#include "genome/operators.h"

namespace bx {

namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

// ---------------------------------------------------------------- rendering

template <class J>
void write_scalar(const J& v, std::string& out) {
  if (v.is_number_float()) {
    double d = v.template get<double>();
    if (std::isnan(d)) return void(out += "nan");
    if (std::isinf(d)) return void(out += d > 0 ? "inf" : "-inf");
  }
  out += v.dump(-1, ' ', false, J::error_handler_t::replace);
}

template <class J>
std::string key_text(const std::string& key) {
  return J(key).dump(-1, ' ', false, J::error_handler_t::replace);
}

// one line, ", " and ": " separators; stops once `out` is longer than
// `limit`, and shows containers deeper than kMaxGenomeDepth as [...] or {...}
// (error messages quote values from any input: neither size nor depth of
// what they print may depend on it)
template <class J>
void write_compact(const J& v, std::string& out, std::size_t limit = SIZE_MAX, int depth = 0) {
  if (out.size() > limit) return;
  if (v.is_structured() && depth >= kMaxGenomeDepth) {
    out += v.is_array() ? "[...]" : "{...}";
  } else if (v.is_array()) {
    out += '[';
    bool first = true;
    for (const auto& e : v) {
      if (out.size() > limit) return;
      if (!first) out += ", ";
      first = false;
      write_compact(e, out, limit, depth + 1);
    }
    out += ']';
  } else if (v.is_object()) {
    out += '{';
    bool first = true;
    for (auto it = v.begin(); it != v.end(); ++it) {
      if (out.size() > limit) return;
      if (!first) out += ", ";
      first = false;
      out += key_text<J>(it.key()) + ": ";
      write_compact(it.value(), out, limit, depth + 1);
    }
    out += '}';
  } else {
    write_scalar(v, out);
  }
}

constexpr std::size_t kLineWidth = 100;

// 2-space indent; a container goes on one line if it fits from `column`
template <class J>
void write_pretty(const J& v, std::size_t indent, std::size_t column, std::string& out) {
  std::string flat;
  write_compact(v, flat);
  if (!v.is_structured() || v.empty() || column + flat.size() <= kLineWidth) {
    out += flat;
    return;
  }
  std::string pad(indent + 2, ' ');
  bool array = v.is_array();
  out += array ? "[\n" : "{\n";
  bool first = true;
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (!first) out += ",\n";
    first = false;
    out += pad;
    std::size_t col = pad.size();
    if (!array) {
      std::string key = key_text<J>(it.key()) + ": ";
      out += key;
      col += key.size();
    }
    write_pretty(it.value(), indent + 2, col, out);
  }
  out += '\n' + std::string(indent, ' ') + (array ? "]" : "}");
}

// ---------------------------------------------------------------- parsing

// A parse failure: thrown and caught inside this file only.
struct ParseFailure {
  std::string message;
};

[[noreturn]] void fail(const std::string& path, std::string_view what, const json& got) {
  std::string msg = path.empty() ? std::string(what) : path + ": " + std::string(what);
  throw ParseFailure{msg + ", got " + json_one_line(got, 120)};
}

// a key of the input as a path shows it: one line, at most 100 characters
// (a JSON key may hold an escaped newline, and be of any length)
std::string field_path(const std::string& path, std::string_view key) {
  std::string k = one_line(key, 100);
  return path.empty() ? k : path + "." + k;
}
std::string index_path(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

std::string join(std::initializer_list<std::string_view> names) {
  std::string s;
  for (auto n : names) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

// `j` must be an object whose fields are all among `known`
void expect_object(const json& j, const std::string& path,
                   std::initializer_list<std::string_view> known) {
  if (!j.is_object()) fail(path, "expected an object", j);
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool ok = false;
    for (auto k : known) ok = ok || k == it.key();
    if (!ok)
      fail(field_path(path, it.key()), "unknown field (expected one of " + join(known) + ")",
           it.value());
  }
}

const json* find(const json& obj, std::string_view key) {
  auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

const json& require(const json& obj, const std::string& path, std::string_view key) {
  if (const json* v = find(obj, key)) return *v;
  fail(path, "missing required field \"" + std::string(key) + "\"", obj);
}

double number(const json& v, const std::string& path) {
  if (!v.is_number()) fail(path, "expected a number", v);
  double d = v.get<double>();
  if (!std::isfinite(d)) fail(path, "expected a finite number", v);
  return d;
}

int integer(const json& v, const std::string& path) {
  if (!v.is_number_integer()) fail(path, "expected an integer", v);
  if (v.is_number_unsigned()) {
    if (v.get<std::uint64_t>() > static_cast<std::uint64_t>(INT_MAX))
      fail(path, "integer out of range", v);
  } else {
    std::int64_t i = v.get<std::int64_t>();
    if (i < INT_MIN || i > INT_MAX) fail(path, "integer out of range", v);
  }
  return v.get<int>();
}

bool boolean(const json& v, const std::string& path) {
  if (!v.is_boolean()) fail(path, "expected true or false", v);
  return v.get<bool>();
}

const std::string& str(const json& v, const std::string& path) {
  if (!v.is_string()) fail(path, "expected a string", v);
  return v.get_ref<const std::string&>();
}

const json& expect_array(const json& v, const std::string& path) {
  if (!v.is_array()) fail(path, "expected an array", v);
  return v;
}

Vec3 vec3(const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 3) fail(path, "expected an array of 3 numbers", v);
  return {number(v[0], index_path(path, 0)), number(v[1], index_path(path, 1)),
          number(v[2], index_path(path, 2))};
}

// A unit axis: zero is an error, anything else is normalized. Vectors already
// unit to 1e-12 are kept as they are, so that reading a written genome is exact.
Vec3 axis(const json& v, const std::string& path) {
  Vec3 a = vec3(v, path);
  double n = norm(a);
  if (n == 0) fail(path, "axis must be non-zero", v);
  return std::abs(n - 1) <= 1e-12 ? a : (1.0 / n) * a;
}

constexpr std::array kShapes{Shape::Box, Shape::Sphere, Shape::Capsule, Shape::Cylinder};
constexpr std::array kJoints{JointType::Fixed,     JointType::Hinge,  JointType::Universal,
                             JointType::Spherical, JointType::Slider, JointType::Cylindrical};
constexpr std::array kFaces{Face::PosX, Face::NegX, Face::PosY, Face::NegY, Face::PosZ, Face::NegZ};
constexpr std::array kPlaces{SourcePlace::Self, SourcePlace::Parent, SourcePlace::Child,
                             SourcePlace::Root, SourcePlace::Global};
constexpr std::array kSensorTypes{SensorType::JointAngle, SensorType::Contact, SensorType::Photoreceptor};
constexpr std::array kDialects{Dialect::Sims1994, Dialect::Miconi2006, Dialect::Chaumont2007,
                               Dialect::Lessin2015};
constexpr std::array<std::string_view, 3> kAxisNames{"x", "y", "z"};

// a name from `all` (spelled as to_string() spells it)
template <class E, std::size_t N>
E name_of(const json& v, const std::string& path, std::string_view kind,
          const std::array<E, N>& all) {
  const std::string& s = str(v, path);
  std::string names;
  for (E e : all) {
    if (to_string(e) == s) return e;
    names += (names.empty() ? "" : ", ") + std::string(to_string(e));
  }
  fail(path, "unknown " + std::string(kind) + " (expected one of " + names + ")", v);
}

// Reads the fields of one genome; knows the dialect's neuron set for parameter names.
class Reader {
 public:
  explicit Reader(Dialect d) : set_(dialect_rules(d).neuron_set), dialect_(d) {}

  NodeGene node(const json& j, const std::string& path) const {
    expect_object(j, path,
                  {"shape", "size", "density", "joint", "recursive_limit", "neurons", "sensors",
                   "effectors", "edges", "lock"});
    NodeGene n;
    if (const json* v = find(j, "shape"))
      n.shape = name_of(*v, field_path(path, "shape"), "shape", kShapes);
    n.size = vec3(require(j, path, "size"), field_path(path, "size"));
    if (const json* v = find(j, "density")) n.density = number(*v, field_path(path, "density"));
    if (const json* v = find(j, "joint")) n.joint = joint(*v, field_path(path, "joint"));
    if (const json* v = find(j, "recursive_limit"))
      n.recursive_limit = integer(*v, field_path(path, "recursive_limit"));
    n.neurons = list(j, path, "neurons", &Reader::neuron);
    n.sensors = list(j, path, "sensors", &Reader::sensor);
    n.effectors = list(j, path, "effectors", &Reader::effector);
    n.edges = list(j, path, "edges", &Reader::edge);
    if (const json* v = find(j, "lock")) n.lock = lock(*v, field_path(path, "lock"));
    return n;
  }

  // ["body", "joint", ...]: NodeLock bits by name (genome/locks.h)
  unsigned lock(const json& v, const std::string& path) const {
    expect_array(v, path);
    unsigned bits = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      std::string ipath = index_path(path, i);
      auto b = parse_lock(str(v[i], ipath));
      if (!b) fail(ipath, "unknown lock (expected one of body, joint, in_edges, out_edges, units)", v[i]);
      if (bits & *b) fail(ipath, "repeated lock", v[i]);
      bits |= *b;
    }
    return bits;
  }

  NeuronGene neuron(const json& j, const std::string& path) const {
    expect_object(j, path, {"fn", "bias", "params", "inputs", "group", "skill", "locked"});
    NeuronGene n;
    if (const json* v = find(j, "skill")) n.skill = str(*v, field_path(path, "skill"));
    if (const json* v = find(j, "locked")) n.locked = boolean(*v, field_path(path, "locked"));
    // a pandemonium group (validate() checks which neurons may have one)
    if (const json* v = find(j, "group")) n.group = integer(*v, field_path(path, "group"));
    std::string fn_path = field_path(path, "fn");
    const json& fn = require(j, path, "fn");
    n.fn = str(fn, fn_path);
    const NeuronFnSpec* spec = find_neuron_fn(set_, n.fn);
    if (!spec) {
      std::string names;
      for (auto s : neuron_fn_names(set_)) names += (names.empty() ? "" : ", ") + std::string(s);
      fail(fn_path,
           "unknown function for dialect " + std::string(to_string(dialect_)) +
               " (expected one of " + names + ")",
           fn);
    }
    if (const json* v = find(j, "bias")) n.bias = number(*v, field_path(path, "bias"));
    // parameters by name; missing ones take their defaults
    for (const ParamSpec& p : spec->params) n.params.push_back(p.default_value);
    if (const json* ps = find(j, "params")) {
      std::string ppath = field_path(path, "params");
      if (!ps->is_object()) fail(ppath, "expected an object of parameters by name", *ps);
      for (auto it = ps->begin(); it != ps->end(); ++it) {
        std::string vpath = field_path(ppath, it.key());
        std::size_t k = 0;
        while (k < spec->params.size() && spec->params[k].name != it.key()) ++k;
        if (k == spec->params.size()) {
          std::string names;
          for (const ParamSpec& p : spec->params)
            names += (names.empty() ? "" : ", ") + std::string(p.name);
          fail(vpath,
               "unknown parameter of " + n.fn +
                   (names.empty() ? " (it has none)" : " (expected one of " + names + ")"),
               it.value());
        }
        n.params[k] =
            spec->params[k].integer ? integer(it.value(), vpath) : number(it.value(), vpath);
      }
    }
    n.inputs = list(j, path, "inputs", &Reader::source);
    return n;
  }

  // {"projectile": int, "release": {"delay_steps": int, "inputs": [source...]}}
  CatapultGene catapult(const json& j, const std::string& path) const {
    expect_object(j, path, {"projectile", "release"});
    CatapultGene c;
    c.projectile = integer(require(j, path, "projectile"), field_path(path, "projectile"));
    if (const json* v = find(j, "release")) {
      std::string rpath = field_path(path, "release");
      expect_object(*v, rpath, {"delay_steps", "inputs"});
      if (const json* d = find(*v, "delay_steps"))
        c.release.delay_steps = integer(*d, field_path(rpath, "delay_steps"));
      c.release.inputs = list(*v, rpath, "inputs", &Reader::source);
    }
    return c;
  }

 private:
  template <class T>
  std::vector<T> list(const json& obj, const std::string& path, std::string_view key,
                      T (Reader::*read)(const json&, const std::string&) const) const {
    std::vector<T> out;
    const json* v = find(obj, key);
    if (!v) return out;
    std::string lpath = field_path(path, key);
    expect_array(*v, lpath);
    for (std::size_t i = 0; i < v->size(); ++i)
      out.push_back((this->*read)((*v)[i], index_path(lpath, i)));
    return out;
  }

  JointGene joint(const json& j, const std::string& path) const {
    expect_object(j, path, {"type", "axis1", "axis2", "limits"});
    JointGene g;
    if (const json* v = find(j, "type"))
      g.type = name_of(*v, field_path(path, "type"), "joint type", kJoints);
    if (const json* v = find(j, "axis1")) g.axis1 = axis(*v, field_path(path, "axis1"));
    if (const json* v = find(j, "axis2")) g.axis2 = axis(*v, field_path(path, "axis2"));
    if (const json* v = find(j, "limits")) {
      std::string lpath = field_path(path, "limits");
      expect_array(*v, lpath);
      for (std::size_t i = 0; i < v->size(); ++i) {
        const json& l = (*v)[i];
        std::string ipath = index_path(lpath, i);
        if (!l.is_array() || l.size() != 2) fail(ipath, "expected [lo, hi]", l);
        g.limits.push_back(
            {number(l[0], index_path(ipath, 0)), number(l[1], index_path(ipath, 1))});
      }
    }
    return g;
  }

  InputGene source(const json& j, const std::string& path) const {
    expect_object(j, path, {"from", "neuron", "sensor", "muscle", "edge", "weight", "gate"});
    InputGene in;
    in.place = name_of(require(j, path, "from"), field_path(path, "from"), "source place", kPlaces);
    const json* neuron = find(j, "neuron");
    const json* sensor = find(j, "sensor");
    const json* muscle = find(j, "muscle");
    if ((neuron != nullptr) + (sensor != nullptr) + (muscle != nullptr) != 1)
      fail(path, "a source names exactly one of \"neuron\", \"sensor\" and \"muscle\"", j);
    in.kind = neuron ? SourceKind::Neuron : sensor ? SourceKind::Sensor : SourceKind::Muscle;
    const char* key = neuron ? "neuron" : sensor ? "sensor" : "muscle";
    in.index = integer(neuron ? *neuron : sensor ? *sensor : *muscle, field_path(path, key));
    const json* edge = find(j, "edge");
    if (in.place == SourcePlace::Child) {
      in.edge = integer(require(j, path, "edge"), field_path(path, "edge"));
    } else if (edge) {
      fail(field_path(path, "edge"), "only \"child\" sources take an edge", *edge);
    }
    if (const json* v = find(j, "weight")) in.weight = number(*v, field_path(path, "weight"));
    // a skill's switch (validate() checks that it is one)
    if (const json* v = find(j, "gate")) in.gate = integer(*v, field_path(path, "gate"));
    return in;
  }

  SensorGene sensor(const json& j, const std::string& path) const {
    expect_object(j, path, {"type", "dof", "face", "direction", "locked"});
    SensorGene s;
    if (const json* v = find(j, "locked")) s.locked = boolean(*v, field_path(path, "locked"));
    s.type =
        name_of(require(j, path, "type"), field_path(path, "type"), "sensor type", kSensorTypes);
    const json* dof = find(j, "dof");
    const json* face = find(j, "face");
    const json* direction = find(j, "direction");
    if (dof && s.type != SensorType::JointAngle)
      fail(field_path(path, "dof"), "only joint_angle sensors have a dof", *dof);
    if (face && s.type != SensorType::Contact)
      fail(field_path(path, "face"), "only contact sensors have a face", *face);
    if (direction && s.type != SensorType::Photoreceptor)
      fail(field_path(path, "direction"), "only photoreceptors have a direction", *direction);
    if (dof) s.dof = integer(*dof, field_path(path, "dof"));
    if (face) s.face = name_of(*face, field_path(path, "face"), "face", kFaces);
    if (s.type == SensorType::Photoreceptor)
      s.direction = vec3(require(j, path, "direction"), field_path(path, "direction"));
    return s;
  }

  EffectorGene effector(const json& j, const std::string& path) const {
    expect_object(j, path, {"dof", "muscle", "bias", "inputs", "locked"});
    EffectorGene e;
    if (const json* v = find(j, "locked")) e.locked = boolean(*v, field_path(path, "locked"));
    if (const json* v = find(j, "dof")) e.dof = integer(*v, field_path(path, "dof"));
    if (const json* v = find(j, "muscle")) e.muscle = muscle(*v, field_path(path, "muscle"));
    if (const json* v = find(j, "bias")) e.bias = number(*v, field_path(path, "bias"));
    e.inputs = list(j, path, "inputs", &Reader::source);
    return e;
  }

  MuscleGene muscle(const json& j, const std::string& path) const {
    expect_object(j, path, {"parent_dir", "child_dir", "strength"});
    MuscleGene m;
    m.parent_dir = vec3(require(j, path, "parent_dir"), field_path(path, "parent_dir"));
    m.child_dir = vec3(require(j, path, "child_dir"), field_path(path, "child_dir"));
    m.strength = number(require(j, path, "strength"), field_path(path, "strength"));
    return m;
  }

  EdgeGene edge(const json& j, const std::string& path) const {
    expect_object(j, path, {"to", "face", "at", "rotation", "scale", "reflect", "terminal_only"});
    EdgeGene e;
    e.to = integer(require(j, path, "to"), field_path(path, "to"));
    if (const json* v = find(j, "face"))
      e.face = name_of(*v, field_path(path, "face"), "face", kFaces);
    if (const json* v = find(j, "at")) {
      std::string apath = field_path(path, "at");
      if (!v->is_array() || v->size() != 2) fail(apath, "expected [u, v]", *v);
      e.u = number((*v)[0], index_path(apath, 0));
      e.v = number((*v)[1], index_path(apath, 1));
    }
    if (const json* v = find(j, "rotation")) e.rotation = vec3(*v, field_path(path, "rotation"));
    if (const json* v = find(j, "scale")) e.scale = number(*v, field_path(path, "scale"));
    if (const json* v = find(j, "reflect")) {
      std::string rpath = field_path(path, "reflect");
      expect_array(*v, rpath);
      for (std::size_t i = 0; i < v->size(); ++i) {
        std::string ipath = index_path(rpath, i);
        const std::string& s = str((*v)[i], ipath);
        int a = 0;
        while (a < 3 && kAxisNames[a] != s) ++a;
        if (a == 3) fail(ipath, "unknown axis (expected one of x, y, z)", (*v)[i]);
        e.reflect.push_back(a);
      }
    }
    if (const json* v = find(j, "terminal_only"))
      e.terminal_only = boolean(*v, field_path(path, "terminal_only"));
    return e;
  }

  NeuronSetId set_;
  Dialect dialect_;
};

Genome parse_genome(const json& j) {
  if (!j.is_object()) fail("", "expected a genome object", j);
  // format and version first: a newer file may have fields this build does not know
  const json& format = require(j, "", "format");
  if (!format.is_string() || format.get<std::string>() != kGenomeFormat)
    fail("format", "not a genome file (expected \"" + std::string(kGenomeFormat) + "\")", format);
  const json& version = require(j, "", "version");
  int ver = integer(version, "version");
  if (ver != kGenomeVersion)
    fail("version",
         "unsupported version " + std::to_string(ver) + " (this build reads " +
             std::to_string(kGenomeVersion) + ")",
         version);
  // "provenance": where a genome file came from (`bestiary best --out`); read
  // by the command line, not part of the genome
  expect_object(j, "", {"format", "version", "dialect", "nodes", "global_neurons", "catapult", "provenance"});
  if (const json* v = find(j, "provenance"); v && !v->is_object()) fail("provenance", "expected an object", *v);

  Genome g;
  g.dialect = name_of(require(j, "", "dialect"), "dialect", "dialect", kDialects);
  Reader r(g.dialect);
  const json& nodes = expect_array(require(j, "", "nodes"), "nodes");
  for (std::size_t i = 0; i < nodes.size(); ++i)
    g.nodes.push_back(r.node(nodes[i], index_path("nodes", i)));
  if (const json* v = find(j, "global_neurons")) {
    expect_array(*v, "global_neurons");
    for (std::size_t i = 0; i < v->size(); ++i)
      g.global_neurons.push_back(r.neuron((*v)[i], index_path("global_neurons", i)));
  }
  if (const json* v = find(j, "catapult")) g.catapult = r.catapult(*v, "catapult");
  // a catapult written before locks existed: its mechanism gets the locks
  // random_catapult() gives it (operators.h), the projectile's size fixed
  if (is_catapult(g) && g.nodes[0].lock == 0 && g.nodes[g.catapult->projectile].lock == 0) {
    g.nodes[0].lock = kLockInEdges;
    g.nodes[g.catapult->projectile].lock = catapult_projectile_lock(false);
  }
  return g;
}

// Builds the JSON value from the parser's events (nlohmann's SAX interface),
// refusing what a genome file must not have: a key given twice in one object
// (JSON would keep the last) and nesting deeper than kMaxGenomeDepth. Each
// event costs O(log keys): nlohmann's callback parser, used before, scanned
// the whole parent array at every object's end (quadratic in its length).
class StrictBuilder {
 public:
  using number_integer_t = json::number_integer_t;
  using number_unsigned_t = json::number_unsigned_t;
  using number_float_t = json::number_float_t;
  using string_t = json::string_t;
  using binary_t = json::binary_t;

  json root;
  std::string error;          // our refusal (path and what), empty if none
  std::size_t error_byte = 0; // parser errors: where the parser stopped
  int error_id = 0;           // parser errors: nlohmann's exception id
  std::string parser_error;   // parser errors: nlohmann's message

  bool null() { return value(nullptr); }
  bool boolean(bool v) { return value(v); }
  bool number_integer(number_integer_t v) { return value(v); }
  bool number_unsigned(number_unsigned_t v) { return value(v); }
  bool number_float(number_float_t v, const string_t&) { return value(v); }
  bool string(string_t& v) { return value(std::move(v)); }
  bool binary(binary_t& v) { return value(json::binary(std::move(v))); }

  bool start_object(std::size_t) { return open(json::object()); }
  bool start_array(std::size_t) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(string_t& k) {
    Frame& f = stack_.back();
    f.key = std::move(k);
    if (f.value->contains(f.key)) {
      error = path() + ": field given twice";
      return false;
    }
    return true;
  }

  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
    error_byte = position;
    error_id = e.id;
    parser_error = e.what();
    return false;
  }

 private:
  struct Frame {
    json* value;      // the array or object being filled
    std::string key;  // objects: the key of the value being read
  };

  // the slot the next value goes into
  json* slot() {
    if (stack_.empty()) return &root;
    Frame& f = stack_.back();
    if (f.value->is_array()) {
      f.value->push_back(nullptr);
      return &f.value->back();
    }
    return &(*f.value)[f.key];
  }

  bool value(json v) {
    *slot() = std::move(v);
    return true;
  }

  bool open(json container) {
    json* at = slot();
    if (static_cast<int>(stack_.size()) >= kMaxGenomeDepth) {
      error = path() + ": nested deeper than " + std::to_string(kMaxGenomeDepth) +
              " levels of arrays and objects (a genome needs 6)";
      return false;
    }
    *at = std::move(container);
    stack_.push_back({at, {}});
    return true;
  }

  bool close() {
    stack_.pop_back();
    return true;
  }

  // the path of the value being read: nodes[1].effectors[0].dof
  std::string path() const {
    std::string p;
    for (const Frame& f : stack_)
      p = f.value->is_object() ? field_path(p, f.key)
                               : index_path(p, f.value->empty() ? 0 : f.value->size() - 1);
    return p;
  }

  std::vector<Frame> stack_;
};

std::string with_source(std::string_view source, const std::string& message) {
  return source.empty() ? message : std::string(source) + ": " + message;
}

// ---------------------------------------------------------------- writing

template <class J>
J vec_json(Vec3 v) {
  return J::array({v.x, v.y, v.z});
}

template <class J>
J source_json(const InputGene& in) {
  J o = J::object();
  o["from"] = std::string(to_string(in.place));
  if (in.place == SourcePlace::Child) o["edge"] = in.edge;
  o[in.kind == SourceKind::Neuron ? "neuron" : in.kind == SourceKind::Sensor ? "sensor" : "muscle"] = in.index;
  o["weight"] = in.weight;
  // written only when set, so a genome without switches reads as before them
  if (in.gate != InputGene::kNoGate) o["gate"] = in.gate;
  return o;
}

template <class J>
J inputs_json(const std::vector<InputGene>& inputs) {
  J a = J::array();
  for (const InputGene& in : inputs) a.push_back(source_json<J>(in));
  return a;
}

template <class J>
J neuron_json(const NeuronGene& n, NeuronSetId set) {
  J o = J::object();
  o["fn"] = n.fn;
  o["bias"] = n.bias;
  // parameters by name (by position if the function is unknown: an invalid genome)
  const NeuronFnSpec* spec = find_neuron_fn(set, n.fn);
  J ps = J::object();
  for (std::size_t k = 0; k < n.params.size(); ++k) {
    bool named = spec && k < spec->params.size();
    std::string name = named ? std::string(spec->params[k].name) : std::to_string(k);
    double v = n.params[k];
    if (named && spec->params[k].integer && v == std::floor(v) && std::abs(v) < 1e15)
      ps[name] = static_cast<std::int64_t>(v);
    else
      ps[name] = v;
  }
  o["params"] = ps;
  o["inputs"] = inputs_json<J>(n.inputs);
  // written only when set, so a genome without groups reads as it did before them
  if (n.group != NeuronGene::kNoGroup) o["group"] = n.group;
  if (!n.skill.empty()) o["skill"] = n.skill;
  if (n.locked) o["locked"] = true;
  return o;
}

template <class J>
J node_json(const NodeGene& n, NeuronSetId set) {
  J o = J::object();
  o["shape"] = std::string(to_string(n.shape));
  o["size"] = vec_json<J>(n.size);
  o["density"] = n.density;
  J joint = J::object();
  joint["type"] = std::string(to_string(n.joint.type));
  joint["axis1"] = vec_json<J>(n.joint.axis1);
  joint["axis2"] = vec_json<J>(n.joint.axis2);
  J limits = J::array();
  for (const Limit& l : n.joint.limits) limits.push_back(J::array({l.lo, l.hi}));
  joint["limits"] = limits;
  o["joint"] = joint;
  o["recursive_limit"] = n.recursive_limit;
  J neurons = J::array();
  for (const NeuronGene& nr : n.neurons) neurons.push_back(neuron_json<J>(nr, set));
  o["neurons"] = neurons;
  J sensors = J::array();
  for (const SensorGene& s : n.sensors) {
    J so = J::object();
    so["type"] = std::string(to_string(s.type));
    if (s.type == SensorType::JointAngle)
      so["dof"] = s.dof;
    else if (s.type == SensorType::Photoreceptor)
      so["direction"] = vec_json<J>(s.direction);
    else
      so["face"] = std::string(to_string(s.face));
    if (s.locked) so["locked"] = true;
    sensors.push_back(so);
  }
  o["sensors"] = sensors;
  J effectors = J::array();
  for (const EffectorGene& e : n.effectors) {
    J eo = J::object();
    if (e.muscle) {
      J mo = J::object();
      mo["parent_dir"] = vec_json<J>(e.muscle->parent_dir);
      mo["child_dir"] = vec_json<J>(e.muscle->child_dir);
      mo["strength"] = e.muscle->strength;
      eo["muscle"] = mo;
    } else {
      eo["dof"] = e.dof;
    }
    eo["bias"] = e.bias;
    eo["inputs"] = inputs_json<J>(e.inputs);
    if (e.locked) eo["locked"] = true;
    effectors.push_back(eo);
  }
  o["effectors"] = effectors;
  J edges = J::array();
  for (const EdgeGene& e : n.edges) {
    J eo = J::object();
    eo["to"] = e.to;
    eo["face"] = std::string(to_string(e.face));
    eo["at"] = J::array({e.u, e.v});
    eo["rotation"] = vec_json<J>(e.rotation);
    eo["scale"] = e.scale;
    J reflect = J::array();
    for (int a : e.reflect) {
      if (a >= 0 && a < 3)
        reflect.push_back(std::string(kAxisNames[a]));
      else
        reflect.push_back(a);
    }
    eo["reflect"] = reflect;
    eo["terminal_only"] = e.terminal_only;
    edges.push_back(eo);
  }
  o["edges"] = edges;
  if (n.lock != 0) {
    J lock = J::array();
    for (const std::string& name : lock_names(n.lock)) lock.push_back(name);
    o["lock"] = lock;
  }
  return o;
}

template <class J>
J genome_json(const Genome& g) {
  NeuronSetId set = dialect_rules(g.dialect).neuron_set;
  J o = J::object();
  o["format"] = std::string(kGenomeFormat);
  o["version"] = kGenomeVersion;
  o["dialect"] = std::string(to_string(g.dialect));
  J nodes = J::array();
  for (const NodeGene& n : g.nodes) nodes.push_back(node_json<J>(n, set));
  o["nodes"] = nodes;
  J globals = J::array();
  for (const NeuronGene& n : g.global_neurons) globals.push_back(neuron_json<J>(n, set));
  o["global_neurons"] = globals;
  // catapults only (chaumont2007 section 4)
  if (g.catapult) {
    J release = J::object();
    release["delay_steps"] = g.catapult->release.delay_steps;
    release["inputs"] = inputs_json<J>(g.catapult->release.inputs);
    J c = J::object();
    c["projectile"] = g.catapult->projectile;
    c["release"] = release;
    o["catapult"] = c;
  }
  return o;
}

}  // namespace

std::string json_one_line(const nlohmann::json& v, std::size_t max_chars) {
  std::string out;
  write_compact(v, out, max_chars > 0 ? max_chars : SIZE_MAX);
  if (max_chars > 3 && out.size() > max_chars) out = out.substr(0, max_chars - 3) + "...";
  return out;
}

Result<Genome> genome_from_json(const nlohmann::json& j, std::string_view source) {
  Genome g;
  try {
    g = parse_genome(j);
  } catch (const ParseFailure& f) {
    return Error{with_source(source, f.message)};
  }
  if (Status s = validate(g); !s) return Error{with_source(source, s.error())};
  return g;
}

Result<nlohmann::json> strict_json_from_string(std::string_view text, std::string_view source) {
  if (text.size() > kMaxGenomeBytes)
    return Error{with_source(source, "too large for a genome: " + std::to_string(text.size()) +
                                         " bytes, above " + std::to_string(kMaxGenomeBytes))};
  StrictBuilder b;
  if (!json::sax_parse(text.begin(), text.end(), &b)) {
    if (!b.error.empty()) return Error{with_source(source, b.error)};
    // "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..."
    std::string what = b.parser_error;
    if (auto p = what.find("] "); p != std::string::npos) what = what.substr(p + 2);
    if (b.error_id < 101 || b.error_id > 199)  // e.g. out_of_range 406: a number too large
      return Error{with_source(source, "invalid JSON: " + what)};
    std::string where = "byte " + std::to_string(b.error_byte);
    int line = 0, column = 0, used = 0;
    if (std::sscanf(what.c_str(), "parse error at line %d, column %d: %n", &line, &column, &used) ==
            2 &&
        used > 0) {
      where = "line " + std::to_string(line) + ", column " + std::to_string(column) + " (" + where +
              ")";
      what = what.substr(static_cast<std::size_t>(used));
    }
    return Error{with_source(source, where + ": invalid JSON: " + what)};
  }
  return std::move(b.root);
}

Result<Genome> genome_from_string(std::string_view text, std::string_view source) {
  auto j = strict_json_from_string(text, source);
  if (!j) return Error{j.error()};
  return genome_from_json(*j, source);
}

Result<Genome> load_genome(const std::string& path) {
  auto text = read_file(path);
  if (!text) return Error{text.error()};
  return genome_from_string(*text, path);
}

nlohmann::json genome_to_json(const Genome& g) { return genome_json<json>(g); }

std::string genome_to_string(const Genome& g) {
  std::string out;
  write_pretty(genome_json<ordered_json>(g), 0, 0, out);
  out += '\n';
  return out;
}

Status save_genome(const std::string& path, const Genome& g) {
  return write_file_atomic(path, genome_to_string(g));
}

}  // namespace bx
