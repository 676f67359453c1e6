// libFuzzer harness for what `tribo sweep` reads of its output folder when it starts again
// (apps/sweep_state.h): the input is DIR/sweep.json, then, after a line `%%%`, DIR/results.csv
// (absent without one), written to the scratch folder and read as a resume of the 12-point rig
// sweep of the test cli.sweep_resumes_after_kills would read them (its hashes and column header; not a chain).
// Bad input must end as InputError naming the file (the CLI's exit status 2); any other exception,
// a sanitizer report or a hang is a finding, as is an accepted sweep.json that does not record
// the spec's hash or more rows than results.csv has complete lines after its header.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "apps/config.h"
#include "apps/sweep_state.h"
#include "fuzz/fuzz_check.h"
#include "fuzz/fuzz_temp_dir.h"

namespace {

constexpr const char* kSpecHash = "5c0e828414b129fc";
constexpr const char* kBaseHash = "289040ed90363f73";
constexpr const char* kHeader =
    "point_id,rig.drive_speed_m_per_s,rig.mass_kg,status,error,wall_s,regime,peak_to_peak_m,breakaways,config_hash";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  tribo::fuzz::clear_scratch();
  const std::filesystem::path& dir = tribo::fuzz::scratch_dir();
  const std::vector<std::string> parts = tribo::fuzz::split_parts(std::string(reinterpret_cast<const char*>(data), size));
  tribo::fuzz::write_file(dir / "sweep.json", parts[0]);
  if (parts.size() > 1) tribo::fuzz::write_file(dir / "results.csv", parts[1]);
  try {
    const std::optional<nlohmann::json> j = tribo::cli::read_sweep_json(dir, kSpecHash, kBaseHash, "");
    TRIBO_FUZZ_CHECK(j && j->is_object() && j->at("spec_hash") == kSpecHash);
  } catch (const tribo::cli::InputError& e) {
    TRIBO_FUZZ_CHECK(std::string_view(e.what()).find("sweep.json") != std::string_view::npos);
  }
  try {
    const std::map<int, std::string> rows = tribo::cli::finished_sweep_rows(dir / "results.csv", kHeader);
    const std::size_t lines = parts.size() > 1 ? static_cast<std::size_t>(std::count(parts[1].begin(), parts[1].end(), '\n')) : 0;
    TRIBO_FUZZ_CHECK(rows.empty() || rows.size() < lines);
    for (const auto& [id, row] : rows) TRIBO_FUZZ_CHECK(row.find('\n') == std::string::npos);
  } catch (const tribo::cli::InputError& e) {
    TRIBO_FUZZ_CHECK(std::string_view(e.what()).find("results.csv") != std::string_view::npos);
  }
  return 0;
}
