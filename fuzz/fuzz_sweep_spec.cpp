// libFuzzer harness for `tribo sweep` specs (apps/sweep_spec.h). The input is up to three files
// separated by a line "%%%": the spec, the base config it may name as "base.toml", and a second
// config "rig.toml" (the rig step of a chain). Without a second part base.toml is a small rig
// config. They are written to a scratch folder; load_sweep_spec reads the spec, then the points
// are enumerated. Bad input must end as InputError or std::invalid_argument; anything else, a
// sanitizer report, a hang or a giant allocation is a finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "apps/config.h"
#include "apps/sweep_spec.h"
#include "fuzz/fuzz_check.h"
#include "fuzz/fuzz_temp_dir.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using tribo::fuzz::scratch_dir;
  tribo::fuzz::clear_scratch();
  const auto parts = tribo::fuzz::split_parts(std::string(reinterpret_cast<const char*>(data), size));
  tribo::fuzz::write_file(scratch_dir() / "spec.toml", parts[0]);
  tribo::fuzz::write_file(scratch_dir() / "base.toml",
                          parts.size() > 1 ? parts[1] : "[rig]\ndrive_speed_m_per_s = 1e-3\n[friction]\nmu_s = 0.3\n");
  if (parts.size() > 2) tribo::fuzz::write_file(scratch_dir() / "rig.toml", parts[2]);
  try {
    const tribo::cli::SweepSpec spec = tribo::cli::load_sweep_spec(scratch_dir() / "spec.toml");
    TRIBO_FUZZ_CHECK(!spec.axes.empty());
    std::size_t expected = spec.zip ? spec.axes.front().values.size() : 1;
    for (const auto& a : spec.axes) {
      TRIBO_FUZZ_CHECK(!a.values.empty());
      if (!spec.zip) expected *= a.values.size();
    }
    // A grid of more than 10⁵ points is enumerated in seconds under the sanitizers (10⁶ in 2.2 s),
    // past the timeout when the cores are shared (twice, 2026-11-29): the fuzzer is here for the
    // parser, so its enumeration is left to the smaller grids.
    if (expected > 100000) return 0;
    const auto points = tribo::cli::sweep_points(spec);
    TRIBO_FUZZ_CHECK(points.size() == expected);
  } catch (const tribo::cli::InputError&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
