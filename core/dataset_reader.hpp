#pragma once
// Reads a dataset folder as a SensorStream: our datasets
// (dataset_format.hpp) and plain TUM RGB-D datasets (rgb.txt + depth.txt, associated as TUM's
// associate.py does, or associations.txt). A folder without wifi.csv has no Wi-Fi
// (has_wifi() is false and description() says so); one without odometry.txt has no odometry; one
// without calibration.yaml uses the TUM default Kinect v1 intrinsics and 5000 depth units per
// metre.
//
// Opening checks everything but the image contents: that the folder is a finished dataset and
// the manifest's SHA-256 of every text file (unless verification is off), each list file line by
// line (rgb.txt and depth.txt too when associations.txt is there: every paired image must be
// listed), stamps that increase from line to line, at least one frame, and that every listed
// image is a file inside the folder. Errors name the file and line. Images are then loaded lazily,
// a few frames ahead of next() on other threads (DatasetReaderOptions::prefetch_frames), and each
// PNG's hash is checked against images.sha256 as it is read, so memory stays flat whatever the
// dataset's length and no byte is read twice.
//
// Ground truth is not part of the stream (SLAM never sees it): read_ground_truth() reads it.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "core/dataset_calibration.hpp"
#include "core/dataset_manifest.hpp"
#include "core/sensor_stream.hpp"
#include "core/tum_file_list.hpp"
#include "core/tum_trajectory.hpp"

namespace wifislam {

struct DatasetReaderOptions {
  /// Compare files with manifest.json's SHA-256 (and PNGs with images.sha256). Off = --no-verify:
  /// read a dataset that was edited on purpose.
  bool verify_checksums = true;
  /// Decode images in next(). Off: frames carry their paths and times only (quick passes over
  /// Wi-Fi and odometry, an export's links); their files are still checked against
  /// images.sha256 when `verify_checksums` is on, only not decoded.
  bool load_images = true;
  /// Frames read, checked and decoded ahead on other threads while the current one is used
  /// (0 = decode in next(), on the caller's thread). The frames, their order and any error are
  /// the same whatever the value; only the wall time changes.
  int prefetch_frames = 4;
};

class DatasetReader final : public SensorStream {
 public:
  /// Throws IoError (folder or file unreadable) or ParseError (file:line of what is wrong).
  explicit DatasetReader(const std::filesystem::path& folder, DatasetReaderOptions options = {});
  ~DatasetReader() override;

  std::optional<SensorEvent> next() override;
  const CameraIntrinsics& intrinsics() const override { return calibration_.intrinsics; }
  Pose camera_in_base() const override { return calibration_.camera_in_base; }
  /// A wifi.csv with at least one scan (a file with its header only, as a scene without access
  /// points gives, holds no Wi-Fi information).
  bool has_wifi() const override { return has_wifi_ && scan_count_ > 0; }
  bool has_odometry() const override { return has_odometry_; }
  std::string description() const override;

  /// Starts the stream again from the first event.
  void rewind();

  bool has_manifest() const { return manifest_.has_value(); }
  const std::optional<DatasetManifest>& manifest() const { return manifest_; }
  const DatasetCalibration& calibration() const { return calibration_; }
  const std::filesystem::path& folder() const { return folder_; }
  std::int64_t frame_count() const { return frame_count_; }
  std::int64_t wifi_scan_count() const { return scan_count_; }
  std::int64_t odometry_count() const { return odometry_count_; }

 private:
  struct Cursors;
  void validate();
  void open_cursors();
  /// Tops up the queue of upcoming frames, starting their decodes.
  void fill_frame_queue();

  std::filesystem::path folder_;
  DatasetReaderOptions options_;
  std::optional<DatasetManifest> manifest_;
  DatasetCalibration calibration_;
  bool has_calibration_file_ = false;
  bool has_wifi_ = false, has_odometry_ = false, has_associations_file_ = false;
  bool has_frames_ = false;
  std::vector<FramePair> associated_;  // plain TUM datasets only (associated in memory)
  std::int64_t frame_count_ = 0, scan_count_ = 0, odometry_count_ = 0;
  std::unique_ptr<Cursors> cursors_;
};

/// What an interrupted `generate` leaves: a folder without manifest.json (written last) that
/// carries this tool's output marker or a `.partial` name (and is no run folder). Its lists end
/// early, so reading it would score a truncated route; DatasetReader refuses it unless checksums
/// are off.
bool is_unfinished_dataset(const std::filesystem::path& folder);

/// Why an existing folder is no dataset at all, or nullopt when it may be one: a SLAM run folder
/// (run.json, and no frame list or manifest), or a folder holding none of a dataset's files
/// (groundtruth.txt, associations.txt, rgb.txt, manifest.json). Said instead of the first file
/// found missing, or of "unfinished" (a run folder carries this tool's marker too).
std::optional<std::string> not_a_dataset(const std::filesystem::path& folder);

/// The (rgb, depth) image pairs of a dataset folder, in the order DatasetReader streams its frames:
/// associations.txt when there is one, else rgb.txt and depth.txt associated as TUM's associate.py
/// does; empty for a folder with neither. Paths are as listed, relative to the folder; whether the
/// images exist is DatasetReader's check. ParseError names the file and line.
std::vector<FramePair> read_frame_pairs(const std::filesystem::path& folder);

/// groundtruth.txt of a dataset folder (camera-to-world poses at the frame times). When the folder
/// has a manifest, the file's SHA-256 is checked (unless `verify_checksums` is false) and the pose
/// count must match its counts; a truncated file is a ParseError naming the file.
Trajectory read_ground_truth(const std::filesystem::path& folder, bool verify_checksums = true);

/// Decodes a TUM depth PNG (16-bit, `units_per_metre`) into metres (CV_32FC1). Throws ParseError
/// naming `name` for anything that is not a 16-bit single-channel PNG.
cv::Mat decode_depth_png(const std::vector<unsigned char>& bytes, double units_per_metre,
                         const std::string& name);

/// Throws ParseError naming `name` when `image` is not the calibration's size: every reader of a
/// dataset's images (the reader, exports that write the pixels elsewhere) refuses the same way.
void check_image_size(const cv::Mat& image, const CameraIntrinsics& k, const std::string& name);

}  // namespace wifislam
