// `wifislam world <scene.yaml> [--plan plan.png] [--svg] [--level ID]`: generate a scene's world,
// optionally draw its floor plan, and print a summary.
#include <filesystem>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/output_folder.hpp"
#include "sim/robot/motion_profile.hpp"
#include "sim/scene/scene_levels.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/site.hpp"
#include "sim/site/site_pictures.hpp"
#include "sim/world/world_generator.hpp"

namespace wifislam::cli {

namespace {

struct WorldArgs {
  std::string scene_path;
  std::string plan_path;
  std::string level;  // empty: the route's level
  bool svg = false;
};

void run_world(const WorldArgs& args) {
  // Both plan files are checked before either is written: `--plan X.png --svg` with X.svg an
  // input wrote the PNG and then refused.
  const std::filesystem::path png = args.plan_path;
  const bool write_svg = !png.empty() && args.svg && png.extension() != ".svg";
  const std::filesystem::path svg = std::filesystem::path(png).replace_extension(".svg");
  check_output_files({png, write_svg ? svg : std::filesystem::path()}, {args.scene_path});
  const sim::scene::Scene scene = sim::scene::load_scene_file(args.scene_path);
  sim::scene::require_level(scene, args.level, "--level");
  // The site as `generate` builds it: a route `world` accepts is one `generate` can drive, and
  // the access points are the ones the dataset's scans hear.
  const sim::site::Site site(scene);
  const sim::world::World& world = site.world();
  const sim::robot::MotionProfile& motion = site.motion();
  const std::vector<radio_model::AccessPoint>& access_points = site.access_points();
  if (!png.empty()) {
    sim::site::draw_site_plan(site, png, args.level);
    fmt::print("wrote {}\n", png.string());
    if (write_svg) {
      sim::site::draw_site_plan(site, svg, args.level);
      fmt::print("wrote {}\n", svg.string());
    }
  }
  fmt::print("scene: {}\n{}route time: {:.1f} s ({} pauses)\naccess points: {}\n", scene.name,
             sim::world::summarize_world(world).to_text(), motion.end_time().seconds(),
             motion.pauses().size(), access_points.size());
  if (!world.storeys.empty()) {
    // The summary above is of the route's level; the others are in the radio's building.
    std::string levels;
    for (const sim::world::Storey& storey : world.storeys)
      levels +=
          fmt::format("{}{} at {:g} m{}", levels.empty() ? "" : ", ", storey.level_id,
                      storey.elevation_m, storey.level_id == world.level_id ? " (route)" : "");
    fmt::print("levels: {}\n", levels);
  }
}

}  // namespace

WIFISLAM_COMMAND(world, 20) {
  auto args = std::make_shared<WorldArgs>();
  CLI::App* app = parent.add_subcommand(
      "world", "Generate a scene's world (floor plan, mesh, route) and print a summary.");
  app->add_option("scene", args->scene_path, "Scene file (YAML)")
      ->required()
      ->check(kNonEmptyInput);  // the scene loader says what is wrong with the path
  app->add_option("--plan", args->plan_path,
                  "Draw the floor plan into this file (PNG, or SVG when it ends in .svg)")
      ->check(kNonEmptyPath);
  app->add_flag("--svg", args->svg, "Also write the plan as SVG next to the PNG");
  app->add_option("--level", args->level,
                  "Level to draw (scene key levels:, by id); default: the route's level");
  app->callback([args] { run_world(*args); });
}

}  // namespace wifislam::cli
