// The Reynolds film solve: problems (a class, so a notebook can edit a field and solve again),
// the geometries of lubrication/geometry.h, and the solver.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>
#include <string>

#include "lubrication/geometry.h"
#include "lubrication/reynolds.h"
#include "python/common.h"

namespace tribo::python {
namespace {

namespace lub = tribo::lubrication;
using Eigen::ArrayXXd;

lub::Cavitation cavitation_from(const std::string& name) {
  if (name == "none") return lub::Cavitation::none;
  if (name == "mass_conserving") return lub::Cavitation::mass_conserving;
  throw std::invalid_argument("cavitation: '" + name + "' is not one of none, mass_conserving");
}
std::string cavitation_name(lub::Cavitation c) { return c == lub::Cavitation::none ? "none" : "mass_conserving"; }

lub::BoundaryY boundary_from(const std::string& name) {
  if (name == "ambient") return lub::BoundaryY::ambient;
  if (name == "periodic") return lub::BoundaryY::periodic;
  throw std::invalid_argument("boundary_y: '" + name + "' is not one of ambient, periodic");
}

// A film h (m) on nodes at spacing dx_m × dy_m, with the rest of the problem from keywords.
lub::ReynoldsProblem make_problem(const ArrayXXd& gap_m, double dx_m, std::optional<double> dy_m,
                                  double viscosity_Pa_s, double sliding_speed_m_per_s,
                                  const std::optional<ArrayXXd>& gap_rate_m_per_s, double pressure_viscosity_per_Pa,
                                  double inlet_pressure_Pa, double outlet_pressure_Pa, const std::string& boundary_y,
                                  const std::string& cavitation) {
  lub::ReynoldsProblem p;
  p.grid = contact::Grid{gap_m.rows(), gap_m.cols(), dx_m, dy_m.value_or(dx_m)};
  p.gap_m = gap_m;
  if (gap_rate_m_per_s) p.gap_rate_m_per_s = *gap_rate_m_per_s;
  p.viscosity_Pa_s = viscosity_Pa_s;
  p.sliding_speed_m_per_s = sliding_speed_m_per_s;
  p.pressure_viscosity_per_Pa = pressure_viscosity_per_Pa;
  p.inlet_pressure_Pa = inlet_pressure_Pa;
  p.outlet_pressure_Pa = outlet_pressure_Pa;
  p.boundary_y = boundary_from(boundary_y);
  p.cavitation = cavitation_from(cavitation);
  lub::validate(p);
  return p;
}

py::dict solve(const lub::ReynoldsProblem& problem, double newton_tolerance, int max_newton_iterations,
               const std::string& complementarity, const std::string& pressure_solver) {
  lub::ReynoldsOptions o;
  o.newton_tolerance = newton_tolerance;
  o.max_newton_iterations = max_newton_iterations;
  if (complementarity == "minimum") o.complementarity = lub::Complementarity::minimum;
  else if (complementarity == "fischer_burmeister") o.complementarity = lub::Complementarity::fischer_burmeister;
  else throw std::invalid_argument("complementarity: '" + complementarity + "' is not one of minimum, fischer_burmeister");
  if (pressure_solver == "automatic") o.pressure_solver = lub::PressureSolver::automatic;
  else if (pressure_solver == "direct") o.pressure_solver = lub::PressureSolver::direct;
  else if (pressure_solver == "multigrid") o.pressure_solver = lub::PressureSolver::multigrid;
  else throw std::invalid_argument("pressure_solver: '" + pressure_solver + "' is not one of automatic, direct, multigrid");
  lub::validate(problem);
  lub::ReynoldsSolution s;
  {
    py::gil_scoped_release release;
    s = lub::solve_reynolds(problem, o);
  }
  py::dict d;
  d["pressure_Pa"] = s.pressure_Pa;
  d["fill_fraction"] = s.fill_fraction;
  d["wetted"] = s.wetted;
  d["load_N"] = s.load_N;
  d["max_pressure_Pa"] = s.max_pressure_Pa;
  d["cavitated_fraction"] = s.cavitated_fraction;
  py::dict sum;
  sum["converged"] = s.summary.converged;
  sum["iterations"] = s.summary.iterations;
  sum["residual"] = s.summary.residual;
  sum["message"] = s.summary.message;
  sum["linear_solver"] = s.summary.linear_solver;
  sum["linear_solver_s"] = s.summary.linear_solver_s;
  sum["linear_iterations"] = s.summary.linear_iterations;
  sum["linear_residual"] = s.summary.linear_residual;
  sum["wall_s"] = s.summary.wall_s;
  d["summary"] = sum;
  // Mass balance of the discrete fluxes (m³/s), for checking a solution in a notebook.
  const lub::FilmFlow f = lub::film_flow(problem, s);
  py::dict flow;
  flow["inflow_x0_m3_per_s"] = f.inflow_x0_m3_per_s;
  flow["outflow_xL_m3_per_s"] = f.outflow_xL_m3_per_s;
  flow["net_outflow_m3_per_s"] = f.net_outflow_m3_per_s;
  flow["squeeze_storage_m3_per_s"] = f.squeeze_storage_m3_per_s;
  flow["max_cell_imbalance_m3_per_s"] = f.max_cell_imbalance_m3_per_s;
  d["flow"] = flow;
  return d;
}

py::dict rough_pair(const ArrayXXd& upper_m, const ArrayXXd& lower_m, double size_m, std::optional<double> mean_gap_m,
                    std::optional<double> normal_load_N, std::optional<double> composite_modulus_Pa,
                    std::optional<double> hardness_Pa, double contact_gap_fraction, double contact_tolerance) {
  lub::RoughPairFilmOptions o;
  o.mean_gap_m = mean_gap_m;
  o.normal_load_N = normal_load_N;
  if (composite_modulus_Pa) o.composite_modulus_Pa = *composite_modulus_Pa;
  if (hardness_Pa) o.hardness_Pa = *hardness_Pa;
  o.contact_gap_fraction = contact_gap_fraction;
  o.contact.tolerance = contact_tolerance;
  if (std::string why; !o.is_valid(&why)) throw std::invalid_argument(why);
  std::optional<lub::RoughPairFilm> film;
  {
    py::gil_scoped_release release;
    film = lub::rough_pair_film(upper_m, lower_m, size_m, o);
  }
  py::dict d;
  d["problem"] = film->problem;
  d["contact_nodes"] = film->contact_nodes;
  d["composite_rms_height_m"] = film->composite_rms_height_m;
  d["floor_m"] = film->floor_m;
  d["mean_film_m"] = film->mean_film_m;
  if (film->contact) {
    const contact::NormalContactResult& c = *film->contact;
    py::dict cd;
    cd["pressure_Pa"] = c.pressure_Pa;
    cd["gap_m"] = c.gap_m;
    cd["area_fraction"] = c.area_fraction;
    cd["real_area_m2"] = c.real_area_m2;
    cd["mean_gap_m"] = c.mean_gap_m;
    cd["approach_m"] = c.approach_m;
    cd["converged"] = c.summary.converged;
    cd["iterations"] = c.summary.iterations;
    cd["residual"] = c.summary.residual;
    cd["message"] = c.summary.message;
    d["contact"] = cd;
  } else {
    d["contact"] = py::none();
  }
  return d;
}

}  // namespace

void bind_lubrication(py::module_& m) {
  using namespace pybind11::literals;

  py::class_<contact::Grid>(m, "Grid", "nx x ny points at spacing dx_m x dy_m (m); fields are arrays (nx, ny).")
      .def(py::init([](Eigen::Index nx, Eigen::Index ny, double dx_m, double dy_m) {
             return contact::Grid{nx, ny, dx_m, dy_m};
           }),
           "nx"_a, "ny"_a, "dx_m"_a, "dy_m"_a)
      .def_readwrite("nx", &contact::Grid::nx)
      .def_readwrite("ny", &contact::Grid::ny)
      .def_readwrite("dx_m", &contact::Grid::dx_m, "spacing along x (m)")
      .def_readwrite("dy_m", &contact::Grid::dy_m, "spacing along y (m)")
      .def("__repr__", [](const contact::Grid& g) {
        return "Grid(nx=" + std::to_string(g.nx) + ", ny=" + std::to_string(g.ny) + ", dx_m=" + std::to_string(g.dx_m) +
               ", dy_m=" + std::to_string(g.dy_m) + ")";
      });

  py::class_<lub::ReynoldsProblem>(m, "ReynoldsProblem",
                                   R"(A Reynolds film problem (lubrication/reynolds.h) on nx x ny nodes.

Fields are float64 arrays (nx, ny), a[i, j] at x = i dx, y = j dy, x the sliding direction; an
empty array (shape (0, 0)) means "not given". Attributes (SI): grid, gap_m (> 0), gap_rate_m_per_s
(dh/dt, m/s; empty = 0), viscosity_Pa_s, pressure_viscosity_per_Pa (Barus psi, 1/Pa),
sliding_speed_m_per_s (U = U1 + U2 along +x), inlet_pressure_Pa, outlet_pressure_Pa, boundary_y
("ambient" | "periodic"), cavitation ("none" | "mass_conserving"), disc (centre_x_m, centre_y_m,
radius_m) or None, pressure_flow_factor_x / _y (Patir-Cheng phi, empty = 1), couette_film_m (empty = gap).)")
      .def(py::init<>(), "An empty problem (every field empty); see reynolds_problem for a filled one.")
      .def_readwrite("grid", &lub::ReynoldsProblem::grid)
      .def_readwrite("gap_m", &lub::ReynoldsProblem::gap_m)
      .def_readwrite("gap_rate_m_per_s", &lub::ReynoldsProblem::gap_rate_m_per_s)
      .def_readwrite("viscosity_Pa_s", &lub::ReynoldsProblem::viscosity_Pa_s)
      .def_readwrite("pressure_viscosity_per_Pa", &lub::ReynoldsProblem::pressure_viscosity_per_Pa)
      .def_readwrite("sliding_speed_m_per_s", &lub::ReynoldsProblem::sliding_speed_m_per_s)
      .def_readwrite("inlet_pressure_Pa", &lub::ReynoldsProblem::inlet_pressure_Pa)
      .def_readwrite("outlet_pressure_Pa", &lub::ReynoldsProblem::outlet_pressure_Pa)
      .def_readwrite("pressure_flow_factor_x", &lub::ReynoldsProblem::pressure_flow_factor_x)
      .def_readwrite("pressure_flow_factor_y", &lub::ReynoldsProblem::pressure_flow_factor_y)
      .def_readwrite("couette_film_m", &lub::ReynoldsProblem::couette_film_m)
      .def_property(
          "boundary_y",
          [](const lub::ReynoldsProblem& p) { return p.boundary_y == lub::BoundaryY::ambient ? "ambient" : "periodic"; },
          [](lub::ReynoldsProblem& p, const std::string& s) { p.boundary_y = boundary_from(s); })
      .def_property(
          "cavitation", [](const lub::ReynoldsProblem& p) { return cavitation_name(p.cavitation); },
          [](lub::ReynoldsProblem& p, const std::string& s) { p.cavitation = cavitation_from(s); })
      .def_property(
          "disc",
          [](const lub::ReynoldsProblem& p) -> py::object {
            if (!p.disc) return py::none();
            return py::make_tuple(p.disc->centre_x_m, p.disc->centre_y_m, p.disc->radius_m);
          },
          [](lub::ReynoldsProblem& p, std::optional<std::tuple<double, double, double>> d) {
            if (!d) p.disc.reset();
            else p.disc = lub::DiscDomain{std::get<0>(*d), std::get<1>(*d), std::get<2>(*d)};
          })
      .def("validate", [](const lub::ReynoldsProblem& p) { lub::validate(p); },
           "Raise ValueError naming the first bad input.");

  m.def("reynolds_problem", &make_problem,
        R"(A rectangular Reynolds problem on the film gap_m (m, array (nx, ny), nodes at dx_m x dy_m).
viscosity_Pa_s (eta0), sliding_speed_m_per_s (U along +x), gap_rate_m_per_s (array (nx, ny), m/s,
None = 0), pressure_viscosity_per_Pa (Barus psi, 0 = isoviscous), inlet/outlet pressures (Pa at
x = 0 / x = Lx), boundary_y "ambient" | "periodic", cavitation "mass_conserving" (JFO) | "none".)",
        "gap_m"_a, "dx_m"_a, "dy_m"_a = py::none(), "viscosity_Pa_s"_a = 0.021, "sliding_speed_m_per_s"_a = 0.0,
        "gap_rate_m_per_s"_a = py::none(), "pressure_viscosity_per_Pa"_a = 0.0, "inlet_pressure_Pa"_a = 0.0,
        "outlet_pressure_Pa"_a = 0.0, "boundary_y"_a = "ambient", "cavitation"_a = "mass_conserving");
  m.def(
      "parallel_discs_problem",
      [](double radius_m, double gap_m, double gap_rate_m_per_s, double viscosity_Pa_s, double sliding_speed_m_per_s,
         int n, const std::string& cavitation) {
        if (n < 5) throw std::invalid_argument("n: must be >= 5 for parallel discs");
        lub::ReynoldsProblem p =
            lub::parallel_discs_problem(radius_m, gap_m, gap_rate_m_per_s, viscosity_Pa_s, sliding_speed_m_per_s, n);
        p.cavitation = cavitation_from(cavitation);
        lub::validate(p);
        return p;
      },
      R"(The thesis slider face on the disc (Appendix III): a circular film of radius radius_m (m),
uniform gap gap_m (m) closing at gap_rate_m_per_s (m/s, < 0 closes), on n x n nodes.)",
      "radius_m"_a = 4.7625e-3, "gap_m"_a = 1e-6, "gap_rate_m_per_s"_a = 0.0, "viscosity_Pa_s"_a = 0.021,
      "sliding_speed_m_per_s"_a = 0.0, "n"_a = 256, "cavitation"_a = "mass_conserving");
  m.def("periodic_film_cell", &lub::periodic_film_cell,
        R"(The Reynolds cell of an n x n periodic film film_m (m) on a patch of side size_m (m):
(n + 1) x n nodes, periodic in y, nothing else set (set viscosity, speed, cavitation after).)",
        "film_m"_a, "size_m"_a);
  m.def("rough_pair_film", &rough_pair,
        R"(The periodic Reynolds cell of two rough surfaces (lubrication/geometry.h rough_pair_film).

upper_m (slider), lower_m (disc): n x n height fields (m) on a square patch of side size_m (m).
Exactly one of mean_gap_m (rigid mean planes this far apart, m) and normal_load_N (pressed by this
solid load on an elastic(-plastic) periodic half-space of composite_modulus_Pa with the cap
hardness_Pa, None = elastic). The film is floored at contact_gap_fraction x composite sigma.
Returns dict: problem (ReynoldsProblem), contact_nodes, composite_rms_height_m, floor_m,
mean_film_m, contact (the contact solve's fields and summary, or None when rigid).)",
        "upper_m"_a, "lower_m"_a, "size_m"_a, "mean_gap_m"_a = py::none(), "normal_load_N"_a = py::none(),
        "composite_modulus_Pa"_a = py::none(), "hardness_Pa"_a = py::none(), "contact_gap_fraction"_a = 1e-3,
        "contact_tolerance"_a = 1e-8);
  m.def("solve_reynolds", &solve,
        R"(Solve a ReynoldsProblem (lubrication/reynolds.h).

Returns dict: pressure_Pa, fill_fraction (theta), wetted (bool) — arrays (nx, ny); load_N (N, the
integral of p), max_pressure_Pa, cavitated_fraction; summary {converged, iterations (Newton),
residual, message, linear_solver, linear_solver_s, linear_iterations, linear_residual, wall_s};
flow {inflow_x0_m3_per_s, outflow_xL_m3_per_s, net_outflow_m3_per_s, squeeze_storage_m3_per_s,
max_cell_imbalance_m3_per_s}. Non-convergence is reported in summary, not raised.)",
        "problem"_a, "newton_tolerance"_a = 1e-10, "max_newton_iterations"_a = 60,
        "complementarity"_a = "minimum", "pressure_solver"_a = "automatic");
}

}  // namespace tribo::python
