#pragma once
// Mean received power from every access point at any receiver position:
//
//   RSSI = P_tx - L_ITU(f, d) - sum over walls crossed L_wall(material, f) - S_ap(x, y)
//
// with L_ITU the ITU-R P.1238 path loss (itu_p1238.hpp), the walls found by Embree on the
// straight AP -> receiver segment (embree_wall_scene.hpp, wall_materials.hpp) and S_ap the AP's
// spatially correlated shadowing (shadowing_field.hpp), shared by both of its radios. Fast
// fading and people are per scan and live in the scanner.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "radio_model/access_point.hpp"
#include "radio_model/embree_wall_scene.hpp"
#include "radio_model/itu_p1238.hpp"
#include "radio_model/shadowing_field.hpp"
#include "radio_model/wall_materials.hpp"
#include "sim/scene/scene.hpp"
#include "sim/world/world_types.hpp"

namespace wifislam {

struct PropagationOptions {
  RadioEnvironment environment = RadioEnvironment::kOffice;
  /// N in the ITU formula; default kDefaultDistanceCoefficient (see itu_p1238.hpp for why).
  std::optional<double> distance_coefficient;
  int floors_between = 0;  // one storey for now; the floor term stays in the formula
  bool walls = true;       // add per-wall losses (off = pure ITU, e.g. with N = 30)
  WallLossTable wall_losses;
  /// Shadowing: sigma 4 dB is ITU-R P.1238-10's site-general corridor LoS fit (4.07 dB); the
  /// recommendation's 8-12 dB (Table 4) also covers building-to-building variation that our
  /// explicit walls already model.
  double shadowing_sigma_db = 4.0;
  double shadowing_decorrelation_m = 3.0;
  /// Scanner: the fading of each radio (fading_process.hpp) with its coherence time at a still
  /// receiver, the per-BSSID spread around it, and random extra loss from people.
  double fast_fading_sigma_db = 2.0;
  double fading_coherence_s = 3.0;
  double bssid_spread_db = 0.5;
  double people_disturbance_db = 0.0;  // 0 = off; else extra loss up to this much
  double people_probability = 0.3;     // chance a person blocks a given AP during one scan

  double distance_coefficient_or_default() const {
    return distance_coefficient.value_or(kDefaultDistanceCoefficient);
  }
  static PropagationOptions from_scene(const RadioSpec& radio);
};

/// The geometry-dependent part of one AP -> receiver link, shared by all its BSSIDs.
struct RadioLink {
  double distance_m = 0.0;
  std::array<int, kWallMaterialCount> walls_per_material{};  // walls crossed, by material
  double shadowing_db = 0.0;
  int wall_count() const;
};

class PropagationModel {
 public:
  /// Builds the Embree wall scene from `world.mesh` and one shadowing field per AP over
  /// `world.plan`'s bounds, from the sub-streams "shadowing/ap<id>" of `seed`.
  PropagationModel(const World& world, std::vector<AccessPoint> access_points,
                   PropagationOptions options, std::uint64_t seed);
  /// Same from a bare mesh and the bounds the shadowing fields must cover (hand-built tests).
  PropagationModel(const Mesh& mesh, const Eigen::Vector2d& bounds_min_m,
                   const Eigen::Vector2d& bounds_max_m, std::vector<AccessPoint> access_points,
                   PropagationOptions options, std::uint64_t seed);

  const std::vector<AccessPoint>& access_points() const { return aps_; }
  const PropagationOptions& options() const { return options_; }
  const EmbreeWallScene& wall_scene() const { return *walls_; }

  RadioLink link(std::size_t ap_index, const Eigen::Vector3d& receiver_m) const;
  /// The link with no wall counted (no ray cast). When walls_only_attenuate(), RSSI computed
  /// from it bounds the true RSSI from above: radio maps use it to skip hopeless APs.
  RadioLink link_without_walls(std::size_t ap_index, const Eigen::Vector3d& receiver_m) const;
  /// True when no wall loss is negative anywhere in the Wi-Fi bands (2.4-5.9 GHz).
  bool walls_only_attenuate() const;
  /// Path loss (ITU + walls, no shadowing) at `frequency_mhz` for a link.
  double path_loss_db(const RadioLink& link, double frequency_mhz) const;
  /// Mean RSSI (shadowing included, no fading) of BSSID `bssid` of AP `ap_index`.
  double mean_rssi_dbm(std::size_t ap_index, const Bssid& bssid, const RadioLink& link) const;
  double mean_rssi_dbm(std::size_t ap_index, const Bssid& bssid,
                       const Eigen::Vector3d& receiver_m) const {
    return mean_rssi_dbm(ap_index, bssid, link(ap_index, receiver_m));
  }
  /// Index of the AP with this id, or nullopt.
  std::optional<std::size_t> index_of(int ap_id) const;

 private:
  std::vector<AccessPoint> aps_;
  PropagationOptions options_;
  std::unique_ptr<EmbreeWallScene> walls_;
  std::vector<ShadowingField> shadowing_;
  double floor_loss_db_ = 0.0;
};

}  // namespace wifislam
