#pragma once
// The least-squares fit of the itu_walls model's constants to a survey.
//
// Model, per link (one AP, one receiver position):
//   RSS = P_ap - N log10(max(d, 1 m)) - sum_m L_m walls_m + shadowing + fast fading
// P_ap is the RSS at 1 m with no wall: tx power minus the ITU formula's frequency term
// (20 log10 f_MHz - 28). Transmit power is rarely known, so every AP gets its own intercept
// P_ap (the tx_power_dbm we report is P_ap converted back at the survey's frequency). N is the
// ITU-R P.1238 distance coefficient (10 x the log-distance path-loss exponent). L_m is the loss
// of one wall of material m, walls_m the simulator's wall count for the link (survey_links.hpp).
//
// Given the wall counts the model is linear in (P_ap, N, L_m), so it is solved exactly by
// linear least squares (Eigen), no iterative solver (Ceres) needed.
//
// What is fitted: the per-AP means of each position's samples (one row per position and AP),
// not the raw samples. Samples at one spot share their shadowing, so treating 60 of them as
// independent would shrink the confidence intervals by about sqrt(60) for nothing; the
// within-position scatter (fast fading) is measured separately (shadowing_statistics.hpp).
// Confidence intervals: 95 %, +-1.96 sqrt(diag((A^T A)^-1) s^2), s^2 the residual variance of
// the means. Neighbouring positions still share shadowing (it decorrelates over metres), which
// makes these about four times too narrow; the command replaces them by intervals that allow
// for it (correlated_intervals.hpp).
//
// Devices: a survey measured by several receivers (its `device` column) gets one RSS offset per
// device but the reference (SurveyLinks::devices' first), a column of ones on that device's rows:
//   RSS = P_ap + o_device - N log10(max(d, 1 m)) - sum_m L_m walls_m + ...
// the offset of receiver_device.hpp's map at unit gain. Groups are per device, so two phones at
// one spot are two rows sharing a position (and their shadowing, in correlated_intervals.hpp).
//
// Materials: a material is fitted when at least kMinLinksPerMaterial links cross it and its
// column adds rank to the design (else it is confounded with the intercepts or N, e.g. every
// link of an AP crossing the same one wall); the others keep the scene's loss at the survey
// frequency and are reported as not identifiable. A material whose loss comes out negative is
// held at 0 dB and the others refitted (loss >= 0, solved by active set), and reported so.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "radio_model/calibrate/survey_links.hpp"
#include "radio_model/wall_materials.hpp"

namespace wifislam::radio_model::calibrate {

inline constexpr int kMinLinksPerMaterial = 3;
/// Two-sided 95 % normal quantile: the fit's confidence intervals are +- kZ95 standard errors.
inline constexpr double kZ95 = 1.959964;

/// The linear model's constants: what "before" (the scene), "after" (the fit) and the plain
/// log-distance baseline all are.
struct LinearRadioModel {
  double distance_coefficient = 22.0;  // N
  std::vector<double> intercept_dbm;   // P_ap, per SurveyLinks::aps index
  std::array<double, radio_model::kWallMaterialCount> wall_loss_db{};
  std::vector<double> device_offset_db;  // per SurveyLinks::devices index; none: all 0
  double predict_dbm(const LinkGroup& g) const;
};

/// The scene's current model at `frequency_mhz`: its N (or the default), its wall losses, each
/// AP's tx power (the AP's own, else `default_tx_power_dbm`).
LinearRadioModel scene_model(const SurveyLinks& links, const radio_model::WallLossTable& walls,
                             std::optional<double> distance_coefficient,
                             double default_tx_power_dbm, double frequency_mhz);

/// RSS at 1 m of an AP of `tx_power_dbm` under the ITU formula, and back.
double intercept_from_tx_dbm(double tx_power_dbm, double frequency_mhz);
double tx_from_intercept_dbm(double intercept_dbm, double frequency_mhz);

struct MaterialFit {
  bool fitted = false;
  bool pinned_at_zero = false;  // its free fit was negative: held at 0 dB, refitted without it
  int links = 0;                // position-AP links crossing the material
  double loss_db = 0.0;         // fitted, or the scene's when not fitted
  double ci95_db = 0.0;         // half width; 0 when not fitted
  std::string reason;           // why it was not fitted
};

struct PropagationFit {
  LinearRadioModel model;
  double distance_coefficient_ci95 = 0.0;  // half widths
  std::vector<double> intercept_ci95_db;
  std::array<MaterialFit, radio_model::kWallMaterialCount> materials;
  std::vector<double> device_offset_ci95_db;  // per device; 0 for the reference
  int rows = 0, parameters = 0;
  double residual_sigma_db = 0.0;  // of the position means, dof-corrected
  /// The final design matrix (one row per link group) and where each unknown sits in it (-1:
  /// not an unknown), for intervals computed after the fit (correlated_intervals.hpp).
  Eigen::MatrixXd design;
  int distance_column = -1;
  std::vector<int> intercept_column;
  std::array<int, radio_model::kWallMaterialCount> material_column{-1, -1, -1, -1, -1};
  std::vector<int> device_column;     // -1 for the reference
  bool correlated_intervals = false;  // true once correlated_intervals.hpp widened them
};

/// Fits `links` (groups of APs without data get no intercept and a NaN). Throws
/// InvalidInputError when the data cannot determine N (fewer rows than unknowns, or every
/// link of the same length). `defaults` gives the loss of materials that are not fitted.
PropagationFit fit_propagation(
    const SurveyLinks& links,
    const std::array<double, radio_model::kWallMaterialCount>& defaults_db);

/// RSS = A - 10 n log10(d), one A for all APs, least squares over every sample (the baseline
/// of the dataset's notes). Returned as a LinearRadioModel (N = 10 n, no walls).
LinearRadioModel fit_log_distance(const SurveyLinks& links);

/// A device left out of the fit, scored on its own samples: the way a map made with some phones
/// serves another. Its offset is the mean residual of its samples at its first
/// `offset_positions` surveyed positions (what a user can measure on arrival); every score is
/// over its samples at the other positions, so the offset is never scored on its own data.
struct HeldOutDeviceScore {
  std::string device;
  int offset_positions = 0;
  int scored_samples = 0;
  double offset_db = 0.0;              // fitted from the first positions
  double rms_without_offset_db = 0.0;  // the fit as it is
  double rms_with_offset_db = 0.0;
  double log_distance_rms_db = 0.0;  // the plain log-distance fit, without and with its offset
  double log_distance_rms_with_offset_db = 0.0;
};
/// `held` holds that device's links only. Throws InvalidInputError when it was surveyed at no
/// more than `offset_positions` positions (nothing left to score).
HeldOutDeviceScore score_held_out_device(const SurveyLinks& held, const LinearRadioModel& fitted,
                                         const LinearRadioModel& log_distance,
                                         int offset_positions);

struct ApResiduals {
  int samples = 0;
  double rms_db = 0.0, bias_db = 0.0;  // of measured - predicted, over samples
};
/// Per AP index, plus all APs together as the last element.
std::vector<ApResiduals> residuals_per_ap(const SurveyLinks& links, const LinearRadioModel& model);

}  // namespace wifislam::radio_model::calibrate
