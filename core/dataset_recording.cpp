#include "core/dataset_recording.hpp"

#include <fmt/format.h>

#include "core/dataset_format.hpp"
#include "core/error.hpp"
#include "core/input_file.hpp"

namespace wifislam {

namespace {

// manifest.json's parameter names (sim/generate/dataset_writer.cpp writes them from a recording).
constexpr const char* kScene = "scene";
constexpr const char* kSeed = "seed";
constexpr const char* kSession = "session";
constexpr const char* kFps = "fps";
constexpr const char* kTimeOrigin = "time_origin_s";

/// The recording in `j`, or the name of the first key that is missing or of the wrong type.
std::optional<DatasetRecording> parse(const nlohmann::json& j, std::string& bad_key) {
  const auto has = [&](const char* key, bool (nlohmann::json::*is)() const noexcept) {
    if (j.contains(key) && (j[key].*is)()) return true;
    bad_key = key;
    return false;
  };
  if (!j.is_object()) return std::nullopt;
  if (!has(kScene, &nlohmann::json::is_string) ||
      !has(kSeed, &nlohmann::json::is_number_unsigned) || !has(kFps, &nlohmann::json::is_number) ||
      !has(kTimeOrigin, &nlohmann::json::is_number_unsigned))
    return std::nullopt;
  DatasetRecording r;
  r.scene = j[kScene].get<std::string>();
  r.seed = j[kSeed].get<std::uint64_t>();
  r.fps = j[kFps].get<double>();
  r.time_origin_s = j[kTimeOrigin].get<std::uint64_t>();
  if (j.contains(kSession)) {
    if (!j[kSession].is_number_unsigned()) {
      bad_key = kSession;
      return std::nullopt;
    }
    r.session = j[kSession].get<std::uint64_t>();
  }
  return r;
}

}  // namespace

std::optional<DatasetRecording> recording_of(const DatasetManifest& manifest) {
  nlohmann::json parameters;
  try {
    parameters = nlohmann::json::parse(manifest.parameters_json);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
  std::string bad_key;
  return parse(parameters, bad_key);
}

nlohmann::ordered_json recording_json(const DatasetRecording& recording) {
  nlohmann::ordered_json j;
  j[kScene] = recording.scene;
  j[kSeed] = recording.seed;
  if (recording.session) j[kSession] = *recording.session;
  j[kFps] = recording.fps;
  j[kTimeOrigin] = recording.time_origin_s;
  return j;
}

DatasetRecording recording_from_json(const nlohmann::json& j, const std::string& file,
                                     const std::string& key) {
  if (!j.is_object()) throw ParseError(file, key, "expected an object");
  std::string bad_key;
  const std::optional<DatasetRecording> r = parse(j, bad_key);
  if (!r) {
    throw ParseError(file, key + "." + bad_key,
                     bad_key == kScene ? "expected a string"
                     : bad_key == kFps ? "expected a number"
                                       : "expected a whole number >= 0");
  }
  return *r;
}

std::optional<DatasetRecording> recording_of_dataset(const std::filesystem::path& folder) {
  const std::filesystem::path manifest = folder / dataset::kManifest;
  if (!input_file_present(manifest, "the dataset's manifest")) return std::nullopt;
  return recording_of(read_dataset_manifest(manifest));
}

nlohmann::json dataset_run_input(const std::filesystem::path& path,
                                 const std::optional<DatasetRecording>& recording) {
  nlohmann::json input = {{"kind", "dataset"}, {"path", path.string()}};
  if (recording) input["recording"] = recording_json(*recording);
  return input;
}

std::string describe(const DatasetRecording& recording) {
  return fmt::format("scene {}, seed {}{}, {} fps, time origin {} s", recording.scene,
                     recording.seed,
                     recording.session ? fmt::format(", session {}", *recording.session) : "",
                     recording.fps, recording.time_origin_s);
}

}  // namespace wifislam
