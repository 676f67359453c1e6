#include "apps/provenance.h"

#include <omp.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <istream>
#include <iterator>
#include <mutex>
#include <vector>

#include "apps/config.h"
#include "tribo_build_info.h"  // TRIBO_GIT_COMMIT, refreshed at every build (cmake/TriboBuildInfo.cmake)

namespace tribo::cli {
namespace {

std::mutex command_line_mutex;
std::vector<std::string> command_line;

// A string that comes back unchanged when written bare after "# key: ".
bool writes_bare(const std::string& s) {
  if (s.empty() || std::isspace(static_cast<unsigned char>(s.front())) || std::isspace(static_cast<unsigned char>(s.back())))
    return false;
  for (unsigned char c : s)
    if (c < 0x20 || c == 0x7f) return false;
  return !nlohmann::json::accept(s);  // "123" or "null" would read back as a number or null
}

}  // namespace

std::string bytes_hash(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

std::string config_hash(const std::filesystem::path& config) {
  std::ifstream in(config, std::ios::binary);
  if (!in) throw InputError(config.string() + ": cannot read");
  return bytes_hash(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
}

void record_command_line(int argc, const char* const* argv) {
  std::lock_guard lock(command_line_mutex);
  command_line.assign(argv, argv + argc);
}

nlohmann::json provenance_json(const std::filesystem::path& config, const std::string& hash) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc);
  nlohmann::json j{{"tribo_version", TRIBO_VERSION},
                   {"git_commit", TRIBO_GIT_COMMIT},
                   {"config", config.empty() ? nlohmann::json(nullptr) : nlohmann::json(std::filesystem::absolute(config).string())},
                   {"config_hash", hash.empty() ? nlohmann::json(nullptr) : nlohmann::json(hash)},
                   {"date_utc", date},
                   {"threads", omp_get_max_threads()}};
  std::lock_guard lock(command_line_mutex);
  if (!command_line.empty()) j["command_line"] = command_line;
  return j;
}

nlohmann::json provenance_json(const std::filesystem::path& config) {
  return provenance_json(config, config.empty() ? std::string() : config_hash(config));
}

std::string csv_provenance_header(const nlohmann::json& provenance) {
  std::string out;
  for (const auto& [key, value] : provenance.items()) {
    const bool bare = value.is_string() && writes_bare(value.get<std::string>());
    out += "# " + key + ": " + (bare ? value.get<std::string>() : value.dump()) + "\n";
  }
  return out;
}

nlohmann::json read_csv_provenance(std::istream& in) {
  nlohmann::json j = nlohmann::json::object();
  while (in.peek() == '#') {
    std::string line;
    std::getline(in, line);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto colon = line.find(": ");
    if (line.rfind("# ", 0) != 0 || colon == std::string::npos) continue;  // a comment, not a key
    const std::string key = line.substr(2, colon - 2), value = line.substr(colon + 2);
    j[key] = nlohmann::json::accept(value) ? nlohmann::json::parse(value) : nlohmann::json(value);
  }
  return j;
}

}  // namespace tribo::cli
