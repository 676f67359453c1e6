#include "apps/sweep_state.h"

#include <charconv>
#include <fstream>
#include <iterator>

#include "apps/config.h"

namespace tribo::cli {

std::optional<nlohmann::json> read_sweep_json(const std::filesystem::path& dir, const std::string& spec_hash,
                                              const std::string& base_hash, const std::string& rig_hash) {
  std::ifstream in(dir / "sweep.json");
  if (!in) return std::nullopt;
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  const auto text = [&](const char* key) {  // "" when absent or not a string
    const auto it = j.find(key);
    return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  if (j.is_discarded() || !j.is_object() || text("spec_hash") != spec_hash || text("base_config_hash") != base_hash ||
      text("rig_config_hash") != rig_hash)
    throw InputError(dir.string() + ": holds a sweep of a different spec or base config (sweep.json); "
                     "resume only with the same files, or use another --out");
  return j;
}

// Complete lines only: a kill mid-write leaves a torn last line, which is dropped.
std::map<int, std::string> finished_sweep_rows(const std::filesystem::path& file, const std::string& expected) {
  std::map<int, std::string> rows;
  std::ifstream in(file, std::ios::binary);
  if (!in) return rows;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t start = 0;
  bool first = true;
  int line_number = 0;
  for (std::size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1) {
    ++line_number;
    const std::string line = text.substr(start, nl - start);
    if (first && line.rfind('#', 0) == 0) continue;  // provenance lines of a results.csv from before 2026-11-27
    if (first) {
      if (line != expected) throw InputError(file.string() + ": its columns differ from this spec's; use another --out");
      first = false;
      continue;
    }
    const std::string id = line.substr(0, line.find(','));
    int point = -1;
    const auto [end, ec] = std::from_chars(id.data(), id.data() + id.size(), point);
    if (ec != std::errc() || end != id.data() + id.size() || point < 0)
      throw InputError(file.string() + ": line " + std::to_string(line_number) + ": the point id '" + id +
                       "' is not a non-negative integer; use another --out");
    if (!rows.emplace(point, line).second)
      throw InputError(file.string() + ": line " + std::to_string(line_number) + ": point " + id + " is there twice; use another --out");
  }
  return rows;
}

}  // namespace tribo::cli
