// libFuzzer harness for the `tribo homogenise` config loader (apps/homogenise_config.h): the
// input is the TOML text, parsed in memory. Bad input must end as InputError or
// std::invalid_argument (exit status 2); anything else is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "apps/config.h"
#include "apps/homogenise_config.h"
#include "fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = "/nonexistent/tribo-fuzz/homogenise.toml";
  try {
    const toml::table doc =
        tribo::cli::parse_toml_text(std::string_view(reinterpret_cast<const char*>(data), size), path);
    const tribo::cli::HomogeniseRun run = tribo::cli::load_homogenise_run(doc, path);
    TRIBO_FUZZ_CHECK(run.speeds_m_per_s.size() >= 2);
    for (double u : run.speeds_m_per_s) TRIBO_FUZZ_CHECK(std::isfinite(u) && u > 0.0);
  } catch (const tribo::cli::InputError& e) {
    // Names a file: the config, or one it refers to (a drive table, a law table).
    TRIBO_FUZZ_CHECK(std::string_view(e.what()).find('/') != std::string_view::npos);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
