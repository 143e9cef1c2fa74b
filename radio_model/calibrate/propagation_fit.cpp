#include "radio_model/calibrate/propagation_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <Eigen/Dense>

#include "core/error.hpp"
#include "radio_model/itu_p1238.hpp"

namespace wifislam::radio_model::calibrate {

namespace {
double log_distance(const LinkGroup& g) { return std::log10(std::max(g.distance_m, 1.0)); }
}  // namespace

double LinearRadioModel::predict_dbm(const LinkGroup& g) const {
  double rss = intercept_dbm[g.ap_index] - distance_coefficient * log_distance(g);
  for (int m = 0; m < radio_model::kWallMaterialCount; ++m)
    rss -= wall_loss_db[m] * g.walls_per_material[m];
  if (g.device_index < device_offset_db.size()) rss += device_offset_db[g.device_index];
  return rss;
}

double intercept_from_tx_dbm(double tx_power_dbm, double frequency_mhz) {
  return tx_power_dbm - (20.0 * std::log10(frequency_mhz) - 28.0);  // itu_p1238_path_loss_db at 1 m
}

double tx_from_intercept_dbm(double intercept_dbm, double frequency_mhz) {
  return intercept_dbm + (20.0 * std::log10(frequency_mhz) - 28.0);
}

LinearRadioModel scene_model(const SurveyLinks& links, const radio_model::WallLossTable& walls,
                             std::optional<double> distance_coefficient,
                             double default_tx_power_dbm, double frequency_mhz) {
  LinearRadioModel m;
  m.distance_coefficient = distance_coefficient.value_or(radio_model::kDefaultDistanceCoefficient);
  for (const SurveyAccessPoint& ap : links.aps) {
    m.intercept_dbm.push_back(
        intercept_from_tx_dbm(ap.tx_power_dbm.value_or(default_tx_power_dbm), frequency_mhz));
  }
  for (int k = 0; k < radio_model::kWallMaterialCount; ++k)
    m.wall_loss_db[k] = walls.laws[k].at(frequency_mhz);
  return m;
}

PropagationFit fit_propagation(
    const SurveyLinks& links,
    const std::array<double, radio_model::kWallMaterialCount>& defaults_db) {
  PropagationFit fit;
  const std::size_t rows = links.groups.size();
  // Unknowns: an intercept per AP with data, N, then the fitted materials.
  std::vector<int> column_of_ap(links.aps.size(), -1);
  int columns = 0;
  for (const LinkGroup& g : links.groups)
    if (column_of_ap[g.ap_index] < 0) column_of_ap[g.ap_index] = columns++;
  const int n_column = columns++;
  // An offset per device with data, but the reference.
  std::vector<int> column_of_device(links.devices.size(), -1);
  for (const LinkGroup& g : links.groups)
    if (g.device_index > 0 && column_of_device[g.device_index] < 0)
      column_of_device[g.device_index] = columns++;

  auto design = [&](const std::vector<int>& materials) {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows),
                                              columns + static_cast<int>(materials.size()));
    for (std::size_t r = 0; r < rows; ++r) {
      const LinkGroup& g = links.groups[r];
      a(r, column_of_ap[g.ap_index]) = 1.0;
      a(r, n_column) = -log_distance(g);
      if (column_of_device[g.device_index] >= 0) a(r, column_of_device[g.device_index]) = 1.0;
      for (std::size_t k = 0; k < materials.size(); ++k)
        a(r, columns + static_cast<int>(k)) = -g.walls_per_material[materials[k]];
    }
    return a;
  };
  auto rank_of = [](const Eigen::MatrixXd& a) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
    qr.setThreshold(1e-9);
    return static_cast<int>(qr.rank());
  };

  if (rank_of(design({})) < columns || static_cast<int>(rows) <= columns) {
    throw InvalidInputError(fmt::format(
        "the survey cannot determine the distance coefficient: {} position-AP links for {} "
        "unknowns (an intercept per AP, N and an offset per device but the first), or all links "
        "of one length per AP, or devices that never measured an AP another device did; survey "
        "more positions at different distances",
        rows, columns));
  }

  // Materials in schema order; each kept only if enough links cross it and it adds rank.
  std::vector<int> fitted;
  for (int m = 0; m < radio_model::kWallMaterialCount; ++m) {
    MaterialFit& mf = fit.materials[m];
    mf.loss_db = defaults_db[m];
    for (const LinkGroup& g : links.groups)
      if (g.walls_per_material[m] > 0.0) ++mf.links;
    if (mf.links == 0) {
      mf.reason = "no surveyed link crosses it";
      continue;
    }
    if (mf.links < kMinLinksPerMaterial) {
      mf.reason = fmt::format("only {} links cross it (at least {} needed)", mf.links,
                              kMinLinksPerMaterial);
      continue;
    }
    std::vector<int> with = fitted;
    with.push_back(m);
    const Eigen::MatrixXd a = design(with);
    if (rank_of(a) < a.cols()) {
      mf.reason = "confounded with the AP intercepts, N or another material";
      continue;
    }
    fitted = with;
  }

  // Materials not fitted enter with their known loss (the scene's, or 0 once pinned).
  std::array<double, radio_model::kWallMaterialCount> known_db = defaults_db;
  Eigen::MatrixXd a;
  Eigen::VectorXd x;
  for (;;) {
    Eigen::VectorXd y(static_cast<Eigen::Index>(rows));
    for (std::size_t r = 0; r < rows; ++r) {
      const LinkGroup& g = links.groups[r];
      double known = 0.0;
      for (int m = 0; m < radio_model::kWallMaterialCount; ++m) {
        if (std::find(fitted.begin(), fitted.end(), m) == fitted.end())
          known += known_db[m] * g.walls_per_material[m];
      }
      y(r) = g.mean_dbm + known;
    }
    a = design(fitted);
    x = a.colPivHouseholderQr().solve(y);
    // A wall cannot amplify: the most negative loss is pinned at 0 dB and the rest refitted
    // (an active-set solution of the loss >= 0 constraint, one material at a time).
    std::size_t worst = fitted.size();
    for (std::size_t k = 0; k < fitted.size(); ++k) {
      const double loss = x(columns + static_cast<int>(k));
      if (loss < 0.0 && (worst == fitted.size() || loss < x(columns + static_cast<int>(worst))))
        worst = k;
    }
    if (worst == fitted.size()) {
      const Eigen::VectorXd residual = y - a * x;
      fit.rows = static_cast<int>(rows);
      fit.parameters = static_cast<int>(a.cols());
      const double dof = static_cast<double>(rows) - static_cast<double>(a.cols());
      fit.residual_sigma_db = std::sqrt(residual.squaredNorm() / dof);
      break;
    }
    const int m = fitted[worst];
    MaterialFit& mf = fit.materials[m];
    mf.pinned_at_zero = true;
    mf.loss_db = 0.0;
    mf.reason = fmt::format("fitted {:.2f} dB; held at 0 dB (a wall cannot amplify)",
                            x(columns + static_cast<int>(worst)));
    known_db[m] = 0.0;
    fitted.erase(fitted.begin() + static_cast<std::ptrdiff_t>(worst));
  }
  const double s2 = fit.residual_sigma_db * fit.residual_sigma_db;
  const Eigen::MatrixXd covariance =
      (a.transpose() * a).ldlt().solve(Eigen::MatrixXd::Identity(a.cols(), a.cols())) * s2;
  auto ci = [&](int c) { return kZ95 * std::sqrt(std::max(covariance(c, c), 0.0)); };

  fit.design = a;
  fit.distance_column = n_column;
  fit.intercept_column = column_of_ap;
  for (std::size_t k = 0; k < fitted.size(); ++k)
    fit.material_column[fitted[k]] = columns + static_cast<int>(k);
  fit.model.distance_coefficient = x(n_column);
  fit.distance_coefficient_ci95 = ci(n_column);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  fit.model.intercept_dbm.assign(links.aps.size(), nan);
  fit.intercept_ci95_db.assign(links.aps.size(), nan);
  for (std::size_t i = 0; i < links.aps.size(); ++i) {
    if (column_of_ap[i] < 0) continue;
    fit.model.intercept_dbm[i] = x(column_of_ap[i]);
    fit.intercept_ci95_db[i] = ci(column_of_ap[i]);
  }
  fit.model.wall_loss_db = known_db;
  fit.device_column = column_of_device;
  fit.model.device_offset_db.assign(links.devices.size(), 0.0);
  fit.device_offset_ci95_db.assign(links.devices.size(), 0.0);
  for (std::size_t d = 0; d < links.devices.size(); ++d) {
    if (column_of_device[d] < 0) continue;
    fit.model.device_offset_db[d] = x(column_of_device[d]);
    fit.device_offset_ci95_db[d] = ci(column_of_device[d]);
  }
  for (std::size_t k = 0; k < fitted.size(); ++k) {
    const int c = columns + static_cast<int>(k);
    MaterialFit& mf = fit.materials[fitted[k]];
    mf.fitted = true;
    mf.loss_db = x(c);
    mf.ci95_db = ci(c);
    fit.model.wall_loss_db[fitted[k]] = x(c);
  }
  return fit;
}

LinearRadioModel fit_log_distance(const SurveyLinks& links) {
  // Normal equations of RSS = A - N log10 d over every sample (two unknowns).
  Eigen::Matrix2d ata = Eigen::Matrix2d::Zero();
  Eigen::Vector2d aty = Eigen::Vector2d::Zero();
  for (const LinkGroup& g : links.groups) {
    const Eigen::Vector2d row(1.0, -log_distance(g));
    for (double r : g.rss_dbm) {
      ata += row * row.transpose();
      aty += row * r;
    }
  }
  const Eigen::Vector2d x = ata.ldlt().solve(aty);
  LinearRadioModel m;
  m.distance_coefficient = x(1);
  m.intercept_dbm.assign(links.aps.size(), x(0));
  return m;
}

HeldOutDeviceScore score_held_out_device(const SurveyLinks& held, const LinearRadioModel& fitted,
                                         const LinearRadioModel& log_distance,
                                         int offset_positions) {
  HeldOutDeviceScore out;
  out.device = held.devices.empty() ? std::string() : held.devices.front();
  out.offset_positions = offset_positions;
  // The fitted models without offsets: the held-out device has none of its own in them.
  LinearRadioModel fit = fitted, plain = log_distance;
  fit.device_offset_db.clear();
  plain.device_offset_db.clear();
  // Positions in survey order (groups are in order of first appearance).
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::size_t> position_of(held.groups.size());
  for (std::size_t i = 0; i < held.groups.size(); ++i) {
    const Eigen::Vector3d& p = held.groups[i].position_m;
    auto it = std::find_if(positions.begin(), positions.end(),
                           [&](const Eigen::Vector3d& q) { return (p - q).norm() < 1e-3; });
    position_of[i] = static_cast<std::size_t>(it - positions.begin());
    if (it == positions.end()) positions.push_back(p);
  }
  if (static_cast<int>(positions.size()) <= offset_positions)
    throw InvalidInputError(fmt::format(
        "the held-out device '{}' was surveyed at {} positions: more than the {} its offset is "
        "fitted from are needed to score it",
        out.device, positions.size(), offset_positions));
  auto mean_residual = [&](const LinearRadioModel& m) {
    double sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < held.groups.size(); ++i) {
      if (static_cast<int>(position_of[i]) >= offset_positions) continue;
      const double predicted = m.predict_dbm(held.groups[i]);
      if (!std::isfinite(predicted)) continue;
      for (double r : held.groups[i].rss_dbm) {
        sum += r - predicted;
        ++n;
      }
    }
    return n > 0 ? sum / n : 0.0;
  };
  auto rms = [&](const LinearRadioModel& m, double offset_db, int* samples) {
    double sum2 = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < held.groups.size(); ++i) {
      if (static_cast<int>(position_of[i]) < offset_positions) continue;
      const double predicted = m.predict_dbm(held.groups[i]);
      if (!std::isfinite(predicted)) continue;  // an AP the fit had no data for
      for (double r : held.groups[i].rss_dbm) {
        const double e = r - predicted - offset_db;
        sum2 += e * e;
        ++n;
      }
    }
    if (samples) *samples = n;
    return n > 0 ? std::sqrt(sum2 / n) : std::numeric_limits<double>::quiet_NaN();
  };
  out.offset_db = mean_residual(fit);
  out.rms_without_offset_db = rms(fit, 0.0, &out.scored_samples);
  out.rms_with_offset_db = rms(fit, out.offset_db, nullptr);
  out.log_distance_rms_db = rms(plain, 0.0, nullptr);
  out.log_distance_rms_with_offset_db = rms(plain, mean_residual(plain), nullptr);
  return out;
}

std::vector<ApResiduals> residuals_per_ap(const SurveyLinks& links, const LinearRadioModel& model) {
  std::vector<ApResiduals> out(links.aps.size() + 1);
  std::vector<double> sum(out.size(), 0.0), sum2(out.size(), 0.0);
  for (const LinkGroup& g : links.groups) {
    const double predicted = model.predict_dbm(g);
    if (!std::isfinite(predicted)) continue;  // an AP the fit had no data for
    for (double r : g.rss_dbm) {
      const double e = r - predicted;
      for (std::size_t k : {g.ap_index, links.aps.size()}) {
        ++out[k].samples;
        sum[k] += e;
        sum2[k] += e * e;
      }
    }
  }
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (out[k].samples == 0) continue;
    out[k].bias_db = sum[k] / out[k].samples;
    out[k].rms_db = std::sqrt(sum2[k] / out[k].samples);
  }
  return out;
}

}  // namespace wifislam::radio_model::calibrate
