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

std::vector<std::string> split_dotted(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
  return parts;
}

SweepAxis read_axis(ConfigTable& t) {
  SweepAxis a;
  a.key = t.required_string("key");
  if (split_dotted(a.key).size() < 1 || a.key.front() == '.' || a.key.back() == '.' || a.key.find("..") != std::string::npos)
    t.fail("key", "must be a dotted config key such as \"rig.drive_speed_m_per_s\"");
  if (t.has("values")) {
    a.values = t.number_array("values");
    if (a.values.empty()) t.fail("values", "must hold at least one value");
    for (const char* k : {"from", "to", "count", "scale"})
      if (t.has(k)) t.fail(k, "give either values or from/to/count, not both");
  } else {
    const double from = t.required_number("from"), to = t.required_number("to");
    const long long count = t.integer("count", 2, 1);
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

SweepOutput read_output(const ConfigTable& t, const std::string& spec) {
  const auto colon = spec.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == spec.size())
    t.fail("columns", "\"" + spec + "\" must read FILE:path, e.g. \"summary.json:regime\"");
  SweepOutput o;
  o.file = spec.substr(0, colon);
  o.path = spec.substr(colon + 1);
  if (o.file.find('/') != std::string::npos || o.file.find("..") != std::string::npos)
    t.fail("columns", "\"" + o.file + "\" must name a file of the point's output folder, without a path");
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

}  // namespace

SweepSpec load_sweep_spec(const std::filesystem::path& path) {
  const toml::table doc = parse_toml_file(path);
  ConfigTable root(doc, path.string(), "");
  SweepSpec spec;
  spec.spec_file = std::filesystem::absolute(path);
  auto base = root.table("base");
  if (!base) root.fail("base", "table [base] is required (command and config)");
  spec.command = base->choice("command", "rig", {"rig", "contact", "reynolds", "homogenise"});
  spec.base_config = (spec.spec_file.parent_path() / base->required_string("config")).lexically_normal();
  base->finish();
  const toml::table base_doc = parse_toml_file(spec.base_config);

  root.accept("axis");
  const toml::array* axes = doc["axis"].as_array();
  if (!axes || axes->empty()) root.fail("axis", "at least one [[axis]] table is required");
  for (std::size_t k = 0; k < axes->size(); ++k) {
    const toml::table* t = (*axes)[k].as_table();
    if (!t) root.fail("axis", "must be an array of tables ([[axis]])");
    ConfigTable axis(*t, path.string(), "axis[" + std::to_string(k) + "]");
    spec.axes.push_back(read_axis(axis));
    // Every table on the way to the key must be a table of the base config (or absent).
    const auto parts = split_dotted(spec.axes.back().key);
    const toml::table* at = &base_doc;
    for (std::size_t i = 0; i + 1 < parts.size() && at; ++i) {
      const toml::node* n = at->get(parts[i]);
      if (n && !n->is_table()) axis.fail("key", "'" + parts[i] + "' is not a table in " + spec.base_config.string());
      at = n ? n->as_table() : nullptr;
    }
    if (at && at->get(parts.back()) && at->get(parts.back())->is_table())
      axis.fail("key", "'" + spec.axes.back().key + "' is a table in " + spec.base_config.string() + ", not a value");
  }
  if (auto s = root.table("sweep")) {
    spec.zip = s->choice("combine", "product", {"product", "zip"}) == "zip";
    spec.jobs = static_cast<int>(s->integer("jobs", 0, 0));
    s->finish();
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
    for (const std::string& c : o->string_array("columns")) {
      spec.outputs.push_back(read_output(*o, c));
      SweepOutput& out = spec.outputs.back();
      // A name already in the table gets its file's stem in front ("law.json:wall_s" → "law_wall_s").
      if (taken.count(out.column)) out.column = std::filesystem::path(out.file).stem().string() + "_" + out.column;
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

toml::table point_config(const SweepSpec& spec, const std::vector<double>& values) {
  toml::table config = parse_toml_file(spec.base_config);
  absolutise_paths(config, spec.base_config.parent_path());
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    const auto parts = split_dotted(spec.axes[a].key);
    toml::table* at = &config;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      if (!at->contains(parts[i])) at->insert(parts[i], toml::table{});
      at = at->get(parts[i])->as_table();
    }
    const double v = values[a];
    // Integral values go in as integers: integer keys (grid, seed) need them, real keys accept them.
    if (std::floor(v) == v && std::abs(v) < 9e15) {
      at->insert_or_assign(parts.back(), static_cast<int64_t>(v));
    } else {
      at->insert_or_assign(parts.back(), v);
    }
  }
  return config;
}

std::string json_field(const std::filesystem::path& file, const std::string& path) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read");
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded()) throw std::runtime_error(file.string() + ": malformed JSON");
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
