#include "radio_model/propagation_model.hpp"

#include <fmt/format.h>

namespace wifislam {

PropagationOptions PropagationOptions::from_scene(const RadioSpec& radio) {
  PropagationOptions o;
  o.environment = radio.environment;
  o.distance_coefficient = radio.distance_coefficient;
  o.shadowing_sigma_db = radio.shadowing_sigma_db;
  o.shadowing_decorrelation_m = radio.shadowing_decorrelation_m;
  o.fast_fading_sigma_db = radio.fast_fading_sigma_db;
  o.fading_coherence_s = radio.fading_coherence_s;
  o.bssid_spread_db = radio.bssid_spread_db;
  o.people_disturbance_db = radio.people_disturbance_db;
  return o;
}

int RadioLink::wall_count() const {
  int n = 0;
  for (int c : walls_per_material) n += c;
  return n;
}

PropagationModel::PropagationModel(const World& world, std::vector<AccessPoint> access_points,
                                   PropagationOptions options, std::uint64_t seed)
    : PropagationModel(world.mesh, world.plan.bounds_min_m, world.plan.bounds_max_m,
                       std::move(access_points), std::move(options), seed) {}

PropagationModel::PropagationModel(const Mesh& mesh, const Eigen::Vector2d& bounds_min_m,
                                   const Eigen::Vector2d& bounds_max_m,
                                   std::vector<AccessPoint> access_points,
                                   PropagationOptions options, std::uint64_t seed)
    : aps_(std::move(access_points)),
      options_(std::move(options)),
      walls_(std::make_unique<EmbreeWallScene>(mesh)),
      floor_loss_db_(itu_p1238_floor_loss_db(options_.environment, options_.floors_between)) {
  // One grid and covariance spectrum for the site, one field per AP from its own stream.
  const ShadowingGrid grid(bounds_min_m, bounds_max_m, options_.shadowing_sigma_db,
                           options_.shadowing_decorrelation_m);
  shadowing_.reserve(aps_.size());
  for (const AccessPoint& ap : aps_)
    shadowing_.push_back(grid.draw(Rng::stream(seed, fmt::format("shadowing/ap{}", ap.id))));
}

RadioLink PropagationModel::link(std::size_t ap_index, const Eigen::Vector3d& receiver_m) const {
  const AccessPoint& ap = aps_[ap_index];
  RadioLink l;
  l.distance_m = (receiver_m - ap.position_m).norm();
  if (options_.walls) {
    thread_local std::vector<WallCrossing> crossings;
    walls_->walls_crossed(ap.position_m, receiver_m, crossings);
    for (const WallCrossing& c : crossings) ++l.walls_per_material[material_index(c.material)];
  }
  l.shadowing_db = shadowing_[ap_index].at_db(receiver_m.head<2>());
  return l;
}

RadioLink PropagationModel::link_without_walls(std::size_t ap_index,
                                               const Eigen::Vector3d& receiver_m) const {
  RadioLink l;
  l.distance_m = (receiver_m - aps_[ap_index].position_m).norm();
  l.shadowing_db = shadowing_[ap_index].at_db(receiver_m.head<2>());
  return l;
}

bool PropagationModel::walls_only_attenuate() const {
  // Loss laws are linear in frequency: checking the band edges covers the bands.
  for (const WallLossLaw& law : options_.wall_losses.laws)
    if (law.at(2400.0) < 0.0 || law.at(5900.0) < 0.0) return false;
  return true;
}

double PropagationModel::path_loss_db(const RadioLink& link, double frequency_mhz) const {
  double loss = itu_p1238_path_loss_db(frequency_mhz, link.distance_m,
                                       options_.distance_coefficient_or_default(), floor_loss_db_);
  for (int m = 0; m < kWallMaterialCount; ++m) {
    if (link.walls_per_material[m] > 0)
      loss += link.walls_per_material[m] * options_.wall_losses.laws[m].at(frequency_mhz);
  }
  return loss;
}

double PropagationModel::mean_rssi_dbm(std::size_t ap_index, const Bssid& bssid,
                                       const RadioLink& link) const {
  return aps_[ap_index].tx_power_dbm - path_loss_db(link, bssid.frequency_mhz()) -
         link.shadowing_db;
}

std::optional<std::size_t> PropagationModel::index_of(int ap_id) const {
  for (std::size_t i = 0; i < aps_.size(); ++i)
    if (aps_[i].id == ap_id) return i;
  return std::nullopt;
}

}  // namespace wifislam
