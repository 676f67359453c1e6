// `tribo reynolds CONFIG.toml` in-process: the CLI's own reader and solve (apps/reynolds_run.h, in
// tribo_cli), so the numbers are the ones reynolds.json holds.
#include <filesystem>

#include <pybind11/eigen.h>
#include <pybind11/stl/filesystem.h>

#include "apps/reynolds_run.h"
#include "python/common.h"

namespace tribo::python {
namespace {

py::dict reynolds_from_toml(const std::filesystem::path& config) {
  const cli::ReynoldsRun run = cli::load_reynolds_run(config);
  cli::ReynoldsSolve solved;
  {
    py::gil_scoped_release release;
    solved = cli::solve_reynolds_run(run);
  }
  const lubrication::ReynoldsSolution& s = solved.solution;
  py::dict d;
  d["summary"] = to_python(solved.summary);
  d["problem"] = run.problem;
  d["pressure_Pa"] = s.pressure_Pa;
  d["fill_fraction"] = s.fill_fraction;
  d["wetted"] = s.wetted;
  d["gap_m"] = run.problem.gap_m;
  return d;
}

}  // namespace

void bind_cli_reynolds(py::module_& m) {
  using namespace pybind11::literals;
  m.def("reynolds_from_toml", &reynolds_from_toml,
        R"(`tribo reynolds CONFIG.toml` in-process ([geometry] parallel_discs | gap_file | rough_pair,
[lubricant], [motion], [grid], [solver]; docs/lubrication.md), read by the CLI's own reader.

Returns dict: summary (reynolds.json, key for key: load_N (N), max_pressure_Pa, cavitated_fraction,
iterations, converged, residual, message, geometry {…}, grid {…}, reference_load_N for discs, …),
problem (the ReynoldsProblem, to edit and pass to solve_reynolds), and the fields pressure_Pa,
fill_fraction, wetted, gap_m — arrays (nx, ny). A bad config raises ValueError with the CLI's
message; non-convergence is summary["converged"] = False.)",
        "path"_a);
}

}  // namespace tribo::python
