#include "study/localisation_data.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include <fmt/format.h>

#include "core/dataset_format.hpp"
#include "core/error.hpp"
#include "core/stop_signal.hpp"
#include "core/tum_trajectory.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/generate/sensor_input.hpp"
#include "sim/scene/scene_levels.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/site.hpp"
#include "slam/feature/orb_feature_extractor.hpp"
#include "slam/wifi/pause_signature_tracker.hpp"

namespace wifislam::study {

namespace {

namespace fs = std::filesystem;

/// Takes the images the protocol keeps (one every interval), extracts their features and follows
/// the pauses, from the events of one stream in time order.
class ImageCollector {
 public:
  ImageCollector(const LocalisationDataOptions& options, const CameraIntrinsics& intrinsics)
      : interval_ns_(std::llround(options.image_interval_s * 1e9)),
        orb_(features(options), intrinsics),
        tracker_(options.wifi) {}

  /// Keeps the frame when the interval has passed; `position_m` is asked only then.
  template <class PositionOf>
  void frame(const RgbdFrame& frame, PositionOf position_m, LocalisationData& out) {
    if (last_ns_ && frame.time.ns - *last_ns_ < interval_ns_ - kSlackNs) return;
    last_ns_ = frame.time.ns;
    out.images.push_back(
        {frame.time, position_m(), orb_.extract(frame).descriptors, tracker_.current()});
  }
  void scan(const WifiScan& scan) { tracker_.observe_scan(scan); }
  void odometry(const OdometryReading& reading) { tracker_.observe_odometry(reading); }

 private:
  static constexpr std::int64_t kSlackNs = 1'000'000;  // stamps a millisecond early still count
  static slam::feature::FeatureOptions features(const LocalisationDataOptions& options) {
    slam::feature::FeatureOptions f;
    f.max_keypoints = options.max_keypoints;
    return f;
  }
  std::int64_t interval_ns_;
  std::optional<std::int64_t> last_ns_;
  slam::feature::OrbFeatureExtractor orb_;
  slam::wifi::PauseSignatureTracker tracker_;
};

/// The moving protocol's scans: the same scene scanning every `interval_s` throughout the run,
/// without rendering (the scanner is part of the scene, so this pipeline builds its own site).
std::vector<PositionedScan> moving_scans(const sim::scene::Scene& resolved, double interval_s) {
  sim::scene::Scene moving = resolved;
  moving.route.pause.scan_while_moving = true;
  moving.sensors.wifi.scan_interval_s = interval_s;
  sim::generate::GenerateOptions no_images;
  no_images.camera = sim::generate::CameraOutput::kNoImages;
  sim::generate::GenerationPipeline pipeline(moving, no_images);
  std::vector<PositionedScan> out;
  while (auto generated = pipeline.next()) {
    if (const auto* scan = std::get_if<WifiScan>(&generated->event)) {
      out.push_back(
          {*scan, pipeline.motion().state_at(pipeline.route_time(scan->time)).position_m});
    }
  }
  return out;
}

/// The ground-truth position at a stamp (groundtruth.txt in time order): interpolated linearly
/// between the poses around it, as eval associates a slow dataset's poses (a 1 fps dataset has a
/// pose a second, and its scans fall between them). A stamp outside the file's span is an error.
Eigen::Vector2d position_at(const Trajectory& truth, Timestamp t, const fs::path& file) {
  const auto after = std::lower_bound(truth.begin(), truth.end(), t,
                                      [](const StampedPose& p, Timestamp x) { return p.time < x; });
  if (after != truth.end() && after->time.ns == t.ns) return after->translation_m.head<2>();
  if (after == truth.end() || after == truth.begin()) {
    throw InvalidInputError(fmt::format(
        "{}: {} lies outside its poses ({} to {}); the stamps of images and scans must fall "
        "within the ground truth",
        file.string(), t.to_tum_string(),
        truth.empty() ? std::string("none") : truth.front().time.to_tum_string(),
        truth.empty() ? std::string("none") : truth.back().time.to_tum_string()));
  }
  const StampedPose& before = *std::prev(after);
  const double share = static_cast<double>(t.ns - before.time.ns) /
                       static_cast<double>(after->time.ns - before.time.ns);
  return (before.translation_m + share * (after->translation_m - before.translation_m)).head<2>();
}

/// The route's level and the building's levels of a scene (empty for one level).
}  // namespace

namespace {

/// The building of `scene` as the scene file writes it: what two runs in one building share.
std::string building_of(const sim::scene::Scene& scene) {
  sim::scene::Scene building;
  building.building = scene.building;
  building.levels = scene.levels;
  building.nodes = scene.nodes;
  building.corridors = scene.corridors;
  building.open_areas = scene.open_areas;
  building.spaces = scene.spaces;
  building.doors = scene.doors;
  building.obstacles = scene.obstacles;
  return sim::scene::resolved_scene_yaml(building);
}

/// Refuses (through `refuse`) two inputs of different buildings; a dataset without scene.yaml
/// says nothing of its building and passes.
template <class Refuse>
void check_same_building(const RouteLevel& map, const RouteLevel& other, const Refuse& refuse) {
  if (!map.building.empty() && !other.building.empty() && map.building != other.building)
    refuse("it is another building than the input's (its walls, corridors or rooms differ)");
}

}  // namespace

RouteLevel route_level_of(const sim::scene::Scene& scene) {
  RouteLevel out;
  out.building = building_of(scene);
  if (!sim::scene::has_levels(scene)) return out;
  out.level = sim::scene::route_level(scene);
  for (const sim::scene::Level& level : scene.levels) out.building_levels.push_back(level.id);
  return out;
}

RouteLevel route_level_of_dataset(const fs::path& dataset) {
  const fs::path scene = dataset / dataset::kScene;
  return fs::exists(scene) ? route_level_of(sim::scene::load_scene_file(scene.string()))
                           : RouteLevel{};
}

void check_other_floor_level(const RouteLevel& map, const RouteLevel& other,
                             const std::string& other_name) {
  const auto refuse = [&](const std::string& why) {
    throw InvalidInputError(fmt::format("--other-floor {}: {}", other_name, why));
  };
  if (map.level.empty() || other.level.empty())
    refuse("both inputs must be of one building of several levels (scene key levels:)");
  if (map.building_levels != other.building_levels)
    refuse("its building has other levels than the input's");
  check_same_building(map, other, refuse);
  if (map.level == other.level)
    refuse(fmt::format("its route is on level '{}', as the input's; give a route on another level",
                       map.level));
}

void check_query_level(const RouteLevel& map, const RouteLevel& queries,
                       const std::string& queries_name) {
  check_same_building(map, queries, [&](const std::string& why) {
    throw InvalidInputError(fmt::format("--queries {}: {}", queries_name, why));
  });
  if (map.level != queries.level) {
    throw InvalidInputError(
        fmt::format("--queries {}: its route is on level '{}', the map's on level '{}'",
                    queries_name, queries.level, map.level));
  }
}

LocalisationData localisation_data_from_scene(const sim::scene::Scene& scene,
                                              const LocalisationDataOptions& options) {
  sim::generate::GenerateOptions overrides;
  overrides.seed = options.seed;
  overrides.fps = 1.0 / options.image_interval_s;  // render only the images the protocol takes
  const sim::scene::Scene resolved = sim::generate::resolve_scene(scene, overrides);
  LocalisationData data;
  data.description = fmt::format(
      "scene {} (seed {}), an image every {:g} s, pause scans and a "
      "scan every {:g} s while moving",
      resolved.name, resolved.seed, options.image_interval_s, options.moving_scan_interval_s);
  sim::generate::GenerationPipeline pipeline(std::make_shared<const sim::site::Site>(resolved), {});
  ImageCollector images(options, resolved.sensors.camera.intrinsics);
  while (auto generated = pipeline.next()) {
    throw_if_stop_requested();  // `paper`: Ctrl-C stops the rendering too
    if (const auto* frame = std::get_if<RgbdFrame>(&generated->event)) {
      const Eigen::Vector2d at = generated->camera_to_world.translation().head<2>();
      images.frame(
          *frame, [&] { return at; }, data);
    } else if (const auto* scan = std::get_if<WifiScan>(&generated->event)) {
      images.scan(*scan);
      data.pause_scans.push_back(
          {*scan, pipeline.motion().state_at(pipeline.route_time(scan->time)).position_m});
    } else if (const auto* odometry = std::get_if<OdometryReading>(&generated->event)) {
      images.odometry(*odometry);
    }
  }
  data.moving_scans = moving_scans(resolved, options.moving_scan_interval_s);
  data.wifi_source = "scene " + resolved.name + " (its access points and scanner)";
  data.route_level = route_level_of(resolved);
  return data;
}

LocalisationData localisation_data_from_dataset(const fs::path& dataset,
                                                const LocalisationDataOptions& options) {
  if (options.seed) {
    throw ParseError("--seed", std::to_string(*options.seed),
                     "a dataset's seed is fixed; --seed applies to scenes");
  }
  const fs::path truth_file = dataset / dataset::kGroundTruth;
  if (!fs::exists(truth_file)) {
    throw InvalidInputError(truth_file.string() + ": missing (localisation is scored against it)");
  }
  const Trajectory truth = read_tum_trajectory(truth_file.string());
  sim::generate::SensorInputOptions input_options;
  input_options.verify_checksums = options.verify_checksums;
  sim::generate::SensorInput input = sim::generate::open_sensor_input(dataset, input_options);
  LocalisationData data;
  data.description = fmt::format(
      "dataset {}, an image every {:g} s, its wifi.csv for both "
      "protocols",
      dataset.string(), options.image_interval_s);
  ImageCollector images(options, input.stream->intrinsics());
  while (auto event = input.stream->next()) {
    throw_if_stop_requested();
    if (const auto* frame = std::get_if<RgbdFrame>(&*event)) {
      images.frame(
          *frame, [&] { return position_at(truth, frame->time, truth_file); }, data);
    } else if (const auto* scan = std::get_if<WifiScan>(&*event)) {
      images.scan(*scan);
      data.pause_scans.push_back({*scan, position_at(truth, scan->time, truth_file)});
    } else if (const auto* odometry = std::get_if<OdometryReading>(&*event)) {
      images.odometry(*odometry);
    }
  }
  data.moving_scans = data.pause_scans;
  data.wifi_source = (dataset / dataset::kWifi).string();
  data.route_level = route_level_of_dataset(dataset);
  return data;
}

void add_other_floor(LocalisationData& data, LocalisationData other,
                     const std::string& other_name) {
  check_other_floor_level(data.route_level, other.route_level, other_name);
  for (LocalisationImage& image : other.images) {
    image.floor = 1;
    data.images.push_back(std::move(image));
  }
  for (auto [scans, others] : {std::pair{&data.pause_scans, &other.pause_scans},
                               std::pair{&data.moving_scans, &other.moving_scans}}) {
    for (PositionedScan& scan : *others) {
      scan.floor = 1;
      scans->push_back(std::move(scan));
    }
  }
  data.other_floor_images = static_cast<int>(other.images.size());
  data.description += fmt::format("; the map also holds level {}'s route ({} images)",
                                  other.route_level.level, data.other_floor_images);
}

void add_query_session(LocalisationData& data, LocalisationData queries,
                       const std::string& queries_name) {
  const auto refuse = [&](const std::string& why) {
    throw InvalidInputError(fmt::format("--queries {}: {}", queries_name, why));
  };
  if (queries.images.empty()) refuse("it gives no image");
  check_query_level(data.route_level, queries.route_level, queries_name);
  std::vector<double> nearest_m;
  for (const LocalisationImage& q : queries.images) {
    double best = std::numeric_limits<double>::infinity();
    for (const LocalisationImage& m : data.images)
      if (m.floor == 0) best = std::min(best, (m.position_m - q.position_m).norm());
    nearest_m.push_back(best);
  }
  std::nth_element(nearest_m.begin(), nearest_m.begin() + nearest_m.size() / 2, nearest_m.end());
  const double median_m = nearest_m[nearest_m.size() / 2];
  if (!(median_m <= kSameRouteMedianM))
    refuse(
        fmt::format("not the map's route: its images lie {:.1f} m (median) from the nearest "
                    "map image, more than {:g} m",
                    median_m, kSameRouteMedianM));
  for (LocalisationImage& image : queries.images) {
    image.query_session = true;
    data.images.push_back(std::move(image));
  }
  for (auto [scans, others] : {std::pair{&data.pause_scans, &queries.pause_scans},
                               std::pair{&data.moving_scans, &queries.moving_scans}}) {
    for (PositionedScan& scan : *others) {
      scan.query_session = true;
      scans->push_back(std::move(scan));
    }
  }
  data.query_session_images = static_cast<int>(queries.images.size());
  data.description += fmt::format("; queries: {}", queries.description);
}

}  // namespace wifislam::study
