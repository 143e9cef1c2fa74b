#pragma once
// What SLAM (and vocabulary training, and localisation) reads: a dataset folder (ours or a plain
// TUM RGB-D one) or a scene file streamed straight from the simulation, behind one SensorStream.
// The one place that decides which a path is, refuses an unfinished dataset, and says what was
// opened in the run.json form.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "core/sensor_stream.hpp"

namespace wifislam::sim::generate {

struct SensorInputOptions {
  /// Datasets: check the files against manifest.json's SHA-256 sums (off also reads what an
  /// interrupted `generate` left).
  bool verify_checksums = true;
  /// Stop after this many frames (< 0: all), scene or dataset.
  std::int64_t max_frames = -1;
  /// Scene input only: frame rate and seed replacing the scene's.
  std::optional<double> fps;
  std::optional<std::uint64_t> scene_seed;
  /// Datasets have their frame rate and seed fixed: a caller whose fps or seed was asked for
  /// (slam) refuses them for a dataset rather than ignore them; one that uses them as defaults
  /// for scenes (vocab train) sets this false.
  bool refuse_scene_options_for_datasets = true;
};

struct SensorInput {
  std::unique_ptr<SensorStream> stream;
  bool is_scene = false;
  /// {"kind": "dataset" | "scene", "path", ...}: what run.json records as its input.
  nlohmann::json description;
};

/// Opens `path`: a folder is a dataset, a regular file a scene. Throws ParseError for --fps or
/// --seed given for a dataset, InvalidInputError for an unfinished dataset, IoError for a path
/// that is neither; the readers' and the scene loader's errors pass through.
SensorInput open_sensor_input(const std::filesystem::path& path, const SensorInputOptions& options);

}  // namespace wifislam::sim::generate
