#include "apps/provenance.h"

#include <omp.h>

#include <cstdint>
#include <ctime>
#include <fstream>
#include <iterator>

#include "apps/config.h"

namespace tribo::cli {

std::string config_hash(const std::filesystem::path& config) {
  std::ifstream in(config, std::ios::binary);
  if (!in) throw InputError(config.string() + ": cannot read");
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (auto it = std::istreambuf_iterator<char>(in); it != std::istreambuf_iterator<char>(); ++it) {
    h ^= static_cast<unsigned char>(*it);
    h *= 0x100000001b3ULL;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

nlohmann::json provenance_json(const std::filesystem::path& config, const std::string& hash) {
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return {{"tribo_version", TRIBO_VERSION},
          {"git_commit", TRIBO_GIT_COMMIT},
          {"config", std::filesystem::absolute(config).string()},
          {"config_hash", hash},
          {"date_utc", date},
          {"threads", omp_get_max_threads()}};
}

}  // namespace tribo::cli
