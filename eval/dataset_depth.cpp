#include "eval/dataset_depth.hpp"

#include "core/dataset_format.hpp"
#include "core/error.hpp"
#include "core/png_codec.hpp"
#include "core/tum_file_list.hpp"
#include "eval/association.hpp"

namespace wifislam::eval {

DatasetDepth::DatasetDepth(const std::filesystem::path& dataset_dir,
                           const CameraIntrinsics& intrinsics, double units_per_metre,
                           const EvalOptions& options)
    : folder_(dataset_dir),
      intrinsics_(intrinsics),
      units_per_metre_(units_per_metre),
      options_(options) {
  const std::filesystem::path list = dataset_dir / dataset::kDepthList;
  if (!std::filesystem::exists(list)) return;
  for (const TumFileEntry& e : read_tum_file_list(list.string())) {
    times_.push_back(e.time);
    paths_.push_back(e.path);
  }
}

const DepthView* DatasetDepth::view(Timestamp t) {
  const std::optional<std::size_t> index = nearest_stamp(times_, t, options_.max_time_difference_s);
  if (!index) return nullptr;
  if (auto it = views_.find(*index); it != views_.end()) return &it->second;
  const std::filesystem::path path = folder_ / paths_[*index];
  if (!std::filesystem::exists(path)) {
    throw IoError(path.string() + ": depth image listed in depth.txt is missing");
  }
  const cv::Mat raw = read_png(path);
  if (raw.type() != CV_16UC1) {
    throw ParseError(path.string(), "", "expected a 16-bit single-channel depth PNG");
  }
  if (raw.cols != intrinsics_.width_px || raw.rows != intrinsics_.height_px) {
    throw ParseError(path.string(), "",
                     "depth image is " + std::to_string(raw.cols) + "x" + std::to_string(raw.rows) +
                         ", calibration says " + std::to_string(intrinsics_.width_px) + "x" +
                         std::to_string(intrinsics_.height_px));
  }
  cv::Mat depth_m;
  raw.convertTo(depth_m, CV_32FC1, 1.0 / units_per_metre_);
  return &views_.emplace(*index, make_depth_view(depth_m, intrinsics_, options_)).first->second;
}

}  // namespace wifislam::eval
