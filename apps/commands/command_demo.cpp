// `wifislam demo`: the main job, small and quick. Builds the embedded demo world (or a given
// scene), draws its floor plan and writes a summary, all into one output folder.
#include <filesystem>
#include <iostream>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "apps/demo_scene.hpp"
#include "core/atomic_file.hpp"
#include "radio_model/ap_placement.hpp"
#include "radio_model/propagation_model.hpp"
#include "radio_model/radio_map.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/plan_drawing.hpp"
#include "sim/world/world_generator.hpp"

namespace {

struct DemoArgs {
  std::string output_dir = "demo-output";
  std::string scene_path;
  bool force = true;
};

void run_demo(const DemoArgs& args) {
  using namespace wifislam;
  const Scene scene = args.scene_path.empty()
                          ? load_scene_yaml(cli::kDemoSceneYaml, "<embedded demo scene>")
                          : load_scene_file(args.scene_path);
  AtomicDirectory out(args.output_dir, args.force);
  const World world = generate_world(scene);
  const std::vector<AccessPoint> access_points = make_access_points(scene, world.plan);
  PlanDrawingOptions plan_options;
  plan_options.title = scene.name + " (seed " + std::to_string(scene.seed) + ")";
  for (const auto& ap : access_points) plan_options.access_points_m.push_back(ap.position_m);
  draw_floor_plan(world, out.staging_path() / "plan.png", plan_options);

  // Strongest-AP radio map at 0.25 m: what the robot's Wi-Fi card would hear, on average.
  const PropagationModel radio(world, access_points, PropagationOptions::from_scene(scene.radio),
                               access_point_seed(scene));
  const RadioMap map = compute_radio_map(radio, world.plan, RadioMapOptions{});
  write_radio_map_png(map, world.plan, access_points, out.staging_path() / "radio_map.png",
                      scene.sensors.wifi.sensitivity_dbm);
  const std::string summary =
      summarize_world(world).to_text() + fmt::format("access points: {}\n", access_points.size());
  write_file_atomic(out.staging_path() / "summary.txt", "scene: " + scene.name + "\n" + summary);
  write_file_atomic(out.staging_path() / "scene.yaml", resolved_scene_yaml(scene));
  out.commit();
  fmt::print("scene: {}\n{}", scene.name, summary);
  const auto dir = std::filesystem::absolute(args.output_dir).lexically_normal().string();
  fmt::print("wrote {0}/plan.png, {0}/radio_map.png, {0}/summary.txt and {0}/scene.yaml\n", dir);
}

}  // namespace

WIFISLAM_COMMAND(demo, 10) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* app = parent.add_subcommand(
      "demo",
      "Run the main job on a small embedded scene: build the world, place its access points,\n"
      "draw its floor plan and strongest-AP radio map, and write a summary into the output\n"
      "folder (replaced if it exists).");
  app->add_option("-o,--output", args->output_dir, "Output folder")->capture_default_str();
  app->add_option("--scene", args->scene_path, "Use this scene file instead of the embedded one")
      ->check(CLI::ExistingFile);
  app->callback([args] { run_demo(*args); });
}
