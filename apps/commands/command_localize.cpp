// `wifislam localize <scene.yaml | dataset/> [--method fabmap,wifi-fabmap,wifi-clusters] -o DIR`:
// the paper's localisation comparison ("Comparison to Wi-Fi augmented FABMAP"): visual FAB-MAP,
// Wi-Fi FAB-MAP and our Wi-Fi clusters on the same query images, with the error CDF.
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "apps/command_registry.hpp"
#include "apps/option_validators.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/wall_clock.hpp"
#include "sim/scene/scene_loader.hpp"
#include "slam/bow/shipped_vocabulary.hpp"
#include "study/localisation_data.hpp"
#include "study/localisation_report.hpp"

namespace wifislam::cli {

namespace {

namespace fs = std::filesystem;

struct LocalizeArgs {
  std::string input, output, methods = "fabmap,wifi-fabmap,wifi-clusters";
  std::string vocabulary, training, wifi_words = "presence", route, other_floor;
  std::string queries, queries_device;
  std::optional<std::uint64_t> queries_session;
  double image_interval_s = 2.0, moving_scan_interval_s = 10.0, map_share = 0.4;
  std::optional<std::uint64_t> seed;
  std::uint64_t fabmap_seed = 1;
  bool naive_bayes = false, force = false, quiet = false, no_verify = false;
};

std::vector<study::LocalisationMethod> parse_methods(const std::string& text) {
  std::vector<study::LocalisationMethod> out;
  if (text.empty() || text.front() == ',' || text.back() == ',' ||
      text.find(",,") != std::string::npos) {
    throw ParseError("--method", text, "empty name in the list");
  }
  std::stringstream in(text);
  for (std::string name; std::getline(in, name, ',');) {
    const auto m = study::parse_localisation_method(name);
    if (!m) {
      throw ParseError("--method", name,
                       "unknown method; known: fabmap, wifi-fabmap, wifi-clusters");
    }
    if (std::find(out.begin(), out.end(), *m) == out.end()) out.push_back(*m);
  }
  if (out.empty()) throw ParseError("--method", text, "no method given");
  return out;
}

study::LocalisationOptions localisation_options(const LocalizeArgs& args) {
  study::LocalisationOptions o;
  o.methods = parse_methods(args.methods);
  o.map_share = args.map_share;
  o.fabmap.naive_bayes = args.naive_bayes;
  o.fabmap.seed = args.fabmap_seed;
  if (args.wifi_words == "thermometer") {
    o.wifi_words = study::WifiWordEncoding::kThermometer;
  } else if (args.wifi_words != "presence") {
    throw ParseError("--wifi-words", args.wifi_words, "expected presence or thermometer");
  }
  return o;
}

/// FAB-MAP's training for the vocabulary: the shipped pair, or the files given (which must have
/// been made together: the training file names its vocabulary's checksum).
slam::place::FabMapTraining load_training(const LocalizeArgs& args) {
  if (args.vocabulary.empty() != args.training.empty()) {
    throw ParseError("--training", args.training.empty() ? args.vocabulary : args.training,
                     "give --vocabulary and --training together (vocab fabmap makes the latter)");
  }
  const fs::path file =
      args.training.empty() ? slam::place::shipped_fabmap_training_path() : fs::path(args.training);
  slam::place::FabMapTraining training = slam::place::FabMapTraining::load(file);
  const std::string checksum = slam::bow::vocabulary_checksum(args.vocabulary);
  if (training.vocabulary_sha256 != checksum) {
    throw InvalidInputError(fmt::format("{}: made for the vocabulary with sha256 {}, not {}",
                                        file.string(), training.vocabulary_sha256, checksum));
  }
  return training;
}

/// The scene, with --route's node sequence (e.g. two laps, so the queries revisit the map).
sim::scene::Scene scene_with_route(const LocalizeArgs& args, bool route_given) {
  sim::scene::Scene scene = sim::scene::load_scene_file(args.input);
  if (!route_given) return scene;
  if (args.route.empty() || args.route.front() == ',' || args.route.back() == ',' ||
      args.route.find(",,") != std::string::npos) {
    throw ParseError("--route", args.route, "expected node ids, comma-separated (e.g. A,B,C,A)");
  }
  scene.route.nodes.clear();
  std::stringstream in(args.route);
  for (std::string node; std::getline(in, node, ',');) scene.route.nodes.push_back(node);
  try {
    sim::scene::validate_scene(scene);
  } catch (const Error& e) {
    throw ParseError("--route", args.route, e.what());
  }
  return scene;
}

/// The query run of --queries-session (and --queries-device): the input scene in that session.
sim::scene::Scene query_session_scene(const LocalizeArgs& args, bool route_given) {
  sim::scene::Scene scene = scene_with_route(args, route_given);
  scene.session = *args.queries_session;
  if (!args.queries_device.empty()) {
    try {
      scene.sensors.wifi.device = sim::scene::load_receiver_device(args.queries_device);
    } catch (const InvalidInputError& e) {
      throw InvalidInputError(fmt::format("--queries-device: {}", e.what()));
    }
  }
  return scene;
}

/// A localisation input: a dataset folder, or a scene file loaded once.
struct LocalisationInput {
  fs::path path;
  std::optional<sim::scene::Scene> scene;  // empty for a dataset folder

  study::RouteLevel route_level() const {
    return scene ? study::route_level_of(*scene) : study::route_level_of_dataset(path);
  }
  study::LocalisationData data(const study::LocalisationDataOptions& options) const {
    return scene ? study::localisation_data_from_scene(*scene, options)
                 : study::localisation_data_from_dataset(path, options);
  }
};

LocalisationInput localisation_input(const fs::path& path) {
  if (fs::is_directory(path)) return {path, {}};
  return {path, sim::scene::load_scene_file(path.string())};
}

void check_query_options(const LocalizeArgs& args, bool map_share_given) {
  if (!args.queries.empty() && args.queries_session)
    throw ParseError("--queries-session", std::to_string(*args.queries_session),
                     "give --queries or --queries-session, not both");
  if (args.queries_session && fs::is_directory(args.input))
    throw ParseError("--queries-session", std::to_string(*args.queries_session),
                     "a dataset is one session; generate another with generate --session and "
                     "give it with --queries");
  if (!args.queries_device.empty() && !args.queries_session)
    throw ParseError("--queries-device", args.queries_device,
                     "applies to the queries of --queries-session (a dataset's device is fixed)");
  if (map_share_given && (!args.queries.empty() || args.queries_session))
    throw ParseError("--map-share", std::to_string(args.map_share),
                     "with a query run the whole input is the map; --map-share splits one run");
  // The same run as queries would find every image in the map: a perfect score that says nothing.
  if (!args.queries.empty() && resolve_path(args.queries) == resolve_path(args.input))
    throw ParseError("--queries", args.queries,
                     "is the input itself; give another run of the same route (another session, "
                     "device or day), or leave it out to split the input with --map-share");
}

void run(const LocalizeArgs& args, bool route_given, bool map_share_given) {
  if (route_given && fs::is_directory(args.input)) {
    throw ParseError("--route", args.route,
                     "a dataset's route is fixed; --route applies to scenes");
  }
  check_query_options(args, map_share_given);
  std::vector<fs::path> inputs = {args.input};
  if (!args.other_floor.empty()) inputs.push_back(args.other_floor);
  if (!args.queries.empty()) inputs.push_back(args.queries);
  if (fs::exists(args.queries_device)) inputs.push_back(args.queries_device);
  // The vocabulary and training files are inputs as much as the dataset: --force must not
  // replace a folder that holds them.
  if (!args.vocabulary.empty()) inputs.push_back(args.vocabulary);
  if (!args.training.empty()) inputs.push_back(args.training);
  const bool replace = check_output_folder({args.output, args.force, {}, inputs});
  const study::LocalisationOptions options = localisation_options(args);
  const auto vocabulary = slam::bow::load_vocabulary(args.vocabulary);
  const slam::place::FabMapTraining training = load_training(args);
  study::LocalisationDataOptions data_options;
  data_options.image_interval_s = args.image_interval_s;
  data_options.moving_scan_interval_s = args.moving_scan_interval_s;
  data_options.seed = args.seed;
  data_options.verify_checksums = !args.no_verify;
  data_options.wifi = options.wifi;
  // The levels of the inputs are checked before any of them is generated (seconds to minutes of
  // rendering).
  const LocalisationInput input =
      fs::is_directory(args.input)
          ? LocalisationInput{args.input, {}}
          : LocalisationInput{args.input, scene_with_route(args, route_given)};
  std::optional<LocalisationInput> other_floor, queries;
  if (!args.other_floor.empty()) {
    other_floor = localisation_input(args.other_floor);
    study::check_other_floor_level(input.route_level(), other_floor->route_level(),
                                   args.other_floor);
  }
  if (!args.queries.empty()) {
    queries = localisation_input(args.queries);
    study::check_query_level(input.route_level(), queries->route_level(), args.queries);
  }

  const auto start = std::chrono::steady_clock::now();
  study::LocalisationData data = input.data(data_options);
  if (other_floor) study::add_other_floor(data, other_floor->data(data_options), args.other_floor);
  if (queries) {
    study::add_query_session(data, queries->data(data_options), args.queries);
  } else if (args.queries_session) {
    study::add_query_session(
        data,
        study::localisation_data_from_scene(query_session_scene(args, route_given), data_options),
        fmt::format("session {}", *args.queries_session));
  }
  if (!args.quiet) {
    fmt::print(stderr, "localize: {}: {} images, {} pause scans, {} moving scans ({:.0f} s)\n",
               data.description, data.images.size(), data.pause_scans.size(),
               data.moving_scans.size(), seconds_since(start));
  }
  const study::LocalisationResult result =
      study::run_localisation(data, *vocabulary, training, options);
  AtomicDirectory out(args.output, replace);
  study::write_localisation_report(out.staging_path(), result, data, options);
  out.commit();
  fmt::print("{}", study::localisation_summary(result, options).dump(1) + "\n");
  fmt::print("wrote {}/ (summary.md, queries.csv, cdf.csv, cdf.png, pr.csv)\n",
             absolute_folder(args.output).string());
}

}  // namespace

WIFISLAM_COMMAND(localize, 67) {
  auto args = std::make_shared<LocalizeArgs>();
  CLI::App* app = parent.add_subcommand(
      "localize",
      "The paper's localisation comparison: visual FAB-MAP (as openFABMAP computes it), Wi-Fi\n"
      "FAB-MAP (Wi-Fi words appended to the visual ones) and ours (candidates from similar Wi-Fi\n"
      "clusters, the same FAB-MAP visual likelihood), on the same images: an image every 2 s,\n"
      "the first 40 % of the route the map, the rest the queries. From a scene both scan\n"
      "protocols are simulated (pauses for ours, a scan every 10 s while moving for Wi-Fi\n"
      "FAB-MAP); a dataset's wifi.csv serves both. Writes the error CDF (cdf.png, cdf.csv), the\n"
      "shares within 1/2/4/5 m, per-query matches and a precision-recall table");
  app->add_option("input", args->input, "Scene file (YAML) or dataset folder")
      ->required()
      ->check(kNonEmptyInput);
  app->add_option("-o,--output", args->output, "Output folder")->required();
  app->add_option("--method", args->methods, "Methods, comma-separated")->capture_default_str();
  app->add_option("--image-interval", args->image_interval_s, "Seconds between images")
      ->capture_default_str()
      ->check(finite_range(0.01, 3600.0));
  app->add_option("--moving-scan-interval", args->moving_scan_interval_s,
                  "Seconds between Wi-Fi FAB-MAP's scans while moving (scenes)")
      ->capture_default_str()
      ->check(finite_range(0.5, 3600.0));
  app->add_option("--map-share", args->map_share, "Share of the route (by time) that is the map")
      ->capture_default_str()
      ->check(finite_range(0.01, 0.99));
  app->add_option(
         "--wifi-words", args->wifi_words,
         "Wi-Fi FAB-MAP's words: presence (one per AP heard) or thermometer (RSSI + 110 in "
         "5 dB bins)")
      ->capture_default_str();
  app->add_option(
      "--route", args->route,
      "Scenes: the route's nodes, comma-separated, replacing the scene's (e.g. two laps\n"
      "A,B,C,D,A,B,C,D,A so that the queries revisit the map)");
  app->add_option(
         "--other-floor", args->other_floor,
         "Scene or dataset of the same building (scene key levels:) with its route on another\n"
         "level: its images and scans join the map, so a query can choose a place on the wrong\n"
         "floor (summary.md's last column)")
      ->check(kNonEmptyInput);
  app->add_option(
         "--queries", args->queries,
         "Scene or dataset of another run of the same route (another session, device or day):\n"
         "its images are the queries and the whole input is the map, in place of --map-share's\n"
         "split of one run")
      ->check(kNonEmptyInput);
  app->add_option("--queries-session", args->queries_session,
                  "Scenes: the queries are the input scene's session K (generate --session): the\n"
                  "same building with its access-point changes by then, the robot's pauses,\n"
                  "sensor noise and Wi-Fi draws of that session; the input (session 0, or its\n"
                  "`session`) is the map")
      ->check(CLI::Range(std::uint64_t{0}, std::uint64_t{1000000}));
  app->add_option("--queries-device", args->queries_device,
                  "With --queries-session: the Wi-Fi device of the query run, a shipped name or\n"
                  "a device file (scenes/README.md, Receiver devices)")
      ->check(kNonEmptyDevice);
  app->add_flag("--naive-bayes", args->naive_bayes, "FAB-MAP without the Chow-Liu tree");
  app->add_flag("--no-verify", args->no_verify, "Datasets: do not check their SHA-256 sums");
  app->add_option("--vocabulary", args->vocabulary, "Vocabulary file (default: the shipped one)")
      ->check(kNonEmptyInput);
  app->add_option("--training", args->training,
                  "FAB-MAP training file for --vocabulary (wifislam vocab fabmap)")
      ->check(kNonEmptyInput);
  app->add_option("--seed", args->seed, "Scenes: replaces the scene's seed")
      ->check(cli::kSeedValidator);
  app->add_option("--fabmap-seed", args->fabmap_seed, "Seed of FAB-MAP's new-place sample")
      ->capture_default_str()
      ->check(cli::kSeedValidator);
  app->add_flag("--force", args->force, "Replace an existing output folder");
  app->add_flag("-q,--quiet", args->quiet, "No progress on stderr");
  app->callback(
      [args, app] { run(*args, app->count("--route") > 0, app->count("--map-share") > 0); });
}

}  // namespace wifislam::cli
