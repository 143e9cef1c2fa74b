#include "core/dataset_reader.hpp"

#include <array>
#include <deque>
#include <exception>
#include <fstream>
#include <future>
#include <iterator>
#include <limits>
#include <system_error>
#include <unordered_set>

#include <fmt/format.h>

#include "core/atomic_file.hpp"
#include "core/dataset_format.hpp"
#include "core/depth_png.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/line_cursor.hpp"
#include "core/output_folder.hpp"
#include "core/png_codec.hpp"
#include "core/run_format.hpp"
#include "core/text_lines.hpp"
#include "core/wifi_csv.hpp"

namespace wifislam {

namespace fs = std::filesystem;

namespace {

// Whether the dataset holds file `p`. A folder or device in a file's place is bad input, not an
// absent file: a calibration.yaml that is a folder must not silently mean the default intrinsics.
bool is_file(const fs::path& p) { return input_file_present(p, "one of a dataset's files"); }

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

}  // namespace

void check_image_size(const cv::Mat& image, const CameraIntrinsics& k, const std::string& name) {
  if (image.cols != k.width_px || image.rows != k.height_px) {
    throw ParseError(name, "",
                     fmt::format("image is {}x{}, the calibration says {}x{}", image.cols,
                                 image.rows, k.width_px, k.height_px));
  }
}

cv::Mat decode_depth_png(const std::vector<unsigned char>& bytes, double units_per_metre,
                         const std::string& name) {
  const cv::Mat raw = decode_png(bytes, name);
  if (raw.type() != CV_16UC1) {
    throw ParseError(name, "",
                     fmt::format("depth image must be 16-bit single-channel (TUM: {} units per "
                                 "metre), got {} channel(s) of {} bytes",
                                 units_per_metre, raw.channels(), raw.elemSize1()));
  }
  return depth_from_png_units(raw, units_per_metre);
}

/// The decoded images of one frame.
struct DecodedImages {
  cv::Mat rgb, depth_m;
};

/// A listed frame whose images are being read, checked and decoded (possibly on another thread).
struct PendingFrame {
  FramePair pair;
  std::future<DecodedImages> images;  // invalid when images are not loaded
};

struct DatasetReader::Cursors {
  std::optional<AssociationsReader> associations;
  std::size_t associated_index = 0;
  std::optional<TumTrajectoryReader> odometry;
  std::optional<WifiCsvReader> wifi;
  std::optional<LineCursor> checksums;
  std::deque<PendingFrame> frames;  // the next frames, in order, decoding ahead
  std::optional<OdometryReading> odometry_reading;
  std::optional<WifiScan> scan;
  bool frames_done = false, odometry_done = false, wifi_done = false;
  std::int64_t frame_index = 0;
};

std::optional<std::string> not_a_dataset(const fs::path& folder) {
  std::error_code ec;
  const auto has = [&](const char* name) { return fs::exists(folder / name, ec); };
  if (has(dataset::kManifest) || has(dataset::kAssociations) || has(dataset::kRgbList)) {
    return std::nullopt;
  }
  if (has(run_folder::kRun)) {
    return folder.string() +
           ": a SLAM run folder (it holds run.json), not a dataset; give the dataset it ran on "
           "(run.json's input)";
  }
  if (!has(dataset::kGroundTruth)) {
    return fmt::format("{}: not a dataset folder: it holds none of {}, {}, {}, {}", folder.string(),
                       dataset::kGroundTruth, dataset::kAssociations, dataset::kRgbList,
                       dataset::kManifest);
  }
  return std::nullopt;
}

bool is_unfinished_dataset(const fs::path& folder) {
  std::error_code ec;
  if (fs::exists(folder / dataset::kManifest, ec)) return false;
  // A run folder carries the marker too, and is no dataset at all (not_a_dataset says so).
  if (fs::exists(folder / run_folder::kRun, ec)) return false;
  fs::path name = folder.filename();
  if (name.empty()) name = folder.parent_path().filename();  // "ds.partial/"
  return fs::exists(folder / kOutputMarkerFile, ec) || name.string().ends_with(".partial");
}

DatasetReader::DatasetReader(const fs::path& folder, DatasetReaderOptions options)
    : folder_(folder), options_(options) {
  std::error_code ec;
  const fs::file_status status = fs::status(folder_, ec);
  if (!fs::exists(status)) {
    throw IoError(folder_.string() + ": not a dataset folder (does not exist)");
  }
  // It is there but cannot be one: bad input, as a folder given for a scene file is.
  if (!fs::is_directory(status)) {
    throw InvalidInputError(folder_.string() + ": not a dataset folder (it is a file)");
  }
  // Every command that reads a dataset refuses it alike (slam, check, export).
  if (options_.verify_checksums && is_unfinished_dataset(folder_)) {
    throw InvalidInputError(folder_.string() +
                            ": an unfinished dataset (no manifest.json: `wifislam generate` was "
                            "interrupted?); generate it again, or pass --no-verify to read what "
                            "is there");
  }
  if (const std::optional<std::string> why = not_a_dataset(folder_)) throw InvalidInputError(*why);
  if (is_file(folder_ / dataset::kManifest)) {
    manifest_ = read_dataset_manifest(folder_ / dataset::kManifest);
    if (!manifest_->colour_images) {
      throw InvalidInputError(folder_.string() +
                              ": holds depth images only (a study case's dataset, kept for its "
                              "evaluation); SLAM needs colour: generate the dataset with "
                              "`wifislam generate`");
    }
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

namespace {

/// A listed image: a relative path that stays inside the dataset folder (an absolute or `..`
/// path would read files the dataset does not hold) and names a regular file. A missing file is
/// an I/O error; one that is there but cannot be a PNG (a folder, a device) is bad input.
void check_image_file(const fs::path& folder, const std::string& relative,
                      const std::string& listed_at) {
  const fs::path listed(relative);
  const fs::path normal = listed.lexically_normal();
  if (listed.is_absolute() || normal.empty() || *normal.begin() == "..") {
    throw ParseError(listed_at, "",
                     fmt::format("image path '{}' leaves the dataset folder; list images by "
                                 "paths relative to it, inside it",
                                 relative));
  }
  std::error_code ec;
  const fs::file_status status = fs::status(folder / listed, ec);
  if (!fs::exists(status)) {
    throw IoError(
        fmt::format("{}: image {} does not exist", listed_at, (folder / listed).string()));
  }
  if (!fs::is_regular_file(status)) {
    throw ParseError(
        listed_at, "",
        fmt::format("image {} is {}, not a PNG image", (folder / listed).string(),
                    fs::is_directory(status) ? "a folder" : "not a regular file (a device?)"));
  }
}

/// Every image of rgb.txt or depth.txt (`name`) checked.
void check_list_images(const fs::path& folder, const char* name,
                       const std::vector<TumFileEntry>& entries) {
  const std::string list = (folder / name).string();
  for (const auto& e : entries)
    check_image_file(folder, e.path, fmt::format("{}:{}", list, e.line));
}

/// rgb.txt or depth.txt, every entry's image checked.
std::vector<TumFileEntry> read_checked_list(const fs::path& folder, const char* name) {
  std::vector<TumFileEntry> entries = read_tum_file_list((folder / name).string());
  check_list_images(folder, name, entries);
  return entries;
}

}  // namespace

void DatasetReader::validate() {
  const bool has_rgb_list = is_file(folder_ / dataset::kRgbList);
  const bool has_depth_list = is_file(folder_ / dataset::kDepthList);
  const std::string assoc_file = (folder_ / dataset::kAssociations).string();
  if (has_associations_file_) {
    // The lists beside associations.txt are part of the dataset too (peers read them): they
    // must be well-formed and hold every image the associations pair. Their images are checked
    // after the associations', so a missing image is reported at the line SLAM reads it from.
    const auto read_list = [&](bool has_list, const char* name) {
      return has_list ? read_tum_file_list((folder_ / name).string()) : std::vector<TumFileEntry>{};
    };
    const std::vector<TumFileEntry> rgb = read_list(has_rgb_list, dataset::kRgbList);
    const std::vector<TumFileEntry> depth = read_list(has_depth_list, dataset::kDepthList);
    std::unordered_set<std::string> rgb_listed, depth_listed;
    for (const auto& e : rgb) rgb_listed.insert(e.path);
    for (const auto& e : depth) depth_listed.insert(e.path);
    const auto check_listed = [&](bool has_list, const std::unordered_set<std::string>& listed,
                                  const std::string& path, const char* list,
                                  const std::string& at) {
      if (has_list && !listed.contains(path)) {
        throw ParseError(at, "", fmt::format("image {} is not listed in {}", path, list));
      }
    };
    AssociationsReader reader(assoc_file);
    while (auto pair = reader.next()) {
      const std::string at = fmt::format("{}:{}", reader.path(), pair->line);
      check_image_file(folder_, pair->rgb_path, at);
      check_image_file(folder_, pair->depth_path, at);
      check_listed(has_rgb_list, rgb_listed, pair->rgb_path, dataset::kRgbList, at);
      check_listed(has_depth_list, depth_listed, pair->depth_path, dataset::kDepthList, at);
      ++frame_count_;
    }
    check_list_images(folder_, dataset::kRgbList, rgb);
    check_list_images(folder_, dataset::kDepthList, depth);
    has_frames_ = true;
    if (frame_count_ == 0) {
      throw InvalidInputError(assoc_file + ": lists no frames; a dataset needs at least one");
    }
  } else if (has_rgb_list && has_depth_list) {
    const auto rgb = read_checked_list(folder_, dataset::kRgbList);
    const auto depth = read_checked_list(folder_, dataset::kDepthList);
    associated_ = associate_tum(rgb, depth, dataset::kAssociationMaxDifferenceS);
    frame_count_ = static_cast<std::int64_t>(associated_.size());
    has_frames_ = true;
    if (frame_count_ == 0) {
      const std::string why =
          rgb.empty() || depth.empty()
              ? fmt::format("{} lists no images",
                            rgb.empty() ? dataset::kRgbList : dataset::kDepthList)
              : fmt::format("no stamp in {} is within {} s of one in {}", dataset::kRgbList,
                            dataset::kAssociationMaxDifferenceS, dataset::kDepthList);
      throw InvalidInputError(
          fmt::format("{}: no frames ({}); a dataset needs at least one", folder_.string(), why));
    }
  } else if (!(manifest_ && !manifest_->images)) {
    throw InvalidInputError(fmt::format("{}: not an RGB-D dataset: found neither {} nor {} + {}",
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
  if (manifest_ && manifest_->images && options_.verify_checksums &&
      is_file(folder_ / dataset::kImageChecksums)) {
    c.checksums.emplace((folder_ / dataset::kImageChecksums).string());
  }
}

void DatasetReader::rewind() { open_cursors(); }

namespace {

/// The images.sha256 entries of one frame's two files ("" = not verified), where each is, and
/// what reading them threw.
struct FrameChecksums {
  std::array<std::string, 2> expected_sha256, where;
  std::exception_ptr error;
};

/// One frame's two files (colour, depth), read and checked against their images.sha256 entries.
std::array<std::vector<unsigned char>, 2> read_checked_frame_files(const fs::path& folder,
                                                                   const FramePair& pair,
                                                                   const std::string& listed_at,
                                                                   const FrameChecksums& sums) {
  const std::array<const std::string*, 2> relative{&pair.rgb_path, &pair.depth_path};
  std::array<std::vector<unsigned char>, 2> bytes;
  for (std::size_t i = 0; i < 2; ++i) bytes[i] = read_bytes(folder / *relative[i], listed_at);
  if (sums.error) std::rethrow_exception(sums.error);
  for (std::size_t i = 0; i < 2; ++i) {
    if (sums.expected_sha256[i].empty()) continue;
    const std::string_view data(reinterpret_cast<const char*>(bytes[i].data()), bytes[i].size());
    if (sha256_hex(data) != sums.expected_sha256[i]) {
      throw ParseError((folder / *relative[i]).string(), "",
                       fmt::format("contents differ from {} (manifest mismatch); use "
                                   "--no-verify to read it anyway",
                                   sums.where[i]));
    }
  }
  return bytes;
}

/// Reads, checks and decodes one frame's images.
DecodedImages load_frame_images(const fs::path& folder, const FramePair& pair,
                                const std::string& listed_at, const FrameChecksums& sums,
                                const CameraIntrinsics& intrinsics, double depth_units_per_metre) {
  const fs::path rgb_file = folder / pair.rgb_path, depth_file = folder / pair.depth_path;
  const auto [rgb_bytes, depth_bytes] = read_checked_frame_files(folder, pair, listed_at, sums);
  DecodedImages out;
  // Read as stored, not converted to colour (which would scale a 16-bit image, a depth map in the
  // RGB list, down to 8 bits, or expand grey or drop alpha without a word): anything but 8-bit
  // colour is refused.
  out.rgb = decode_png(rgb_bytes, rgb_file.string());
  if (out.rgb.depth() != CV_8U) {
    throw ParseError(rgb_file.string(), "",
                     fmt::format("an RGB image must have 8 bits per channel, this one has {} "
                                 "(a depth image listed as RGB at {}?)",
                                 8 * out.rgb.elemSize1(), listed_at));
  }
  if (out.rgb.channels() != 3) {
    throw ParseError(rgb_file.string(), "",
                     fmt::format("an RGB image must have 3 colour channels, this one has {} ({}; "
                                 "listed at {})",
                                 out.rgb.channels(),
                                 out.rgb.channels() == 1   ? "grey"
                                 : out.rgb.channels() == 2 ? "grey with alpha"
                                                           : "colour with alpha",
                                 listed_at));
  }
  check_image_size(out.rgb, intrinsics, rgb_file.string());
  out.depth_m = decode_depth_png(depth_bytes, depth_units_per_metre, depth_file.string());
  check_image_size(out.depth_m, intrinsics, depth_file.string());
  return out;
}

}  // namespace

void DatasetReader::fill_frame_queue() {
  Cursors& c = *cursors_;
  // PNG decoding is most of the time a dataset takes to read (~55 % of `wifislam slam`'s wall
  // time on c_hall); decoding the next frames on other threads while SLAM works on this one
  // keeps the pipeline fed. Checksum entries are read here, in order; the hashes are compared
  // where the bytes are. Results and errors come out in frame order, whatever the timing.
  const std::size_t ahead = options_.load_images ? 1 + std::max(0, options_.prefetch_frames) : 1;
  while (c.frames.size() < ahead && !c.frames_done) {
    std::optional<FramePair> pair;
    if (c.associations) {
      pair = c.associations->next();
    } else if (c.associated_index < associated_.size()) {
      pair = associated_[c.associated_index++];
    }
    if (!pair) {
      c.frames_done = true;
      break;
    }
    PendingFrame pending{std::move(*pair), {}};
    const FramePair& p = pending.pair;
    const std::string listed_at =
        p.line > 0       ? fmt::format("{}:{}", (folder_ / dataset::kAssociations).string(), p.line)
        : p.rgb_line > 0 ? fmt::format("{}:{}", (folder_ / dataset::kRgbList).string(), p.rgb_line)
                         : (folder_ / dataset::kRgbList).string();
    FrameChecksums sums;
    if (c.checksums) {
      try {
        for (std::size_t i = 0; i < 2; ++i) {
          const std::string& relative = i == 0 ? p.rgb_path : p.depth_path;
          TextLine line;
          if (!c.checksums->next(line)) {
            throw ParseError(
                c.checksums->path(), "",
                fmt::format("ends before the entry for {} (manifest mismatch)", relative));
          }
          const auto fields = split_fields(line.text);
          sums.where[i] = c.checksums->where(line.number);
          if (fields.size() != 2 || fields[1] != relative) {
            throw ParseError(sums.where[i], "", fmt::format("expected the entry for {}", relative));
          }
          sums.expected_sha256[i] = std::string(fields[0]);
        }
      } catch (...) {
        sums.error = std::current_exception();
        c.checksums.reset();  // the entries are out of step from here: stop reading them
      }
    }
    if (!options_.load_images && (sums.error || !sums.expected_sha256[0].empty())) {
      // Not decoded, but still checked: an export links these files, and `check --no-images`
      // says they match. Checked when the frame is taken, so errors keep the frame order.
      pending.images =
          std::async(std::launch::deferred, [folder = folder_, pair = p, listed_at, sums] {
            read_checked_frame_files(folder, pair, listed_at, sums);
            return DecodedImages{};
          });
    }
    if (options_.load_images) {
      auto task = [folder = folder_, pair = p, listed_at, sums,
                   intrinsics = calibration_.intrinsics,
                   units = calibration_.depth_units_per_metre] {
        return load_frame_images(folder, pair, listed_at, sums, intrinsics, units);
      };
      const bool parallel = options_.prefetch_frames > 0;
      try {
        pending.images = std::async(parallel ? std::launch::async : std::launch::deferred, task);
      } catch (const std::system_error&) {
        // No thread to be had (process limits): decode when the frame is taken.
        pending.images = std::async(std::launch::deferred, task);
      }
    }
    c.frames.push_back(std::move(pending));
  }
}

std::optional<SensorEvent> DatasetReader::next() {
  Cursors& c = *cursors_;
  fill_frame_queue();
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
  const Timestamp t_frame = c.frames.empty() ? never : c.frames.front().pair.rgb_time;
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
  if (c.frames.empty()) return std::nullopt;

  PendingFrame pending = std::move(c.frames.front());
  c.frames.pop_front();
  const FramePair& pair = pending.pair;
  RgbdFrame frame;
  frame.time = pair.rgb_time;
  frame.index = c.frame_index++;
  frame.rgb_path = pair.rgb_path;
  frame.depth_path = pair.depth_path;
  if (pending.images.valid()) {
    DecodedImages images = pending.images.get();
    frame.rgb = std::move(images.rgb);
    frame.depth_m = std::move(images.depth_m);
  }
  fill_frame_queue();  // start the next decode before SLAM takes this frame
  return SensorEvent{std::move(frame)};
}

std::string DatasetReader::description() const {
  std::string kind = manifest_ ? "wifislam dataset" : "TUM RGB-D dataset";
  // A dataset without images has poses at its frame times but streams no frames: "0 frames"
  // beside a Python Dataset's length (its ground-truth stamps) would contradict it.
  std::string out =
      has_frames_
          ? fmt::format("{} {} ({} frames", kind, folder_.string(), frame_count_)
          : fmt::format("{} {} (no images: poses and sensor readings only", kind, folder_.string());
  out += has_wifi_ ? fmt::format(", {} Wi-Fi scans", scan_count_)
                   : "; no Wi-Fi: the folder has no wifi.csv";
  out += has_odometry_ ? fmt::format(", {} odometry readings", odometry_count_) : "; no odometry";
  if (!has_calibration_file_) out += "; no calibration.yaml: default Kinect v1 intrinsics";
  if (manifest_ && !options_.verify_checksums) out += "; checksums not verified";
  return out + ")";
}

std::vector<FramePair> read_frame_pairs(const fs::path& folder) {
  std::vector<FramePair> pairs;
  if (is_file(folder / dataset::kAssociations)) {
    AssociationsReader reader((folder / dataset::kAssociations).string());
    while (auto pair = reader.next()) pairs.push_back(std::move(*pair));
  } else if (is_file(folder / dataset::kRgbList) && is_file(folder / dataset::kDepthList)) {
    pairs = associate_tum(read_tum_file_list((folder / dataset::kRgbList).string()),
                          read_tum_file_list((folder / dataset::kDepthList).string()),
                          dataset::kAssociationMaxDifferenceS);
  }
  return pairs;
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
