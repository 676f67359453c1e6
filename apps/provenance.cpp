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

std::string git_commit() { return TRIBO_GIT_COMMIT; }

std::string build_identity() {
  static const std::string identity = [] {
    const std::string commit = git_commit();
    if (commit != "unknown" && commit.find("+dirty") == std::string::npos) return commit;
    std::ifstream exe("/proc/self/exe", std::ios::binary);
    if (!exe) return commit + "#unreadable";
    return commit + "#" + bytes_hash(std::string(std::istreambuf_iterator<char>(exe), std::istreambuf_iterator<char>()));
  }();
  return identity;
}

void record_command_line(int argc, const char* const* argv) {
  std::lock_guard lock(command_line_mutex);
  command_line.assign(argv, argv + argc);
}

nlohmann::json provenance_json(const std::filesystem::path& config, const std::string& hash, const InputFiles& inputs) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc);
  nlohmann::json j{{"tribo_version", TRIBO_VERSION},
                   {"git_commit", git_commit()},
                   {"config", config.empty() ? nlohmann::json(nullptr) : nlohmann::json(std::filesystem::absolute(config).string())},
                   {"config_hash", hash.empty() ? nlohmann::json(nullptr) : nlohmann::json(hash)},
                   {"inputs", nlohmann::json::array()},
                   {"date_utc", date},
                   {"threads", omp_get_max_threads()}};
  auto listed = [&](const std::filesystem::path& p, const std::string& h) {
    j["inputs"].push_back({{"path", std::filesystem::absolute(p).lexically_normal().string()}, {"hash", h}});
  };
  if (!config.empty()) listed(config, hash);
  for (const std::filesystem::path& p : inputs) listed(p, config_hash(p));
  std::lock_guard lock(command_line_mutex);
  if (!command_line.empty()) j["command_line"] = command_line;
  return j;
}

nlohmann::json provenance_json(const std::filesystem::path& config, const InputFiles& inputs) {
  return provenance_json(config, config.empty() ? std::string() : config_hash(config), inputs);
}

}  // namespace tribo::cli
