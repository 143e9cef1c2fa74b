#include "interop/peer_export.hpp"

#include <cmath>
#include <map>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "core/dataset_format.hpp"
#include "core/dataset_reader.hpp"
#include "core/error.hpp"
#include "core/output_folder.hpp"
#include "core/shell_quoted.hpp"
#include "core/stop_signal.hpp"
#include "core/tum_file_list.hpp"
#include "interop/euroc_export.hpp"
#include "interop/kapture_export.hpp"
#include "interop/orbslam2_settings.hpp"
#include "interop/relative_link.hpp"
#include "interop/rosbag_export.hpp"
#include "interop/rtabmap_calibration.hpp"

namespace wifislam::interop {

namespace fs = std::filesystem;

namespace {

constexpr std::pair<Peer, const char*> kPeerNames[] = {{Peer::kRtabmap, "rtabmap"},
                                                       {Peer::kOrbslam2, "orbslam2"},
                                                       {Peer::kEuroc, "euroc"},
                                                       {Peer::kKapture, "kapture"},
                                                       {Peer::kRosbag, "rosbag"}};

}  // namespace

const char* to_string(Peer peer) {
  for (const auto& [p, name] : kPeerNames)
    if (p == peer) return name;
  return "?";
}

std::optional<Peer> peer_from_string(std::string_view name) {
  for (const auto& [p, text] : kPeerNames)
    if (name == text) return p;
  return std::nullopt;
}

std::vector<std::string> peer_names() {
  std::vector<std::string> names;
  for (const auto& [p, name] : kPeerNames) names.emplace_back(name);
  return names;
}

namespace {

/// One link of the export: `name` inside `dir`, to `source` (relative to the dataset folder).
struct Link {
  std::string dir, name, source;
  Timestamp stamp;
  std::string listed_at;  // where the stamp comes from, for messages
};

std::string image_name(Timestamp t) { return t.to_tum_string() + ".png"; }

std::string listed_at(const fs::path& dataset, const FramePair& p) {
  if (p.line > 0) return fmt::format("{}:{}", (dataset / dataset::kAssociations).string(), p.line);
  if (p.rgb_line > 0)
    return fmt::format("{}:{}", (dataset / dataset::kRgbList).string(), p.rgb_line);
  return dataset.string();
}

/// Adds `link` unless its dir/name is taken: by the same image (a depth map associated twice
/// links once), or by another, which two files of one name cannot be.
void add_link(std::vector<Link>& links, std::map<std::string, std::size_t>& by_name, Link link) {
  const std::string key = link.dir + "/" + link.name;
  const auto [it, fresh] = by_name.emplace(key, links.size());
  if (fresh) {
    links.push_back(std::move(link));
    return;
  }
  const Link& first = links[it->second];
  if (first.source == link.source) return;
  throw InvalidInputError(fmt::format(
      "{}: stamp {} names two images ({} and {}, first at {}); peers name frames by their stamps, "
      "so every frame needs a time of its own",
      link.listed_at, link.stamp.to_tum_string(), first.source, link.source, first.listed_at));
}

/// The TUM camera a plain TUM folder without calibration.yaml is from, by its name (as the TUM
/// sequences are named, e.g. rgbd_dataset_freiburg1_desk).
std::optional<TumCamera> camera_by_folder_name(const fs::path& folder) {
  const std::string name = folder.filename().string();
  for (const TumCamera& camera : tum_cameras()) {
    if (name.find(camera.name) != std::string::npos) return camera;
  }
  return std::nullopt;
}

void rtabmap_warnings(PeerExportSummary& s, const DatasetCalibration& calibration) {
  // The tool reads rtabmap_calib.yaml, which we write from the dataset's intrinsics, unless the
  // folder's name holds a TUM camera's name: then it writes that camera's calibration over ours.
  const std::string folder = s.output.filename().string();
  for (const TumCamera& camera : tum_cameras()) {
    if (folder.find(camera.name) == std::string::npos) continue;
    if (s.tum_camera && camera.name == std::string(s.tum_camera->name)) continue;
    s.warnings.push_back(fmt::format(
        "the folder's name '{}' says {}, so rtabmap-rgbd_dataset would replace {} with {}'s "
        "intrinsics ({}), not the dataset's ({}): use a name without 'freiburg1/2/3'",
        folder, camera.name, kRtabmapCalibration, camera.name,
        describe_intrinsics(camera.intrinsics), describe_intrinsics(s.intrinsics)));
  }
  if (calibration.depth_units_per_metre != dataset::kDepthUnitsPerMetre) {
    s.warnings.push_back(fmt::format(
        "the depth images hold {} units per metre; rtabmap-rgbd_dataset reads them as TUM's {}, "
        "so its depth will be scaled wrongly",
        calibration.depth_units_per_metre, dataset::kDepthUnitsPerMetre));
  }
}

nlohmann::ordered_json intrinsics_json(const CameraIntrinsics& k) {
  return {{"width_px", k.width_px}, {"height_px", k.height_px}, {"fx_px", k.fx_px},
          {"fy_px", k.fy_px},       {"cx_px", k.cx_px},         {"cy_px", k.cy_px}};
}

/// As the dataset reader refuses it (is_unfinished_dataset), with export's own hint.
void refuse_unfinished_dataset(const fs::path& dataset, const PeerExportOptions& options) {
  if (options.verify_checksums && is_unfinished_dataset(dataset)) {
    throw InvalidInputError(dataset.string() +
                            ": an unfinished dataset (no manifest.json: `wifislam generate` was "
                            "interrupted?); generate it again, or pass --no-verify to export what "
                            "is there");
  }
}

/// The calibration the peers will see, and which TUM camera it is (in `summary`). A plain TUM
/// folder has no calibration.yaml (the reader then assumes TUM's default 525 px), but its name
/// says which Kinect recorded it, as the peers read it; its frame rate is the one its frames
/// were taken at (the mean over `pairs`), not the 30 fps the reader assumes.
DatasetCalibration peer_calibration(const fs::path& dataset, const DatasetReader& reader,
                                    const std::vector<FramePair>& pairs,
                                    PeerExportSummary& summary) {
  std::error_code ec;
  DatasetCalibration calibration = reader.calibration();
  if (fs::exists(dataset / dataset::kCalibration, ec)) {
    summary.tum_camera = matching_tum_camera(calibration.intrinsics);
  } else {
    summary.tum_camera = camera_by_folder_name(dataset);
    if (summary.tum_camera) calibration.intrinsics = summary.tum_camera->intrinsics;
    const double span_s = pairs.back().rgb_time.seconds_since(pairs.front().rgb_time);
    if (pairs.size() >= 2 && span_s > 0) {
      const double fps = static_cast<double>(pairs.size() - 1) / span_s;
      calibration.camera_fps = std::round(fps * 1000.0) / 1000.0;
    }
  }
  summary.intrinsics = calibration.intrinsics;
  return calibration;
}

/// Every link of the export and, for ORB-SLAM2, its associations list.
struct ExportPlan {
  std::vector<Link> links;
  std::map<std::string, std::size_t> by_name;  // dir/name -> index in links
  std::string associations;
};

/// rtabmap-rgbd_dataset reads times from the file names and rejects a frame at time 0 or
/// before, and with it the sequence.
void require_positive_time(const FramePair& p, const std::string& at) {
  if (p.rgb_time.ns > 0) return;
  throw InvalidInputError(fmt::format(
      "{}: frame time {} is not a positive time; rtabmap-rgbd_dataset reads times from the "
      "file names and rejects such a frame and with it the sequence. This dataset starts at "
      "0 s (generated before datasets had a time origin): generate it again (scene key "
      "sensors.time_origin_s, by default {} s)",
      at, p.rgb_time.to_tum_string(), dataset::kDefaultTimeOriginS));
}

/// The links (and association line) of one frame pair.
void plan_frame(const fs::path& dataset, const FramePair& p, bool rtabmap, ExportPlan& plan) {
  const std::string at = listed_at(dataset, p);
  if (rtabmap) {
    require_positive_time(p, at);
    // Both folders under the rgb stamp: the tool pairs them by position in the sorted listing.
    add_link(plan.links, plan.by_name,
             {kRtabmapRgbDir, image_name(p.rgb_time), p.rgb_path, p.rgb_time, at});
    add_link(plan.links, plan.by_name,
             {kRtabmapDepthDir, image_name(p.rgb_time), p.depth_path, p.rgb_time, at});
    return;
  }
  const Link rgb{dataset::kRgbDir, image_name(p.rgb_time), p.rgb_path, p.rgb_time, at};
  const Link depth{dataset::kDepthDir, image_name(p.depth_time), p.depth_path, p.depth_time, at};
  plan.associations += format_association_line(
      {p.rgb_time, rgb.dir + "/" + rgb.name, p.depth_time, depth.dir + "/" + depth.name});
  add_link(plan.links, plan.by_name, rgb);
  add_link(plan.links, plan.by_name, depth);
}

/// Every link and list line, checked before anything is written.
ExportPlan plan_export(const fs::path& dataset, const std::vector<FramePair>& pairs, bool rtabmap) {
  ExportPlan plan;
  for (const FramePair& p : pairs) plan_frame(dataset, p, rtabmap, plan);
  return plan;
}

/// The image folders and their links in `staging`, and a link to the ground truth when the
/// dataset has one; returns whether it has.
bool write_links(const fs::path& dataset, const std::vector<Link>& links, bool rtabmap,
                 const fs::path& final_path, const fs::path& staging) {
  fs::create_directory(staging / (rtabmap ? kRtabmapRgbDir : dataset::kRgbDir));
  fs::create_directory(staging / (rtabmap ? kRtabmapDepthDir : dataset::kDepthDir));
  for (const Link& l : links) {
    link_relative(dataset / l.source, final_path / l.dir / l.name, staging / l.dir / l.name);
  }
  std::error_code ec;
  const bool has_ground_truth = fs::exists(dataset / dataset::kGroundTruth, ec);
  if (has_ground_truth) {
    link_relative(dataset / dataset::kGroundTruth, final_path / dataset::kGroundTruth,
                  staging / dataset::kGroundTruth);
  }
  return has_ground_truth;
}

/// The peer's own files (ORB-SLAM2: associations and settings; RTAB-Map: warnings about what
/// its reader will take from the folder) and the command that runs it.
void write_peer_files(const ExportPlan& plan, const DatasetCalibration& calibration, bool rtabmap,
                      const fs::path& staging, PeerExportSummary& summary) {
  const std::string dir = summary.output.string();
  if (rtabmap) {
    write_file_atomic(staging / kRtabmapCalibration,
                      rtabmap_calibration_yaml(calibration.intrinsics));
    rtabmap_warnings(summary, calibration);
    summary.run_command = fmt::format("rtabmap-rgbd_dataset {}", shell_word(dir));
    return;
  }
  write_file_atomic(staging / dataset::kAssociations, plan.associations);
  write_file_atomic(staging / kOrbslam2Settings, orbslam2_settings_yaml(calibration));
  summary.run_command =
      fmt::format("Examples/RGB-D/rgbd_tum Vocabulary/ORBvoc.txt {} {} {}",
                  shell_word((summary.output / kOrbslam2Settings).string()), shell_word(dir),
                  shell_word((summary.output / dataset::kAssociations).string()));
}

/// How the export holds the images: the bag carries their bytes, the other layouts link them.
const char* images_held(Peer peer) {
  return peer == Peer::kRosbag ? "in the bag: each image's bytes are a message"
                               : "relative symbolic links to the dataset's files";
}

nlohmann::ordered_json export_json(const PeerExportSummary& summary) {
  nlohmann::ordered_json j;
  j["format"] = kExportFormatName;
  j["format_version"] = kExportFormatVersion;
  j["peer"] = to_string(summary.peer);
  j["dataset"] = summary.dataset.string();
  j["links"] = images_held(summary.peer);
  j["frames"] = summary.frames;
  j["first_time"] = summary.first_time.to_tum_string();
  j["last_time"] = summary.last_time.to_tum_string();
  j["intrinsics"] = intrinsics_json(summary.intrinsics);
  j["tum_camera"] = summary.tum_camera ? nlohmann::ordered_json(summary.tum_camera->name)
                                       : nlohmann::ordered_json(nullptr);
  j["warnings"] = summary.warnings;
  j["run"] = summary.run_command;
  return j;
}

/// The EuRoC and Kapture layouts: everything read and checked first, then written atomically.
PeerExportSummary export_layout(const fs::path& dataset, const fs::path& output,
                                const PeerExportOptions& options,
                                const std::vector<FramePair>& pairs,
                                const DatasetCalibration& calibration, PeerExportSummary& summary) {
  const bool euroc = options.peer == Peer::kEuroc;
  const bool rosbag = options.peer == Peer::kRosbag;
  std::optional<EurocInput> euroc_input;
  std::optional<KaptureInput> kapture_input;
  if (euroc) {
    euroc_input = read_euroc_input(dataset, pairs, calibration);
  } else if (rosbag) {
    check_rosbag_input(dataset);
  } else {
    kapture_input = read_kapture_input(dataset, pairs, calibration);
  }
  AtomicDirectory folder(output, options.overwrite);
  summary.output = folder.final_path();
  const std::string dir = summary.output.string();
  if (rosbag) {
    // The bag carries the images' bytes (the other layouts link them): its reader checks each
    // PNG against images.sha256 as it decodes it, unless --no-verify.
    write_rosbag(dataset, calibration, folder.staging_path(), options.verify_checksums);
    summary.run_command =
        fmt::format("rosbag info {}", shell_word((summary.output / kBagFile).string()));
  } else if (euroc) {
    write_euroc(dataset, *euroc_input, summary.output, folder.staging_path());
    summary.run_command = fmt::format(
        "Examples/Monocular-Inertial/mono_inertial_euroc Vocabulary/ORBvoc.txt SETTINGS.yaml {} "
        "{} (SETTINGS: cam0's intrinsics and T_BS, imu0's noise; see "
        "docs/peers.md)",
        shell_word(dir), shell_word((summary.output / "timestamps.txt").string()));
  } else {
    write_kapture(dataset, *kapture_input, summary.output, folder.staging_path());
    if (kapture_input->scans.empty())
      summary.warnings.push_back(dataset.string() +
                                 " has no Wi-Fi scans: records_wifi.txt is empty");
    summary.run_command = fmt::format("kapture_print.py -i {}", shell_word(dir));
  }
  write_file_atomic(folder.staging_path() / kExportJson, export_json(summary).dump(2) + "\n");
  folder.commit();
  return summary;
}

}  // namespace

PeerExportSummary export_for_peer(const fs::path& dataset_path, const fs::path& output,
                                  const PeerExportOptions& options) {
  const fs::path dataset = resolve_path(dataset_path);
  refuse_unfinished_dataset(dataset, options);
  DatasetReaderOptions read;
  read.verify_checksums = options.verify_checksums;
  read.load_images = false;
  read.prefetch_frames = 0;
  // Checks the manifest, every list line and that every listed image exists.
  DatasetReader reader(dataset, read);
  if (reader.frame_count() == 0) {
    throw InvalidInputError(dataset.string() +
                            ": has no images to export (generated with --no-images?)");
  }
  // The links point at the dataset's images: check each against images.sha256 now, without
  // decoding it (the bag's writer checks each as it decodes it).
  if (options.verify_checksums && options.peer != Peer::kRosbag) {
    while (reader.next()) throw_if_stop_requested();  // `export`: Ctrl-C stops the check too
  }
  const std::vector<FramePair> pairs = read_frame_pairs(dataset);

  PeerExportSummary summary;
  summary.dataset = dataset;
  summary.peer = options.peer;
  summary.frames = static_cast<std::int64_t>(pairs.size());
  summary.first_time = pairs.front().rgb_time;
  summary.last_time = pairs.back().rgb_time;
  const DatasetCalibration calibration = peer_calibration(dataset, reader, pairs, summary);
  if (options.peer == Peer::kEuroc || options.peer == Peer::kKapture ||
      options.peer == Peer::kRosbag)
    return export_layout(dataset, output, options, pairs, calibration, summary);
  const bool rtabmap = options.peer == Peer::kRtabmap;
  const ExportPlan plan = plan_export(dataset, pairs, rtabmap);

  AtomicDirectory folder(output, options.overwrite);
  summary.output = folder.final_path();
  const fs::path staging = folder.staging_path();
  const bool has_ground_truth = write_links(dataset, plan.links, rtabmap, summary.output, staging);
  write_peer_files(plan, calibration, rtabmap, staging, summary);
  if (!has_ground_truth) {
    summary.warnings.push_back(dataset.string() +
                               " has no groundtruth.txt: the peer reports no trajectory error");
  }
  write_file_atomic(staging / kExportJson, export_json(summary).dump(2) + "\n");
  folder.commit();
  return summary;
}

std::string PeerExportSummary::full_report() const {
  std::string r;
  r += fmt::format("export       {} ({} layout)\n", output.string(), to_string(peer));
  r += fmt::format("dataset      {}\n", dataset.string());
  r += fmt::format("frames       {} (stamps {} .. {}), images {}\n", frames,
                   first_time.to_tum_string(), last_time.to_tum_string(),
                   peer == Peer::kRosbag ? "in the bag" : "linked, not copied");
  r += fmt::format("intrinsics   {}\n", describe_intrinsics(intrinsics));
  r += fmt::format(
      "TUM camera   {}\n",
      tum_camera
          ? fmt::format("{} ({})", tum_camera->name, describe_intrinsics(tum_camera->intrinsics))
      : peer == Peer::kOrbslam2 ? std::string("none matches (the settings carry the dataset's own "
                                              "intrinsics)")
                                : std::string("none matches"));
  r += fmt::format("run          {}\n", run_command);
  return r;
}

}  // namespace wifislam::interop
