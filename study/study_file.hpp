#pragma once
// A study file (studies/*.yaml): a base scene and the axes to sweep over scene keys and SLAM
// options; the cases are the product of the axes (or a listed subset), each with a stable id.
//
//   version: 1
//   name: ap_placement
//   description: ...                   # optional
//   scene: ../scenes/c_hall.yaml       # the base scene, relative to the study file
//   level: radio                       # radio (no rendering) or slam (vanilla and Wi-Fi runs)
//   set:                               # optional: scene keys for every case, before the axes
//     access_points.line_from_m: [2, 2]
//   axes:                              # in order; each key takes each of its values
//     access_points.count: [10, 20, 40, 70]
//     access_points.placement: [grid, random, rooms, colinear]
//     seed: [1001, 1002, 1003]
//   cases:                             # optional: only these combinations, instead of all
//     - {access_points.count: 10, access_points.placement: grid, seed: 1001}
//   slam: {frontend: rgbdslam, fps: 1, max_frames: -1, settings: {min_matches: 50}}
//
// Axis keys: a scene key path as scene files spell it ("radio.shadowing_sigma_db",
// "corridors[*].material" for every corridor; sim/scene/scene_keys.hpp), a SLAM option as
// "slam.<option>" ("slam.min_matches", "slam.wifi_similarity"; the keys of `wifislam slam --set`),
// or "frontend". An unknown key is a located error with "did you mean". Level radio reads only the
// Wi-Fi module's options (wifi_similarity, wifi_floor_dbm, wifi_pause_gap_s, wifi_pause_motion_m):
// any other SLAM option, and slam.frontend, fps or max_frames, is refused there. A value is any
// YAML scalar; scene values are checked when each case's scene is loaded (before any work runs).

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace wifislam::study {

enum class StudyLevel { kRadio, kSlam };
const char* to_string(StudyLevel level);

/// kFrontend: `frontend`, our front ends or "external:X"; kSystem: `system`, the same with the
/// "external:" optional (study/front_end_choice.hpp).
enum class AxisKind { kSceneKey, kSlamOption, kFrontend, kSystem };

struct StudyAxis {
  std::string key;  // as written in the file
  AxisKind kind = AxisKind::kSceneKey;
  std::vector<std::string> values;  // scalar texts, in file order
  std::string where;                // file:line:column of the key
};

/// One case: a value for every axis, in axis order.
struct StudyCase {
  std::vector<std::string> values;
  /// Stable id: the axis values, "key=value" joined with ";" in axis order, hashed (12 hex
  /// digits of SHA-256) and prefixed with the case's index in the full product, so ids sort in
  /// study order and never depend on shards, threads or which cases ran before.
  std::string id;
  std::size_t index = 0;
};

struct StudySlamSettings {
  std::string frontend = "rgbdslam";
  std::optional<double> fps;
  std::int64_t max_frames = -1;
  std::vector<std::string> settings;  // "key=value", applied before the axes
};

struct StudyFile {
  std::filesystem::path path;
  std::string name, description;
  std::filesystem::path scene_path;  // resolved against the study file's folder
  StudyLevel level = StudyLevel::kRadio;
  std::vector<StudyAxis> axes;
  std::vector<StudyCase> cases;  // the product, or the listed subset, in order
  /// Scene keys set for every case (key path, value as flow YAML), applied before the axes.
  std::vector<std::pair<std::string, std::string>> scene_set;
  StudySlamSettings slam;
  /// SHA-256 of the file's bytes: shards and merges refuse databases of another study file.
  std::string file_hash;
};

/// Reads and checks a study file. ParseError (file:line:column, key) for malformed YAML, a
/// missing or unknown key ("did you mean"), an empty axis, a listed case that misses an axis or
/// names a value the axis does not have, or a duplicate case.
StudyFile load_study_file(const std::filesystem::path& path);
StudyFile load_study_yaml(const std::string& text, const std::filesystem::path& path);

/// The front end a `frontend` or `system` axis value names, a system file given as a relative
/// path taken from the study file's folder (as `scene:` is): "system: [../sys/x.yaml]" means the
/// same file from any current directory. The value stays as written in ids and columns.
std::string axis_front_end(const StudyFile& study, AxisKind kind, const std::string& value);

/// Every file a study reads: the study file, its scene, the system files its `frontend` and
/// `system` axes name, and vocabulary files of its SLAM settings and axes. An output must not
/// replace or lie in any of them (core/output_folder.hpp).
std::vector<std::filesystem::path> input_files(const StudyFile& study);

/// Column-safe name of an axis key ("access_points.count" -> "access_points_count").
std::string column_name(const std::string& axis_key);

/// Cases of shard `index` of `count` (case index modulo count), in order.
std::vector<StudyCase> shard_cases(const StudyFile& study, int index, int count);

}  // namespace wifislam::study
