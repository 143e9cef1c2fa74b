#include "radio_model/propagation_model.hpp"

#include "radio_model/shadowing_cache.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"

namespace wifislam::radio_model {

double PropagationOptions::shadowing_sigma_db_for(RadioBand band, bool line_of_sight) const {
  if (shadowing_sigma_db) return *shadowing_sigma_db;
  switch (model) {
    case PathLossModel::kItuWalls:
      return 4.0;
    case PathLossModel::kItuSiteGeneral:
      return itu_p1238_coefficients(environment, band).shadow_sigma_db;
    case PathLossModel::kItuSiteGeneralFit:
      return itu_p1238_office_fit(line_of_sight).sigma_db;
  }
  return 0.0;
}

double PropagationOptions::max_shadowing_sigma_db() const {
  double sigma = 0.0;
  for (RadioBand band : {RadioBand::k2_4GHz, RadioBand::k5GHz})
    for (bool los : {true, false}) sigma = std::max(sigma, shadowing_sigma_db_for(band, los));
  return sigma;
}

double RadioLink::wall_count() const {
  double n = 0;
  for (double c : walls_per_material) n += c;
  return n;
}

PropagationModel::PropagationModel(const WallMesh& walls, const Eigen::Vector2d& bounds_min_m,
                                   const Eigen::Vector2d& bounds_max_m,
                                   std::vector<AccessPoint> access_points,
                                   PropagationOptions options, std::uint64_t seed)
    : aps_(std::move(access_points)),
      options_(std::move(options)),
      walls_(std::make_unique<EmbreeWallScene>(walls)) {
  const std::vector<double>& floors = options_.storey_elevations_m;
  for (std::size_t k = 1; k < floors.size(); ++k) {
    if (!(floors[k] > floors[k - 1])) {
      throw InvalidInputError(fmt::format(
          "radio model: storey elevations must rise (storey {} at {} m, storey {} at {} m)", k - 1,
          floors[k - 1], k, floors[k]));
    }
  }
  // One grid and covariance spectrum for the site, one field per AP from its own stream.
  // Unit variance: each link scales it by its own sigma (shadowing_db). One field per AP, from
  // its own stream, shared with every other model of this site (shadowing_cache.hpp).
  const double unit_sigma = options_.max_shadowing_sigma_db() > 0.0 ? 1.0 : 0.0;
  shadowing_.reserve(aps_.size());
  for (const AccessPoint& ap : aps_) {
    std::vector<std::shared_ptr<const ShadowingField>>& storeys = shadowing_.emplace_back();
    const std::size_t storey_count = std::max<std::size_t>(1, options_.storey_elevations_m.size());
    for (std::size_t k = 0; k < storey_count; ++k) {
      storeys.push_back(shared_shadowing_field(bounds_min_m, bounds_max_m, unit_sigma,
                                               options_.shadowing_decorrelation_m, seed, ap.id,
                                               static_cast<int>(k)));
    }
    for (const Bssid& bssid : ap.bssids) {
      const double f = bssid.frequency_mhz();
      if (std::any_of(wall_losses_at_.begin(), wall_losses_at_.end(),
                      [&](const WallLossesAt& w) { return w.frequency_mhz == f; }))
        continue;
      WallLossesAt& w = wall_losses_at_.emplace_back();
      w.frequency_mhz = f;
      for (int m = 0; m < kWallMaterialCount; ++m)
        w.loss_db[m] = options_.wall_losses.laws[m].at(f);
    }
  }
}

RadioLink PropagationModel::link(std::size_t ap_index, const Eigen::Vector3d& receiver_m) const {
  const AccessPoint& ap = aps_[ap_index];
  RadioLink l;
  l.distance_m = (receiver_m - ap.position_m).norm();
  // itu_site_general counts no wall, so it casts rays only in a building with floor slabs.
  const bool count_walls = options_.model != PathLossModel::kItuSiteGeneral;
  if (options_.walls && (count_walls || walls_->has_slabs())) {
    thread_local std::vector<WallCrossing> crossings;
    walls_->walls_crossed(ap.position_m, receiver_m, crossings);
    for (const WallCrossing& c : crossings) {
      if (!c.slab && !count_walls) continue;
      std::array<double, kWallMaterialCount>& per_material =
          c.slab ? l.slabs_per_material : l.walls_per_material;
      if (c.slab) ++l.slabs_crossed;
      if (c.material == c.exit_material) {
        per_material[material_index(c.material)] += 1.0;
      } else {
        per_material[material_index(c.material)] += 0.5;
        per_material[material_index(c.exit_material)] += 0.5;
      }
    }
  }
  l.shadowing_normal = shadowing_normal(ap_index, receiver_m);
  return l;
}

double PropagationModel::shadowing_normal(std::size_t ap_index,
                                          const Eigen::Vector3d& receiver_m) const {
  const auto& fields = shadowing_[ap_index];
  const Eigen::Vector2d xy = receiver_m.head<2>();
  double s = fields[0]->at_db(xy);
  const std::vector<double>& floors = options_.storey_elevations_m;
  for (std::size_t k = 1; k < fields.size() && floors[k] <= receiver_m.z(); ++k) {
    const double rho = std::exp(-(floors[k] - floors[k - 1]) / options_.shadowing_decorrelation_m);
    s = rho * s + std::sqrt(1.0 - rho * rho) * fields[k]->at_db(xy);
  }
  return s;
}

RadioLink PropagationModel::link_without_walls(std::size_t ap_index,
                                               const Eigen::Vector3d& receiver_m) const {
  RadioLink l;
  l.distance_m = (receiver_m - aps_[ap_index].position_m).norm();
  l.shadowing_normal = shadowing_normal(ap_index, receiver_m);
  return l;
}

bool PropagationModel::walls_only_attenuate() const {
  if (options_.model == PathLossModel::kItuSiteGeneral) return true;  // walls are not counted
  if (options_.model == PathLossModel::kItuSiteGeneralFit) {
    // The NLoS row loses more than the LoS row (itu_p1238_fit_loss_db), but its larger sigma can
    // make a link's shadowing a gain bigger than that margin: bounds hold only without it.
    return options_.shadowing_sigma_db.has_value();
  }
  // Every law is monotonic over the bands (linear, or a measured loss plus an absorption that grows
  // with the conductivity), so its values at the band edges bound it.
  for (const WallLossLaw& law : options_.wall_losses.laws)
    if (law.at(2400.0) < 0.0 || law.at(5900.0) < 0.0) return false;
  return true;
}

double PropagationModel::path_loss_db(const RadioLink& link, double frequency_mhz) const {
  switch (options_.model) {
    case PathLossModel::kItuWalls:
      break;
    case PathLossModel::kItuSiteGeneral: {
      const RadioBand band = frequency_mhz < 4000.0 ? RadioBand::k2_4GHz : RadioBand::k5GHz;
      return itu_p1238_path_loss_db(
          frequency_mhz, link.distance_m,
          itu_p1238_coefficients(options_.environment, band).distance_coefficient,
          itu_p1238_floor_loss_db(options_.environment, frequency_mhz, link.slabs_crossed));
    }
    case PathLossModel::kItuSiteGeneralFit:
      return itu_p1238_fit_loss_db(itu_p1238_office_fit(link.line_of_sight()), frequency_mhz,
                                   link.distance_m) +
             itu_p1238_floor_loss_db(options_.environment, frequency_mhz, link.slabs_crossed);
  }
  double loss = itu_p1238_path_loss_db(frequency_mhz, link.distance_m,
                                       options_.distance_coefficient_or_default(), 0.0);
  const WallLossesAt* known = nullptr;
  for (const WallLossesAt& w : wall_losses_at_)
    if (w.frequency_mhz == frequency_mhz) known = &w;
  for (int m = 0; m < kWallMaterialCount; ++m) {
    const double crossed = link.walls_per_material[m] + link.slabs_per_material[m];
    if (crossed > 0) {
      loss +=
          crossed * (known ? known->loss_db[m] : options_.wall_losses.laws[m].at(frequency_mhz));
    }
  }
  return loss;
}

double PropagationModel::mean_rssi_dbm(std::size_t ap_index, const Bssid& bssid,
                                       const RadioLink& link) const {
  return aps_[ap_index].tx_power_dbm - path_loss_db(link, bssid.frequency_mhz()) -
         shadowing_db(link, bssid.band);
}

double PropagationModel::shadowing_db(const RadioLink& link, RadioBand band) const {
  return options_.shadowing_sigma_db_for(band, link.line_of_sight()) * link.shadowing_normal;
}

std::optional<std::size_t> PropagationModel::index_of(int ap_id) const {
  for (std::size_t i = 0; i < aps_.size(); ++i)
    if (aps_[i].id == ap_id) return i;
  return std::nullopt;
}

}  // namespace wifislam::radio_model
