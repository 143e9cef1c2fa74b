#pragma once
// wifi.csv: Wi-Fi scans, one row per BSSID heard per scan, with LaMAR's Wi-Fi record columns
// (core/dataset_format.hpp):
//
//   timestamp,sensor_id,mac_addr,frequency_khz,rssi_dbm,name,scan_time_start_us,scan_time_end_us
//   3500000,wifi0,02:1a:2b:3c:4d:50,2412000,-61,campus,0,3500000
//
// timestamp = when the scan reported (its end), microseconds; name = SSID. The rows of one scan
// are consecutive and share timestamp, sensor_id and the scan start/end; scans come in
// non-decreasing timestamp order. A scan that heard nothing has no rows. Fields are plain
// (no quoting), so SSIDs and sensor ids may not contain commas or line breaks.

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/line_cursor.hpp"
#include "core/wifi_scan.hpp"

namespace wifislam {

/// The header line (without newline).
std::string wifi_csv_header();
/// The rows of one scan, each ending in '\n'. Throws InvalidInputError for a sensor id or SSID
/// that contains a comma or line break, or times that are not whole microseconds.
std::string format_wifi_csv_rows(const WifiScan& scan);

/// Streams scans from a wifi.csv file. Errors are ParseError("file:line", column, ...): wrong
/// number of fields, a field that is not a number, a BSSID that is not a MAC address, a scan end
/// before its start, timestamps going backwards.
class WifiCsvReader {
 public:
  explicit WifiCsvReader(const std::string& path);
  /// The next scan, or nullopt at the end of the file.
  std::optional<WifiScan> next();
  /// Rows read so far.
  std::size_t rows() const { return rows_; }

 private:
  struct Row {
    int line = 0;
    WifiScan key;  // times and sensor id
    WifiReading reading;
  };
  std::optional<Row> read_row();

  LineCursor cursor_;
  std::optional<Row> pending_;
  bool header_checked_ = false;
  Timestamp last_time_{std::numeric_limits<std::int64_t>::min()};
  std::size_t rows_ = 0;
};

/// All scans of a file.
std::vector<WifiScan> read_wifi_csv(const std::string& path);

}  // namespace wifislam
