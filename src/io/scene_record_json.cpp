#include "io/scene_record_json.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <type_traits>

#include "core/text.h"
#include "io/rounding.h"

namespace bx {

namespace {

using nlohmann::json;

json vec_json(Vec3 v) { return json::array({round_to(v.x, 1e-6), round_to(v.y, 1e-6), round_to(v.z, 1e-6)}); }

// a pose as a replay's frames hold one: [x, y, z, qw, qx, qy, qz]
json pose_json(const Pose& p) {
  const Quat q = to_quat(p.R);
  json a = vec_json(p.p);
  for (double v : {q.w, q.x, q.y, q.z}) a.push_back(round_to(v, 1e-6));
  return a;
}

// one event's payload, under its type's name
json event_json(const SceneEvent& e) {
  json j = {{"t", round_to(e.t, 1e-6)}};
  std::visit(
      [&](const auto& w) {
        using W = std::decay_t<decltype(w)>;
        if constexpr (std::is_same_v<W, SceneGrid>) {
          j["grid"] = {{"origin", vec_json(w.origin)}, {"cell", round_to(w.cell, 1e-6)},
                       {"width", w.width},         {"height", w.height},
                       {"cells", w.cells}};
        } else if constexpr (std::is_same_v<W, SceneCell>) {
          j["cell"] = {{"x", w.x}, {"y", w.y}, {"kind", w.kind}};
        } else if constexpr (std::is_same_v<W, SceneCarry>) {
          j["carry"] = {{"part", w.part}, {"kind", w.kind}};
        } else if constexpr (std::is_same_v<W, SceneField>) {
          json values = json::array();
          for (double v : w.values) values.push_back(round_to(v, 1e-3));
          j["field"] = {{"name", w.name},
                        {"width", w.width},
                        {"height", w.height},
                        {"range", {round_to(w.lo, 1e-6), round_to(w.hi, 1e-6)}},
                        {"values", values}};
        } else {
          j["counter"] = {{"name", w.name}, {"value", w.value}};
          if (!w.unit.empty()) j["counter"]["unit"] = w.unit;
        }
      },
      e.what);
  return j;
}

// ---- reading: each check names the field's path ----

struct Bad : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void fail(const std::string& path, const std::string& what, const json& got) {
  std::string shown = got.dump();
  if (shown.size() > 60) shown = shown.substr(0, 57) + "...";
  throw Bad(path + ": " + what + ", got " + shown);
}

const json& at(const json& j, const std::string& path, const char* key) {
  if (!j.contains(key)) throw Bad(path + "." + key + ": missing");
  return j.at(key);
}

const json& object(const json& j, const std::string& path) {
  if (!j.is_object()) fail(path, "expected an object", j);
  return j;
}

// a list that may be left out: empty then
const json& list(const json& j, const std::string& path, const char* key) {
  static const json empty = json::array();
  if (!j.contains(key)) return empty;
  const json& a = j.at(key);
  if (!a.is_array()) fail(path + "." + key, "expected an array", a);
  return a;
}

double number(const json& j, const std::string& path, const char* key) {
  const json& v = at(j, path, key);
  if (!v.is_number() || !std::isfinite(v.get<double>())) fail(path + "." + key, "expected a number", v);
  return v.get<double>();
}

int integer(const json& j, const std::string& path, const char* key, int lo, int hi, const std::string& range) {
  const json& v = at(j, path, key);
  if (!v.is_number_integer()) fail(path + "." + key, "expected an integer", v);
  const long long n = v.get<long long>();
  if (n < lo || n > hi) fail(path + "." + key, range, v);
  return static_cast<int>(n);
}

std::string text(const json& j, const std::string& path, const char* key) {
  const json& v = at(j, path, key);
  if (!v.is_string()) fail(path + "." + key, "expected a string", v);
  return v.get<std::string>();
}

std::string color(const json& j, const std::string& path, const char* key) {
  const std::string c = text(j, path, key);
  bool ok = c.size() == 7 && c[0] == '#';
  for (std::size_t i = 1; ok && i < c.size(); ++i) ok = std::isxdigit(static_cast<unsigned char>(c[i])) != 0;
  if (!ok) fail(path + "." + key, "expected \"#rrggbb\"", c);
  return c;
}

Vec3 vec(const json& j, const std::string& path, const char* key) {
  const json& v = at(j, path, key);
  if (!v.is_array() || v.size() != 3) fail(path + "." + key, "expected 3 numbers", v);
  Vec3 out;
  double* xyz[3] = {&out.x, &out.y, &out.z};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!v[i].is_number()) fail(path + "." + key, "expected 3 numbers", v);
    *xyz[i] = v[i].get<double>();
  }
  return out;
}

// a pose as pose_json writes it; its quaternion of unit length, but for the
// file's rounding (or a hand-written one's)
Pose pose(const json& j, const std::string& path, const char* key) {
  const json& v = at(j, path, key);
  const char* what = "expected [x, y, z, qw, qx, qy, qz] with a unit quaternion";
  if (!v.is_array() || v.size() != 7) fail(path + "." + key, what, v);
  double x[7];
  for (std::size_t i = 0; i < 7; ++i) {
    if (!v[i].is_number()) fail(path + "." + key, what, v);
    x[i] = v[i].get<double>();
  }
  const double n = std::sqrt(x[3] * x[3] + x[4] * x[4] + x[5] * x[5] + x[6] * x[6]);
  if (!(std::abs(n - 1) <= 1e-3)) fail(path + "." + key, what, v);
  return {{x[0], x[1], x[2]}, from_quat({x[3], x[4], x[5], x[6]})};
}

const char* const kShapes[] = {"box", "sphere", "capsule", "cylinder"};
constexpr int kMaxCells = 1 << 20;
const char* const kEventTypes[] = {"grid", "cell", "carry", "field", "counter"};

// what the events have said so far, to check the next one against
struct Seen {
  double t = -INFINITY;
  int width = 0, height = 0;  // the current grid's, 0 before the first
};

SceneEvent read_event(const json& e, const std::string& path, int kinds, Seen& seen) {
  object(e, path);
  SceneEvent out;
  out.t = number(e, path, "t");
  if (out.t < seen.t) fail(path + ".t", "expected a time >= " + g_number(seen.t), e["t"]);
  seen.t = out.t;
  const char* type = nullptr;
  for (const char* k : kEventTypes)
    if (e.contains(k)) {
      if (type) throw Bad(path + ": expected one of grid, cell, carry, field, counter, got both " + type + " and " + k);
      type = k;
    }
  if (!type) fail(path, "expected one of grid, cell, carry, field, counter", e);
  const std::string at_ = path + "." + type;
  const json& w = object(e[type], at_);
  const std::string kind_range = "no such cell kind (the record has " + std::to_string(kinds) + ")";
  if (std::string(type) == "grid") {
    SceneGrid g;
    g.origin = vec(w, at_, "origin");
    g.cell = number(w, at_, "cell");
    if (!(g.cell > 0)) fail(at_ + ".cell", "expected a width > 0", w["cell"]);
    g.width = integer(w, at_, "width", 1, kMaxCells, "expected a count from 1");
    g.height = integer(w, at_, "height", 1, kMaxCells / g.width, "expected a count from 1");
    const json& cells = at(w, at_, "cells");
    if (!cells.is_array() || cells.size() != static_cast<std::size_t>(g.width) * g.height)
      fail(at_ + ".cells", "expected " + std::to_string(g.width * g.height) + " cell kinds", cells.is_array() ? json(cells.size()) : cells);
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (!cells[k].is_number_integer() || cells[k].get<long long>() < 0 || cells[k].get<long long>() >= kinds)
        fail(at_ + ".cells[" + std::to_string(k) + "]", kind_range, cells[k]);
      g.cells.push_back(cells[k].get<int>());
    }
    seen.width = g.width;
    seen.height = g.height;
    out.what = std::move(g);
  } else if (std::string(type) == "cell") {
    if (seen.width == 0) throw Bad(at_ + ": a cell changed before any grid was laid");
    SceneCell c;
    c.x = integer(w, at_, "x", 0, seen.width - 1, "outside the grid's " + std::to_string(seen.width) + " columns");
    c.y = integer(w, at_, "y", 0, seen.height - 1, "outside the grid's " + std::to_string(seen.height) + " rows");
    c.kind = integer(w, at_, "kind", 0, kinds - 1, kind_range);
    out.what = c;
  } else if (std::string(type) == "carry") {
    SceneCarry c;
    c.part = integer(w, at_, "part", 0, kMaxCells, "expected a part index >= 0");
    c.kind = integer(w, at_, "kind", -1, kinds - 1, kind_range + " or -1 for nothing");
    out.what = c;
  } else if (std::string(type) == "field") {
    SceneField f;
    f.name = text(w, at_, "name");
    f.width = integer(w, at_, "width", 1, kMaxCells, "expected a count from 1");
    f.height = integer(w, at_, "height", 1, kMaxCells / f.width, "expected a count from 1");
    const json& range = at(w, at_, "range");
    if (!range.is_array() || range.size() != 2 || !range[0].is_number() || !range[1].is_number() ||
        !(range[0].get<double>() < range[1].get<double>()))
      fail(at_ + ".range", "expected [lo, hi] with lo < hi", range);
    f.lo = range[0].get<double>();
    f.hi = range[1].get<double>();
    const json& values = at(w, at_, "values");
    if (!values.is_array() || values.size() != static_cast<std::size_t>(f.width) * f.height)
      fail(at_ + ".values", "expected " + std::to_string(f.width * f.height) + " numbers", values.is_array() ? json(values.size()) : values);
    for (std::size_t k = 0; k < values.size(); ++k) {
      if (!values[k].is_number()) fail(at_ + ".values[" + std::to_string(k) + "]", "expected a number", values[k]);
      f.values.push_back(values[k].get<double>());
    }
    out.what = std::move(f);
  } else {
    SceneCounter c;
    c.name = text(w, at_, "name");
    c.value = number(w, at_, "value");
    if (w.contains("unit")) c.unit = text(w, at_, "unit");
    out.what = std::move(c);
  }
  return out;
}

}  // namespace

json scene_record_to_json(const SceneRecord& r) {
  json j = json::object();
  if (!r.markers.empty()) {
    json a = json::array();
    for (const SceneMarker& m : r.markers) a.push_back({{"name", m.name}, {"t", round_to(m.t, 1e-6)}});
    j["markers"] = a;
  }
  if (!r.points.empty()) {
    json a = json::array();
    for (const ScenePoint& p : r.points)
      a.push_back({{"name", p.name}, {"p", vec_json(p.p)}, {"size", round_to(p.size, 1e-6)}, {"color", p.color}});
    j["points"] = a;
  }
  if (!r.props.empty()) {
    json a = json::array();
    for (const SceneProp& p : r.props)
      a.push_back({{"name", p.name},
                   {"shape", p.shape},
                   {"size", vec_json(p.size)},
                   {"pose", pose_json(p.pose)},
                   {"spin", round_to(p.spin, 1e-6)},
                   {"t", round_to(p.t, 1e-6)},
                   {"color", p.color}});
    j["props"] = a;
  }
  if (!r.parts.empty()) {
    json a = json::array();
    for (const ScenePart& p : r.parts) {
      json o{{"name", p.name}, {"part", p.part}, {"color", p.color}};
      if (p.scored) o["scored"] = true;  // written only when set: older replays read the same
      a.push_back(std::move(o));
    }
    j["parts"] = a;
  }
  if (!r.cell_kinds.empty()) {
    json a = json::array();
    for (const SceneCellKind& k : r.cell_kinds) a.push_back({{"name", k.name}, {"color", k.color}, {"item", k.item}});
    j["cell_kinds"] = a;
  }
  if (!r.events.empty()) {
    json a = json::array();
    for (const SceneEvent& e : r.events) a.push_back(event_json(e));
    j["events"] = a;
  }
  return j;
}

Result<SceneRecord> scene_record_from_json(const json& j, const std::string& path) {
  try {
    object(j, path);
    SceneRecord r;
    const json& markers = list(j, path, "markers");
    for (std::size_t i = 0; i < markers.size(); ++i) {
      const std::string at_ = path + ".markers[" + std::to_string(i) + "]";
      object(markers[i], at_);
      r.markers.push_back({text(markers[i], at_, "name"), number(markers[i], at_, "t")});
    }
    const json& points = list(j, path, "points");
    for (std::size_t i = 0; i < points.size(); ++i) {
      const std::string at_ = path + ".points[" + std::to_string(i) + "]";
      object(points[i], at_);
      ScenePoint p{text(points[i], at_, "name"), vec(points[i], at_, "p"), number(points[i], at_, "size"),
                   color(points[i], at_, "color")};
      if (!(p.size > 0)) fail(at_ + ".size", "expected a diameter > 0", points[i]["size"]);
      r.points.push_back(std::move(p));
    }
    const json& props = list(j, path, "props");
    for (std::size_t i = 0; i < props.size(); ++i) {
      const std::string at_ = path + ".props[" + std::to_string(i) + "]";
      const json& d = object(props[i], at_);
      SceneProp p;
      p.name = text(d, at_, "name");
      p.shape = text(d, at_, "shape");
      if (std::find(std::begin(kShapes), std::end(kShapes), p.shape) == std::end(kShapes))
        fail(at_ + ".shape", "expected one of box, sphere, capsule, cylinder", d["shape"]);
      p.size = vec(d, at_, "size");
      if (!(p.size.x > 0 && p.size.y > 0 && p.size.z > 0)) fail(at_ + ".size", "expected extents > 0", d["size"]);
      p.pose = pose(d, at_, "pose");
      p.spin = number(d, at_, "spin");
      p.t = number(d, at_, "t");
      if (!(p.t >= 0)) fail(at_ + ".t", "expected a time >= 0", d["t"]);
      p.color = color(d, at_, "color");
      r.props.push_back(std::move(p));
    }
    const json& parts = list(j, path, "parts");
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const std::string at_ = path + ".parts[" + std::to_string(i) + "]";
      object(parts[i], at_);
      ScenePart sp{text(parts[i], at_, "name"),
                   integer(parts[i], at_, "part", 0, kMaxCells, "expected a part index >= 0"),
                   color(parts[i], at_, "color")};
      if (parts[i].contains("scored")) {
        const json& scored = parts[i]["scored"];
        if (!scored.is_boolean()) fail(at_ + ".scored", "expected true or false", scored);
        sp.scored = scored.get<bool>();
      }
      r.parts.push_back(std::move(sp));
    }
    const json& kinds = list(j, path, "cell_kinds");
    for (std::size_t i = 0; i < kinds.size(); ++i) {
      const std::string at_ = path + ".cell_kinds[" + std::to_string(i) + "]";
      object(kinds[i], at_);
      const json& item = at(kinds[i], at_, "item");
      if (!item.is_boolean()) fail(at_ + ".item", "expected true or false", item);
      r.cell_kinds.push_back({text(kinds[i], at_, "name"), color(kinds[i], at_, "color"), item.get<bool>()});
    }
    const json& events = list(j, path, "events");
    Seen seen;
    for (std::size_t i = 0; i < events.size(); ++i)
      r.events.push_back(read_event(events[i], path + ".events[" + std::to_string(i) + "]",
                                    static_cast<int>(r.cell_kinds.size()), seen));
    return r;
  } catch (const Bad& e) {
    return Error{e.what()};
  }
}

}  // namespace bx
