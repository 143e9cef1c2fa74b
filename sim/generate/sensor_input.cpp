#include "sim/generate/sensor_input.hpp"

#include <fmt/format.h>

#include "core/dataset_format.hpp"
#include "core/dataset_reader.hpp"
#include "core/dataset_recording.hpp"
#include "core/error.hpp"
#include "core/frame_limited_stream.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/generate/generator_stream.hpp"
#include "sim/scene/scene_loader.hpp"

namespace wifislam::sim::generate {

namespace {

namespace fs = std::filesystem;

SensorInput open_dataset(const fs::path& input, const SensorInputOptions& options) {
  // A dataset's frame rate and noise are fixed when it is generated: say so rather than ignore
  // the options.
  if (options.refuse_scene_options_for_datasets && options.fps) {
    throw InvalidInputError(fmt::format(
        "--fps {}: applies to scene input only; a dataset's frame rate is fixed (generate it "
        "again with `wifislam generate --fps`)",
        *options.fps));
  }
  if (options.refuse_scene_options_for_datasets && options.scene_seed) {
    throw InvalidInputError(fmt::format(
        "--seed {}: applies to scene input only; a dataset was rendered with its scene's seed "
        "(for SLAM's own draws use --set seed=N)",
        *options.scene_seed));
  }
  // An unfinished dataset (an interrupted `generate`) is the reader's refusal, as for `check`.
  DatasetReaderOptions reader_options;
  reader_options.verify_checksums = options.verify_checksums;
  SensorInput out;
  check_max_frames(options.max_frames);
  auto reader = std::make_unique<DatasetReader>(input, reader_options);
  out.description = dataset_run_input(
      input, reader->manifest() ? recording_of(*reader->manifest()) : std::nullopt);
  out.description["max_frames"] = options.max_frames;
  // Every reader of this input works on the frames (SLAM, a vocabulary, localisation): a dataset
  // of poses, odometry and Wi-Fi only gave an empty run and exit 0.
  if (reader->frame_count() == 0) {
    throw InvalidInputError(input.string() +
                            ": has no images (generated with --no-images?); this command works on "
                            "its RGB-D frames");
  }
  out.stream = std::move(reader);
  if (options.max_frames >= 0) {
    out.stream = std::make_unique<FrameLimitedStream>(std::move(out.stream), options.max_frames);
  }
  return out;
}

SensorInput open_scene(const fs::path& input, const SensorInputOptions& options) {
  const scene::Scene scene = scene::load_scene_file(input.string());
  GenerateOptions generate;
  generate.seed = options.scene_seed;
  generate.fps = options.fps;
  generate.max_frames = options.max_frames;
  SensorInput out;
  out.is_scene = true;
  auto stream = std::make_unique<GeneratorStream>(scene, generate);
  // The recording of the scene as the stream resolved it (seed and fps overrides applied).
  out.description = {{"kind", "scene"},
                     {"path", input.string()},
                     {"scene", scene.name},
                     {"scene_seed", generate.seed.value_or(scene.seed)},
                     {"fps", generate.fps.value_or(scene.sensors.camera.fps)},
                     {"max_frames", options.max_frames},
                     {"recording", recording_json(recording_of_scene(stream->pipeline().scene()))}};
  out.stream = std::move(stream);
  return out;
}

}  // namespace

SensorInput open_sensor_input(const fs::path& path, const SensorInputOptions& options) {
  if (fs::is_directory(path)) return open_dataset(path, options);
  if (!fs::is_regular_file(path)) {
    throw IoError(path.string() + ": neither a dataset folder nor a scene file");
  }
  return open_scene(path, options);
}

}  // namespace wifislam::sim::generate
