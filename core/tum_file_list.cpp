#include "core/tum_file_list.hpp"

#include <algorithm>
#include <cstdlib>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/text_lines.hpp"

namespace wifislam {

namespace {

Timestamp parse_time(std::string_view field, const std::string& where) {
  const auto t = Timestamp::parse(field);
  if (!t) throw ParseError(where, "", fmt::format("bad timestamp '{}'", field));
  return *t;
}

}  // namespace

std::optional<TumFileEntry> TumFileListReader::next() {
  TextLine line;
  if (!cursor_.next(line)) return std::nullopt;
  const std::string where = cursor_.where(line.number);
  const auto fields = split_fields(line.text);
  if (fields.size() != 2) {
    throw ParseError(where, "",
                     fmt::format("expected 2 fields 'timestamp filename', got {}", fields.size()));
  }
  TumFileEntry e{parse_time(fields[0], where), std::string(fields[1]), line.number};
  require_later_stamp(last_, e.time, fields[0], where);
  return e;
}

std::vector<TumFileEntry> read_tum_file_list(const std::string& path) {
  TumFileListReader reader(path);
  std::vector<TumFileEntry> out;
  while (auto e = reader.next()) out.push_back(std::move(*e));
  return out;
}

std::optional<FramePair> AssociationsReader::next() {
  TextLine line;
  if (!cursor_.next(line)) return std::nullopt;
  const std::string where = cursor_.where(line.number);
  const auto fields = split_fields(line.text);
  if (fields.size() != 4) {
    throw ParseError(where, "",
                     fmt::format("expected 4 fields 't_rgb rgb_file t_depth depth_file', got {}",
                                 fields.size()));
  }
  FramePair p{parse_time(fields[0], where), std::string(fields[1]), parse_time(fields[2], where),
              std::string(fields[3]), line.number};
  require_later_stamp(last_, p.rgb_time, fields[0], where);
  return p;
}

std::vector<FramePair> associate_tum(const std::vector<TumFileEntry>& rgb,
                                     const std::vector<TumFileEntry>& depth,
                                     double max_difference_s) {
  const std::int64_t max_ns = std::llround(max_difference_s * 1e9);
  struct Candidate {
    std::int64_t diff_ns;
    std::size_t r, d;
  };
  std::vector<Candidate> candidates;
  // Both lists are sorted by time, so the depth stamps within reach of an rgb stamp form a
  // window that only moves forward.
  std::size_t lo = 0;
  for (std::size_t r = 0; r < rgb.size(); ++r) {
    while (lo < depth.size() && depth[lo].time.ns < rgb[r].time.ns - max_ns) ++lo;
    for (std::size_t d = lo; d < depth.size() && depth[d].time.ns <= rgb[r].time.ns + max_ns; ++d) {
      const std::int64_t diff = std::abs(rgb[r].time.ns - depth[d].time.ns);
      if (diff < max_ns) candidates.push_back({diff, r, d});
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.diff_ns < b.diff_ns; });
  std::vector<char> rgb_used(rgb.size(), 0), depth_used(depth.size(), 0);
  std::vector<FramePair> pairs;
  for (const Candidate& c : candidates) {
    if (rgb_used[c.r] || depth_used[c.d]) continue;
    rgb_used[c.r] = depth_used[c.d] = 1;
    pairs.push_back(
        {rgb[c.r].time, rgb[c.r].path, depth[c.d].time, depth[c.d].path, 0, rgb[c.r].line});
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const FramePair& a, const FramePair& b) { return a.rgb_time < b.rgb_time; });
  return pairs;
}

std::string format_tum_file_line(Timestamp time, const std::string& path) {
  return time.to_tum_string() + " " + path + "\n";
}

std::string format_association_line(const FramePair& p) {
  return p.rgb_time.to_tum_string() + " " + p.rgb_path + " " + p.depth_time.to_tum_string() + " " +
         p.depth_path + "\n";
}

std::optional<StampedPose> TumTrajectoryReader::next() {
  TextLine line;
  if (!cursor_.next(line)) return std::nullopt;
  const std::string where = cursor_.where(line.number);
  const auto fields = split_fields(line.text);
  StampedPose p = parse_tum_pose_fields(fields, where);
  require_later_stamp(last_, p.time, fields[0], where);
  return p;
}

}  // namespace wifislam
