// Helpers shared by the binding files of the `tribo._tribo` module.
#pragma once

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include <string>

namespace tribo::python {

namespace py = pybind11;

// A JSON document as Python objects (dict / list / float / str / None). Goes through the JSON
// text on purpose: nlohmann writes doubles in their shortest round-trip form, as the CLI writes
// its .json files, so a value read here is the bit-identical double a user reads from the file.
inline py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

void bind_contact(py::module_& m);
void bind_lubrication(py::module_& m);
void bind_rig(py::module_& m);
void bind_homogenise(py::module_& m);
void bind_cli_contact(py::module_& m);
void bind_cli_reynolds(py::module_& m);

}  // namespace tribo::python
