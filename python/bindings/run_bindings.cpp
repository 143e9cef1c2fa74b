// The commands that write folders (generate, slam) and the evaluation, each calling the library
// function its CLI command calls, with the GIL released while it works. They return what the
// command prints as plain data (paths, summaries, metrics) for the package to hand back.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <nlohmann/json.hpp>

#include "core/dataset_format.hpp"
#include "core/dataset_reader.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/run_format.hpp"
#include "eval/alignment.hpp"
#include "eval/eval_options.hpp"
#include "eval/evaluate_run.hpp"
#include "eval/requirement.hpp"
#include "python/bindings/bindings.hpp"
#include "python/bindings/numpy_convert.hpp"
#include "sim/generate/dataset_writer.hpp"
#include "sim/scene/scene_loader.hpp"
#include "slam/slam_options.hpp"
#include "study/slam_run.hpp"

namespace wifislam::python {

namespace py = pybind11;
namespace fs = std::filesystem;

namespace {

/// JSON as Python values (dicts keep their key order).
py::object to_python(const nlohmann::ordered_json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

py::dict generate_summary_dict(const sim::generate::GenerateSummary& s) {
  py::dict out;
  out["dataset"] = absolute_folder(s.output).string();
  out["scene"] = s.scene_name;
  out["seed"] = s.seed;
  out["fps"] = s.fps;
  out["frames"] = s.frames;
  out["wifi_scans"] = s.wifi_scans;
  out["wifi_scans_empty"] = s.wifi_scans_empty;
  out["wifi_readings"] = s.wifi_readings;
  out["odometry_readings"] = s.odometry_readings;
  out["imu_samples"] = s.imu_samples;
  out["pauses"] = s.pauses;
  out["access_points"] = s.access_points;
  out["bssids"] = s.bssids;
  out["duration_s"] = s.duration_s;
  out["route_length_m"] = s.route_length_m;
  out["bytes_written"] = s.bytes_written;
  out["total_s"] = s.total_s;
  out["report"] = s.full_report();
  return out;
}

/// Called after each frame of long work run with the GIL released: runs Python's pending signal
/// handlers, so that Ctrl-C (or a handler's exception) stops the work at the next frame. The
/// exception unwinds the C++ work, whose staging folder is removed as on any error, and reaches
/// Python as raised. Only the main thread runs handlers; elsewhere this is a no-op.
void stop_on_python_signal() {
  py::gil_scoped_acquire acquire;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

/// `generate`: `scene_path` is the file the scene came from (an input that must not be
/// replaced), empty for a scene built from a dict.
py::dict generate(const sim::scene::Scene& scene, const fs::path& output,
                  std::optional<std::uint64_t> seed, std::optional<double> fps,
                  std::int64_t max_frames, bool images, int threads, bool force) {
  if (threads < 0) {
    throw InvalidInputError(
        fmt::format("threads: expected 0 (every core) or a number of threads, got {}", threads));
  }
  std::vector<fs::path> inputs;
  // The file the scene was loaded from; Scene.from_yaml's and from_dict's source_name only
  // labels messages ("<dict>", or any text), so it is an input only where it names a file.
  std::error_code ec;
  if (!scene.source_path.empty() && fs::is_regular_file(scene.source_path, ec))
    inputs.push_back(scene.source_path);
  sim::generate::GenerateOptions options;
  options.seed = seed;
  options.fps = fps;
  options.max_frames = max_frames;
  options.camera = images ? sim::generate::CameraOutput::kColourAndDepth
                          : sim::generate::CameraOutput::kNoImages;
  options.threads = threads;
  options.on_progress = [](const sim::generate::GenerateProgress&) { stop_on_python_signal(); };
  sim::generate::GenerateSummary summary;
  {
    py::gil_scoped_release release;
    options.overwrite = check_output_folder({output, force, {}, inputs});
    summary = sim::generate::generate_dataset(scene, output, options);
  }
  return generate_summary_dict(summary);
}

py::dict slam(const fs::path& input, const fs::path& output, const std::string& frontend, bool wifi,
              const std::map<std::string, std::string>& settings, bool force, bool verify,
              std::int64_t max_frames, std::optional<double> fps,
              std::optional<std::uint64_t> seed) {
  study::SlamRunRequest request;
  request.input = input;
  request.output = output;
  request.options.frontend = frontend;
  request.options.wifi.enabled = wifi;
  // Errors name the Python argument the key came from, not the command line's --set.
  for (const auto& [key, value] : settings)
    slam::set_option(request.options, key, value, "settings");
  request.force = force;
  request.verify_checksums = verify;
  request.max_frames = max_frames;
  request.fps = fps;
  request.scene_seed = seed;
  request.on_frame = [](std::int64_t) { stop_on_python_signal(); };
  study::SlamRunResult result;
  {
    py::gil_scoped_release release;
    result = study::run_slam_to_folder(request);
  }
  py::dict out;
  out["run"] = result.run_dir.string();
  // What ran: `settings` may set the front end or the Wi-Fi switch too, after the arguments.
  out["frontend"] = request.options.frontend;
  out["wifi"] = request.options.wifi.enabled;
  if (result.summary) {
    out["summary"] = to_python(nlohmann::ordered_json(result.summary->to_json()));
    out["report"] = result.summary->FullReport();
  } else {
    py::dict external;
    external["status"] = result.external->status;
    external["system_file"] = result.external_system_file;
    external["wall_s"] = result.external->process.wall_s;
    external["cpu_s"] = result.external->process.cpu_s;
    out["external"] = std::move(external);
  }
  return out;
}

eval::EvalOptions eval_options(const std::string& align, double time_offset_s,
                               const std::map<std::string, std::string>& settings) {
  eval::EvalOptions options;
  const std::optional<eval::AlignmentMode> mode = eval::parse_alignment_mode(align);
  if (!mode) throw InvalidInputError("align '" + align + "': expected none, se3 or sim3");
  options.align = *mode;
  options.time_offset_s = time_offset_s;
  for (const auto& [key, value] : settings) eval::set_option(options, key, value, "settings");
  return options;
}

std::string fspath(const py::object& path) {
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

/// A trajectory argument: an N x 8 array, a TUM file, or a folder: a run folder's trajectory.txt
/// for the estimate, a dataset folder's groundtruth.txt for the ground truth. A dataset folder
/// given as the estimate is refused: it would be scored against itself.
Trajectory trajectory_of(const py::object& value, const std::string& what, bool is_estimate,
                         bool verify, std::string& name) {
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__")) {
    const fs::path path = fspath(value);
    name = path.string();
    if (fs::is_directory(path)) {
      if (is_estimate) {
        if (fs::is_regular_file(path / run_folder::kTrajectory))
          return read_tum_trajectory((path / run_folder::kTrajectory).string());
        throw InvalidInputError(fmt::format(
            "{}: {} is a folder without {}: give a run folder, a trajectory file or an array{}",
            what, name, run_folder::kTrajectory,
            fs::exists(path / dataset::kGroundTruth) ? " (this is a dataset folder)" : ""));
      }
      if (fs::is_regular_file(path / dataset::kGroundTruth)) return read_ground_truth(path, verify);
      throw InvalidInputError(
          fmt::format("{}: {} is a folder without {}: give a dataset folder, a trajectory file "
                      "or an array",
                      what, name, dataset::kGroundTruth));
    }
    return read_tum_trajectory(path.string());
  }
  name = what + " array";
  return trajectory_from_array(py::array::ensure(value), what);
}

py::object evaluate(const py::object& estimate, const py::object& ground_truth,
                    const std::string& align, double time_offset_s,
                    const std::map<std::string, std::string>& settings, bool verify) {
  const eval::EvalOptions options = eval_options(align, time_offset_s, settings);
  const auto is_path = [](const py::object& v) {
    return py::isinstance<py::str>(v) || py::hasattr(v, "__fspath__");
  };
  nlohmann::ordered_json flat;
  if (is_path(estimate) && is_path(ground_truth)) {
    const std::string estimate_path = fspath(estimate);
    const std::string dataset = fspath(ground_truth);
    if (fs::is_directory(dataset)) {
      // What `wifislam eval RUN --gt DATASET` computes, loop closures and timing included.
      {
        py::gil_scoped_release release;
        flat = eval::evaluate_run(estimate_path, dataset, options, verify).flat_metrics();
      }
      return to_python(flat);
    }
  }
  std::string estimate_name, ground_truth_name;
  const Trajectory est = trajectory_of(estimate, "estimate", true, verify, estimate_name);
  const Trajectory gt =
      trajectory_of(ground_truth, "ground_truth", false, verify, ground_truth_name);
  {
    py::gil_scoped_release release;
    flat = eval::evaluate_trajectory(est, gt, options, estimate_name, ground_truth_name)
               .flat_metrics();
  }
  return to_python(flat);
}

/// Each requirement checked on a metrics dict as `eval --require` checks it: returns the
/// descriptions; RequirementNotMetError (an AssertionError) names each one not met.
std::vector<std::string> require(const py::dict& metrics, const std::vector<std::string>& texts) {
  std::vector<eval::Requirement> requirements;
  for (const std::string& text : texts) requirements.push_back(eval::parse_requirement(text));
  const nlohmann::ordered_json flat = nlohmann::ordered_json::parse(
      py::module_::import("json").attr("dumps")(metrics).cast<std::string>());
  eval::check_metric_names(requirements, flat);
  std::vector<std::string> lines, failed;
  for (const eval::RequirementResult& r : eval::check_requirements(requirements, flat)) {
    lines.push_back(r.describe());
    if (!r.met) failed.push_back(r.describe());
  }
  if (!failed.empty()) {
    std::string message = fmt::format("{} of {} requirements not met", failed.size(), texts.size());
    for (const std::string& f : failed) message += "\n  " + f;
    throw RequirementNotMetError(message);
  }
  return lines;
}

}  // namespace

void bind_runs(py::module_& m) {
  m.def("_generate", &generate, py::arg("scene"), py::arg("output"), py::arg("seed"),
        py::arg("fps"), py::arg("max_frames"), py::arg("images"), py::arg("threads"),
        py::arg("force"));
  m.def("_slam", &slam, py::arg("input"), py::arg("output"), py::arg("frontend"), py::arg("wifi"),
        py::arg("settings"), py::arg("force"), py::arg("verify"), py::arg("max_frames"),
        py::arg("fps"), py::arg("seed"));
  m.def("_evaluate", &evaluate, py::arg("estimate"), py::arg("ground_truth"), py::arg("align"),
        py::arg("time_offset_s"), py::arg("settings"), py::arg("verify"));
  m.def("_require", &require, py::arg("metrics"), py::arg("requirements"));
  m.def(
      "_read_trajectory",
      [](const std::string& path) { return trajectory_array(read_tum_trajectory(path)); },
      py::arg("path"));
}

}  // namespace wifislam::python
