// libFuzzer harness for the `tribo gap diagnose --model` loader (apps/gap_model.h): the input is the
// TOML text, parsed in memory and loaded as if it were /nonexistent/tribo-fuzz/model.toml (a law
// table named in it then names nothing). Bad input must end as InputError or std::invalid_argument
// (exit status 2); a model that loads has a positive rig wherever it states one; anything else is a
// finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "apps/config.h"
#include "apps/gap_model.h"
#include "fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = "/nonexistent/tribo-fuzz/model.toml";
  try {
    const toml::table doc = tribo::cli::parse_toml_text(std::string_view(reinterpret_cast<const char*>(data), size), path);
    const tribo::cli::GapModel m = tribo::cli::load_gap_model(doc, path);
    TRIBO_FUZZ_CHECK(m.rig.mass_kg > 0.0 && m.rig.stiffness_N_per_m > 0.0 && m.rig.damping_N_s_per_m >= 0.0);
    TRIBO_FUZZ_CHECK(m.missing_rig_keys.size() <= 3);
  } catch (const tribo::cli::InputError& e) {
    TRIBO_FUZZ_CHECK(std::string_view(e.what()).find('/') != std::string_view::npos);  // names the model or a file it names
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
