#pragma once
// Mean received power from every access point at any receiver position, by one of three path
// loss models (radio.model):
//
//  itu_walls (default): ITU-R P.1238's distance law with a stated N plus every wall and floor
//    slab on the straight AP -> receiver segment, found by Embree (embree_wall_scene.hpp,
//    wall_materials.hpp):
//      RSSI = P_tx - L_ITU(f, d; N) - sum over walls and slabs crossed L(material, f) - S
//    N = radio.distance_coefficient, default 22 (itu_p1238.hpp says why). A slab costs its
//    material's loss like a wall (concrete: TR 38.901's 5 + 4 f, which matches a 0.2 m slab:
//    wall_materials.hpp); P.1238's floor factor is not added on top. Shadowing sigma 4 dB by
//    default.
//  itu_site_general: P.1238-7's site-general model for radio.environment, no walls: N from
//    Table 2, the floor penetration factor Lf(n) of Table 3 for the n floor slabs the segment
//    crosses (Embree counts them; itu_p1238_floor_loss_db has the rows), and shadowing sigma from
//    Table 4, each for the BSSID's band (2.4 GHz row, 5.2 GHz row for 5 GHz); the walls of the
//    building are in N, as the recommendation fitted it.
//  itu_site_general_fit: P.1238-11's alpha/beta/gamma fit (office rows), line of sight where the
//    segment crosses no wall or slab and non line of sight where it crosses any (Embree decides
//    which; the walls themselves add no loss), shadowing sigma the row's. The fit is for both
//    ends on one floor; a link through floors adds Lf(n) as itu_site_general does.
//
// S is the AP's spatially correlated shadowing (shadowing_field.hpp): one unit-variance field
// per AP, shared by both of its radios, scaled by the model's sigma for the link (or by
// radio.shadowing_sigma_db when the scene sets it, under any model). Fast fading and people are
// per scan and live in the scanner.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "radio_model/access_point.hpp"
#include "radio_model/embree_wall_scene.hpp"
#include "radio_model/itu_p1238.hpp"
#include "radio_model/path_loss_choice.hpp"
#include "radio_model/radio_defaults.hpp"
#include "radio_model/shadowing_field.hpp"
#include "radio_model/wall_materials.hpp"
#include "radio_model/wall_mesh.hpp"

namespace wifislam::radio_model {

struct PropagationOptions {
  PathLossModel model = PathLossModel::kItuWalls;
  RadioEnvironment environment = RadioEnvironment::kOffice;
  /// N in the ITU formula; default kDefaultDistanceCoefficient (see itu_p1238.hpp for why).
  std::optional<double> distance_coefficient;
  /// Count walls and slabs (off = the distance law alone, under every model).
  bool walls = true;
  WallLossTable wall_losses;
  /// Shadowing sigma; nullopt: the model's (shadowing_sigma_db_for). Under itu_walls that is
  /// 4 dB, ITU-R P.1238-11's site-general corridor LoS fit (4.07 dB); the recommendation's
  /// 8-12 dB (P.1238-7 Table 4) also covers building-to-building variation that our explicit
  /// walls already model.
  std::optional<double> shadowing_sigma_db;
  double shadowing_decorrelation_m = defaults::kShadowingDecorrelationM;
  /// The floor elevations of the building's storeys, lowest first (empty or one: one storey).
  /// Shadowing is correlated in 3-D: one field per AP and storey, mixed so that two receivers
  /// at the same (x, y) on storeys dz apart correlate as exp(-dz / decorrelation), as two
  /// receivers dz apart on one storey do (PropagationModel::shadowing_normal).
  std::vector<double> storey_elevations_m;
  /// Scanner: the fading of each radio (fading_process.hpp) with its coherence time at a still
  /// receiver, the per-BSSID spread around it, and random extra loss from people.
  double fast_fading_sigma_db = defaults::kFastFadingSigmaDb;
  double fading_coherence_s = defaults::kFadingCoherenceS;
  double bssid_spread_db = defaults::kBssidSpreadDb;
  double people_disturbance_db =
      defaults::kPeopleDisturbanceDb;  // 0 = off; else extra loss up to this much
  double people_probability = 0.3;     // chance a person blocks a given AP during one scan

  double distance_coefficient_or_default() const {
    return distance_coefficient.value_or(kDefaultDistanceCoefficient);
  }
  /// The shadowing sigma of a link in `band`, with or without a wall on it.
  double shadowing_sigma_db_for(RadioBand band, bool line_of_sight) const;
  /// The largest sigma any link can have (0: no shadowing at all).
  double max_shadowing_sigma_db() const;
};

/// The geometry-dependent part of one AP -> receiver link, shared by all its BSSIDs.
struct RadioLink {
  double distance_m = 0.0;
  /// Walls crossed, by material; a crossing that enters through one material and leaves through
  /// another counts half a wall of each (embree_wall_scene.hpp). Counted under itu_walls and
  /// itu_site_general_fit (which needs only whether there is one); empty under itu_site_general.
  std::array<double, kWallMaterialCount> walls_per_material{};
  /// Floor slabs crossed, by material (counted as walls are, under every model; empty without
  /// slabs), and how many.
  std::array<double, kWallMaterialCount> slabs_per_material{};
  int slabs_crossed = 0;
  /// The AP's shadowing field at the receiver, in standard deviations (scaled per band by the
  /// model: PropagationModel::shadowing_db).
  double shadowing_normal = 0.0;
  /// Walls crossed (slabs not included).
  double wall_count() const;
  /// No wall and no slab on the segment.
  bool line_of_sight() const { return wall_count() == 0.0 && slabs_crossed == 0; }
};

class PropagationModel {
 public:
  /// Builds the Embree wall scene from `walls` and one shadowing field per AP over the rectangle
  /// `bounds_min_m`..`bounds_max_m` (the plan's bounds: every receiver stands inside it), from the
  /// sub-streams "shadowing/ap<id>" of `seed`. The walls are copied into Embree: `walls` need not
  /// outlive the model.
  PropagationModel(const WallMesh& walls, const Eigen::Vector2d& bounds_min_m,
                   const Eigen::Vector2d& bounds_max_m, std::vector<AccessPoint> access_points,
                   PropagationOptions options, std::uint64_t seed);

  const std::vector<AccessPoint>& access_points() const { return aps_; }
  const PropagationOptions& options() const { return options_; }
  const EmbreeWallScene& wall_scene() const { return *walls_; }

  RadioLink link(std::size_t ap_index, const Eigen::Vector3d& receiver_m) const;
  /// The link with no wall counted (no ray cast). When walls_only_attenuate(), RSSI computed
  /// from it bounds the true RSSI from above: radio maps use it to skip hopeless APs. (Under
  /// itu_site_general_fit it is the LoS link, whose loss is below the NLoS loss: see
  /// itu_p1238_fit_loss_db.)
  RadioLink link_without_walls(std::size_t ap_index, const Eigen::Vector3d& receiver_m) const;
  /// True when a wall on the link can only lower RSSI anywhere in the Wi-Fi bands (2.4-5.9 GHz):
  /// under itu_walls no wall loss is negative, and neither the NLoS fit nor its sigma can give more
  /// than the LoS one.
  bool walls_only_attenuate() const;
  /// Path loss (no shadowing) at `frequency_mhz` for a link, by the model.
  double path_loss_db(const RadioLink& link, double frequency_mhz) const;
  /// AP `ap_index`'s unit shadowing at `receiver_m`. On storey k (the last elevation at or below
  /// the receiver's z): S_0 = W_0(x, y) and S_k = rho_k S_(k-1) + sqrt(1 - rho_k^2) W_k(x, y),
  /// rho_k = exp(-(e_k - e_(k-1)) / decorrelation), W_k the AP's independent field of storey k.
  /// One storey: W_0, the field a one-storey building has always had.
  double shadowing_normal(std::size_t ap_index, const Eigen::Vector3d& receiver_m) const;
  /// The link's shadowing in dB for a BSSID in `band`.
  double shadowing_db(const RadioLink& link, RadioBand band) const;
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
  /// [AP][storey], shared with other models of the site (shadowing_cache.hpp).
  std::vector<std::vector<std::shared_ptr<const ShadowingField>>> shadowing_;
  /// Every material's wall loss at each frequency the access points' BSSIDs use, computed once:
  /// the P.2040 absorption laws cost a pow and logs per call, and a scan asks per BSSID. Values
  /// are those of WallLossLaw::at (the same call, made earlier).
  struct WallLossesAt {
    double frequency_mhz;
    std::array<double, kWallMaterialCount> loss_db;
  };
  std::vector<WallLossesAt> wall_losses_at_;
};

}  // namespace wifislam::radio_model
