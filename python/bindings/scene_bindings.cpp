// Scene: loaded from a file or from YAML text (the package turns a dict into JSON text, which is
// YAML), with the loader's located errors; back out as the resolved YAML or as a dict.
#include <memory>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <yaml-cpp/yaml.h>

#include "core/error.hpp"
#include "python/bindings/bindings.hpp"
#include "sim/scene/scene_loader.hpp"

namespace wifislam::python {

namespace py = pybind11;

namespace {

/// A YAML scalar as the Python value it reads as: quoted scalars are strings; plain ones are
/// null, booleans, integers or floats when they parse as such (YAML 1.2 core schema), else strings.
py::object scalar_to_python(const YAML::Node& node) {
  const std::string& text = node.Scalar();
  if (node.Tag() == "!") return py::str(text);
  if (text == "~" || text == "null" || text == "Null" || text == "NULL") return py::none();
  if (text == "true" || text == "True" || text == "TRUE") return py::bool_(true);
  if (text == "false" || text == "False" || text == "FALSE") return py::bool_(false);
  // A whole number of any size (a seed is up to 2**64 - 1, past long long): Python's own int.
  const std::size_t digits_from = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
  if (text.size() > digits_from &&
      text.find_first_not_of("0123456789", digits_from) == std::string::npos) {
    return py::reinterpret_steal<py::object>(PyLong_FromString(text.c_str(), nullptr, 10));
  }
  try {
    std::size_t used = 0;
    const double real = std::stod(text, &used);
    if (used == text.size()) return py::float_(real);
  } catch (const std::exception&) {
  }
  return py::str(text);
}

py::object yaml_to_python(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      py::dict out;
      for (const auto& item : node) {
        out[py::str(item.first.Scalar())] = yaml_to_python(item.second);
      }
      return out;
    }
    case YAML::NodeType::Sequence: {
      py::list out;
      for (const auto& item : node) out.append(yaml_to_python(item));
      return out;
    }
    case YAML::NodeType::Scalar:
      return scalar_to_python(node);
    default:
      return py::none();
  }
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<sim::scene::Scene, std::shared_ptr<sim::scene::Scene>>(
      m, "Scene",
      "A scene: building, appearance, access points, route and sensors (scenes/README.md).\n\n"
      "Scene.load(path) reads a scene file, Scene.from_dict(d) takes a dict of the same schema\n"
      "and Scene.from_yaml(text) YAML text; to_dict() and to_yaml() give the scene back with\n"
      "every key, defaults filled in. Errors are the loader's, located: ParseError naming the\n"
      "line and key path (corridors[2].width_m), InvalidInputError for a scene that cannot be\n"
      "built, IoError for an unreadable file.")
      .def_static(
          "load",
          [](const std::string& path) {
            return std::make_shared<sim::scene::Scene>(sim::scene::load_scene_file(path));
          },
          py::arg("path"))
      .def_static(
          "from_yaml",
          [](const std::string& text, const std::string& source_name) {
            return std::make_shared<sim::scene::Scene>(
                sim::scene::load_scene_yaml(text, source_name));
          },
          py::arg("text"), py::arg("source_name") = "<yaml>")
      .def("to_yaml",
           [](const sim::scene::Scene& scene) { return sim::scene::resolved_scene_yaml(scene); })
      .def("to_dict",
           [](const sim::scene::Scene& scene) {
             return yaml_to_python(YAML::Load(
                 sim::scene::resolved_scene_yaml(scene, sim::scene::TextQuoting::kWhereAmbiguous)));
           })
      .def_property_readonly("name", [](const sim::scene::Scene& s) { return s.name; })
      .def_property_readonly("seed", [](const sim::scene::Scene& s) { return s.seed; })
      .def_property_readonly("fps", [](const sim::scene::Scene& s) { return s.sensors.camera.fps; })
      .def_property_readonly("source_path",
                             [](const sim::scene::Scene& s) { return s.source_path; })
      // Pickled as its resolved YAML (what a dataset's scene.yaml holds, and what loads back to
      // the same scene) and the file it came from: multiprocessing's spawn and forkserver
      // workers, and copy.deepcopy, take a Scene as they take a Frame. wifislam/__init__.py's
      // Scene.__reduce__ pairs this state with _scene_unpickled, a factory: pickling through
      // __new__ and __setstate__ would need Scene.__new__, which gives an instance without a
      // scene (pybind11 allocates the value only when __init__ or __setstate__ builds it), and
      // any method of one crashed the interpreter. The package replaces __new__ with a TypeError.
      .def("_pickle_state",
           [](const sim::scene::Scene& s) {
             return py::make_tuple(sim::scene::resolved_scene_yaml(s), s.source_path);
           })
      .def("__repr__", [](const sim::scene::Scene& s) {
        return "<wifislam.Scene '" + s.name + "' seed " + std::to_string(s.seed) +
               (s.source_path.empty() ? "" : " from " + s.source_path) + ">";
      });
  m.def("_scene_unpickled", [](const std::string& resolved_yaml, const std::string& source_path) {
    // Located errors of the copy name the resolved text, whose lines are not the file's.
    auto scene = std::make_shared<sim::scene::Scene>(sim::scene::load_scene_yaml(
        resolved_yaml,
        source_path.empty() ? "<pickled scene>" : "<pickled copy of " + source_path + ">"));
    scene->source_path = source_path;
    return scene;
  });
}

}  // namespace wifislam::python
