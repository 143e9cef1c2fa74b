// `wifislam radiomap`: mean RSSI over the floor plan of a scene, for one access point or the
// strongest one per cell, as a heat-map PNG (and optionally the grid as CSV).
#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/core.h>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "sim/scene/scene_levels.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/site_pictures.hpp"

namespace wifislam::cli {

namespace {

struct RadiomapArgs {
  std::string scene_path;
  std::optional<int> ap_id;
  bool strongest = false;
  double resolution_m = 0.25;
  std::optional<double> height_m;  // default: the site's receiver height (the camera's)
  std::string band = "best";
  std::string output = "radiomap.png";
  std::string csv;
  std::string level;  // empty: the route's level
};

void run_radiomap(const RadiomapArgs& args) {
  check_output_files({args.output, args.csv}, {args.scene_path});
  const sim::scene::Scene scene = sim::scene::load_scene_file(args.scene_path);
  sim::scene::require_level(scene, args.level, "--level");
  sim::scene::require_height_under_ceiling(scene, args.height_m, "--height");
  const sim::site::Site site(scene);
  radio_model::RadioMapOptions options;
  options.resolution_m = args.resolution_m;
  options.receiver_height_m = args.height_m.value_or(site.receiver_height_m());
  options.ap_id = args.strongest ? std::nullopt : args.ap_id;
  options.band = args.band == "2.4" ? radio_model::RadioMapBand::k2_4GHz
                 : args.band == "5" ? radio_model::RadioMapBand::k5GHz
                                    : radio_model::RadioMapBand::kBest;
  const radio_model::RadioMap map =
      sim::site::draw_site_radio_map(site, options, args.output, args.level);
  fmt::print("wrote {} ({} x {} cells at {} m, {} access points)\n", args.output, map.cols,
             map.rows, map.resolution_m, site.access_points().size());
  if (!args.csv.empty()) {
    radio_model::write_radio_map_csv(map, args.csv);
    fmt::print("wrote {}\n", args.csv);
  }
}

}  // namespace

WIFISLAM_COMMAND(radiomap, 40) {
  auto args = std::make_shared<RadiomapArgs>();
  CLI::App* app = parent.add_subcommand(
      "radiomap",
      "Draw a scene's mean RSSI (ITU-R P.1238 + walls + shadowing) as a heat map over its\n"
      "floor plan, for one access point (--ap ID) or the strongest at every cell (--strongest).");
  app->add_option("scene", args->scene_path, "Scene file (YAML)")
      ->required()
      ->check(kNonEmptyInput);  // the scene loader says what is wrong with the path
  auto* ap = app->add_option("--ap", args->ap_id, "Access point id (0 .. count-1)");
  auto* strongest =
      app->add_flag("--strongest", args->strongest, "Strongest access point at every cell");
  ap->excludes(strongest);
  strongest->excludes(ap);
  app->add_option("--res", args->resolution_m, "Grid resolution (m), 0.01 to 10")
      ->capture_default_str()
      ->check(finite_range(0.01, 10.0));
  app->add_option("--height", args->height_m,
                  "Receiver height above the floor (m), below the scene's ceiling; default: the "
                  "camera height (sensors.camera.height_m), where datasets scan");
  app->add_option("--band", args->band, "Radio: 2.4, 5 or best (the stronger of the two)")
      ->capture_default_str()
      ->check(CLI::IsMember({"2.4", "5", "best"}));
  app->add_option("--level", args->level,
                  "Level to map (scene key levels:, by id); the receiver stands on its floor and "
                  "hears the access points of every level; default: the route's level");
  app->add_option("-o,--output", args->output, "Heat-map PNG to write")
      ->capture_default_str()
      ->check(kNonEmptyPath);
  app->add_option("--csv", args->csv, "Also write the grid as CSV (x_m,y_m,rssi_dbm,ap_id)")
      ->check(kNonEmptyPath);
  app->callback([args] {
    if (!args->strongest && !args->ap_id)
      throw InvalidInputError("radiomap: give --ap ID or --strongest");
    run_radiomap(*args);
  });
}

}  // namespace wifislam::cli
