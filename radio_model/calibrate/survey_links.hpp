#pragma once
// A survey turned into what the fit needs: one group per (receiver position, access point) with
// its samples, and the geometry of that link as the simulator sees it: the 3-D distance and the
// walls crossed per material, counted by the same PropagationModel::link (the same Embree wall
// scene and counting rule) that computes simulated RSSI.

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "radio_model/calibrate/rss_survey.hpp"
#include "radio_model/propagation_model.hpp"
#include "radio_model/wall_materials.hpp"
#include "radio_model/wall_mesh.hpp"

namespace wifislam::radio_model::calibrate {

struct LinkGroup {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  std::size_t ap_index = 0;      // into SurveyLinks::aps
  std::size_t device_index = 0;  // into SurveyLinks::devices
  std::vector<double> rss_dbm;
  double mean_dbm = 0.0;
  double distance_m = 0.0;
  std::array<double, radio_model::kWallMaterialCount> walls_per_material{};
  int first_line = 0;
  std::optional<bool> line_of_sight;  // the survey's flag (first sample's), when it has one
};

/// How the scene's walls agree with a survey's line-of-sight flags: links the survey calls LOS
/// that cross no wall in the scene, and links it calls NLOS that cross at least one.
struct LineOfSightAgreement {
  int los_links = 0, los_clear = 0;
  int nlos_links = 0, nlos_blocked = 0;
};

struct SurveyLinks {
  std::vector<SurveyAccessPoint> aps;
  /// The receivers, the reference (offset 0) first; one empty name for a survey of one device.
  std::vector<std::string> devices;
  std::vector<LinkGroup> groups;  // by first appearance in the survey
  std::size_t sample_count() const;
  LineOfSightAgreement line_of_sight_agreement() const;
};

/// The building a survey was taken in, as the fit needs it: its walls, the rectangle its plan
/// spans, its free space and ceiling (positions outside are rejected), and the radio options walls
/// are counted under. The simulator builds it from a scene (sim/site/survey_site.hpp).
struct SurveySite {
  std::string name;                 // the scene's, for messages
  std::string access_points_where;  // where an AP without a file line was declared
  WallMesh walls;
  Eigen::Vector2d bounds_min_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d bounds_max_m = Eigen::Vector2d::Zero();
  double ceiling_m = 0.0;
  std::function<bool(const Eigen::Vector2d&)> in_free_space;
  PropagationOptions options;  // the scene's; walls are counted under itu_walls whatever it says
  std::uint64_t seed = 0;
};

/// The survey's devices in order of first appearance with `reference` (when named) moved first.
/// Throws InvalidInputError when the survey has no device of that name.
std::vector<std::string> devices_reference_first(const Survey& survey,
                                                 const std::string& reference = "");

/// Groups `survey` by position (to the millimetre), AP and device and counts each link's walls in
/// `site`. `devices` fixes the device order (a test survey scored against a fit takes the fit's);
/// empty: devices_reference_first(survey). Throws ParseError located in the survey for a sample
/// from an AP not in `aps` or a device not in `devices`, or at a position outside the scene's
/// free space or above its ceiling, and located at the AP (its aps.csv line, else the scene's
/// `access_points`) for an AP outside the free space.
SurveyLinks survey_links(const Survey& survey, const std::vector<SurveyAccessPoint>& aps,
                         const SurveySite& site, std::vector<std::string> devices = {});

}  // namespace wifislam::radio_model::calibrate
