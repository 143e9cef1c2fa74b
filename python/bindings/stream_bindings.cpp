// Frames in route order from a SensorStream, the one interface SLAM reads: the simulator's
// in-memory stream (sim/generate/generator_stream.hpp, exactly what a reader of the dataset gets)
// or a dataset folder (core/dataset_reader.hpp). Each frame carries the Wi-Fi scans and odometry
// readings that came before it in the stream (since the previous frame), and its ground truth.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <variant>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "core/dataset_format.hpp"
#include "core/dataset_reader.hpp"
#include "core/error.hpp"
#include "core/imu_csv.hpp"
#include "python/bindings/bindings.hpp"
#include "python/bindings/numpy_convert.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/generate/generator_stream.hpp"

namespace wifislam::python {

namespace py = pybind11;
namespace fs = std::filesystem;

namespace {

/// One frame and what came with it, gathered with the GIL released.
struct GatheredFrame {
  RgbdFrame frame;
  std::optional<Pose> camera_to_world;
  std::vector<WifiScan> scans;
  std::vector<OdometryReading> odometry;
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual SensorStream& stream() = 0;
  /// The stream's next event (a source may add events of its own).
  virtual std::optional<SensorEvent> next_event() { return stream().next(); }
  /// Ground truth of the frame just read, if known.
  virtual std::optional<Pose> ground_truth(const RgbdFrame& frame) const = 0;
  virtual void rewind() = 0;
  /// Throws when what the source reads has changed since it was opened (a dataset folder
  /// replaced or removed): a pass would mix the two.
  virtual void check_unchanged() const {}

  /// Starts a pass over the stream from its first event and returns the pass's number; an
  /// earlier pass ends there (its next_frame raises). The stream has one read position, so
  /// two passes cannot interleave: each `for` loop in Python is a pass, and a second loop must
  /// not silently continue where the first stopped, nor steal its frames. A stream that has
  /// not been read yet is not rewound (a Simulator's rewind builds its pipeline again).
  std::uint64_t begin_pass() {
    py::gil_scoped_release release;
    const std::lock_guard<std::mutex> lock(mutex_);
    check_unchanged();
    if (read_since_rewind_) {
      rewind();
      read_since_rewind_ = false;
    }
    return ++pass_;
  }

  /// The next frame of pass `pass` as a dict, or None at the end of the stream (scans after
  /// the last frame belong to no frame and are not returned).
  py::object next_frame(std::uint64_t pass) {
    std::optional<GatheredFrame> gathered;
    {
      py::gil_scoped_release release;
      // One reader at a time: with the GIL released, two threads iterating one source would
      // both advance its stream. Each frame goes to exactly one of them.
      const std::lock_guard<std::mutex> lock(mutex_);
      if (pass != pass_) {
        throw std::runtime_error(
            "this iteration ended when another iteration of the same frames began (each "
            "starts at the first frame, and the frames have one read position): finish one "
            "loop before starting the next, or share one iterator, frames = iter(source), "
            "between threads");
      }
      read_since_rewind_ = true;
      gathered = gather();
    }
    if (!gathered) return py::none();
    return frame_dict(*gathered);
  }

 private:
  std::optional<GatheredFrame> gather() {
    GatheredFrame out;
    while (std::optional<SensorEvent> event = next_event()) {
      if (auto* scan = std::get_if<WifiScan>(&*event)) {
        out.scans.push_back(std::move(*scan));
      } else if (auto* reading = std::get_if<OdometryReading>(&*event)) {
        out.odometry.push_back(*reading);
      } else {
        out.frame = std::move(std::get<RgbdFrame>(*event));
        out.camera_to_world = ground_truth(out.frame);
        return out;
      }
    }
    return std::nullopt;
  }

  std::mutex mutex_;
  std::uint64_t pass_ = 0;  // the number of the latest pass; guarded by mutex_
  bool read_since_rewind_ = false;

  static py::dict scan_dict(const WifiScan& scan) {
    py::list readings;
    for (const WifiReading& r : scan.readings) {
      py::dict reading;
      reading["bssid"] = r.bssid.to_string();
      reading["rssi_dbm"] = r.rssi_dbm;
      reading["frequency_khz"] = r.frequency_khz;
      reading["ssid"] = r.ssid;
      readings.append(std::move(reading));
    }
    py::dict out;
    out["stamp_ns"] = scan.time.ns;
    out["start_ns"] = scan.start_time.ns;
    out["end_ns"] = scan.end_time.ns;
    out["sensor_id"] = scan.sensor_id;
    out["readings"] = std::move(readings);
    return out;
  }

  static py::dict frame_dict(const GatheredFrame& g) {
    py::dict out;
    out["index"] = g.frame.index;
    out["stamp_ns"] = g.frame.time.ns;
    out["rgb"] = g.frame.rgb.empty() ? py::object(py::none()) : py::object(rgb_array(g.frame.rgb));
    out["depth"] =
        g.frame.depth_m.empty() ? py::object(py::none()) : py::object(depth_array(g.frame.depth_m));
    out["pose"] =
        g.camera_to_world ? py::object(pose_array(*g.camera_to_world)) : py::object(py::none());
    py::list scans, odometry;
    for (const WifiScan& s : g.scans) scans.append(scan_dict(s));
    for (const OdometryReading& o : g.odometry) {
      odometry.append(py::make_tuple(o.time.ns, pose_array(o.base_in_odom)));
    }
    out["scans"] = std::move(scans);
    out["odometry"] = std::move(odometry);
    return out;
  }
};

class SimulatorSource final : public FrameSource {
 public:
  SimulatorSource(const sim::scene::Scene& scene, const sim::generate::GenerateOptions& options)
      : stream_(scene, options) {}
  SensorStream& stream() override { return stream_; }
  void rewind() override { stream_.rewind(); }
  std::optional<Pose> ground_truth(const RgbdFrame&) const override {
    return stream_.last_frame_ground_truth();
  }
  const sim::scene::Scene& scene() const { return stream_.pipeline().scene(); }
  std::int64_t frame_count() const { return stream_.pipeline().schedule().frame_count(); }

 private:
  sim::generate::GeneratorStream stream_;
};

/// What a dataset folder's list files are now (size and modification time of each, absent ones
/// too): a folder replaced (`generate --force`) or removed since it was opened differs.
std::vector<std::pair<std::int64_t, std::int64_t>> folder_state(const fs::path& folder) {
  std::vector<std::pair<std::int64_t, std::int64_t>> out;
  for (const char* name : {dataset::kManifest, dataset::kRgbList, dataset::kDepthList,
                           dataset::kGroundTruth, dataset::kWifi, dataset::kImu}) {
    std::error_code ec;
    const auto size = fs::file_size(folder / name, ec);
    const auto time = fs::last_write_time(folder / name, ec);
    out.emplace_back(ec ? -1 : static_cast<std::int64_t>(size),
                     ec ? -1 : static_cast<std::int64_t>(time.time_since_epoch().count()));
  }
  return out;
}

class DatasetSource final : public FrameSource {
 public:
  DatasetSource(const fs::path& folder, bool verify, bool load_images)
      : folder_(folder),
        state_(folder_state(folder)),
        reader_(folder, DatasetReaderOptions{verify, load_images, 4}) {
    if (fs::is_regular_file(folder / dataset::kGroundTruth)) {
      ground_truth_ = read_ground_truth(folder, verify);
      for (const StampedPose& p : ground_truth_) by_stamp_.emplace(p.time.ns, p.pose());
    }
  }
  SensorStream& stream() override { return reader_; }
  /// A dataset generated without images (`images=False`, `--no-images`) streams no frames: its
  /// frames are then its ground-truth stamps, which are the frame times the simulator used, so
  /// a Dataset of such a folder gives the frames a Simulator with images=False gives (poses,
  /// scans and odometry; rgb and depth None), ordered as every stream orders its events (at
  /// one stamp: odometry, then Wi-Fi, then the frame).
  std::optional<SensorEvent> next_event() override {
    if (!pose_only()) return reader_.next();
    if (!pending_ && !reader_done_) {
      pending_ = reader_.next();
      reader_done_ = !pending_;
    }
    const bool frame_left = next_pose_ < ground_truth_.size();
    if (pending_ && (!frame_left || event_time(*pending_) <= ground_truth_[next_pose_].time)) {
      std::optional<SensorEvent> event = std::move(pending_);
      pending_.reset();
      return event;
    }
    if (!frame_left) return std::nullopt;
    RgbdFrame frame;
    frame.index = static_cast<std::int64_t>(next_pose_);
    frame.time = ground_truth_[next_pose_++].time;
    return SensorEvent{std::move(frame)};
  }
  void rewind() override {
    reader_.rewind();
    pending_.reset();
    reader_done_ = false;
    next_pose_ = 0;
  }
  std::int64_t frame_count() const {
    return pose_only() ? static_cast<std::int64_t>(ground_truth_.size()) : reader_.frame_count();
  }
  void check_unchanged() const override {
    // A pass reads the files again; the frame count, ground truth and checks are those of the
    // folder as it was opened. One replaced or removed since would mix the two.
    if (folder_state(folder_) != state_) {
      throw InvalidInputError(
          folder_.string() +
          ": the dataset folder has changed since it was opened (replaced or removed); open it "
          "again: wifislam.Dataset(path)");
    }
  }
  /// The ground-truth pose at the frame's stamp: our datasets have one per frame; a plain TUM
  /// dataset's motion-capture stamps are not the frames', and its frames get None.
  std::optional<Pose> ground_truth(const RgbdFrame& frame) const override {
    const auto it = by_stamp_.find(frame.time.ns);
    if (it == by_stamp_.end()) return std::nullopt;
    return it->second;
  }
  DatasetReader& reader() { return reader_; }
  const Trajectory& ground_truth_trajectory() const { return ground_truth_; }
  /// imu.csv, read once when first asked for (a 200 Hz file is 10^5 rows and more; most uses
  /// never need it), from the folder as it was opened; none when the dataset has no IMU.
  const std::optional<std::vector<ImuReading>>& imu() {
    if (!imu_read_) {
      check_unchanged();  // opening checked the file's SHA-256 against the manifest
      if (fs::is_regular_file(folder_ / dataset::kImu))
        imu_ = read_imu_csv((folder_ / dataset::kImu).string());
      imu_read_ = true;
    }
    return imu_;
  }

 private:
  bool pose_only() const { return reader_.manifest() && !reader_.manifest()->images; }
  static Timestamp event_time(const SensorEvent& event) {
    return std::visit([](const auto& e) { return e.time; }, event);
  }

  fs::path folder_;
  std::vector<std::pair<std::int64_t, std::int64_t>> state_;
  DatasetReader reader_;
  Trajectory ground_truth_;
  std::map<std::int64_t, Pose> by_stamp_;
  std::optional<std::vector<ImuReading>> imu_;
  bool imu_read_ = false;
  // Pose-only datasets: the reader's next event, held while earlier frames go first.
  std::optional<SensorEvent> pending_;
  bool reader_done_ = false;
  std::size_t next_pose_ = 0;
};

py::dict intrinsics_dict(const CameraIntrinsics& k) {
  py::dict out;
  out["width_px"] = k.width_px;
  out["height_px"] = k.height_px;
  out["fx_px"] = k.fx_px;
  out["fy_px"] = k.fy_px;
  out["cx_px"] = k.cx_px;
  out["cy_px"] = k.cy_px;
  return out;
}

template <typename Source, typename Class>
void bind_stream_facts(Class& cls) {
  cls.def("begin_pass", &Source::begin_pass)
      .def("next_frame", &Source::next_frame, py::arg("pass"))
      .def_property_readonly("intrinsics",
                             [](Source& s) { return intrinsics_dict(s.stream().intrinsics()); })
      .def_property_readonly("camera_in_base",
                             [](Source& s) { return pose_array(s.stream().camera_in_base()); })
      .def_property_readonly("has_wifi", [](Source& s) { return s.stream().has_wifi(); })
      .def_property_readonly("has_odometry", [](Source& s) { return s.stream().has_odometry(); })
      .def_property_readonly("description", [](Source& s) { return s.stream().description(); });
}

}  // namespace

void bind_streams(py::module_& m) {
  py::class_<FrameSource>(m, "_FrameSource");
  auto simulator =
      py::class_<SimulatorSource, FrameSource>(m, "_Simulator")
          .def(py::init([](const sim::scene::Scene& scene, std::optional<std::uint64_t> seed,
                           std::optional<double> fps, std::int64_t max_frames, bool images) {
                 sim::generate::GenerateOptions options;
                 options.seed = seed;
                 options.fps = fps;
                 options.max_frames = max_frames;
                 options.camera = images ? sim::generate::CameraOutput::kColourAndDepth
                                         : sim::generate::CameraOutput::kNoImages;
                 py::gil_scoped_release release;  // builds the world and renderer
                 return std::make_unique<SimulatorSource>(scene, options);
               }),
               py::arg("scene"), py::arg("seed"), py::arg("fps"), py::arg("max_frames"),
               py::arg("images"))
          .def_property_readonly("frame_count", &SimulatorSource::frame_count)
          .def_property_readonly("scene", [](const SimulatorSource& s) {
            return std::make_shared<sim::scene::Scene>(s.scene());
          });
  bind_stream_facts<SimulatorSource>(simulator);

  auto dataset =
      py::class_<DatasetSource, FrameSource>(m, "_Dataset")
          .def(py::init([](const std::string& folder, bool verify, bool load_images) {
                 py::gil_scoped_release release;  // checks every file's SHA-256
                 return std::make_unique<DatasetSource>(folder, verify, load_images);
               }),
               py::arg("folder"), py::arg("verify"), py::arg("load_images"))
          .def_property_readonly("frame_count", [](DatasetSource& d) { return d.frame_count(); })
          .def_property_readonly("wifi_scan_count",
                                 [](DatasetSource& d) { return d.reader().wifi_scan_count(); })
          .def_property_readonly(
              "ground_truth",
              [](const DatasetSource& d) { return trajectory_array(d.ground_truth_trajectory()); })
          .def_property_readonly("imu",
                                 // With the GIL held: the first access reads the file into
                                 // the source, which threads may share.
                                 [](DatasetSource& d) -> py::object {
                                   const auto& imu = d.imu();
                                   return imu ? py::object(imu_array(*imu)) : py::none();
                                 })
          .def_property_readonly("imu_in_base", [](DatasetSource& d) -> py::object {
            const auto& imu = d.reader().calibration().imu;
            return imu ? py::object(pose_array(imu->imu_in_base)) : py::object(py::none());
          });
  bind_stream_facts<DatasetSource>(dataset);
}

}  // namespace wifislam::python
