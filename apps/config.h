// Reading TOML configs (toml++) into plain parameter structs, with one clear
// error per bad input: the file, the dotted key and the reason. Only the CLI
// parses files; libraries take structs (STYLE §4).
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tribo::cli {

// Bad user input. The message is complete ("file: key: reason"); main() prints it and exits 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Range { any, positive, non_negative, unit_interval };

// Parses a TOML file; a missing, unreadable or malformed file is an InputError naming line and column.
toml::table parse_toml_file(const std::filesystem::path& path);
// The same for TOML text already in memory; `source` names it in the error (the fuzz harnesses).
toml::table parse_toml_text(std::string_view text, const std::string& source);

// A view of one TOML table that records which keys were read, so that finish() can reject
// unknown keys (typos must not silently fall back to defaults).
class ConfigTable {
 public:
  ConfigTable(const toml::table& table, std::string file, std::string prefix);

  // Numbers: integers are accepted where reals are expected; NaN and infinities are rejected.
  double number(const std::string& key, double fallback, Range range = Range::any);
  double required_number(const std::string& key, Range range = Range::any);
  std::optional<double> optional_number(const std::string& key, Range range = Range::any);
  // An integer in [min_value, max_value]: counts that size allocations or are narrowed to int
  // need an upper bound, or a typo like 1e9 becomes a giant allocation or wraps around.
  long long integer(const std::string& key, long long fallback, long long min_value,
                    long long max_value = std::numeric_limits<long long>::max());
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key, const std::string& fallback);
  std::string required_string(const std::string& key);
  // A file the config names (a required string, relative to the config's folder): the resolved
  // path, recorded among input_files() so that provenance can hash what the run read.
  std::filesystem::path input_file(const std::string& key);
  // The files input_file() resolved, in this table and every table() taken from it or its root.
  const std::vector<std::filesystem::path>& input_files() const { return *input_files_; }
  // One of `choices`; anything else is an error listing them.
  std::string choice(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& choices);
  std::vector<double> number_array(const std::string& key, Range range = Range::any);
  std::vector<std::string> string_array(const std::string& key);
  // Sub-table, or nullopt when absent; a key holding a non-table is an error.
  std::optional<ConfigTable> table(const std::string& key);
  bool has(const std::string& key) const;
  // Marks a key as known without reading it (read elsewhere).
  void accept(const std::string& key);
  // Refuses a key that an earlier version read: an InputError naming the file, the old key and
  // `replacement`, the key to use now (dotted from the config's root).
  void refuse_renamed(const std::string& old_key, const std::string& replacement) const;
  // Throws an InputError naming the first key that was never read.
  void finish() const;

  // "file: key 'prefix.key': reason" — for checks that span several keys.
  [[noreturn]] void fail(const std::string& key, const std::string& reason) const;
  const std::string& file() const { return file_; }
  std::string dotted(const std::string& key) const;

 private:
  // A sub-table (table()): it shares `input_files` with the table it was taken from.
  ConfigTable(const toml::table& table, std::string file, std::string prefix,
              std::shared_ptr<std::vector<std::filesystem::path>> input_files);
  const toml::node* node(const std::string& key);
  double checked(const std::string& key, const toml::node& n, Range range) const;

  const toml::table* table_;
  std::string file_;
  std::string prefix_;
  std::set<std::string> read_;
  std::shared_ptr<std::vector<std::filesystem::path>> input_files_;  // shared with the sub-tables
};

// Runs `build` (a library constructor or validator) and turns its std::invalid_argument into an
// InputError naming the config key that holds the offending value.
template <class F>
auto input_guard(const ConfigTable& table, const std::string& key, F&& build) {
  try {
    return build();
  } catch (const std::invalid_argument& e) {
    table.fail(key, e.what());
  }
}

}  // namespace tribo::cli
