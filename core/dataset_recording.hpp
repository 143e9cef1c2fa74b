#pragma once
// Which recording a dataset holds: the scene it was generated from, its seed and session, the
// camera's frame rate and the time origin, as manifest.json's "parameters" give them. Together
// they fix the ground truth's stamps and poses. A run folder keeps the recording of its input
// (run.json "input"."recording"), so `eval` can refuse to score a run against the ground truth of
// another recording: a run of seed 1001 scored against seed 1002's poses gives an error figure
// that measures nothing, and timestamps alone cannot tell (every seed has the same frame times).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/dataset_manifest.hpp"

namespace wifislam {

struct DatasetRecording {
  std::string scene;
  std::uint64_t seed = 0;
  std::optional<std::uint64_t> session;  // absent when the scene names none
  double fps = 0.0;
  std::uint64_t time_origin_s = 0;

  bool operator==(const DatasetRecording&) const = default;
};

/// The recording manifest.json's parameters name; nullopt when they lack any of scene, seed, fps
/// and time_origin_s (a manifest written by another tool or an older version).
std::optional<DatasetRecording> recording_of(const DatasetManifest& manifest);

/// As run.json keeps it: {"scene", "seed", ["session",] "fps", "time_origin_s"}, the keys and
/// order of manifest.json's parameters.
nlohmann::ordered_json recording_json(const DatasetRecording& recording);

/// recording_json's object back; ParseError naming `file` and `key` when it is malformed.
DatasetRecording recording_from_json(const nlohmann::json& j, const std::string& file,
                                     const std::string& key);

/// The recording of the dataset in `folder`, from its manifest.json; nullopt when the folder has
/// no manifest (a TUM folder, an unfinished dataset) or the manifest names no recording.
std::optional<DatasetRecording> recording_of_dataset(const std::filesystem::path& folder);

/// run.json's "input" for a run of the dataset at `path`: {"kind": "dataset", "path",
/// "recording"} (no "recording" when it is not known). The one place every run of a dataset
/// (`slam`, compare, studies, external systems) describes its input.
nlohmann::json dataset_run_input(const std::filesystem::path& path,
                                 const std::optional<DatasetRecording>& recording);

/// "scene c_hall, seed 1001, 3 fps, time origin 1700000000 s" (and the session when there is one).
std::string describe(const DatasetRecording& recording);

}  // namespace wifislam
