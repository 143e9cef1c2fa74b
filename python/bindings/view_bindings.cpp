// One rendered RGB-D view (what `wifislam render` draws), a scene's radio map (what `wifislam
// radiomap` computes) as numpy grids, the planar camera pose both commands take, and the PNG
// codecs datasets are written with (so a frame held in Python can be compared byte for byte).
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <string>

#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "core/error.hpp"
#include "core/png_codec.hpp"
#include "python/bindings/bindings.hpp"
#include "python/bindings/numpy_convert.hpp"
#include "radio_model/propagation_model.hpp"
#include "sim/generate/as_stored.hpp"
#include "sim/render/depth_png.hpp"
#include "sim/render/depth_sensor_model.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "sim/scene/scene_levels.hpp"
#include "sim/site/radio_map_over_plan.hpp"
#include "sim/site/site.hpp"
#include "sim/site/site_pictures.hpp"
#include "sim/world/world_generator.hpp"

namespace wifislam::python {

namespace py = pybind11;

namespace {

/// The receiver or camera height must lie between the floor and the ceiling (as the CLI says).
void check_height(const std::string& option, double height_m, double ceiling_m) {
  if (!(height_m > 0.0 && height_m < ceiling_m)) {
    throw InvalidInputError(
        fmt::format("{}: {} m is not between the floor and the ceiling (0 to {} m, the scene's "
                    "building.wall_height_m)",
                    option, height_m, ceiling_m));
  }
}

/// A scene's world on an OSMesa renderer, built once for many views.
class Renderer {
 public:
  explicit Renderer(const sim::scene::Scene& scene)
      : scene_(scene),
        world_(sim::world::generate_world(scene)),
        renderer_(scene.sensors.camera.intrinsics) {
    renderer_.set_world(world_, scene_);
  }

  /// Colour as rendered, and depth through the scene's depth sensor model (or ideal, with
  /// `noise` false) as a dataset stores it: in 1/5000 m steps.
  py::tuple render(const py::array& pose_array_in, bool noise, std::int64_t frame_index) {
    const Pose pose = pose_from_array(pose_array_in, "pose");
    sim::render::RenderedView view;
    cv::Mat depth_m;
    {
      py::gil_scoped_release release;
      // One render at a time: the GIL is released, and the OpenGL context serves one thread.
      const std::lock_guard<std::mutex> lock(render_mutex_);
      view = renderer_.render(pose);
      sim::scene::DepthSensorSpec spec = scene_.sensors.depth;
      if (!noise) spec.noise = spec.quantisation = spec.dropouts = false;
      const sim::render::DepthSensorModel sensor(spec, scene_.sensors.camera.intrinsics,
                                                 scene_.seed);
      depth_m =
          sim::generate::depth_as_stored(depth_to_png_units(sensor.measure(view, frame_index)));
    }
    return py::make_tuple(rgb_array(view.color_bgr), depth_array(depth_m));
  }

  py::array_t<double> planar_pose(double x_m, double y_m, double yaw_deg,
                                  std::optional<double> height_m) const {
    if (!(std::isfinite(x_m) && std::isfinite(y_m) && std::isfinite(yaw_deg))) {
      throw InvalidInputError(
          fmt::format("camera pose: x_m, y_m and yaw_deg must be finite numbers, got {}, {}, {}",
                      x_m, y_m, yaw_deg));
    }
    const sim::scene::CameraSpec& camera = scene_.sensors.camera;
    const double h = height_m.value_or(camera.height_m);
    check_height("height_m", h, world_.plan.wall_height_m);
    return pose_array(camera_pose_from_planar(x_m, y_m, yaw_deg * std::numbers::pi / 180.0, h,
                                              camera.pitch_deg * std::numbers::pi / 180.0));
  }

 private:
  sim::scene::Scene scene_;
  sim::world::World world_;
  sim::render::RgbdRenderer renderer_;
  std::mutex render_mutex_;
};

py::dict radio_map(const sim::scene::Scene& scene, double resolution_m, std::optional<int> ap_id,
                   const std::string& band, std::optional<double> height_m,
                   const std::string& level) {
  if (band != "2.4" && band != "5" && band != "best") {
    throw InvalidInputError("band '" + band + "': expected '2.4', '5' or 'best'");
  }
  if (height_m) check_height("height_m", *height_m, scene.building.wall_height_m);
  sim::scene::require_level(scene, level, "level");
  std::optional<sim::site::Site> site;
  radio_model::RadioMap map;
  {
    py::gil_scoped_release release;
    site.emplace(scene);
    radio_model::RadioMapOptions options;
    options.resolution_m = resolution_m;
    options.receiver_height_m = height_m.value_or(site->receiver_height_m());
    options.ap_id = ap_id;
    options.band = band == "2.4" ? radio_model::RadioMapBand::k2_4GHz
                   : band == "5" ? radio_model::RadioMapBand::k5GHz
                                 : radio_model::RadioMapBand::kBest;
    map = sim::site::compute_site_radio_map(*site, options, level);
  }
  py::array_t<float> rssi({map.rows, map.cols});
  py::array_t<std::int32_t> best({map.rows, map.cols});
  std::copy(map.rssi_dbm.begin(), map.rssi_dbm.end(), rssi.mutable_data());
  std::copy(map.best_ap_id.begin(), map.best_ap_id.end(), best.mutable_data());
  py::list access_points;
  for (const radio_model::AccessPoint& ap : site->access_points()) {
    py::dict entry;
    entry["id"] = ap.id;
    entry["position_m"] = py::make_tuple(ap.position_m.x(), ap.position_m.y(), ap.position_m.z());
    entry["tx_power_dbm"] = ap.tx_power_dbm;
    entry["base_mac"] = ap.base_mac().to_string();
    access_points.append(std::move(entry));
  }
  py::dict out;
  out["rssi_dbm"] = std::move(rssi);
  out["best_ap_id"] = std::move(best);
  out["origin_m"] = py::make_tuple(map.origin_m.x(), map.origin_m.y());
  out["resolution_m"] = map.resolution_m;
  out["access_points"] = std::move(access_points);
  return out;
}

py::bytes png_bytes(const std::vector<unsigned char>& png) {
  return py::bytes(reinterpret_cast<const char*>(png.data()), png.size());
}

}  // namespace

void bind_views(py::module_& m) {
  py::class_<Renderer>(m, "_Renderer")
      .def(py::init([](const sim::scene::Scene& scene) {
             py::gil_scoped_release release;  // builds the world's mesh
             return std::make_unique<Renderer>(scene);
           }),
           py::arg("scene"))
      .def("render", &Renderer::render, py::arg("pose"), py::arg("noise"), py::arg("frame_index"))
      .def("planar_pose", &Renderer::planar_pose, py::arg("x_m"), py::arg("y_m"),
           py::arg("yaw_deg"), py::arg("height_m"));
  m.def("_radio_map", &radio_map, py::arg("scene"), py::arg("resolution_m"), py::arg("ap"),
        py::arg("band"), py::arg("height_m"), py::arg("level"));
  m.def(
      "_encode_rgb_png",
      [](const py::array& rgb) { return png_bytes(encode_png(bgr_mat(rgb, "rgb"))); },
      py::arg("rgb"));
  m.def(
      "_encode_depth_png",
      [](const py::array& depth) {
        return png_bytes(encode_png(depth_to_png_units(depth_mat(depth, "depth"))));
      },
      py::arg("depth"));
}

}  // namespace wifislam::python
