#include "core/wifi_csv.hpp"

#include <cstdint>
#include <limits>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/text_lines.hpp"

namespace wifislam {

namespace {

constexpr const char* kColumns[] = {"timestamp",          "sensor_id",       "mac_addr",
                                    "frequency_khz",      "rssi_dbm",        "name",
                                    "scan_time_start_us", "scan_time_end_us"};
constexpr std::size_t kColumnCount = 8;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

std::int64_t whole_us(Timestamp t, const char* what) {
  if (t.ns % 1000 != 0) {
    throw InvalidInputError(
        fmt::format("wifi.csv: {} {} ns is not a whole number of microseconds", what, t.ns));
  }
  return t.ns / 1000;
}

void check_plain(const std::string& text, const char* what) {
  if (text.find_first_of(",\r\n") != std::string::npos) {
    throw InvalidInputError(fmt::format(
        "wifi.csv: {} '{}' contains a comma or line break, which the format cannot hold", what,
        text));
  }
}

}  // namespace

std::string wifi_csv_header() {
  std::string header;
  for (std::size_t i = 0; i < kColumnCount; ++i) {
    if (i) header += ',';
    header += kColumns[i];
  }
  return header;
}

std::string format_wifi_csv_rows(const WifiScan& scan) {
  check_plain(scan.sensor_id, "sensor_id");
  const std::int64_t t = whole_us(scan.time, "timestamp");
  const std::int64_t start = whole_us(scan.start_time, "scan_time_start_us");
  const std::int64_t end = whole_us(scan.end_time, "scan_time_end_us");
  std::string out;
  for (const WifiReading& r : scan.readings) {
    check_plain(r.ssid, "SSID");
    out += fmt::format("{},{},{},{},{},{},{},{}\n", t, scan.sensor_id, r.bssid.to_string(),
                       r.frequency_khz, r.rssi_dbm, r.ssid, start, end);
  }
  return out;
}

WifiCsvReader::WifiCsvReader(const std::string& path) : cursor_(path) {}

std::optional<WifiCsvReader::Row> WifiCsvReader::read_row() {
  TextLine line;
  while (cursor_.next(line)) {
    const std::string where = cursor_.where(line.number);
    const auto fields = split_fields(line.text, ',');
    if (!header_checked_) {
      header_checked_ = true;
      if (trim(fields[0]) == kColumns[0]) {  // the header line
        for (std::size_t i = 0; i < kColumnCount; ++i) {
          if (fields.size() != kColumnCount || trim(fields[i]) != kColumns[i]) {
            throw ParseError(where, "", "expected the header '" + wifi_csv_header() + "'");
          }
        }
        continue;
      }
    }
    if (fields.size() != kColumnCount) {
      throw ParseError(where, "",
                       fmt::format("expected {} comma-separated fields ({}), got {}", kColumnCount,
                                   wifi_csv_header(), fields.size()));
    }
    auto integer = [&](std::size_t column) {
      long long value = 0;
      if (!parse_int64(trim(fields[column]), value)) {
        throw ParseError(
            where, kColumns[column],
            fmt::format("{} is not an integer: '{}'", kColumns[column], trim(fields[column])));
      }
      return static_cast<std::int64_t>(value);
    };
    // Microseconds to nanoseconds must not wrap: times are 64-bit nanoseconds inside, which
    // reach the year 2262 (as far as Timestamp::parse reads TUM timestamps).
    auto microseconds = [&](std::size_t column) {
      constexpr std::int64_t kLimitUs = std::numeric_limits<std::int64_t>::max() / 1000;
      const std::int64_t us = integer(column);
      if (us < -kLimitUs || us > kLimitUs) {
        throw ParseError(where, kColumns[column],
                         fmt::format("{} {} us is beyond the year 2262, the last time 64-bit "
                                     "nanoseconds hold",
                                     kColumns[column], us));
      }
      return Timestamp::from_ns(us * 1000);
    };
    Row row;
    row.line = line.number;
    row.key.time = microseconds(0);
    row.key.sensor_id = std::string(trim(fields[1]));
    if (row.key.sensor_id.empty()) throw ParseError(where, "sensor_id", "sensor_id is empty");
    const auto mac = MacAddress::parse(trim(fields[2]));
    if (!mac) {
      throw ParseError(where, "mac_addr",
                       fmt::format("mac_addr '{}' is not a BSSID of the form aa:bb:cc:dd:ee:ff",
                                   trim(fields[2])));
    }
    row.reading.bssid = *mac;
    row.reading.frequency_khz = integer(3);
    if (row.reading.frequency_khz <= 0) {
      throw ParseError(where, "frequency_khz", "frequency_khz must be positive");
    }
    const std::int64_t rssi = integer(4);
    if (rssi < kMinRssiDbm || rssi > kMaxRssiDbm) {
      throw ParseError(where, "rssi_dbm",
                       fmt::format("rssi_dbm {} is outside the range a receiver reports ({} to "
                                   "{} dBm)",
                                   rssi, kMinRssiDbm, kMaxRssiDbm));
    }
    row.reading.rssi_dbm = static_cast<int>(rssi);
    row.reading.ssid = std::string(trim(fields[5]));
    row.key.start_time = microseconds(6);
    row.key.end_time = microseconds(7);
    if (row.key.end_time < row.key.start_time) {
      throw ParseError(where, "scan_time_end_us", "scan_time_end_us is before scan_time_start_us");
    }
    if (row.key.time < last_time_) {
      throw ParseError(where, "timestamp", "timestamp is earlier than the previous row's");
    }
    last_time_ = row.key.time;
    ++rows_;
    return row;
  }
  return std::nullopt;
}

std::optional<WifiScan> WifiCsvReader::next() {
  if (!pending_) pending_ = read_row();
  if (!pending_) return std::nullopt;
  WifiScan scan = std::move(pending_->key);
  scan.readings.push_back(std::move(pending_->reading));
  pending_.reset();
  while (auto row = read_row()) {
    if (row->key.time == scan.time && row->key.sensor_id == scan.sensor_id &&
        row->key.start_time == scan.start_time && row->key.end_time == scan.end_time) {
      scan.readings.push_back(std::move(row->reading));
    } else {
      pending_ = std::move(row);
      break;
    }
  }
  return scan;
}

std::vector<WifiScan> read_wifi_csv(const std::string& path) {
  WifiCsvReader reader(path);
  std::vector<WifiScan> scans;
  while (auto scan = reader.next()) scans.push_back(std::move(*scan));
  return scans;
}

}  // namespace wifislam
