// `tribo._tribo`: the pybind11 module behind the `tribo` Python package (python/tribo/__init__.py).
//
// Conventions for every binding:
//   fields     a 2-D float64 NumPy array of shape (nx, ny) with a[i, j] = f(i, j), i along x —
//              the Eigen::ArrayXXd layout of contact/grid.h (returned arrays are Fortran-ordered,
//              so memory order matches Eigen's j·nx + i; any 2-D array is accepted as input);
//   units      SI, named in every argument and key (…_m, …_Pa, …_N, …_m_per_s);
//   errors     bad input → ValueError with tribo's one-line message (the CLI's InputError and the
//              libraries' std::invalid_argument); a solver that does not converge is not an
//              error: its summary says converged = False and why.
#include <pybind11/pybind11.h>

#include <stdexcept>

#include "apps/config.h"
#include "python/common.h"

PYBIND11_MODULE(_tribo, m) {
  m.doc() = "tribo: rough-surface contact, Reynolds films, homogenised friction laws and the friction rig";
  // InputError derives from std::runtime_error, which pybind11 would raise as RuntimeError; it is
  // bad input, so ValueError like std::invalid_argument (which pybind11 maps already).
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const tribo::cli::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  tribo::python::bind_contact(m);
  tribo::python::bind_lubrication(m);
  tribo::python::bind_rig(m);
  tribo::python::bind_homogenise(m);
  tribo::python::bind_cli_contact(m);
  tribo::python::bind_cli_reynolds(m);
}
