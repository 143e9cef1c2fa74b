#include "fuzz/fuzz_targets.hpp"

#include <fstream>
#include <optional>
#include <string_view>

#include "core/dataset_reader.hpp"
#include "core/error.hpp"
#include "core/tum_file_list.hpp"
#include "core/tum_trajectory.hpp"
#include "fuzz/dataset_bundle.hpp"
#include "fuzz/scratch_folder.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/scene/scene_loader.hpp"

namespace wifislam::fuzz {
namespace {

namespace fs = std::filesystem;

std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

void check(bool holds, const std::string& what) {
  if (!holds) throw InvariantBroken(what);
}

// Runs `body`; wifislam's own errors are the accepted way to refuse an input (the CLI turns them
// into exit 2 or 3 with a located message). Everything else propagates to the fuzzer.
template <class Body>
void refusing_with_our_errors(Body&& body) {
  try {
    body();
  } catch (const Error&) {
  }
}

// Events the scene target pulls from the generator: a few seconds of the route is enough to run
// the schedule, odometry and scanner code on the fuzzed scene; the whole route would be slow.
constexpr int kSceneEventBudget = 400;

// The scene target's generator stops after this many frames (no images are rendered).
constexpr std::int64_t kSceneFrameBudget = 20;

bool same_pose(const StampedPose& a, const StampedPose& b) {
  return a.time == b.time && a.translation_m == b.translation_m &&
         a.rotation.coeffs() == b.rotation.coeffs();
}

fs::path write_input_file(std::string_view bytes, const std::string& name) {
  const fs::path path = fresh_scratch_folder() / name;
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path;
}

void read_every_event(const fs::path& folder, bool verify_checksums) {
  DatasetReaderOptions options;
  options.verify_checksums = verify_checksums;
  options.prefetch_frames = 0;  // decode on this thread: findings point at one stack
  DatasetReader reader(folder, options);
  (void)reader.description();
  std::int64_t frames = 0;
  while (auto event = reader.next()) {
    if (std::holds_alternative<RgbdFrame>(*event)) ++frames;
  }
  check(frames == reader.frame_count(), "dataset: frames streamed differ from frames counted");
}

}  // namespace

void run_scene(const std::uint8_t* data, std::size_t size) {
  refusing_with_our_errors([&] {
    const Scene scene = load_scene_yaml(std::string(as_text(data, size)), "fuzz.yaml");
    const std::string resolved = resolved_scene_yaml(scene);
    check(resolved_scene_yaml(load_scene_yaml(resolved, "resolved.yaml")) == resolved,
          "scene: resolved YAML does not load back to the same scene");
    GenerateOptions options;
    options.images = false;
    options.max_frames = kSceneFrameBudget;
    GenerationPipeline pipeline(scene, options);
    for (int i = 0; i < kSceneEventBudget && pipeline.next(); ++i) {
    }
  });
}

void run_dataset(const std::uint8_t* data, std::size_t size) {
  const fs::path& folder = fresh_scratch_folder();
  write_bundle_files(unpack_bundle(as_text(data, size)), folder);
  for (const bool verify : {true, false}) {
    refusing_with_our_errors([&] { read_every_event(folder, verify); });
    refusing_with_our_errors([&] { (void)read_ground_truth(folder, verify); });
  }
}

void run_trajectory(const std::uint8_t* data, std::size_t size) {
  const fs::path path = write_input_file(as_text(data, size), "trajectory.txt");
  std::optional<Trajectory> whole;
  refusing_with_our_errors([&] { whole = read_tum_trajectory(path.string()); });
  Trajectory streamed;
  bool stream_failed = false;
  try {
    TumTrajectoryReader reader(path.string());
    while (auto pose = reader.next()) streamed.push_back(*pose);
  } catch (const Error&) {
    stream_failed = true;
  }
  check(whole.has_value() == !stream_failed,
        "trajectory: the whole-file and streaming readers disagree on whether the file is valid");
  if (!whole) return;
  check(whole->size() == streamed.size(), "trajectory: the two readers read different counts");
  std::string written;
  for (std::size_t i = 0; i < streamed.size(); ++i) {
    check(same_pose((*whole)[i], streamed[i]), "trajectory: the two readers read different poses");
    written += format_tum_line(streamed[i]) + "\n";
  }
  // What we write reads back bit for bit (tum_trajectory.hpp).
  const fs::path again = write_input_file(written, "again.txt");
  const Trajectory back = read_tum_trajectory(again.string());
  check(back.size() == streamed.size(), "trajectory: written poses read back as a different count");
  for (std::size_t i = 0; i < back.size(); ++i) {
    check(same_pose(back[i], streamed[i]),
          "trajectory: a written pose does not read back bit for bit: " + format_tum_line(back[i]));
  }
}

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
      {"scene", &run_scene},
      {"dataset", &run_dataset},
      {"trajectory", &run_trajectory},
  };
  return all;
}

}  // namespace wifislam::fuzz
