// `wifislam study place SCENE --budget K -o DIR`: greedy access-point placement against random
// placement (study/greedy_placement.hpp does the work).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "apps/commands/study_subcommands.hpp"
#include "apps/option_validators.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "sim/scene/scene_loader.hpp"
#include "slam/slam_options.hpp"
#include "study/greedy_placement.hpp"
#include "study/placement_files.hpp"

namespace wifislam::cli {

namespace {

struct PlaceArgs {
  std::string scene, output, seed;
  int budget = 0, random_draws = 5;
  double spacing_m = 3.0;
  std::vector<std::string> settings;
  bool force = false, quiet = false;
};

void place_command(const PlaceArgs& args) {
  const sim::scene::Scene scene = sim::scene::load_scene_file(args.scene);
  slam::SlamOptions slam_options;
  for (const std::string& s : args.settings) {
    // Placement scores pause signatures with the Wi-Fi module alone: no front end runs, and
    // set_option_assignment's refusal would name a --frontend flag this command lacks.
    // Only the Wi-Fi module's own options: min_matches or stm_size changed nothing, silently.
    const std::string key = s.substr(0, s.find('='));
    if (key.rfind("wifi_", 0) != 0 || !slam::option_front_end(key).empty()) {
      throw ParseError("--set", s,
                       "study place runs no front end (it scores the Wi-Fi module's pause "
                       "signatures); set the Wi-Fi module's options, e.g. wifi_similarity");
    }
    slam::set_option_assignment(slam_options, s);
  }
  slam::validate(slam_options);
  const bool replace = check_output_folder({args.output, args.force, {}, {args.scene}});
  study::PlacementOptions options;
  options.budget = args.budget;
  options.candidate_spacing_m = args.spacing_m;
  options.random_draws = args.random_draws;
  options.seed = args.seed.empty() ? scene.seed : std::stoull(args.seed);
  options.wifi = slam_options.wifi;
  if (!args.quiet) {
    options.on_progress = [](const std::string& line) { fmt::print(stderr, "place: {}\n", line); };
  }
  const study::PlacementResult result = study::greedy_placement(scene, options);

  fmt::print("{}", study::placement_table(result));
  AtomicDirectory out(args.output, replace);
  study::write_placement_files(result, options, args.scene, scene.name, out.staging_path());
  out.commit();
  fmt::print(
      "{} candidates, {} pauses -> {}/ (placement.csv, access_points.yaml, placement and "
      "resolution figures)\n",
      result.candidates.size(), result.pause_positions_m.size(), args.output);
}

}  // namespace

void add_study_place_command(CLI::App* app) {
  auto args = std::make_shared<PlaceArgs>();
  CLI::App* place = app->add_subcommand(
      "place",
      "Greedy access-point placement: add APs one at a time, each at the candidate position\n"
      "(rooms, corridors, halls) that best tells places along the route apart, next to the same\n"
      "numbers of APs placed at random among the same candidates (radio level, no rendering)");
  place->add_option("scene", args->scene, "Scene file (YAML): the plan, route and radio")
      ->required()
      ->check(kNonEmptyInput);
  place->add_option("--budget", args->budget, "Access points to place")
      ->required()
      ->check(CLI::Range(1, study::kMaxPlacementCandidates));
  place
      ->add_option("-o,--output", args->output,
                   "Folder: placement.csv, access_points.yaml (a scene block),\n"
                   "placement.png/.svg (positions), error.png/.svg and resolution.png/.svg\n"
                   "(greedy vs random)")
      ->required();
  place->add_option("--spacing", args->spacing_m, "Candidate positions no closer than this [m]")
      ->capture_default_str()
      ->check(wifislam::cli::finite_range(0.5, 1000.0));
  place
      ->add_option("--random-draws", args->random_draws,
                   "Random placements per count (their median is reported)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  place->add_option("--seed", args->seed, "Seed of the random placements (default: the scene's)")
      ->check(cli::kSeedValidator);
  place->add_option("--set", args->settings,
                    "SLAM option key=value for the Wi-Fi module, e.g. --set wifi_similarity=0.85");
  place->add_flag("--force", args->force, "Replace an existing output folder of this tool");
  place->add_flag("-q,--quiet", args->quiet, "No progress lines on stderr");
  place->footer(
      "Resolution: the distance beyond which the median similarity of the route's pause pairs\n"
      "stays below wifi_similarity (smaller tells closer places apart; 'none': places never "
      "look\n"
      "different, or not even the nearest are recognised, as with one AP). Each step minimises\n"
      "it, then the share of pairs over\n"
      "12 m counted similar, then maximises the share under 4 m. Every candidate's scans are\n"
      "simulated once and each placement keeps its APs' readings, so greedy and random see the\n"
      "same draws.");
  place->callback([args] { place_command(*args); });
}

}  // namespace wifislam::cli
