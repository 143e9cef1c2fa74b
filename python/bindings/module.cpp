// The `wifislam._wifislam` extension. The `wifislam` package (python/wifislam/__init__.py)
// wraps it with docstrings, frames as dataclasses and argument handling; users import that.
#include "python/bindings/bindings.hpp"

PYBIND11_MODULE(_wifislam, m) {
  m.doc() = "wifislam's libraries for Python (use the `wifislam` package, which wraps this).";
  m.attr("__version__") = WIFISLAM_VERSION;
  wifislam::python::bind_errors(m);
  wifislam::python::bind_scene(m);
  wifislam::python::bind_streams(m);
  wifislam::python::bind_views(m);
  wifislam::python::bind_runs(m);
}
