// The library's typed errors (core/error.hpp) as Python exceptions that carry the CLI's message.
// Bad input is a ValueError (ParseError, InvalidInputError) and an unreadable or unwritable file
// an OSError (IoError), as the issue of the module asks; each is its own subclass so a caller can
// tell a malformed file from an impossible scene.
#include <pybind11/pybind11.h>

#include "core/error.hpp"
#include "python/bindings/bindings.hpp"

namespace wifislam::python {

void bind_errors(pybind11::module_& m) {
  namespace py = pybind11;
  py::register_exception<ParseError>(m, "ParseError", PyExc_ValueError);
  py::register_exception<InvalidInputError>(m, "InvalidInputError", PyExc_ValueError);
  py::register_exception<IoError>(m, "IoError", PyExc_OSError);
  py::register_exception<ExternalSystemError>(m, "ExternalSystemError", PyExc_RuntimeError);
  py::register_exception<RequirementNotMetError>(m, "RequirementNotMetError", PyExc_AssertionError);
  // OSMesa or Embree unusable on this machine: not the caller's input.
  py::register_exception<EnvironmentError>(m, "FacilityError", PyExc_RuntimeError);
}

}  // namespace wifislam::python
