// `tribo contact CONFIG.toml` in-process: the CLI's own reader and solve (apps/contact_run.h, in
// tribo_cli), so the numbers are the ones contact.json holds.
#include <filesystem>

#include <pybind11/eigen.h>
#include <pybind11/stl/filesystem.h>

#include "apps/contact_run.h"
#include "python/common.h"

namespace tribo::python {
namespace {

py::dict contact_from_toml(const std::filesystem::path& config) {
  const cli::ContactRun run = cli::load_contact_run(config, false);
  cli::ContactSolve solved;
  {
    py::gil_scoped_release release;
    solved = cli::solve_contact_run(run);
  }
  const contact::NormalContactResult& r = solved.result;
  py::dict d;
  d["summary"] = to_python(solved.summary);
  d["gap0_m"] = run.gap0_m;
  d["pressure_Pa"] = r.pressure_Pa;
  d["gap_m"] = r.gap_m;
  d["displacement_m"] = r.displacement_m;
  d["plastic_increment_m"] = r.plastic_increment_m;
  return d;
}

}  // namespace

void bind_cli_contact(py::module_& m) {
  using namespace pybind11::literals;
  m.def("contact_from_toml", &contact_from_toml,
        R"(`tribo contact CONFIG.toml` in-process ([surface] sphere | gaussian | file, [domain], [material],
[load], [solver]; docs/contact.md), read by the CLI's own reader.

Returns dict: summary (contact.json, key for key: area_fraction, real_area_m2 (m^2), max_pressure_Pa,
mean_gap_m, approach_m, converged, iterations, residual, message, surface_rq_m, …) and the fields
gap0_m (initial gap, m), pressure_Pa, gap_m, displacement_m, plastic_increment_m — arrays (nx, ny).
A bad config raises ValueError with the CLI's message; non-convergence is summary["converged"] = False.)",
        "path"_a);
}

}  // namespace tribo::python
