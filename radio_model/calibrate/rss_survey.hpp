#pragma once
// Measured RSS at known positions, and the access points they come from.
//
// Our survey CSV (long format, one row per AP heard in one scan at one spot; other tools can
// write it without knowing our scene format). The header names the columns, in any order:
//   x_m, y_m, ap_id, rss_dbm   required
//   z_m                        receiver height per row (else the height the caller gives)
//   device                     the receiver that measured the row (a name; a survey by several
//                              phones gets one RSS offset per device: propagation_fit.hpp)
// An AP not heard in a scan has no row (no sentinel values). '#' lines and blank lines are
// skipped.
//
// The Royal Holloway dataset (Feng, Nguyen, Luo 2024; assets/surveys/royal_holloway/) is read as
// shipped: X,Y are grid indices of 0.6 m cells, columns "APk RSS(dBm)" give AP id k, -200 means
// not heard. (Its corridor uses columns AP2..AP5 for its four APs; column AP1 is empty.)
//
// Access point CSV: id,x_m,y_m,z_m[,tx_power_dbm] (header as written).
//
// Every malformed row is a ParseError at file:line naming the column.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace wifislam::radio_model::calibrate {

struct SurveySample {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  int ap_id = 0;
  double rss_dbm = 0.0;
  int line = 0;  // in the survey file, for located errors
  /// Whether the survey says the AP is in line of sight (the Royal Holloway "LOS APs" column);
  /// unknown in our format. Used only to check a scene's walls against the survey.
  std::optional<bool> line_of_sight;
  std::string device = {};  // empty when the survey has no device column
};

struct Survey {
  std::string path;
  std::vector<SurveySample> samples;
  std::string where(int line) const { return path + ":" + std::to_string(line); }
  /// The devices of the samples, in order of first appearance (one empty name without a device
  /// column).
  std::vector<std::string> devices() const;
};

enum class SurveyFormat { kLong, kRoyalHolloway };

/// The grid cell of the Royal Holloway dataset (its README: "Grid size: 0.6 x 0.6 m2").
inline constexpr double kRoyalHollowayCellM = 0.6;

/// Reads a survey; rows without a height get `receiver_height_m`. Throws ParseError (located)
/// or IoError.
Survey read_survey(const std::string& path, SurveyFormat format, double receiver_height_m);

struct SurveyAccessPoint {
  int id = 0;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  std::optional<double> tx_power_dbm;
  std::string where;  // "file:line", empty for the scene's own APs
};

/// Reads an access point CSV. Throws ParseError (located: bad number, repeated id) or IoError.
std::vector<SurveyAccessPoint> read_access_points_csv(const std::string& path);

}  // namespace wifislam::radio_model::calibrate
