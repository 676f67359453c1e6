#include "apps/sweep_spec.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "apps/config.h"
#include "apps/output.h"

namespace tribo::cli {
namespace {

// More points than any study runs: a typo in `count` must not enumerate billions of configs.
constexpr long long kMaxSweepPoints = 1'000'000;

std::vector<std::string> split_dotted(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
  return parts;
}

SweepAxis read_axis(ConfigTable& t) {
  SweepAxis a;
  a.key = t.required_string("key");
  if (t.has("values")) {
    a.values = t.number_array("values");
    if (a.values.empty()) t.fail("values", "must hold at least one value");
    for (const char* k : {"from", "to", "count", "scale"})
      if (t.has(k)) t.fail(k, "give either values or from/to/count, not both");
  } else {
    const double from = t.required_number("from"), to = t.required_number("to");
    const long long count = t.integer("count", 2, 1, kMaxSweepPoints);  // bounds the allocation below
    const std::string scale = t.choice("scale", "linear", {"linear", "log"});
    if (scale == "log" && !(from > 0.0 && to > 0.0)) t.fail("scale", "a log range needs from and to > 0");
    for (long long k = 0; k < count; ++k) {
      const double f = count == 1 ? 0.0 : static_cast<double>(k) / static_cast<double>(count - 1);
      a.values.push_back(scale == "log" ? from * std::pow(to / from, f) : from + (to - from) * f);
    }
    a.values.back() = count == 1 ? from : to;  // the end point exactly as written
  }
  t.finish();
  return a;
}

SweepOutput read_output(const ConfigTable& t, const std::string& spec, const std::vector<SweepStep>& steps) {
  const auto colon = spec.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == spec.size())
    t.fail("columns", "\"" + spec + "\" must read FILE:path, e.g. \"summary.json:regime\"");
  SweepOutput o;
  o.file = spec.substr(0, colon);
  o.path = spec.substr(colon + 1);
  // In a chain "STEP/FILE" picks the step's folder; otherwise a bare file name of the point's folder.
  std::string name = o.file;
  if (const auto slash = o.file.find('/'); slash != std::string::npos && steps.size() > 1) {
    bool known = false;
    for (const SweepStep& s : steps) known = known || o.file.substr(0, slash) == s.command;
    if (!known) t.fail("columns", "\"" + o.file + "\": '" + o.file.substr(0, slash) + "' is not a step of this chain");
    name = o.file.substr(slash + 1);
  }
  if (name.empty() || name.find('/') != std::string::npos || name.find("..") != std::string::npos)
    t.fail("columns", "\"" + o.file + "\" must name a file of the point's output folder, without a path" +
                          (steps.size() > 1 ? std::string(" (or STEP/FILE, e.g. \"rig/summary.json\")") : ""));
  // The path's last name, with the array indices on the way appended ("stribeck.12.mu" → "mu_12").
  for (const std::string& part : split_dotted(o.path))
    if (part.find_first_not_of("0123456789") != std::string::npos) o.column = part;
  for (const std::string& part : split_dotted(o.path))
    if (part.find_first_not_of("0123456789") == std::string::npos) o.column += "_" + part;
  return o;
}

// A path-valued string of the base config, made absolute when it names an existing file beside it.
void absolutise_paths(toml::table& table, const std::filesystem::path& dir) {
  for (auto&& [key, node] : table) {
    if (auto* sub = node.as_table()) {
      absolutise_paths(*sub, dir);
    } else if (auto* s = node.as_string()) {
      const std::filesystem::path p(s->get());
      std::error_code ec;
      if (!p.empty() && p.is_relative() && std::filesystem::exists(dir / p, ec)) *s = (dir / p).lexically_normal().string();
    }
  }
}

// Where a key as written lands: the chain step ("homogenise:surface.hurst") and the dotted key
// inside that step's config, every table on the way a table of it (or absent) and the key itself
// not a table. `fail(reason)` throws, naming the key where the spec holds it.
struct KeyTarget {
  std::size_t step = 0;
  std::string config_key;
};
template <class Fail>
KeyTarget resolve_key(const std::string& written, const SweepSpec& spec, const std::vector<toml::table>& step_docs,
                      Fail&& fail) {
  KeyTarget target;
  std::string key = written;
  if (spec.steps.size() > 1) {
    const auto colon = key.find(':');
    bool found = false;
    if (colon != std::string::npos)
      for (std::size_t s = 0; s < spec.steps.size(); ++s)
        if (key.substr(0, colon) == spec.steps[s].command) {
          target.step = s;
          found = true;
        }
    if (!found)
      fail("in a chain the key names its step first: \"homogenise:surface.hurst\" or "
           "\"rig:rig.drive_speed_m_per_s\", not \"" + key + "\"");
    key = key.substr(colon + 1);
    if (spec.steps[target.step].command == "rig" && (key == "friction.law" || key == "friction.table"))
      fail("'" + key + "' of the rig step is set by the chain (the point's own law.json)");
  }
  if (key.empty() || key.front() == '.' || key.back() == '.' || key.find("..") != std::string::npos ||
      key.find(':') != std::string::npos)
    fail("must be a dotted config key such as \"rig.drive_speed_m_per_s\"");
  target.config_key = key;
  const auto parts = split_dotted(key);
  const std::string config = spec.steps[target.step].config.string();
  const toml::table* at = &step_docs[target.step];
  for (std::size_t i = 0; i + 1 < parts.size() && at; ++i) {
    const toml::node* n = at->get(parts[i]);
    if (n && !n->is_table()) fail("'" + parts[i] + "' is not a table in " + config);
    at = n ? n->as_table() : nullptr;
  }
  if (at && at->get(parts.back()) && at->get(parts.back())->is_table())
    fail("'" + key + "' is a table in " + config + ", not a value");
  return target;
}

// The table on the way to a dotted key of `config`, created where missing.
toml::table* table_on_the_way(toml::table& config, const std::vector<std::string>& parts) {
  toml::table* at = &config;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (!at->contains(parts[i])) at->insert(parts[i], toml::table{});
    at = at->get(parts[i])->as_table();
  }
  return at;
}

}  // namespace

SweepSpec load_sweep_spec(const std::filesystem::path& path) {
  const toml::table doc = parse_toml_file(path);
  ConfigTable root(doc, path.string(), "");
  SweepSpec spec;
  spec.spec_file = std::filesystem::absolute(path);
  auto base = root.table("base");
  if (!base) root.fail("base", "table [base] is required (command and config)");
  spec.command = base->choice("command", "rig", {"rig", "contact", "reynolds", "ehl", "homogenise", "homogenise+rig"});
  const auto step_config = [&](const std::string& key) {
    const auto file = (spec.spec_file.parent_path() / base->required_string(key)).lexically_normal();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) base->fail(key, "no such file: " + file.string());
    return file;
  };
  if (spec.command == "homogenise+rig") {
    // The chain: homogenise writes the point's law.json, the rig runs with it.
    spec.steps.push_back({"homogenise", step_config("config"), "config"});
    spec.steps.push_back({"rig", step_config("rig_config"), "rig_config"});
  } else {
    spec.steps.push_back({spec.command, step_config("config"), "config"});
    if (base->has("rig_config")) base->fail("rig_config", "is only used with command = \"homogenise+rig\"");
  }
  spec.base_config = spec.steps.front().config;
  base->accept("set");
  base->finish();
  std::vector<toml::table> step_docs;
  for (const SweepStep& s : spec.steps) step_docs.push_back(parse_toml_file(s.config));
  if (const toml::node* set = doc["base"]["set"].node()) {
    // [base.set]: values every point's config gets, of any type ("pin.shape" = "spherical").
    if (!set->is_table()) base->fail("set", "must be a table of dotted config keys and their values");
    const ConfigTable where(*set->as_table(), path.string(), "base.set");
    for (auto&& [k, value] : *set->as_table()) {
      const std::string key(k.str());
      const auto fail = [&](const std::string& reason) { where.fail(key, reason); };
      if (value.is_table()) fail("must be a value; write the whole dotted key (\"pin.shape\" = \"spherical\")");
      const KeyTarget target = resolve_key(key, spec, step_docs, fail);
      SweepSetting setting{key, target.step, target.config_key, toml::array{}};
      value.visit([&](auto&& v) { setting.value.push_back(v); });
      spec.settings.push_back(std::move(setting));
    }
  }
  if (spec.steps.size() > 1) {
    // The rig step's friction law is the point's homogenised one; another law there is a mistake.
    const toml::table& rig = step_docs.back();
    if (const toml::node* f = rig.get("friction"); f && !f->is_table())
      throw InputError(spec.steps.back().config.string() + ": key 'friction': must be a table");
    if (const auto law = rig["friction"]["law"].value<std::string>(); law && *law != "homogenised")
      throw InputError(spec.steps.back().config.string() + ": key 'friction.law': the chain runs the rig with the "
                       "point's homogenised law, so it must be \"homogenised\" (or absent), not \"" + *law + "\"");
  }

  root.accept("axis");
  const toml::array* axes = doc["axis"].as_array();
  if (!axes || axes->empty()) root.fail("axis", "at least one [[axis]] table is required");
  std::set<std::string> axis_keys;
  for (std::size_t k = 0; k < axes->size(); ++k) {
    const toml::table* t = (*axes)[k].as_table();
    if (!t) root.fail("axis", "must be an array of tables ([[axis]])");
    ConfigTable axis(*t, path.string(), "axis[" + std::to_string(k) + "]");
    spec.axes.push_back(read_axis(axis));
    SweepAxis& a = spec.axes.back();
    const KeyTarget target =
        resolve_key(a.key, spec, step_docs, [&](const std::string& reason) { axis.fail("key", reason); });
    a.step = target.step, a.config_key = target.config_key;
    if (!axis_keys.insert(a.key).second) axis.fail("key", "'" + a.key + "' is already an axis");
    for (const SweepSetting& set : spec.settings)
      if (set.key == a.key) axis.fail("key", "'" + a.key + "' is set in [base.set] already");
  }
  if (auto s = root.table("sweep")) {
    spec.zip = s->choice("combine", "product", {"product", "zip"}) == "zip";
    spec.jobs = static_cast<int>(s->integer("jobs", 0, 0));
    spec.artefacts = s->boolean("artefacts", false);
    s->finish();
  }
  if (!spec.zip) {
    // The product of the axes is enumerated in memory (sweep_points): refuse it before it grows.
    std::size_t points = 1;
    for (const SweepAxis& a : spec.axes) {
      points *= a.values.size();
      if (points > static_cast<std::size_t>(kMaxSweepPoints))
        root.fail("axis", "the axes' product has more than " + std::to_string(kMaxSweepPoints) + " points");
    }
  }
  if (spec.zip)
    for (const SweepAxis& a : spec.axes)
      if (a.values.size() != spec.axes.front().values.size())
        root.fail("sweep.combine", "zipped axes must have equal lengths ('" + a.key + "' has " +
                                       std::to_string(a.values.size()) + ", '" + spec.axes.front().key + "' " +
                                       std::to_string(spec.axes.front().values.size()) + ")");
  if (auto o = root.table("outputs")) {
    std::set<std::string> taken = {"point_id", "status", "error", "wall_s"};
    for (const SweepAxis& a : spec.axes) taken.insert(a.key);
    const std::vector<std::string> columns = o->string_array("columns");
    // names = [...]: the columns' own names, e.g. "mu_at_8.2e-4_m_per_s" for "law.json:stribeck.13.mu".
    std::vector<std::string> names;
    if (o->has("names")) {
      names = o->string_array("names");
      if (names.size() != columns.size())
        o->fail("names", "must hold one name per column (" + std::to_string(names.size()) + " names, " +
                             std::to_string(columns.size()) + " columns)");
      for (const std::string& n : names)
        if (n.empty() || n.find_first_of(",\"\n\r") != std::string::npos)
          o->fail("names", "\"" + n + "\" must be non-empty, without commas, quotes or line breaks");
    }
    for (std::size_t k = 0; k < columns.size(); ++k) {
      spec.outputs.push_back(read_output(*o, columns[k], spec.steps));
      SweepOutput& out = spec.outputs.back();
      if (!names.empty()) {
        out.column = names[k];
      } else if (taken.count(out.column)) {
        // A name already in the table gets its file's stem in front ("law.json:wall_s" → "law_wall_s").
        out.column = std::filesystem::path(out.file).filename().stem().string() + "_" + out.column;
      }
      if (!taken.insert(out.column).second) o->fail("columns", "two outputs would both be the column '" + out.column + "'");
    }
    o->finish();
  }
  root.finish();
  return spec;
}

std::vector<std::vector<double>> sweep_points(const SweepSpec& spec) {
  std::vector<std::vector<double>> points;
  if (spec.zip) {
    for (std::size_t k = 0; k < spec.axes.front().values.size(); ++k) {
      std::vector<double> p;
      for (const SweepAxis& a : spec.axes) p.push_back(a.values[k]);
      points.push_back(p);
    }
    return points;
  }
  points.emplace_back();
  for (const SweepAxis& a : spec.axes) {
    std::vector<std::vector<double>> next;
    for (const auto& p : points)
      for (double v : a.values) {
        next.push_back(p);
        next.back().push_back(v);
      }
    points = std::move(next);
  }
  return points;
}

toml::table point_config(const SweepSpec& spec, const std::vector<double>& values, std::size_t step) {
  const SweepStep& s = spec.steps.at(step);
  toml::table config = parse_toml_file(s.config);
  absolutise_paths(config, s.config.parent_path());
  for (const SweepSetting& set : spec.settings) {
    if (set.step != step) continue;
    const auto parts = split_dotted(set.config_key);
    set.value.get(0)->visit([&](auto&& v) { table_on_the_way(config, parts)->insert_or_assign(parts.back(), v); });
  }
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    if (spec.axes[a].step != step) continue;
    const auto parts = split_dotted(spec.axes[a].config_key);
    toml::table* at = table_on_the_way(config, parts);
    const double v = values[a];
    // Integral values go in as integers: integer keys (grid, seed) need them, real keys accept them.
    if (std::floor(v) == v && std::abs(v) < 9e15) {
      at->insert_or_assign(parts.back(), static_cast<int64_t>(v));
    } else {
      at->insert_or_assign(parts.back(), v);
    }
  }
  if (spec.steps.size() > 1 && s.command == "rig") {
    toml::table* friction = table_on_the_way(config, {"friction", "law"});
    friction->insert_or_assign("law", "homogenised");
    friction->insert_or_assign("table", "../" + step_folder(spec, 0) + "/law.json");
  }
  return config;
}

nlohmann::json setting_json(const SweepSetting& set) {
  std::ostringstream os;
  os << toml::json_formatter{set.value};
  return nlohmann::json::parse(os.str()).at(0);
}

std::string step_folder(const SweepSpec& spec, std::size_t step) {
  return spec.steps.size() > 1 ? spec.steps.at(step).command : std::string();
}

std::string json_field(const std::filesystem::path& file, const std::string& path) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded()) throw std::runtime_error(file.string() + ": malformed JSON");
  return json_field(j, file, path);
}

std::string json_field(const nlohmann::json& j, const std::filesystem::path& file, const std::string& path) {
  const nlohmann::json* at = &j;
  for (const std::string& part : split_dotted(path)) {
    if (at->is_array() && !part.empty() && part.find_first_not_of("0123456789") == std::string::npos &&
        std::stoul(part) < at->size()) {
      at = &(*at)[std::stoul(part)];
    } else if (at->is_object() && at->contains(part)) {
      at = &(*at)[part];
    } else {
      throw std::runtime_error(file.string() + ": no value at '" + path + "'");
    }
  }
  if (at->is_number()) return exact(at->get<double>());
  if (at->is_boolean()) return at->get<bool>() ? "1" : "0";
  if (at->is_string()) return at->get<std::string>();
  if (at->is_null()) return "";
  throw std::runtime_error(file.string() + ": '" + path + "' is not a number, string or boolean");
}

}  // namespace tribo::cli
