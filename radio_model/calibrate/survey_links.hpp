#pragma once
// A survey turned into what the fit needs: one group per (receiver position, access point) with
// its samples, and the geometry of that link as the simulator sees it: the 3-D distance and the
// walls crossed per material, counted by the same PropagationModel::link (the same Embree wall
// scene and counting rule) that computes simulated RSSI.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "radio_model/calibrate/rss_survey.hpp"
#include "radio_model/wall_materials.hpp"
#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam::radio_model::calibrate {

struct LinkGroup {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  std::size_t ap_index = 0;  // into SurveyLinks::aps
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
  std::vector<LinkGroup> groups;  // by first appearance in the survey
  std::size_t sample_count() const;
  LineOfSightAgreement line_of_sight_agreement() const;
};

/// Groups `survey` by position (to the millimetre) and AP and counts each link's walls in
/// `world`. Throws ParseError located in the survey for a sample from an AP not in `aps`, or at a
/// position outside the scene's free space or above its ceiling, and located at the AP (its
/// aps.csv line, else the scene's `access_points`) for an AP outside the free space.
SurveyLinks survey_links(const Survey& survey, const std::vector<SurveyAccessPoint>& aps,
                         const sim::Scene& scene, const sim::World& world);

}  // namespace wifislam::radio_model::calibrate
