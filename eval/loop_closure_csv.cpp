#include "eval/loop_closure_csv.hpp"

#include <array>
#include <cmath>

#include "core/error.hpp"
#include "core/run_format.hpp"
#include "core/text_lines.hpp"

namespace wifislam::eval {

namespace {
constexpr const auto& kColumns = run_folder::loop_closures_column::kAll;
}

std::vector<DetectedLoopClosure> read_loop_closures_csv(const std::filesystem::path& path) {
  std::vector<DetectedLoopClosure> out;
  for_each_csv_row(path.string(), kColumns, [&](const CsvRow& row) {
    const std::vector<std::string_view>& fields = row.fields;
    const std::string& where = row.where;
    auto integer = [&](std::size_t i) {
      long long v = 0;
      if (!parse_int64(fields[i], v)) {
        throw ParseError(where, kColumns[i], "'" + std::string(fields[i]) + "' is not an integer");
      }
      return static_cast<std::int64_t>(v);
    };
    auto number = [&](std::size_t i) {
      double v = 0;
      if (!parse_double(fields[i], v) || !std::isfinite(v)) {
        throw ParseError(where, kColumns[i],
                         "'" + std::string(fields[i]) + "' is not a finite number");
      }
      return v;
    };
    auto stamp = [&](std::size_t i) {
      const std::optional<Timestamp> t = Timestamp::parse(fields[i]);
      if (!t) {
        throw ParseError(where, kColumns[i], "'" + std::string(fields[i]) + "' is not a time");
      }
      return *t;
    };
    DetectedLoopClosure lc;
    lc.line = row.line;
    lc.from_keyframe = integer(0);
    lc.to_keyframe = integer(1);
    lc.from_frame = integer(2);
    lc.to_frame = integer(3);
    lc.from_time = stamp(4);
    lc.to_time = stamp(5);
    lc.role = std::string(fields[6]);
    lc.inliers = integer(7);
    lc.rms_reprojection_px = number(8);
    const Eigen::Vector3d t(number(9), number(10), number(11));
    const Eigen::Quaterniond q(number(15), number(12), number(13), number(14));
    if (q.norm() < 1e-9) throw ParseError(where, "qw", "zero quaternion");
    if (lc.from_keyframe < 0 || lc.to_keyframe < 0) {
      throw ParseError(where, "from_keyframe", "keyframe ids must be >= 0");
    }
    lc.from_to = pose_from_translation_quaternion(t, q);
    out.push_back(lc);
  });
  return out;
}

}  // namespace wifislam::eval
