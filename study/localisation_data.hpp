#pragma once
// The inputs of the paper's localisation comparison ("Comparison to Wi-Fi augmented FABMAP"):
// images every `image_interval_s` with their true positions and ORB descriptors, and two Wi-Fi
// scan protocols with the true position of each scan:
//   - pause scans (the paper's method): the robot pauses every few metres and scans; every image
//     carries the signature of the last pause before it (slam/wifi/pause_signature_tracker.hpp,
//     the same association the SLAM front ends make);
//   - moving scans (Wi-Fi FAB-MAP, Nowakowski et al. 2017): a scan every `moving_scan_interval_s`
//     while the robot moves.
// From a scene both protocols are simulated on the same route, motion and access points (the
// moving one without rendering). A dataset holds one protocol: both Wi-Fi methods read its
// wifi.csv, and its groundtruth.txt gives the positions.

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/timestamp.hpp"
#include "core/wifi_scan.hpp"
#include "sim/scene/scene.hpp"
#include "slam/wifi/wifi_options.hpp"
#include "slam/wifi/wifi_signature.hpp"

namespace wifislam::study {

struct LocalisationImage {
  Timestamp time;
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // true camera position on the floor
  cv::Mat descriptors;                                   // ORB, one row each
  /// The signature of the last pause before the image (null before the first scan).
  std::shared_ptr<const slam::wifi::WifiSignature> pause_signature;
  /// 0: on the route's level; 1: from the route on another floor joined to the map
  /// (add_other_floor), whose images are all map and never queries.
  int floor = 0;
  /// From the query session joined with add_query_session: a query, never map.
  bool query_session = false;
};

struct PositionedScan {
  WifiScan scan;
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // true receiver position
  int floor = 0;                                         // as LocalisationImage::floor
  bool query_session = false;                            // as LocalisationImage::query_session
};

/// Where a localisation input's route is, in a building of several levels (scene `levels:`): the
/// route's level and the building's level ids; both empty for a one-level scene or a dataset
/// without scene.yaml. `building` is the building itself (its walls, corridors, rooms, spaces,
/// doors and obstacles as the scene file writes them; not the seed, access points, route or
/// sensors, which another run of the same building may change); empty without a scene.
struct RouteLevel {
  std::string level;
  std::vector<std::string> building_levels;
  std::string building;
};

struct LocalisationData {
  std::vector<LocalisationImage> images;  // in time order
  std::vector<PositionedScan> pause_scans, moving_scans;
  std::string description;  // what was read or simulated
  std::string wifi_source;  // where the scans come from (a dataset's wifi.csv), for messages
  RouteLevel route_level;
  int other_floor_images = 0;    // images joined from another floor (add_other_floor)
  int query_session_images = 0;  // images of a query session (add_query_session): the queries
};

struct LocalisationDataOptions {
  double image_interval_s = 2.0;         // the paper's protocol: an image every 2 s
  double moving_scan_interval_s = 10.0;  // and a Wi-Fi scan every 10 s while moving
  int max_keypoints = 1000;
  std::optional<std::uint64_t> seed;  // scenes only: replaces the scene's seed
  bool verify_checksums = true;       // datasets: check manifest.json's SHA-256 sums
  slam::wifi::WifiOptions wifi;       // pause recognition
};

/// Both protocols simulated from `scene` (images rendered only at the image interval).
LocalisationData localisation_data_from_scene(const sim::scene::Scene& scene,
                                              const LocalisationDataOptions& options);

/// A dataset folder: every image at least `image_interval_s` after the last one taken, its
/// position from groundtruth.txt (nearest stamp), and its wifi.csv as both protocols.
LocalisationData localisation_data_from_dataset(const std::filesystem::path& dataset,
                                                const LocalisationDataOptions& options);

/// A scene's route level, and a dataset folder's (from its scene.yaml): read without generating
/// anything, so that the command checks its inputs' levels before the long work.
RouteLevel route_level_of(const sim::scene::Scene& scene);
RouteLevel route_level_of_dataset(const std::filesystem::path& dataset);

/// The level rules of add_other_floor and add_query_session, and that both inputs are one
/// building (RouteLevel::building): InvalidInputError naming `other_name` / `queries_name`.
void check_other_floor_level(const RouteLevel& map, const RouteLevel& other,
                             const std::string& other_name);
void check_query_level(const RouteLevel& map, const RouteLevel& queries,
                       const std::string& queries_name);

/// Joins `other`, a route on another level of the same building, to `data`'s map: its images
/// and scans, with floor 1, become map places a query may wrongly choose, the way a building's
/// floors look alike. Throws InvalidInputError naming `other_name` when either input is not of a
/// building of several levels, the buildings' levels differ, or both routes are on one level.
void add_other_floor(LocalisationData& data, LocalisationData other, const std::string& other_name);

/// Makes `queries`, another visit of the same route (another session, device or day), the
/// queries, and every image of `data` the map: the map and the queries then come from two runs
/// instead of one run's first part and the rest (localization's --queries). Throws
/// InvalidInputError naming `queries_name` when the two are not of the same route: on other
/// levels, or with its images' median distance to the nearest map image above
/// kSameRouteMedianM.
void add_query_session(LocalisationData& data, LocalisationData queries,
                       const std::string& queries_name);
/// Two runs of one route put their images well within this of each other (images every 2 s at
/// 0.5 m/s are 1 m apart); runs of other routes do not.
inline constexpr double kSameRouteMedianM = 2.0;

}  // namespace wifislam::study
