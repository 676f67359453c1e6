// libFuzzer harness for the experiment-bundle reader (gap/bundle.h). The input is the bundle's
// files one after another, separated by a line "%%%", in the order
//   experiment.toml, static_friction.csv, runs.csv, regimes.csv, traces/a.csv, traces/b.csv
// (fewer parts: the later files are absent; a part that is exactly "-" is an absent file). They
// are written to a scratch folder and read with read_bundle. The documented error is
// std::invalid_argument naming the file; anything else escaping is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "fuzz/fuzz_check.h"
#include "fuzz/fuzz_temp_dir.h"
#include "gap/bundle.h"

namespace {

bool finite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using tribo::fuzz::scratch_dir;
  static const char* const kFiles[] = {"experiment.toml", "static_friction.csv", "runs.csv",
                                       "regimes.csv",     "traces/a.csv",        "traces/b.csv"};
  tribo::fuzz::clear_scratch();
  const auto parts = tribo::fuzz::split_parts(std::string(reinterpret_cast<const char*>(data), size));
  for (std::size_t k = 0; k < parts.size() && k < std::size(kFiles); ++k) {
    if (parts[k] == "-" || parts[k] == "-\n") continue;
    tribo::fuzz::write_file(scratch_dir() / kFiles[k], parts[k]);
  }
  try {
    const tribo::gap::ExperimentBundle b = tribo::gap::read_bundle(scratch_dir());
    TRIBO_FUZZ_CHECK(!b.static_points.empty() || !b.runs.empty() || !b.regimes.empty());
    for (const auto& r : b.runs) {
      const auto& t = r.trace;
      TRIBO_FUZZ_CHECK(t.t_s.size() >= 3 && finite(t.t_s));
      for (std::size_t i = 1; i < t.t_s.size(); ++i) TRIBO_FUZZ_CHECK(t.t_s[i] > t.t_s[i - 1]);
      for (const auto* c : {&t.x_m, &t.xdot_m_per_s, &t.friction_N, &t.mu, &t.x_drive_m, &t.v_drive_m_per_s, &t.normal_stress_Pa})
        TRIBO_FUZZ_CHECK(c->empty() || (c->size() == t.t_s.size() && finite(*c)));
      TRIBO_FUZZ_CHECK(std::isfinite(r.v_m_per_s) && r.v_m_per_s >= 0.0);
    }
    for (const auto& p : b.static_points) TRIBO_FUZZ_CHECK(p.phi_dot_per_s > 0.0 && std::isfinite(p.mu_s) && p.mu_s >= 0.0);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
