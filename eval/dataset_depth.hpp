#pragma once
// The depth images of a dataset folder (depth.txt + depth/<t>.png, 16-bit, units per metre from
// calibration.yaml), looked up by timestamp and turned into DepthViews for overlap tests. Views
// are built on first use and kept (a few tens of kB each). A dataset written without images has
// no depth.txt: available() is false and overlap falls back to the geometric bound.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/camera_intrinsics.hpp"
#include "core/timestamp.hpp"
#include "eval/eval_options.hpp"
#include "eval/view_overlap.hpp"

namespace wifislam::eval {

class DatasetDepth {
 public:
  /// Reads depth.txt when present (ParseError naming file:line for a malformed line).
  DatasetDepth(const std::filesystem::path& dataset_dir, const CameraIntrinsics& intrinsics,
               double units_per_metre, const EvalOptions& options);

  bool available() const { return !times_.empty(); }
  /// The view of the depth image nearest to `t` (closer than max_time_difference_s), or null.
  /// Throws IoError / ParseError naming the PNG when it is missing or not a 16-bit image.
  const DepthView* view(Timestamp t);
  std::size_t loaded_views() const { return views_.size(); }

 private:
  std::filesystem::path folder_;
  CameraIntrinsics intrinsics_;
  double units_per_metre_;
  EvalOptions options_;
  std::vector<Timestamp> times_;
  std::vector<std::string> paths_;
  std::map<std::size_t, DepthView> views_;
};

}  // namespace wifislam::eval
