#include "radio_model/calibrate/rss_survey.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/text_lines.hpp"
#include "radio_model/access_point.hpp"

namespace wifislam::radio_model::calibrate {

namespace {

// Received power a Wi-Fi card can report: anything outside is a unit or sign mistake.
constexpr double kMinRssDbm = -150.0, kMaxRssDbm = 30.0;
constexpr double kRoyalHollowayNotHeardDbm = -200.0;
constexpr double kMaxCoordinateM = 10000.0;  // the scene's own limit

bool skipped(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  return first == std::string::npos || text[first] == '#';
}

std::string joined(const std::vector<std::string_view>& fields) {
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i) out += (i ? "," : "") + std::string(fields[i]);
  return out;
}

std::vector<std::string_view> fields_of(const TextLine& line) {
  std::string_view text = line.text;
  if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
  return split_fields(text, ',');
}

double number(std::string_view field, const std::string& where, const char* column) {
  double v = 0.0;
  if (!parse_double(field, v) || !std::isfinite(v))
    throw ParseError(where, column, fmt::format("expected a number, got '{}'", field));
  return v;
}

double coordinate(std::string_view field, const std::string& where, const char* column) {
  const double v = number(field, where, column);
  if (std::abs(v) > kMaxCoordinateM)
    throw ParseError(where, column,
                     fmt::format("{} m is more than 10 km from the origin (a unit mistake?)", v));
  return v;
}

int ap_id(std::string_view field, const std::string& where, const char* column) {
  long long id = 0;
  if (!parse_int64(field, id) || id < 0 || id > 1'000'000)
    throw ParseError(where, column,
                     fmt::format("expected an access point id (integer >= 0), got '{}'", field));
  return static_cast<int>(id);
}

double rss(std::string_view field, const std::string& where, const char* column) {
  const double v = number(field, where, column);
  if (v < kMinRssDbm || v > kMaxRssDbm)
    throw ParseError(
        where, column,
        fmt::format("{} dBm is not a received power ({} to {} dBm)", v, kMinRssDbm, kMaxRssDbm));
  return v;
}

/// Column positions of a long-format header, by name.
struct LongColumns {
  std::size_t count = 0;
  std::optional<std::size_t> x, y, z, ap, rss, device;
};

LongColumns long_columns(const std::vector<std::string_view>& header, const std::string& where) {
  LongColumns c;
  c.count = header.size();
  const std::pair<const char*, std::optional<std::size_t>*> known[] = {
      {"x_m", &c.x},    {"y_m", &c.y},       {"z_m", &c.z},
      {"ap_id", &c.ap}, {"rss_dbm", &c.rss}, {"device", &c.device}};
  for (std::size_t i = 0; i < header.size(); ++i) {
    bool found = false;
    for (const auto& [name, slot] : known) {
      if (header[i] != name) continue;
      if (*slot)
        throw ParseError(where, name, fmt::format("column '{}' appears twice in the header", name));
      *slot = i;
      found = true;
    }
    if (!found)
      throw ParseError(where, std::string(header[i]),
                       fmt::format("unknown column '{}' (the columns are x_m, y_m, z_m, ap_id, "
                                   "rss_dbm and device; for the Royal Holloway files use --format "
                                   "royal-holloway)",
                                   header[i]));
  }
  for (const auto& [name, slot] : {std::pair{"x_m", c.x}, std::pair{"y_m", c.y},
                                   std::pair{"ap_id", c.ap}, std::pair{"rss_dbm", c.rss}}) {
    if (!slot)
      throw ParseError(where, name,
                       fmt::format("the header '{}' lacks the column '{}' (expected e.g. "
                                   "'x_m,y_m,ap_id,rss_dbm' or 'x_m,y_m,z_m,ap_id,rss_dbm,device')",
                                   joined(header), name));
  }
  return c;
}

std::string device_name(std::string_view field, const std::string& where) {
  const auto first = field.find_first_not_of(' ');
  const auto last = field.find_last_not_of(' ');
  if (first == std::string_view::npos)
    throw ParseError(where, "device", "expected a device name, got an empty field");
  return std::string(field.substr(first, last - first + 1));
}

Survey read_long(const std::string& path, double receiver_height_m) {
  Survey survey{path, {}};
  std::optional<LongColumns> columns;
  for (const TextLine& line : read_text_lines(path)) {
    if (skipped(line.text)) continue;
    const std::string where = survey.where(line.number);
    const auto f = fields_of(line);
    if (!columns) {
      columns = long_columns(f, where);
      continue;
    }
    const LongColumns& c = *columns;
    if (f.size() != c.count)
      throw ParseError(where, "", fmt::format("expected {} fields, got {}", c.count, f.size()));
    SurveySample s;
    s.line = line.number;
    s.position_m = {coordinate(f[*c.x], where, "x_m"), coordinate(f[*c.y], where, "y_m"),
                    c.z ? number(f[*c.z], where, "z_m") : receiver_height_m};
    s.ap_id = ap_id(f[*c.ap], where, "ap_id");
    s.rss_dbm = rss(f[*c.rss], where, "rss_dbm");
    if (c.device) s.device = device_name(f[*c.device], where);
    survey.samples.push_back(s);
  }
  if (!columns) throw ParseError(path, "", "empty survey: no header and no rows");
  if (survey.samples.empty()) throw ParseError(path, "", "no survey rows after the header");
  return survey;
}

Survey read_royal_holloway(const std::string& path, double receiver_height_m) {
  static constexpr const char* kHeader =
      "X,Y,AP1 RTT(mm),AP2 RTT(mm),AP3 RTT(mm),AP4 RTT(mm),AP5 RTT(mm),AP1 RSS(dBm),"
      "AP2 RSS(dBm),AP3 RSS(dBm),AP4 RSS(dBm),AP5 RSS(dBm),LOS APs";
  static constexpr const char* kRssColumns[] = {"AP1 RSS(dBm)", "AP2 RSS(dBm)", "AP3 RSS(dBm)",
                                                "AP4 RSS(dBm)", "AP5 RSS(dBm)"};
  constexpr std::size_t kFirstRss = 7, kFields = 13;
  Survey survey{path, {}};
  bool header_seen = false;
  for (const TextLine& line : read_text_lines(path)) {
    if (skipped(line.text)) continue;
    const std::string where = survey.where(line.number);
    const auto f = fields_of(line);
    if (!header_seen) {
      if (joined(f) != kHeader)
        throw ParseError(
            where, "",
            fmt::format("expected the Royal Holloway header '{}', got '{}'", kHeader, joined(f)));
      header_seen = true;
      continue;
    }
    if (f.size() != kFields)
      throw ParseError(where, "", fmt::format("expected {} fields, got {}", kFields, f.size()));
    const Eigen::Vector3d p(coordinate(f[0], where, "X") * kRoyalHollowayCellM,
                            coordinate(f[1], where, "Y") * kRoyalHollowayCellM, receiver_height_m);
    // "LOS APs": space-separated AP numbers in line of sight of this spot.
    std::array<bool, 6> los{};
    for (std::string_view id : split_fields(f[kFields - 1])) {
      long long k = 0;
      if (!parse_int64(id, k) || k < 1 || k > 5)
        throw ParseError(where, "LOS APs", fmt::format("expected AP numbers 1-5, got '{}'", id));
      los[k] = true;
    }
    for (int k = 0; k < 5; ++k) {
      const double v = number(f[kFirstRss + k], where, kRssColumns[k]);
      if (v == kRoyalHollowayNotHeardDbm) continue;
      SurveySample s;
      s.line = line.number;
      s.position_m = p;
      s.ap_id = k + 1;  // column APk
      s.line_of_sight = los[k + 1];
      s.rss_dbm = rss(f[kFirstRss + k], where, kRssColumns[k]);
      survey.samples.push_back(s);
    }
  }
  if (!header_seen) throw ParseError(path, "", "empty survey: no header and no rows");
  if (survey.samples.empty()) throw ParseError(path, "", "no survey rows after the header");
  return survey;
}

}  // namespace

std::vector<std::string> Survey::devices() const {
  std::vector<std::string> out;
  for (const SurveySample& s : samples)
    if (std::find(out.begin(), out.end(), s.device) == out.end()) out.push_back(s.device);
  return out;
}

Survey read_survey(const std::string& path, SurveyFormat format, double receiver_height_m) {
  return format == SurveyFormat::kRoyalHolloway ? read_royal_holloway(path, receiver_height_m)
                                                : read_long(path, receiver_height_m);
}

std::vector<SurveyAccessPoint> read_access_points_csv(const std::string& path) {
  std::vector<SurveyAccessPoint> aps;
  std::map<int, std::string> seen;
  bool header_seen = false, with_tx = false;
  for (const TextLine& line : read_text_lines(path)) {
    if (skipped(line.text)) continue;
    const std::string where = path + ":" + std::to_string(line.number);
    const auto f = fields_of(line);
    if (!header_seen) {
      const std::string header = joined(f);
      if (header == "id,x_m,y_m,z_m,tx_power_dbm") {
        with_tx = true;
      } else if (header != "id,x_m,y_m,z_m") {
        throw ParseError(where, "",
                         fmt::format("expected the header 'id,x_m,y_m,z_m' or "
                                     "'id,x_m,y_m,z_m,tx_power_dbm', got '{}'",
                                     header));
      }
      header_seen = true;
      continue;
    }
    const std::size_t expected = with_tx ? 5 : 4;
    if (f.size() != expected)
      throw ParseError(where, "", fmt::format("expected {} fields, got {}", expected, f.size()));
    SurveyAccessPoint ap;
    ap.where = where;
    ap.id = ap_id(f[0], where, "id");
    if (auto [it, fresh] = seen.emplace(ap.id, where); !fresh)
      throw ParseError(
          where, "id",
          fmt::format("access point {} is listed twice (first at {})", ap.id, it->second));
    ap.position_m = {coordinate(f[1], where, "x_m"), coordinate(f[2], where, "y_m"),
                     number(f[3], where, "z_m")};
    if (with_tx) {
      ap.tx_power_dbm = number(f[4], where, "tx_power_dbm");
      if (*ap.tx_power_dbm < kMinTxPowerDbm || *ap.tx_power_dbm > kMaxTxPowerDbm)
        throw ParseError(where, "tx_power_dbm",
                         fmt::format("{} dBm is not a Wi-Fi transmit power (expected {} to {})",
                                     f[4], kMinTxPowerDbm, kMaxTxPowerDbm));
    }
    aps.push_back(ap);
  }
  if (aps.empty()) throw ParseError(path, "", "no access points listed");
  return aps;
}

}  // namespace wifislam::radio_model::calibrate
