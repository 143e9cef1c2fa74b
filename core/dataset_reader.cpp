#include "core/dataset_reader.hpp"

#include <fstream>
#include <iterator>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

#include "core/atomic_file.hpp"
#include "core/dataset_format.hpp"
#include "core/error.hpp"
#include "core/line_cursor.hpp"
#include "core/text_lines.hpp"
#include "core/wifi_csv.hpp"

namespace wifislam {

namespace fs = std::filesystem;

namespace {

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

std::vector<unsigned char> read_bytes(const fs::path& path, const std::string& listed_at) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw IoError(fmt::format("{}: cannot open image (listed at {})", path.string(), listed_at));
  }
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                   std::istreambuf_iterator<char>());
  if (in.bad()) throw IoError(path.string() + ": read error");
  return bytes;
}

void check_size(const cv::Mat& image, const CameraIntrinsics& k, const std::string& name) {
  if (image.cols != k.width_px || image.rows != k.height_px) {
    throw ParseError(name, "",
                     fmt::format("image is {}x{}, the calibration says {}x{}", image.cols,
                                 image.rows, k.width_px, k.height_px));
  }
}

}  // namespace

cv::Mat decode_depth_png(const std::vector<unsigned char>& bytes, double units_per_metre,
                         const std::string& name) {
  const cv::Mat raw = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  if (raw.empty()) throw ParseError(name, "", "not a readable PNG image (corrupt or truncated)");
  if (raw.type() != CV_16UC1) {
    throw ParseError(name, "",
                     fmt::format("depth image must be 16-bit single-channel (TUM: {} units per "
                                 "metre), got {} channel(s) of {} bytes",
                                 units_per_metre, raw.channels(), raw.elemSize1()));
  }
  cv::Mat depth_m;
  raw.convertTo(depth_m, CV_32F, 1.0 / units_per_metre);
  return depth_m;
}

struct DatasetReader::Cursors {
  std::optional<AssociationsReader> associations;
  std::size_t associated_index = 0;
  std::optional<TumTrajectoryReader> odometry;
  std::optional<WifiCsvReader> wifi;
  std::optional<LineCursor> checksums;
  std::optional<FramePair> frame;
  std::optional<OdometryReading> odometry_reading;
  std::optional<WifiScan> scan;
  bool frames_done = false, odometry_done = false, wifi_done = false;
  std::int64_t frame_index = 0;
};

DatasetReader::DatasetReader(const fs::path& folder, DatasetReaderOptions options)
    : folder_(folder), options_(options) {
  std::error_code ec;
  if (!fs::is_directory(folder_, ec)) {
    throw IoError(folder_.string() + ": not a dataset folder (does not exist or is not a folder)");
  }
  if (is_file(folder_ / dataset::kManifest)) {
    manifest_ = read_dataset_manifest(folder_ / dataset::kManifest);
    if (options_.verify_checksums) verify_manifest_files(folder_, *manifest_);
  }
  if (is_file(folder_ / dataset::kCalibration)) {
    calibration_ = read_calibration_yaml(folder_ / dataset::kCalibration);
    has_calibration_file_ = true;
  }
  has_wifi_ = is_file(folder_ / dataset::kWifi);
  has_odometry_ = is_file(folder_ / dataset::kOdometry);
  has_associations_file_ = is_file(folder_ / dataset::kAssociations);
  validate();
  open_cursors();
}

DatasetReader::~DatasetReader() = default;

void DatasetReader::validate() {
  auto check_exists = [&](const std::string& relative, const std::string& listed_at) {
    if (!is_file(folder_ / relative)) {
      throw IoError(
          fmt::format("{}: image {} does not exist", listed_at, (folder_ / relative).string()));
    }
  };
  const bool lists = is_file(folder_ / dataset::kRgbList) && is_file(folder_ / dataset::kDepthList);
  if (has_associations_file_) {
    AssociationsReader reader((folder_ / dataset::kAssociations).string());
    while (auto pair = reader.next()) {
      const std::string at = fmt::format("{}:{}", reader.path(), pair->line);
      check_exists(pair->rgb_path, at);
      check_exists(pair->depth_path, at);
      ++frame_count_;
    }
    has_frames_ = true;
  } else if (lists) {
    const std::string rgb_list = (folder_ / dataset::kRgbList).string();
    const std::string depth_list = (folder_ / dataset::kDepthList).string();
    const auto rgb = read_tum_file_list(rgb_list);
    const auto depth = read_tum_file_list(depth_list);
    for (const auto& e : rgb) check_exists(e.path, fmt::format("{}:{}", rgb_list, e.line));
    for (const auto& e : depth) check_exists(e.path, fmt::format("{}:{}", depth_list, e.line));
    associated_ = associate_tum(rgb, depth, dataset::kAssociationMaxDifferenceS);
    frame_count_ = static_cast<std::int64_t>(associated_.size());
    has_frames_ = true;
  } else if (!(manifest_ && !manifest_->images)) {
    throw IoError(fmt::format("{}: not an RGB-D dataset: found neither {} nor {} + {}",
                              folder_.string(), dataset::kAssociations, dataset::kRgbList,
                              dataset::kDepthList));
  }
  if (has_odometry_) {
    TumTrajectoryReader reader((folder_ / dataset::kOdometry).string());
    while (reader.next()) ++odometry_count_;
  }
  if (has_wifi_) {
    WifiCsvReader reader((folder_ / dataset::kWifi).string());
    while (reader.next()) ++scan_count_;
  }
  if (manifest_ && options_.verify_checksums) {
    auto check_count = [&](const char* key, std::int64_t got, const char* file) {
      const auto it = manifest_->counts.find(key);
      if (it != manifest_->counts.end() && it->second != got) {
        throw ParseError((folder_ / file).string(), "",
                         fmt::format("has {} {}, {} says {} (truncated or edited?)", got, key,
                                     dataset::kManifest, it->second));
      }
    };
    if (has_associations_file_) check_count("frames", frame_count_, dataset::kAssociations);
    if (has_odometry_) check_count("odometry_readings", odometry_count_, dataset::kOdometry);
    if (has_wifi_) check_count("wifi_scans", scan_count_, dataset::kWifi);
  }
}

void DatasetReader::open_cursors() {
  cursors_ = std::make_unique<Cursors>();
  Cursors& c = *cursors_;
  if (has_associations_file_) c.associations.emplace((folder_ / dataset::kAssociations).string());
  if (has_odometry_) c.odometry.emplace((folder_ / dataset::kOdometry).string());
  if (has_wifi_) c.wifi.emplace((folder_ / dataset::kWifi).string());
  if (manifest_ && manifest_->images && options_.verify_checksums && options_.load_images &&
      is_file(folder_ / dataset::kImageChecksums)) {
    c.checksums.emplace((folder_ / dataset::kImageChecksums).string());
  }
}

void DatasetReader::rewind() { open_cursors(); }

std::optional<SensorEvent> DatasetReader::next() {
  Cursors& c = *cursors_;
  if (!c.frame && !c.frames_done) {
    if (c.associations) {
      c.frame = c.associations->next();
    } else if (c.associated_index < associated_.size()) {
      c.frame = associated_[c.associated_index++];
    }
    c.frames_done = !c.frame;
  }
  if (!c.odometry_reading && !c.odometry_done) {
    if (c.odometry) {
      if (auto p = c.odometry->next()) c.odometry_reading = OdometryReading{p->time, p->pose()};
    }
    c.odometry_done = !c.odometry_reading;
  }
  if (!c.scan && !c.wifi_done) {
    if (c.wifi) c.scan = c.wifi->next();
    c.wifi_done = !c.scan;
  }
  // Earliest first; ties: odometry, then Wi-Fi, then the frame (sensor_stream.hpp).
  const Timestamp never{std::numeric_limits<std::int64_t>::max()};
  const Timestamp t_odo = c.odometry_reading ? c.odometry_reading->time : never;
  const Timestamp t_wifi = c.scan ? c.scan->time : never;
  const Timestamp t_frame = c.frame ? c.frame->rgb_time : never;
  if (c.odometry_reading && t_odo <= t_wifi && t_odo <= t_frame) {
    SensorEvent e = *c.odometry_reading;
    c.odometry_reading.reset();
    return e;
  }
  if (c.scan && t_wifi <= t_frame) {
    SensorEvent e = std::move(*c.scan);
    c.scan.reset();
    return e;
  }
  if (!c.frame) return std::nullopt;

  const FramePair pair = std::move(*c.frame);
  c.frame.reset();
  RgbdFrame frame;
  frame.time = pair.rgb_time;
  frame.index = c.frame_index++;
  frame.rgb_path = pair.rgb_path;
  frame.depth_path = pair.depth_path;
  if (options_.load_images) {
    const std::string listed_at =
        pair.line > 0 ? fmt::format("{}:{}", (folder_ / dataset::kAssociations).string(), pair.line)
                      : (folder_ / dataset::kRgbList).string();
    const fs::path rgb_file = folder_ / pair.rgb_path, depth_file = folder_ / pair.depth_path;
    const auto rgb_bytes = read_bytes(rgb_file, listed_at);
    const auto depth_bytes = read_bytes(depth_file, listed_at);
    if (c.checksums) {
      for (const auto& [relative, bytes] :
           {std::pair{&pair.rgb_path, &rgb_bytes}, std::pair{&pair.depth_path, &depth_bytes}}) {
        TextLine line;
        if (!c.checksums->next(line)) {
          throw ParseError(
              c.checksums->path(), "",
              fmt::format("ends before the entry for {} (manifest mismatch)", *relative));
        }
        const auto fields = split_fields(line.text);
        const std::string where = c.checksums->where(line.number);
        if (fields.size() != 2 || fields[1] != *relative) {
          throw ParseError(where, "", fmt::format("expected the entry for {}", *relative));
        }
        const std::string_view data(reinterpret_cast<const char*>(bytes->data()), bytes->size());
        if (sha256_hex(data) != fields[0]) {
          throw ParseError((folder_ / *relative).string(), "",
                           fmt::format("contents differ from {} (manifest mismatch); use "
                                       "--no-verify to read it anyway",
                                       where));
        }
      }
    }
    frame.rgb = cv::imdecode(rgb_bytes, cv::IMREAD_COLOR);
    if (frame.rgb.empty()) {
      throw ParseError(rgb_file.string(), "", "not a readable PNG image (corrupt or truncated)");
    }
    check_size(frame.rgb, calibration_.intrinsics, rgb_file.string());
    frame.depth_m =
        decode_depth_png(depth_bytes, calibration_.depth_units_per_metre, depth_file.string());
    check_size(frame.depth_m, calibration_.intrinsics, depth_file.string());
  }
  return SensorEvent{std::move(frame)};
}

std::string DatasetReader::description() const {
  std::string kind = manifest_ ? "wifislam dataset" : "TUM RGB-D dataset";
  std::string out = fmt::format("{} {} ({} frames", kind, folder_.string(), frame_count_);
  if (!has_frames_) out += ": poses, odometry and Wi-Fi only, no images";
  out += has_wifi_ ? fmt::format(", {} Wi-Fi scans", scan_count_)
                   : "; no Wi-Fi: the folder has no wifi.csv";
  out += has_odometry_ ? fmt::format(", {} odometry readings", odometry_count_) : "; no odometry";
  if (!has_calibration_file_) out += "; no calibration.yaml: default Kinect v1 intrinsics";
  if (manifest_ && !options_.verify_checksums) out += "; checksums not verified";
  return out + ")";
}

Trajectory read_ground_truth(const fs::path& folder, bool verify_checksums) {
  const fs::path file = folder / dataset::kGroundTruth;
  if (!is_file(file)) throw IoError(file.string() + ": no ground truth in this dataset");
  if (verify_checksums && is_file(folder / dataset::kManifest)) {
    const DatasetManifest manifest = read_dataset_manifest(folder / dataset::kManifest);
    for (const ManifestFile& f : manifest.files) {
      if (f.path == dataset::kGroundTruth && sha256_file_hex(file) != f.sha256) {
        // Still parse first: a malformed line is the more useful message.
        const Trajectory t = read_tum_trajectory(file.string());
        throw ParseError(file.string(), "",
                         fmt::format("{} poses; contents differ from {} (manifest mismatch: "
                                     "truncated or edited?)",
                                     t.size(), dataset::kManifest));
      }
    }
    Trajectory t = read_tum_trajectory(file.string());
    const auto it = manifest.counts.find("groundtruth_poses");
    if (it != manifest.counts.end() && it->second != static_cast<std::int64_t>(t.size())) {
      throw ParseError(file.string(), "",
                       fmt::format("has {} poses, {} says {} (truncated?)", t.size(),
                                   dataset::kManifest, it->second));
    }
    return t;
  }
  return read_tum_trajectory(file.string());
}

}  // namespace wifislam
