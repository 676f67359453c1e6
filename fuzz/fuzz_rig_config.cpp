// libFuzzer harness for the `tribo rig` config loader (apps/rig_config.h): the input is the TOML
// text, parsed in memory and loaded as if it were /nonexistent/tribo-fuzz/rig.toml (relative file
// names in it then name nothing). Bad input must end as InputError or std::invalid_argument (the
// CLI's exit status 2); any other exception, a sanitizer report or a hang is a finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "apps/config.h"
#include "apps/rig_config.h"
#include "fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = "/nonexistent/tribo-fuzz/rig.toml";
  try {
    const toml::table doc =
        tribo::cli::parse_toml_text(std::string_view(reinterpret_cast<const char*>(data), size), path);
    const tribo::cli::RigRun run = tribo::cli::load_rig_run(doc, path);
    TRIBO_FUZZ_CHECK(run.law != nullptr);
    TRIBO_FUZZ_CHECK(run.rig.mass_kg > 0.0 && run.rig.stiffness_N_per_m > 0.0 && run.options.duration_s > 0.0);
  } catch (const tribo::cli::InputError& e) {
    // Names a file: the config, or one it refers to (a drive table, a law table).
    TRIBO_FUZZ_CHECK(std::string_view(e.what()).find('/') != std::string_view::npos);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
