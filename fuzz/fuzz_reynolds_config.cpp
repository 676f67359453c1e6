// libFuzzer harness for the `tribo reynolds` config loader (apps/reynolds_run.h): the input is the
// TOML text, parsed in memory as /nonexistent/tribo-fuzz/reynolds.toml (a gap file named in it then
// names nothing). Bad input must end as InputError or std::invalid_argument (exit status 2); a
// config that loads must hold a film the solver accepts; anything else is a finding.
// Loading a rough pair generates both surfaces, and with a load solves their contact by the BEM —
// seconds under the sanitizers at large grids, past the fuzzer's timeout when the cores are
// shared. The fuzzer is here for the parser, which small grids exercise, so a rough pair on more
// than 256² nodes (a rigid 994² pair took 35 s), or pressed by a load on more than 64² (the
// default grid is 256²), is skipped; so is any other valid grid above 1024² (up to the loader's
// 8192², fields of 0.5 GiB each, past the fuzzer's memory limit).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "apps/config.h"
#include "apps/reynolds_run.h"
#include "fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = "/nonexistent/tribo-fuzz/reynolds.toml";
  try {
    const toml::table doc = tribo::cli::parse_toml_text(std::string_view(reinterpret_cast<const char*>(data), size), path);
    const std::int64_t n = doc["grid"]["n"].value_exact<std::int64_t>().value_or(256);
    if (doc["geometry"]["kind"].value_or(std::string_view{}) == "rough_pair") {
      if (n > (doc["geometry"]["normal_load_N"] ? 64 : 256)) return 0;
    } else if (n > 1024 && n <= 8192) {
      return 0;  // a valid grid of up to 0.5 GiB a field: the fuzzer's memory limit, not a defect
    }
    const tribo::cli::ReynoldsRun run = tribo::cli::load_reynolds_run(doc, path);
    const auto& pr = run.problem;
    TRIBO_FUZZ_CHECK(pr.grid.nx >= 1 && pr.grid.ny >= 1 && pr.grid.dx_m > 0.0 && pr.grid.dy_m > 0.0);
    TRIBO_FUZZ_CHECK(pr.gap_m.rows() == pr.grid.nx && pr.gap_m.cols() == pr.grid.ny && pr.gap_m.allFinite());
    TRIBO_FUZZ_CHECK(std::isfinite(pr.viscosity_Pa_s) && pr.viscosity_Pa_s > 0.0);
    TRIBO_FUZZ_CHECK(std::isfinite(pr.sliding_speed_m_per_s));
  } catch (const tribo::cli::InputError& e) {
    TRIBO_FUZZ_CHECK(std::string_view(e.what()).find('/') != std::string_view::npos);  // names the config or a file it names
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
