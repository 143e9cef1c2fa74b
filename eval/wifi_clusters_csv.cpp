#include "eval/wifi_clusters_csv.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/mac_address.hpp"
#include "core/text_lines.hpp"

namespace wifislam::eval {

std::vector<WifiCluster> read_wifi_clusters_csv(const std::filesystem::path& path) {
  const std::vector<TextLine> lines = read_text_lines(path.string());
  std::vector<WifiCluster> out;
  bool header_seen = false;
  for (const TextLine& line : lines) {
    if (line.text.empty() || line.text[0] == '#') continue;
    const std::string where = path.string() + ":" + std::to_string(line.number);
    const std::vector<std::string_view> fields = split_fields(line.text, ',');
    if (!header_seen) {
      header_seen = true;
      if (fields.size() != 4 || fields[0] != "cluster_id" || fields[1] != "founder_keyframe" ||
          fields[2] != "keyframes" || fields[3] != "representative_signature") {
        throw ParseError(where, "header",
                         "expected 'cluster_id,founder_keyframe,keyframes,"
                         "representative_signature'");
      }
      continue;
    }
    if (fields.size() != 4) {
      throw ParseError(where, "",
                       "expected 4 comma-separated fields, found " + std::to_string(fields.size()));
    }
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
  }
  if (!header_seen) {
    throw ParseError(path.string() + ":1", "header", "empty file: expected the CSV header");
  }
  return out;
}

}  // namespace wifislam::eval
