// Homogenisation (homogenise/): one rough patch's micro solves, the whole pipeline as
// `tribo homogenise` runs it, and reading law.json — all from the CLI's config reader
// (apps/homogenise_config.h) so options and defaults are the CLI's.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>

#include "apps/homogenise_config.h"
#include "apps/homogenise_run.h"
#include "homogenise/patch.h"
#include "python/common.h"
#include "rig/law_table.h"

namespace tribo::python {
namespace {

py::dict options_summary(const homogenise::HomogeniseOptions& o) {
  py::dict d;
  d["grid"] = o.surface.grid;
  d["size_m"] = o.surface.size_m;
  d["rms_height_m"] = o.surface.rms_height_m;
  d["seed"] = o.surface.seed;
  d["realisations"] = o.realisations;
  d["e_star_Pa"] = o.e_star_Pa;
  d["hardness_Pa"] = o.hardness_Pa;
  d["alpha"] = o.alpha;
  d["interface_shear_strength_Pa"] = o.interface_shear_strength_Pa;
  d["viscosity_Pa_s"] = o.lubricant.viscosity_Pa_s;
  d["pin_radius_m"] = o.pin.radius_m;
  d["normal_load_N"] = o.pin.normal_load_N;
  d["separation_ratios"] = o.separation_ratios;
  return d;
}

py::dict patch_from_toml(const std::filesystem::path& config, int realisation) {
  const cli::HomogeniseRun run = cli::load_homogenise_run(config);
  if (realisation < 0) throw std::invalid_argument("realisation: must be >= 0");
  homogenise::PatchResult p;
  {
    py::gil_scoped_release release;
    p = homogenise::solve_patch(run.options, realisation);
  }
  py::dict d = to_python(homogenise::to_json(p));
  d["options"] = options_summary(run.options);
  return d;
}

py::object homogenise_from_toml(const std::filesystem::path& config, const std::filesystem::path& out, bool plots) {
  const cli::HomogeniseRun run = cli::load_homogenise_run(config);
  nlohmann::json law;
  {
    py::gil_scoped_release release;
    law = cli::homogenise_into(run, config, out, plots);
  }
  return to_python(law);
}

py::dict read_law(const std::filesystem::path& path) {
  const rig::LawTable t = rig::read_law_table(path);  // validates: a defect is a ValueError
  py::dict table;
  table["separation_m"] = py::array(py::cast(t.separation_m));
  table["solid_load_N"] = py::array(py::cast(t.solid_load_N));
  table["real_area_m2"] = py::array(py::cast(t.real_area_m2));
  table["lift_per_eta_u_m"] = py::array(py::cast(t.lift_per_eta_u_m));
  table["squeeze_per_eta_m"] = py::array(py::cast(t.squeeze_per_eta_m));
  table["shear_per_eta_u_m"] = py::array(py::cast(t.shear_per_eta_u_m));
  std::ifstream in(path);
  py::dict d;
  d["table"] = table;
  d["document"] = to_python(nlohmann::json::parse(in));
  return d;
}

}  // namespace

void bind_homogenise(py::module_& m) {
  using namespace pybind11::literals;
  m.def("homogenise_patch_from_toml", &patch_from_toml,
        R"(Every micro solve of one rough realisation (seed = surface.seed + realisation) of a
`tribo homogenise` config (docs/homogenise.md), on the calling thread.

Returns dict (lists per table separation): separation_m (m), solid_pressure_Pa (nominal N_s/L^2),
area_fraction (A_r/L^2), phi_x, phi_y, phi_s (Patir-Cheng flow factors), film_over_sigma,
phi_f, couette_shear_factor, phi_fp, contact_fraction, lift_per_eta_u_per_m (rugosity lift p/(eta U), 1/m);
mu_s_max, mu_boundary at the pin's nominal pressure on the junction grid (and _coarse, _coarser on its half and
quarter); first_contact_separation_m; bem_iterations,
stage_wall_s, unconverged, messages; options (the config's main values).)",
        "path"_a, "realisation"_a = 0);
  m.def("homogenise_from_toml", &homogenise_from_toml,
        R"(Run `tribo homogenise CONFIG --out OUT` in-process: realisations (cached in OUT/patches, so a
killed run resumes), cell table, pin table, OUT/law.json, stribeck.csv, area.csv (plots only with
plots=True). Returns law.json as a dict (junction.mu_s_max, table {…}, stribeck [{U_m_per_s, mu, …}], …).)",
        "path"_a, "out_dir"_a, "plots"_a = false);
  m.def("read_law", &read_law,
        R"(Read a friction law file law.json ("tribo-law-1", rig/law_table.h), checked as the rig checks it
(a defect raises ValueError). Returns dict: table {separation_m (m), solid_load_N (N), real_area_m2 (m^2),
lift_per_eta_u_m, squeeze_per_eta_m, shear_per_eta_u_m (m)} as arrays, and document (the whole file).)",
        "path"_a);
}

}  // namespace tribo::python
