// How an output was made: tribo version and commit, the command line, the config file and its
// hash, the time and the thread count (and the seed, where the command has one) — written into
// every JSON result as "provenance" and as "# key: value" lines at the top of every CSV, so that a
// number can be traced to the code and inputs that made it.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace tribo::cli {

// FNV-1a 64-bit hash of the file's bytes, as 16 hex digits (identifies the inputs of a cached
// result; not a cryptographic digest). Throws InputError when the file cannot be read.
std::string config_hash(const std::filesystem::path& config);
// The same hash of bytes in memory: a config that a sweep's point runs without writing it.
std::string bytes_hash(std::string_view bytes);

// {"tribo_version", "git_commit", "command_line" (when recorded), "config", "config_hash",
// "date_utc", "threads"}. `git_commit` is the commit the binary was built from, with "+dirty"
// when tracked files had changes.
nlohmann::json provenance_json(const std::filesystem::path& config, const std::string& hash);

// As above, hashing `config`; an empty path (a command without a config file) gives null config
// and config_hash.
nlohmann::json provenance_json(const std::filesystem::path& config);

// Records argv for provenance_json's "command_line" (called once, from main).
void record_command_line(int argc, const char* const* argv);

// The provenance as CSV comment lines, "# key: value\n" per key in key order, to go above
// a CSV's column header. A string is written as it is unless that would not read back as the same
// string — a control character (a newline would end the comment), edge spaces, or text that
// parses as JSON ("123", "null") — then as a JSON string; other values as JSON. Every reader of
// tribo's CSVs skips leading lines that start with '#'.
std::string csv_provenance_header(const nlohmann::json& provenance);

// The provenance back from a CSV's leading "# key: value" lines (the inverse of
// csv_provenance_header). Reads up to, not including, the first line not starting with '#'.
nlohmann::json read_csv_provenance(std::istream& in);

}  // namespace tribo::cli
