// `wifislam render <scene.yaml> --pose x,y,yaw -o <prefix>`: render one RGB-D view of a scene's
// world and write <prefix>_rgb.png, <prefix>_depth.png (TUM: uint16, 5000 per metre, 0 = no
// reading) and <prefix>_depth_color.png (false colour, for people).
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/pose.hpp"
#include "core/text_lines.hpp"
#include "sim/render/depth_png.hpp"
#include "sim/render/depth_sensor_model.hpp"
#include "sim/render/rgbd_renderer.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/scene/scene_schema.hpp"
#include "sim/world/plan_queries.hpp"
#include "sim/world/world_generator.hpp"

namespace wifislam::cli {

namespace {

struct RenderArgs {
  std::string scene_path;
  std::string pose;
  std::optional<double> height_m;
  bool no_noise = false;
  std::int64_t frame_index = 0;
  std::string prefix;
};

struct PlanarPose {
  double x_m = 0, y_m = 0, yaw_deg = 0;
};

/// x,y,yaw as plain decimals (core's parse_double: no hexadecimal, no inf or nan), x and y within
/// the 10 km every scene coordinate lies in (sim/scene/scene_schema.hpp).
PlanarPose parse_pose(const std::string& text) {
  const std::vector<std::string_view> fields = split_fields(text, ',');
  double values[3] = {0, 0, 0};
  bool ok = fields.size() == 3;
  for (std::size_t i = 0; ok && i < 3; ++i) {
    std::string_view field = fields[i];  // "1, 2, 90" as well as "1,2,90"
    while (!field.empty() && field.front() == ' ') field.remove_prefix(1);
    while (!field.empty() && field.back() == ' ') field.remove_suffix(1);
    ok = parse_double(field, values[i]);
  }
  if (!ok) {
    throw InvalidInputError(fmt::format(
        "--pose: expected x,y,yaw (metres, metres, degrees counter-clockwise from +x), got '{}'",
        text));
  }
  const sim::scene::schema::Limits& limits = sim::scene::schema::kCoordinateM;
  for (const double v : {values[0], values[1]}) {
    if (v < limits.lo || v > limits.hi) {
      throw InvalidInputError(fmt::format(
          "--pose: x and y must lie within {} m of the origin, as every scene coordinate does; "
          "got '{}'",
          limits.hi, text));
    }
  }
  return {values[0], values[1], values[2]};
}

void run_render(const RenderArgs& args) {
  const PlanarPose planar = parse_pose(args.pose);
  const std::string rgb_path = args.prefix + "_rgb.png";
  const std::string depth_path = args.prefix + "_depth.png";
  const std::string color_path = args.prefix + "_depth_color.png";
  for (const std::string& path : {rgb_path, depth_path, color_path}) {
    check_output_file(path, {args.scene_path});
  }
  const sim::scene::Scene scene = sim::scene::load_scene_file(args.scene_path);
  const sim::world::World world = sim::world::generate_world(scene);
  const sim::scene::CameraSpec& camera = scene.sensors.camera;
  const double height_m = args.height_m.value_or(camera.height_m);
  if (!(height_m > 0.0 && height_m < world.plan.wall_height_m)) {
    throw InvalidInputError(
        fmt::format("--height: {} m is not between the floor and the ceiling "
                    "(0 to {} m)",
                    height_m, world.plan.wall_height_m));
  }
  // A view from inside a wall or outside the building is blank, but may be what is wanted (a
  // wall's material, say): drawn, with a warning rather than a silent 0 % of depth readings.
  if (!sim::world::regions_contain(world.plan.free_space, {planar.x_m, planar.y_m})) {
    fmt::print(stderr,
               "wifislam: warning: ({}, {}) m is not in the free space of scene '{}' (inside a "
               "wall or outside the building): the camera sees little or nothing\n",
               planar.x_m, planar.y_m, scene.name);
  }
  const Pose pose =
      camera_pose_from_planar(planar.x_m, planar.y_m, planar.yaw_deg * std::numbers::pi / 180.0,
                              height_m, camera.pitch_deg * std::numbers::pi / 180.0);

  sim::render::RgbdRenderer renderer(camera.intrinsics);
  renderer.set_world(world, scene);
  const sim::render::RenderedView view = renderer.render(pose);
  sim::scene::DepthSensorSpec depth_spec = scene.sensors.depth;
  if (args.no_noise) depth_spec.noise = depth_spec.quantisation = depth_spec.dropouts = false;
  const sim::render::DepthSensorModel sensor(depth_spec, camera.intrinsics, scene.seed);
  const cv::Mat depth_m = sensor.measure(view, args.frame_index);

  sim::render::write_color_png(rgb_path, view.color_bgr);
  sim::render::write_depth_png(depth_path, depth_m);
  sim::render::write_depth_false_color_png(color_path, depth_m, depth_spec.min_range_m,
                                           depth_spec.max_range_m);

  double lo = 0, hi = 0;
  const int readings = cv::countNonZero(depth_m > 0.0f);
  if (readings > 0) cv::minMaxLoc(depth_m, &lo, &hi, nullptr, nullptr, depth_m > 0.0f);
  fmt::print("wrote {}\nwrote {}\nwrote {}\n", rgb_path, depth_path, color_path);
  fmt::print("depth readings: {:.1f} % of pixels, {:.3f} to {:.3f} m\n",
             100.0 * readings / static_cast<double>(depth_m.total()), lo, hi);
}

}  // namespace

WIFISLAM_COMMAND(render, 30) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* app = parent.add_subcommand(
      "render", "Render one RGB-D view of a scene (colour, TUM depth PNG, false-colour depth).");
  app->add_option("scene", args->scene_path, "Scene file (YAML)")
      ->required()
      ->check(kNonEmptyInput);  // the scene loader says what is wrong with the path
  app->add_option("--pose", args->pose,
                  "Camera position and heading: x,y,yaw (metres, metres, degrees counter-"
                  "clockwise from +x)")
      ->required();
  app->add_option("--height", args->height_m,
                  "Camera height above the floor in metres (default: the scene's camera)");
  app->add_flag("--no-noise", args->no_noise,
                "Ideal depth: no noise, quantisation or dropouts (the valid range still applies)");
  app->add_option("--frame", args->frame_index, "Frame index that seeds the depth noise")
      ->default_val(0)
      ->check(at_least(0));
  app->add_option("-o,--output", args->prefix,
                  "Output prefix: writes <prefix>_rgb.png, <prefix>_depth.png, "
                  "<prefix>_depth_color.png")
      ->required()
      ->check(kNonEmptyPath);
  app->callback([args] { run_render(*args); });
}

}  // namespace wifislam::cli
