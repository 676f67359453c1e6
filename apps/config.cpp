#include "apps/config.h"
#include "numerics/format.h"

#include <cmath>
#include <sstream>

namespace tribo::cli {

toml::table parse_toml_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(path.string() + ": cannot read config file (missing or not a regular file)");
  }
  try {
    return toml::parse_file(path.string());
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << path.string() << ":" << e.source().begin.line << ":" << e.source().begin.column
       << ": malformed TOML: " << e.description();
    throw InputError(os.str());
  }
}

toml::table parse_toml_text(std::string_view text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << source << ":" << e.source().begin.line << ":" << e.source().begin.column << ": malformed TOML: " << e.description();
    throw InputError(os.str());
  }
}

ConfigTable::ConfigTable(const toml::table& table, std::string file, std::string prefix)
    : ConfigTable(table, std::move(file), std::move(prefix), std::make_shared<std::vector<std::filesystem::path>>()) {}

ConfigTable::ConfigTable(const toml::table& table, std::string file, std::string prefix,
                         std::shared_ptr<std::vector<std::filesystem::path>> input_files)
    : table_(&table), file_(std::move(file)), prefix_(std::move(prefix)), input_files_(std::move(input_files)) {}

std::string ConfigTable::dotted(const std::string& key) const {
  return prefix_.empty() ? key : prefix_ + "." + key;
}

void ConfigTable::fail(const std::string& key, const std::string& reason) const {
  throw InputError(file_ + ": key '" + dotted(key) + "': " + reason);
}

bool ConfigTable::has(const std::string& key) const { return table_->contains(key); }

void ConfigTable::accept(const std::string& key) { read_.insert(key); }

void ConfigTable::refuse_renamed(const std::string& old_key, const std::string& replacement) const {
  if (has(old_key)) fail(old_key, "was renamed: use '" + replacement + "' instead");
}

const toml::node* ConfigTable::node(const std::string& key) {
  read_.insert(key);
  return table_->get(key);
}

double ConfigTable::checked(const std::string& key, const toml::node& n, Range range) const {
  double value = 0.0;
  if (auto d = n.value_exact<double>()) {
    value = *d;
  } else if (auto i = n.value_exact<int64_t>()) {
    value = static_cast<double>(*i);
  } else {
    fail(key, "expected a number");
  }
  if (!std::isfinite(value)) fail(key, "must be a finite number (got " + numerics::shortest(value) + ")");
  switch (range) {
    case Range::any: break;
    case Range::positive:
      if (!(value > 0.0)) fail(key, "must be positive (got " + numerics::shortest(value) + ")");
      break;
    case Range::non_negative:
      if (value < 0.0) fail(key, "must not be negative (got " + numerics::shortest(value) + ")");
      break;
    case Range::unit_interval:
      if (value < 0.0 || value > 1.0) fail(key, "must lie in [0, 1] (got " + numerics::shortest(value) + ")");
      break;
  }
  return value;
}

double ConfigTable::number(const std::string& key, double fallback, Range range) {
  const toml::node* n = node(key);
  return n ? checked(key, *n, range) : fallback;
}

double ConfigTable::required_number(const std::string& key, Range range) {
  const toml::node* n = node(key);
  if (!n) fail(key, "is required");
  return checked(key, *n, range);
}

std::optional<double> ConfigTable::optional_number(const std::string& key, Range range) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  return checked(key, *n, range);
}

long long ConfigTable::integer(const std::string& key, long long fallback, long long min_value, long long max_value) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  auto i = n->value_exact<int64_t>();
  if (!i) fail(key, "expected an integer");
  if (*i < min_value) fail(key, "must be at least " + std::to_string(min_value) + " (got " + std::to_string(*i) + ")");
  if (*i > max_value) fail(key, "must be at most " + std::to_string(max_value) + " (got " + std::to_string(*i) + ")");
  return *i;
}

bool ConfigTable::boolean(const std::string& key, bool fallback) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  auto b = n->value_exact<bool>();
  if (!b) fail(key, "expected true or false");
  return *b;
}

std::string ConfigTable::string(const std::string& key, const std::string& fallback) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  auto s = n->value_exact<std::string>();
  if (!s) fail(key, "expected a string");
  return *s;
}

std::string ConfigTable::required_string(const std::string& key) {
  if (!has(key)) {
    read_.insert(key);
    fail(key, "is required");
  }
  return string(key, "");
}

std::filesystem::path ConfigTable::input_file(const std::string& key) {
  const std::filesystem::path path = std::filesystem::path(file_).parent_path() / required_string(key);
  input_files_->push_back(path);
  return path;
}

std::string ConfigTable::choice(const std::string& key, const std::string& fallback,
                                const std::vector<std::string>& choices) {
  std::string value = string(key, fallback);
  for (const auto& c : choices) {
    if (c == value) return value;
  }
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + ("\"" + c + "\"");
  fail(key, "unknown value \"" + value + "\" (expected one of " + list + ")");
}

std::vector<double> ConfigTable::number_array(const std::string& key, Range range) {
  const toml::node* n = node(key);
  if (!n) return {};
  const toml::array* arr = n->as_array();
  if (!arr) fail(key, "expected an array of numbers");
  std::vector<double> out;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    out.push_back(checked(key + "[" + std::to_string(i) + "]", *arr->get(i), range));
  }
  return out;
}

std::vector<std::string> ConfigTable::string_array(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) return {};
  const toml::array* arr = n->as_array();
  if (!arr) fail(key, "expected an array of strings");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    auto s = arr->get(i)->value_exact<std::string>();
    if (!s) fail(key + "[" + std::to_string(i) + "]", "expected a string");
    out.push_back(*s);
  }
  return out;
}

std::optional<ConfigTable> ConfigTable::table(const std::string& key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const toml::table* t = n->as_table();
  if (!t) fail(key, "expected a table");
  return ConfigTable(*t, file_, dotted(key), input_files_);
}

void ConfigTable::finish() const {
  for (const auto& [k, v] : *table_) {
    const std::string key(k.str());
    if (!read_.count(key)) fail(key, "unknown key");
  }
}

}  // namespace tribo::cli
