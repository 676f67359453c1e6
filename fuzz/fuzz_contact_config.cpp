// libFuzzer harness for the `tribo contact` config loader (apps/contact_run.h), both subcommands:
// the first byte picks `contact` (even) or `contact junction` (odd), the rest is the TOML text,
// parsed in memory as /nonexistent/tribo-fuzz/contact.toml (a topography file named in it then
// names nothing). Bad input must end as InputError or std::invalid_argument (exit status 2); a
// config that loads must hold a gap and a material the solver accepts; anything else is a finding.
// A valid [domain] grid above 512 is skipped: loading synthesises the surface, and a 4512² one
// (the loader accepts up to 16384 on purpose) is seconds of legitimate work that only times out the
// fuzzer (2026-11-28) — the parser is what this harness is for.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "apps/config.h"
#include "apps/contact_run.h"
#include "fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const bool junction = data[0] % 2 == 1;
  const std::string path = "/nonexistent/tribo-fuzz/contact.toml";
  try {
    const toml::table doc = tribo::cli::parse_toml_text(std::string_view(reinterpret_cast<const char*>(data) + 1, size - 1), path);
    // value_exact, as the loader reads it: toml++'s value<int64_t> converts a float such as 1e42
    // with a cast whose overflow is undefined (its first libFuzzer run, 2026-11-28).
    if (const auto grid = doc["domain"]["grid"].value_exact<std::int64_t>(); grid && *grid > 512) return 0;
    const tribo::cli::ContactRun run = tribo::cli::load_contact_run(doc, path, junction);
    TRIBO_FUZZ_CHECK(run.grid.nx >= 1 && run.grid.ny >= 1 && run.grid.dx_m > 0.0 && run.grid.dy_m > 0.0);
    TRIBO_FUZZ_CHECK(run.gap0_m.rows() == run.grid.nx && run.gap0_m.cols() == run.grid.ny && run.gap0_m.allFinite());
    TRIBO_FUZZ_CHECK(std::isfinite(run.e_star_Pa) && run.e_star_Pa > 0.0);
    TRIBO_FUZZ_CHECK(!run.hardness_Pa || (std::isfinite(*run.hardness_Pa) && *run.hardness_Pa > 0.0));
    TRIBO_FUZZ_CHECK(std::isfinite(run.normal_load_N) && run.normal_load_N >= 0.0);
  } catch (const tribo::cli::InputError& e) {
    TRIBO_FUZZ_CHECK(std::string_view(e.what()).find('/') != std::string_view::npos);  // names the config or a file it names
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
