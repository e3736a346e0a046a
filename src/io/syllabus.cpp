#include "io/syllabus.h"

#include <algorithm>

#include <toml++/toml.h>

#include <set>
#include <sstream>

#include "core/hash.h"
#include "core/text.h"
#include "genome/genotype_file.h"
#include "genome/shipped_creatures.h"
#include "io/toml_numbers.h"

namespace bx {

namespace {

constexpr std::string_view kStartNames[] = {"random", "best", "population", "file"};
constexpr int kStarts = 4;

// a TOML table as text that toml::parse reads back to it
std::string table_text(const toml::table& t) {
  std::ostringstream ss;
  ss << toml::toml_formatter(t);
  return ss.str();
}

// appended piecewise: GCC 12 warns falsely (-Wrestrict) on "x" + string&&
std::string in_quotes(std::string_view s) {
  std::string q = "\"";
  q.append(one_line(s, 100)).append("\"");
  return q;
}

// a stage's own keys (name, uses, group, start, file, body, encapsulate) from its table, which then
// keeps its config sections only
Status read_stage_keys(toml::table& t, StageDef& st, const std::string& where, bool first) {
  auto name = t["name"].value<std::string>();
  if (!name || name->empty())
    return Error{where + ".name: every stage needs a name (a non-empty string)"};
  st.name = *name;
  if (auto* node = t.get("uses")) {
    auto* arr = node->as_array();
    if (!arr) return Error{where + ".uses: expected an array of stage names"};
    for (auto& u : *arr) {
      auto v = u.value<std::string>();
      if (!v) return Error{where + ".uses: expected an array of stage names"};
      st.uses.push_back(*v);
    }
  }
  if (auto* node = t.get("group")) {
    auto v = node->value<std::string>();
    if (!v) return Error{where + ".group: expected a string (its pandemonium group)"};
    st.group = *v;
  }
  st.start = first ? StageStart::Random : StageStart::Best;
  if (auto* node = t.get("start")) {
    auto v = node->value<std::string>();
    int found = -1;
    for (int i = 0; v && i < kStarts; ++i)
      if (*v == kStartNames[i]) found = i;
    if (found < 0)
      return Error{where + ".start: expected one of random, best, population, file, got " +
                   (v ? in_quotes(*v) : std::string("something else than a string"))};
    st.start = static_cast<StageStart>(found);
    if (first && st.start != StageStart::Random && st.start != StageStart::File)
      return Error{where + ".start: the first stage has no stage before it to start from; it starts \"random\" or "
                   "\"file\", got " + in_quotes(*v)};
    if (!first && st.start == StageStart::File)
      return Error{where + ".start: only the first stage starts from a file (a later one starts from what the last "
                   "left: best or population), got \"file\""};
  }
  for (const char* k : {"file", "file_hash"})
    if (auto* node = t.get(k)) {
      auto v = node->value<std::string>();
      if (!v || v->empty() || !node->is_string())
        return Error{where + "." + k + ": expected a non-empty string" +
                     (std::string_view(k) == "file" ? " (a canonical creature's name, creatures/, or a genome file's path)"
                                                    : " (the hash of the file's text, which the reader writes)")};
      (std::string_view(k) == "file" ? st.file : st.file_hash) = *v;
    }
  if (st.start == StageStart::File && st.file.empty())
    return Error{where + ".file: start = \"file\" needs the genome file to start from (a canonical creature's "
                 "name, creatures/, or a path)"};
  if (st.start != StageStart::File && !st.file.empty())
    return Error{where + ".file: given, but the stage starts \"" + std::string(kStartNames[static_cast<int>(st.start)]) +
                 "\" (start = \"file\" starts from it)"};
  if (st.file.empty() && !st.file_hash.empty())
    return Error{where + ".file_hash: given without file (the reader writes it, with the file it read)"};
  if (st.start == StageStart::File && st.file_hash.empty()) {
    // read now, so a bad file is an error before the run begins; the run
    // reads it again at the stage's start and refuses it if it changed
    auto text = read_creature_text(st.file);
    if (!text) return Error{where + ".file: " + text.error()};
    if (auto g = genotype_from_file_text(text->text, text->source); !g) return Error{where + ".file: " + g.error()};
    st.file_hash = fnv1a64_hex(text->text);
  }
  if (auto* node = t.get("body")) {
    auto v = node->value<std::string>();
    if (!v || (*v != "free" && *v != "locked"))
      return Error{where + ".body: expected \"free\" or \"locked\", got " +
                   (v ? in_quotes(*v) : std::string("something else than a string"))};
    st.lock_body = *v == "locked";
    if (st.lock_body && st.start == StageStart::Random)
      return Error{where + ".body: \"locked\" locks the bodies the stage starts from, and start = \"random\" takes "
                   "none (random genotypes have no body yet)"};
  }
  if (auto* node = t.get("encapsulate")) {
    auto v = node->value<bool>();
    if (!v || !node->is_boolean())
      return Error{where + ".encapsulate: expected true or false (whether its skill is encapsulated when it ends)"};
    st.encapsulate = *v;
  }
  if (auto* node = t.get("retest_tolerance")) {
    auto v = node->value<double>();
    if (!v || !(node->is_number()) || !(*v >= 0 && *v < 1))
      return Error{where + ".retest_tolerance: expected a number in [0, 1) (the share of a leaf skill's fitness a "
                   "child may lose), got " + (v ? g_number(*v) : std::string("something else than a number"))};
    if (first)
      return Error{where + ".retest_tolerance: the first stage has no skill learned before it to retest"};
    st.retest_tolerance = *v;
  }
  if (auto* node = t.get("reconcile")) {
    auto v = node->value<std::string>();
    if (!v || v->empty() || !node->is_string())
      return Error{where + ".reconcile: expected the name of an earlier stage whose skill it evolves again"};
    st.reconcile = *v;
  }
  for (const char* k :
       {"name", "uses", "group", "start", "file", "file_hash", "body", "encapsulate", "retest_tolerance", "reconcile"})
    t.erase(k);
  for (auto&& [key, node] : t)
    if (!node.is_table())
      return Error{where + "." + one_line(key.str(), 100) +
                   ": unknown stage key (a stage has name, uses, group, start, file, body, encapsulate, "
                   "retest_tolerance, reconcile and config sections)"};
  return Ok{};
}

}  // namespace

std::string_view stage_start_name(StageStart s) { return kStartNames[static_cast<int>(s)]; }

int Syllabus::find(std::string_view name) const {
  for (std::size_t i = 0; i < stages.size(); ++i)
    if (stages[i].name == name) return static_cast<int>(i);
  return -1;
}

int Syllabus::group_id(std::string_view group) const {
  if (group.empty()) return -1;
  std::vector<std::string_view> seen;
  for (const StageDef& st : stages) {
    if (st.group.empty() || std::find(seen.begin(), seen.end(), st.group) != seen.end()) continue;
    if (st.group == group) return static_cast<int>(seen.size());
    seen.push_back(st.group);
  }
  return -1;
}

Result<Syllabus> read_syllabus(std::string_view text, std::string_view source,
                               const std::vector<std::string>& overrides) {
  const std::string src(source);
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error&) {
    // read_run_config reports it with its position
    auto cfg = read_run_config(text, source, overrides);
    if (!cfg) return Error{cfg.error()};
    return Error{src + ": not TOML"};
  }
  // before a stage's tables are written out again, where 1e-400 would be 0.0
  if (Status s = check_number_range(root, text, source); !s) return Error{s.error()};
  Syllabus out;
  toml::node* stages_node = root.get("stage");
  if (!stages_node) {
    auto cfg = read_run_config(text, source, overrides);
    if (!cfg) return Error{cfg.error()};
    StageDef one;
    one.cfg = std::move(*cfg);
    out.stages.push_back(std::move(one));
    return out;
  }
  toml::array* stages = stages_node->as_array();
  if (!stages || stages->empty() || !stages->is_array_of_tables())
    return Error{src + ": stage: expected [[stage]] tables, one per stage"};
  toml::table base = root;
  base.erase("stage");
  const std::string base_text = table_text(base);
  for (std::size_t i = 0; i < stages->size(); ++i) {
    toml::table t = *(*stages)[i].as_table();
    StageDef st;
    std::string where = src + ": stage " + std::to_string(i + 1);
    if (Status s = read_stage_keys(t, st, where, i == 0); !s) return Error{s.error()};
    where = src + ": stage " + in_quotes(st.name);
    if (out.find(st.name) >= 0) return Error{where + ".name: given to two stages"};
    for (const std::string& u : st.uses) {
      if (u == st.name) return Error{where + ".uses: " + in_quotes(u) + " is this stage (a stage cannot use itself)"};
      if (out.find(u) >= 0) continue;
      bool later = false;
      for (std::size_t j = i + 1; j < stages->size(); ++j)
        if (auto n = (*(*stages)[j].as_table())["name"].value<std::string>(); n && *n == u) later = true;
      if (later) return Error{where + ".uses: " + in_quotes(u) + " is learned after it (a stage uses only earlier ones)"};
      std::vector<std::string> names;
      for (const auto& s : out.stages) names.push_back(s.name);
      return Error{where + ".uses: " + in_quotes(u) + ": no earlier stage has this name" + did_you_mean(u, names)};
    }
    auto cfg = read_run_config({{base_text, src}, {table_text(t), where}}, overrides);
    if (!cfg) return Error{cfg.error()};
    st.cfg = std::move(*cfg);
    if (i > 0) {
      const RunConfig& first = out.stages.front().cfg;
      if (st.cfg.dialect != first.dialect)
        return Error{where + ": genome.dialect: every stage evolves the first stage's dialect (" +
                     std::string(to_string(first.dialect)) + "), got " + std::string(to_string(st.cfg.dialect))};
      if (st.cfg.sim.creature != first.sim.creature)
        return Error{where + ": genotype.kind: every stage evolves the first stage's creature kind (" +
                     evolved_name(first) + "), got " + evolved_name(st.cfg)};
    }
    if (!st.reconcile.empty()) {
      const int j = out.find(st.reconcile);
      if (j < 0 || !out.stages[j].encapsulate)
        return Error{where + ".reconcile: " + in_quotes(st.reconcile) +
                     (j < 0 ? ": no earlier stage has this name" : ": that stage's skill is not encapsulated")};
      if (!out.stages[j].uses.empty())
        return Error{where + ".reconcile: " + in_quotes(st.reconcile) +
                     " uses other skills: only a leaf skill (one that drives the body) is reconciled to it"};
      if (st.encapsulate || !st.uses.empty() || st.start != StageStart::Best || st.retest_tolerance)
        return Error{where + ".reconcile: a reconciling stage starts from the last one's best (start = \"best\") and "
                     "has no encapsulate, uses or retest_tolerance of its own: it evolves " + in_quotes(st.reconcile) +
                     "'s wires again"};
      // the skill's own task, run alone; only its wires evolve
      st.cfg.sim = out.stages[j].cfg.sim;
      st.cfg.sim.develop.skill = st.reconcile;
      st.cfg.operators.reconcile_skill = st.reconcile;
    }
    out.stages.push_back(std::move(st));
    if (out.stages.back().retest_tolerance && out.leaf_skills(static_cast<int>(i)).empty())
      return Error{where + ".retest_tolerance: no leaf skill is learned before it (an earlier stage that "
                   "encapsulates its skill and uses none)"};
  }
  return out;
}

std::vector<int> Syllabus::leaf_skills(int k) const {
  std::vector<int> out;
  for (int j = 0; j < k && j < static_cast<int>(stages.size()); ++j)
    if (stages[j].encapsulate && stages[j].uses.empty()) out.push_back(j);
  return out;
}

int Syllabus::learned_in(int j, int k) const {
  int last = j;
  for (int i = j + 1; i < k && i < static_cast<int>(stages.size()); ++i)
    if (stages[i].reconcile == stages[j].name) last = i;
  return last;
}

std::vector<SimConfig> task_table(const Syllabus& s) {
  std::vector<SimConfig> rows;
  for (const StageDef& st : s.stages) rows.push_back(st.cfg.sim);
  for (int k = 0; k < static_cast<int>(s.stages.size()); ++k) {
    if (!s.stages[k].retest_tolerance) continue;
    for (int j : s.leaf_skills(k)) {
      SimConfig alone = s.stages[j].cfg.sim;
      alone.develop.skill = s.stages[j].name;
      rows.push_back(std::move(alone));
    }
  }
  return rows;
}

std::vector<RetestRow> retest_rows(const Syllabus& s, int k) {
  int row = static_cast<int>(s.stages.size());
  for (int i = 0; i < static_cast<int>(s.stages.size()); ++i) {
    if (!s.stages[i].retest_tolerance) continue;
    const std::vector<int> leaves = s.leaf_skills(i);
    if (i == k) {
      std::vector<RetestRow> out;
      for (int j : leaves) out.push_back({j, row++});
      return out;
    }
    row += static_cast<int>(leaves.size());
  }
  return {};
}

std::string syllabus_to_toml(const Syllabus& s) {
  const std::string base = config_to_toml(s.stages.front().cfg);
  if (!s.staged()) return base;
  // config_to_toml writes every key in one order: a stage's table is the
  // lines in which its config's text differs from the first's, under their sections
  auto lines = [](const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
  };
  const std::vector<std::string> b = lines(base);
  std::ostringstream ss;
  ss << base;
  for (const StageDef& st : s.stages) {
    ss << "\n[[stage]]\nname = " << toml::value<std::string>(st.name);
    if (!st.uses.empty()) {
      toml::array uses;
      for (const auto& u : st.uses) uses.push_back(u);
      ss << "\nuses = " << uses;
    }
    if (!st.group.empty()) ss << "\ngroup = " << toml::value<std::string>(st.group);
    ss << "\nstart = \"" << stage_start_name(st.start) << "\"\n";
    if (!st.file.empty())
      ss << "file = " << toml::value<std::string>(st.file) << "\nfile_hash = " << toml::value<std::string>(st.file_hash)
         << "\n";
    if (st.lock_body) ss << "body = \"locked\"\n";
    if (st.encapsulate) ss << "encapsulate = true\n";
    if (st.retest_tolerance) ss << "retest_tolerance = " << toml::value<double>(*st.retest_tolerance) << "\n";
    if (!st.reconcile.empty()) ss << "reconcile = " << toml::value<std::string>(st.reconcile) << "\n";
    const std::vector<std::string> own = lines(config_to_toml(st.cfg));
    std::string section, written;
    for (std::size_t k = 0; k < own.size() && k < b.size(); ++k) {
      if (!own[k].empty() && own[k].front() == '[') section = own[k].substr(1, own[k].size() - 2);
      if (own[k] == b[k]) continue;
      if (section != written) {
        ss << "[stage." << section << "]\n";
        written = section;
      }
      ss << own[k] << "\n";
    }
  }
  return ss.str();
}

}  // namespace bx
