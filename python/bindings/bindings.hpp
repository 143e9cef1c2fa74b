#pragma once
// The parts of the `wifislam._wifislam` extension module, one per concern; module.cpp calls each.
// The module is a thin layer: every call goes to the library function the CLI's command calls.

#include <pybind11/pybind11.h>

namespace wifislam::python {

void bind_errors(pybind11::module_& m);   // the library's errors as Python exceptions
void bind_scene(pybind11::module_& m);    // Scene: load, YAML text, as a dict
void bind_streams(pybind11::module_& m);  // frames from the simulator and from datasets
void bind_views(pybind11::module_& m);    // one rendered view, radio maps, PNG codecs
void bind_runs(pybind11::module_& m);     // generate, slam, evaluate

}  // namespace wifislam::python
