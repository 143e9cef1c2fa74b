#include "eval/wifi_clusters_csv.hpp"

#include <array>
#include <cmath>

#include "core/error.hpp"
#include "core/mac_address.hpp"
#include "core/text_lines.hpp"

namespace wifislam::eval {

namespace {
constexpr std::array<const char*, 4> kColumns = {"cluster_id", "founder_keyframe", "keyframes",
                                                 "representative_signature"};
}

std::vector<WifiCluster> read_wifi_clusters_csv(const std::filesystem::path& path) {
  std::vector<WifiCluster> out;
  for_each_csv_row(path.string(), kColumns, [&](const CsvRow& row) {
    const std::vector<std::string_view>& fields = row.fields;
    const std::string& where = row.where;
    WifiCluster c;
    long long v = 0;
    if (!parse_int64(fields[0], v) || v < 0) {
      throw ParseError(where, "cluster_id", "'" + std::string(fields[0]) + "' is not an id");
    }
    c.id = v;
    if (!parse_int64(fields[1], v) || v < 0) {
      throw ParseError(where, "founder_keyframe",
                       "'" + std::string(fields[1]) + "' is not a keyframe id");
    }
    c.founder_keyframe = v;
    for (std::string_view k : split_fields(fields[2])) {
      if (!parse_int64(k, v) || v < 0) {
        throw ParseError(where, "keyframes", "'" + std::string(k) + "' is not a keyframe id");
      }
      c.keyframes.push_back(v);
    }
    if (!fields[3].empty()) {
      for (std::string_view pair : split_fields(fields[3], ';')) {
        const std::size_t eq = pair.find('=');
        double rssi = 0;
        if (eq == std::string_view::npos || !parse_double(pair.substr(eq + 1), rssi) ||
            !std::isfinite(rssi) || !MacAddress::parse(pair.substr(0, eq))) {
          throw ParseError(where, "representative_signature",
                           "'" + std::string(pair) + "' is not ap=rssi_dbm");
        }
        c.representative_signature.emplace_back(std::string(pair.substr(0, eq)), rssi);
      }
    }
    out.push_back(std::move(c));
  });
  return out;
}

}  // namespace wifislam::eval
