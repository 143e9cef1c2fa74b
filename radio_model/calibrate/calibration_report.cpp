#include "radio_model/calibrate/calibration_report.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "radio_model/access_point.hpp"

namespace wifislam::radio_model::calibrate {

namespace {

// The scene schema's ranges (sim/scene/scene_schema.hpp).
struct Range {
  double lo, hi;
};
constexpr Range kDistanceCoefficient{10.0, 60.0}, kSigmaDb{0.0, 30.0}, kDecorrelationM{0.5, 1000.0},
    kWallLossDb{0.0, 100.0}, kTxPowerDbm{kMinTxPowerDbm, kMaxTxPowerDbm};

std::string clamped(double v, Range r, std::string& note, const char* key) {
  const double c = std::clamp(v, r.lo, r.hi);
  if (c != v) note += fmt::format("  # {}: fitted {:.2f}, clamped to the schema's range", key, v);
  return fmt::format("{:.2f}", c);
}

WallMaterial material(int m) { return static_cast<WallMaterial>(m); }

std::string residual_cell(const ApResiduals& r) {
  return r.samples ? fmt::format("{:.2f} / {:+.2f}", r.rms_db, r.bias_db) : "-";
}

nlohmann::json residuals_json(const SurveyLinks& links, const LinearRadioModel& model) {
  const auto rs = residuals_per_ap(links, model);
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t k = 0; k < rs.size(); ++k) {
    const std::string key = k < links.aps.size() ? std::to_string(links.aps[k].id) : "all";
    out[key] = {{"samples", rs[k].samples}, {"rms_db", rs[k].rms_db}, {"bias_db", rs[k].bias_db}};
  }
  return out;
}

std::vector<int> samples_per_device(const SurveyLinks& links) {
  std::vector<int> n(links.devices.size(), 0);
  for (const LinkGroup& g : links.groups) n[g.device_index] += static_cast<int>(g.rss_dbm.size());
  return n;
}

/// Whether the report has a devices section: several devices, or one held out.
bool reports_devices(const Calibration& c) { return c.train.devices.size() > 1 || c.held_out; }

double offset_of(const PropagationFit& f, std::size_t d) {
  return d < f.model.device_offset_db.size() ? f.model.device_offset_db[d] : 0.0;
}
double offset_ci_of(const PropagationFit& f, std::size_t d) {
  return d < f.device_offset_ci95_db.size() ? f.device_offset_ci95_db[d] : 0.0;
}

}  // namespace

std::string calibration_scene_yaml(const Calibration& c) {
  const PropagationFit& f = c.fit;
  std::string y = fmt::format(
      "# wifislam radio calibrate: {} fitted to {} ({} samples, {} position-AP links) at {} MHz.\n"
      "# Replace the scene's radio and access_points blocks with these. Access point k of the\n"
      "# list below is the k-th of the fit (ids in the comments).\n",
      c.scene_name, c.survey_path, c.train.sample_count(), c.train.groups.size(), c.frequency_mhz);
  std::string note;
  y += "radio:\n  model: itu_walls\n";
  y += "  distance_coefficient: " +
       clamped(f.model.distance_coefficient, kDistanceCoefficient, note, "N") + note + "\n";
  note.clear();
  y += "  shadowing_sigma_db: " + clamped(c.shadowing.shadowing_sigma_db, kSigmaDb, note, "sigma") +
       note + "\n";
  note.clear();
  y += "  shadowing_decorrelation_m: " +
       clamped(c.shadowing.decorrelation_m, kDecorrelationM, note, "L") + note + "\n";
  note.clear();
  y += "  fast_fading_sigma_db: " +
       clamped(c.shadowing.fast_fading_sigma_db, kSigmaDb, note, "fading") + note + "\n";
  note.clear();
  std::string walls;
  for (int m = 0; m < radio_model::kWallMaterialCount; ++m) {
    if (!f.materials[m].fitted && !f.materials[m].pinned_at_zero) continue;
    walls += fmt::format("    {}: {}", to_string(material(m)),
                         clamped(f.materials[m].loss_db, kWallLossDb, note, "loss"));
    walls += note + "\n";
    note.clear();
  }
  if (!walls.empty()) y += "  wall_loss_db:\n" + walls;
  if (c.train.devices.size() > 1) {
    // The intercepts are the reference device's; the others read these offsets from it, as a
    // device's rss_offset_db (scenes/README.md, "Receiver devices").
    y += fmt::format("# Tx powers below are as device '{}' reads them. Offsets of the others:\n",
                     c.train.devices.front());
    for (std::size_t d = 1; d < c.train.devices.size(); ++d)
      y += fmt::format("#   {}: rss_offset_db {:.2f} (95 % CI +-{:.2f})\n", c.train.devices[d],
                       offset_of(f, d), offset_ci_of(f, d));
  }
  y += "access_points:\n  placement: explicit\n  list:\n";
  for (std::size_t i = 0; i < c.train.aps.size(); ++i) {
    const SurveyAccessPoint& ap = c.train.aps[i];
    const Eigen::Vector3d& p = ap.position_m;
    const double intercept = f.model.intercept_dbm[i];
    if (!std::isfinite(intercept)) {
      y += fmt::format("    - {{position_m: [{}, {}, {}]}}  # id {}: not heard in the survey\n",
                       p.x(), p.y(), p.z(), ap.id);
      continue;
    }
    const std::string tx =
        clamped(tx_from_intercept_dbm(intercept, c.frequency_mhz), kTxPowerDbm, note, "tx");
    y += fmt::format("    - {{position_m: [{}, {}, {}], tx_power_dbm: {}}}  # id {}{}\n", p.x(),
                     p.y(), p.z(), tx, ap.id, note);
    note.clear();
  }
  return y;
}

std::string calibration_report_markdown(const Calibration& c) {
  const PropagationFit& f = c.fit;
  std::string md = fmt::format("# Radio calibration of {}\n\n", c.scene_name);
  md += fmt::format(
      "Survey `{}`: {} samples, {} position-AP links. Frequency {} MHz. Fitted on the per-position "
      "means ({} rows, {} unknowns); 95 % confidence intervals {}.\n\n",
      c.survey_path, c.train.sample_count(), c.train.groups.size(), c.frequency_mhz, f.rows,
      f.parameters,
      f.correlated_intervals
          ? "allowing for shadowing shared between positions (the sandwich covariance under the "
            "fitted exponential shadowing model, radio_model/calibrate/correlated_intervals.hpp)"
          : "from (A^T A)^-1 s^2, rows taken as independent");
  md += "| constant | before (scene) | fitted | 95 % CI |\n| --- | --- | --- | --- |\n";
  md += fmt::format(
      "| N (distance coefficient; path-loss exponent x 10) | {:.2f} | {:.2f} | +-{:.2f} |\n",
      c.before.distance_coefficient, f.model.distance_coefficient, f.distance_coefficient_ci95);
  for (int m = 0; m < radio_model::kWallMaterialCount; ++m) {
    const MaterialFit& mf = f.materials[m];
    md += fmt::format("| wall loss {} (dB, {} links) | {:.2f} | {} | {} |\n",
                      to_string(material(m)), mf.links, c.before.wall_loss_db[m],
                      mf.fitted           ? fmt::format("{:.2f}", mf.loss_db)
                      : mf.pinned_at_zero ? std::string("0 (held)")
                                          : std::string("not identifiable"),
                      mf.fitted ? fmt::format("+-{:.2f}", mf.ci95_db) : mf.reason);
  }
  for (std::size_t i = 0; i < c.train.aps.size(); ++i) {
    md += fmt::format("| AP {} tx power (dBm) | {:.2f} | {:.2f} | +-{:.2f} |\n", c.train.aps[i].id,
                      tx_from_intercept_dbm(c.before.intercept_dbm[i], c.frequency_mhz),
                      tx_from_intercept_dbm(f.model.intercept_dbm[i], c.frequency_mhz),
                      f.intercept_ci95_db[i]);
  }
  const ShadowingStatistics& s = c.shadowing;
  md += fmt::format(
      "| shadowing sigma (dB) | | {:.2f} | (means' residual sigma {:.2f}) |\n"
      "| shadowing decorrelation (m) | | {:.2f} | not estimated |\n"
      "| fast fading sigma (dB, within-position scatter) | | {:.2f} | |\n\n",
      s.shadowing_sigma_db, s.mean_residual_sigma_db, s.decorrelation_m, s.fast_fading_sigma_db);
  if (reports_devices(c)) {
    const std::vector<int> samples = samples_per_device(c.train);
    md += fmt::format(
        "## Devices\n\nOne RSS offset per device (what it reads minus what the reference `{}` "
        "reads at the same spot, dB), fitted with the rest; the tx powers above are the "
        "reference's.\n\n| device | samples | offset (dB) | 95 % CI |\n| --- | --- | --- | --- |\n",
        c.train.devices.front());
    for (std::size_t d = 0; d < c.train.devices.size(); ++d) {
      md += d == 0 ? fmt::format("| {} (reference) | {} | 0 | |\n", c.train.devices[d], samples[d])
                   : fmt::format("| {} | {} | {:+.2f} | +-{:.2f} |\n", c.train.devices[d],
                                 samples[d], offset_of(f, d), offset_ci_of(f, d));
    }
    md += "\n";
    if (c.held_out) {
      const HeldOutDeviceScore& h = *c.held_out;
      md += fmt::format(
          "Held-out device `{}`, left out of the fit: its offset from its first {} positions is "
          "{:+.2f} dB. Residual rms on its {} samples at its other positions:\n\n"
          "| model | without its offset (dB) | with its offset (dB) |\n| --- | --- | --- |\n"
          "| the fit | {:.2f} | {:.2f} |\n| plain log-distance | {:.2f} | {:.2f} |\n\n",
          h.device, h.offset_positions, h.offset_db, h.scored_samples, h.rms_without_offset_db,
          h.rms_with_offset_db, h.log_distance_rms_db, h.log_distance_rms_with_offset_db);
    }
  }
  md += fmt::format(
      "Plain log-distance fit (one intercept, no walls): RSS = {:.2f} - {:.2f} "
      "log10(d), n = {:.2f}.\n\n",
      c.baseline.intercept_dbm.empty() ? 0.0 : c.baseline.intercept_dbm[0],
      c.baseline.distance_coefficient, c.baseline.distance_coefficient / 10.0);
  auto table = [&](const SurveyLinks& links, const std::string& title) {
    const auto before = residuals_per_ap(links, c.before);
    const auto after = residuals_per_ap(links, f.model);
    const auto base = residuals_per_ap(links, c.baseline);
    std::string t = fmt::format(
        "## Residuals (measured - predicted), {}: rms / bias in dB\n\n"
        "| AP | samples | before (scene) | after (fit) | plain log-distance |\n"
        "| --- | --- | --- | --- | --- |\n",
        title);
    for (std::size_t k = 0; k < after.size(); ++k) {
      const std::string name =
          k < links.aps.size() ? std::to_string(links.aps[k].id) : std::string("all");
      t += fmt::format("| {} | {} | {} | {} | {} |\n", name, after[k].samples,
                       residual_cell(before[k]), residual_cell(after[k]), residual_cell(base[k]));
    }
    return t + "\n";
  };
  for (const SurveyLinks* links : {&c.train, c.test ? &*c.test : nullptr}) {
    if (!links) continue;
    const LineOfSightAgreement a = links->line_of_sight_agreement();
    if (a.los_links + a.nlos_links == 0) continue;
    md += fmt::format(
        "Scene walls against the survey's line-of-sight flags ({}): {} of {} LOS links cross no "
        "wall, {} of {} NLOS links cross at least one.\n\n",
        links == &c.train ? "fitted survey" : "held-out survey", a.los_clear, a.los_links,
        a.nlos_blocked, a.nlos_links);
  }
  md += table(c.train, "fitted survey `" + c.survey_path + "`");
  if (c.test) md += table(*c.test, "held-out survey `" + c.test_path + "`");
  return md;
}

std::string calibration_report_json(const Calibration& c) {
  const PropagationFit& f = c.fit;
  nlohmann::json j;
  j["scene"] = c.scene_name;
  j["survey"] = c.survey_path;
  j["frequency_mhz"] = c.frequency_mhz;
  j["samples"] = c.train.sample_count();
  j["links"] = c.train.groups.size();
  j["distance_coefficient"] = {{"before", c.before.distance_coefficient},
                               {"fitted", f.model.distance_coefficient},
                               {"ci95", f.distance_coefficient_ci95}};
  nlohmann::json walls = nlohmann::json::object();
  for (int m = 0; m < radio_model::kWallMaterialCount; ++m) {
    const MaterialFit& mf = f.materials[m];
    nlohmann::json w = {{"links", mf.links},
                        {"before_db", c.before.wall_loss_db[m]},
                        {"fitted", mf.fitted},
                        {"held_at_zero", mf.pinned_at_zero}};
    if (mf.fitted) {
      w["loss_db"] = mf.loss_db;
      w["ci95_db"] = mf.ci95_db;
    } else {
      w["reason"] = mf.reason;
    }
    walls[to_string(material(m))] = w;
  }
  j["wall_loss"] = walls;
  nlohmann::json aps = nlohmann::json::array();
  for (std::size_t i = 0; i < c.train.aps.size(); ++i) {
    aps.push_back(nlohmann::json{
        {"id", c.train.aps[i].id},
        {"tx_power_dbm", tx_from_intercept_dbm(f.model.intercept_dbm[i], c.frequency_mhz)},
        {"ci95_db", f.intercept_ci95_db[i]}});
  }
  j["access_points"] = aps;
  if (reports_devices(c)) {
    const std::vector<int> samples = samples_per_device(c.train);
    nlohmann::json devices = nlohmann::json::array();
    for (std::size_t d = 0; d < c.train.devices.size(); ++d)
      devices.push_back({{"device", c.train.devices[d]},
                         {"reference", d == 0},
                         {"samples", samples[d]},
                         {"offset_db", offset_of(f, d)},
                         {"ci95_db", offset_ci_of(f, d)}});
    j["devices"] = devices;
    if (c.held_out) {
      const HeldOutDeviceScore& h = *c.held_out;
      j["held_out_device"] = {
          {"device", h.device},
          {"offset_positions", h.offset_positions},
          {"offset_db", h.offset_db},
          {"scored_samples", h.scored_samples},
          {"rms_without_offset_db", h.rms_without_offset_db},
          {"rms_with_offset_db", h.rms_with_offset_db},
          {"log_distance_rms_db", h.log_distance_rms_db},
          {"log_distance_rms_with_offset_db", h.log_distance_rms_with_offset_db}};
    }
  }
  j["shadowing_sigma_db"] = c.shadowing.shadowing_sigma_db;
  j["mean_residual_sigma_db"] = c.shadowing.mean_residual_sigma_db;
  j["shadowing_decorrelation_m"] = c.shadowing.decorrelation_m;
  j["fast_fading_sigma_db"] = c.shadowing.fast_fading_sigma_db;
  j["log_distance"] = {
      {"intercept_dbm", c.baseline.intercept_dbm.empty() ? 0.0 : c.baseline.intercept_dbm[0]},
      {"exponent", c.baseline.distance_coefficient / 10.0}};
  auto residuals = [&](const SurveyLinks& links) {
    return nlohmann::json{{"before", residuals_json(links, c.before)},
                          {"after", residuals_json(links, f.model)},
                          {"log_distance", residuals_json(links, c.baseline)}};
  };
  auto agreement = [](const SurveyLinks& links) {
    const LineOfSightAgreement a = links.line_of_sight_agreement();
    return nlohmann::json{{"los_links", a.los_links},
                          {"los_clear", a.los_clear},
                          {"nlos_links", a.nlos_links},
                          {"nlos_blocked", a.nlos_blocked}};
  };
  j["line_of_sight"]["train"] = agreement(c.train);
  if (c.test) j["line_of_sight"]["test"] = agreement(*c.test);
  j["residuals"]["train"] = residuals(c.train);
  if (c.test) {
    j["test_survey"] = c.test_path;
    j["residuals"]["test"] = residuals(*c.test);
  }
  return j.dump(2) + "\n";
}

}  // namespace wifislam::radio_model::calibrate
