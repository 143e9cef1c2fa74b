#include "fuzz/fuzz_targets.hpp"

#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "core/dataset_reader.hpp"
#include "core/error.hpp"
#include "core/tum_file_list.hpp"
#include "core/tum_trajectory.hpp"
#include "core/yaml_document.hpp"
#include "fuzz/dataset_bundle.hpp"
#include "fuzz/scratch_folder.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/scene/scene_loader.hpp"
#include "study/study_file.hpp"
#include "study/study_runner.hpp"

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

void write_file(const fs::path& path, std::string_view bytes) {
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

fs::path write_input_file(std::string_view bytes, const std::string& name) {
  const fs::path path = fresh_scratch_folder() / name;
  write_file(path, bytes);
  return path;
}

// The study target's base scene, read once. A missing file is a broken build, not a finding of
// the input at hand, so it stops the run loudly.
const std::string& study_scene_text() {
  static const std::string text = [] {
    std::ifstream in(WIFISLAM_FUZZ_STUDY_SCENE, std::ios::binary);
    if (!in) throw std::runtime_error("fuzz: cannot read " WIFISLAM_FUZZ_STUDY_SCENE);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  }();
  return text;
}

// Whether a study file that loaded lists its cases (StudyFile does not keep that).
bool lists_cases(const std::string& text) {
  return static_cast<bool>(parse_yaml_document(text, "study.yaml")["cases"]);
}

// The invariants of a loaded study (study_file.hpp) that hold whatever the file says.
void check_study_cases(const study::StudyFile& s, bool listed) {
  check(!s.axes.empty() && !s.cases.empty(), "study: loaded without axes or cases");
  std::size_t product = 1;
  std::set<std::string> columns;
  for (const study::StudyAxis& axis : s.axes) {
    check(!axis.values.empty(), "study: axis " + axis.key + " has no values");
    check(
        std::set<std::string>(axis.values.begin(), axis.values.end()).size() == axis.values.size(),
        "study: axis " + axis.key + " repeats a value");
    check(columns.insert(study::column_name(axis.key)).second,
          "study: two axes share the column " + study::column_name(axis.key));
    // The loaded cases are indexed into the product, so it fits a size_t.
    product *= axis.values.size();
  }
  if (!listed) {
    check(s.cases.size() == product, "study: the cases are not the product of the axes");
  }
  check(s.cases.size() <= product, "study: more cases than the axes' product");
  std::set<std::string> ids;
  for (std::size_t i = 0; i < s.cases.size(); ++i) {
    const study::StudyCase& c = s.cases[i];
    check(c.values.size() == s.axes.size(), "study: case " + c.id + " misses axis values");
    check(c.index < product, "study: case " + c.id + " indexes past the product");
    check(listed || c.index == i, "study: case " + c.id + " is not at its product index");
    check(ids.insert(c.id).second, "study: two cases share the id " + c.id);
    check(c.id.rfind(fmt::format("{:05d}-", c.index), 0) == 0,
          "study: case id " + c.id + " does not start with its index");
    // Ids sort in study order (study_file.hpp).
    check(i == 0 || (s.cases[i - 1].index < c.index && s.cases[i - 1].id < c.id),
          "study: cases are not in study order: " + c.id);
    // The values are the product's entry at the index, the last axis varying fastest.
    std::size_t rest = c.index;
    for (std::size_t a = s.axes.size(); a-- > 0;) {
      const std::vector<std::string>& values = s.axes[a].values;
      check(c.values[a] == values[rest % values.size()],
            "study: case " + c.id + " has the wrong value for axis " + s.axes[a].key);
      rest /= values.size();
    }
  }
  // Shards partition the cases, each in order and at its index modulo the shard count.
  for (const int count : {1, 2, 3, 7}) {
    std::size_t seen = 0;
    for (int index = 0; index < count; ++index) {
      std::size_t previous = 0;
      bool first = true;
      for (const study::StudyCase& c : study::shard_cases(s, index, count)) {
        check(c.index % static_cast<std::size_t>(count) == static_cast<std::size_t>(index),
              fmt::format("study: case {} in shard {}/{}", c.id, index, count));
        check(first || previous < c.index, "study: a shard's cases are out of order");
        check(ids.count(c.id) == 1, "study: shard case " + c.id + " is not a case");
        previous = c.index;
        first = false;
        ++seen;
      }
    }
    check(seen == s.cases.size(),
          fmt::format("study: {} shards do not cover the cases once", count));
  }
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
    const sim::scene::Scene scene =
        sim::scene::load_scene_yaml(std::string(as_text(data, size)), "fuzz.yaml");
    const std::string resolved = sim::scene::resolved_scene_yaml(scene);
    check(sim::scene::resolved_scene_yaml(sim::scene::load_scene_yaml(resolved, "resolved.yaml")) ==
              resolved,
          "scene: resolved YAML does not load back to the same scene");
    sim::generate::GenerateOptions options;
    options.camera = sim::generate::CameraOutput::kNoImages;
    options.max_frames = kSceneFrameBudget;
    sim::generate::GenerationPipeline pipeline(scene, options);
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

void run_study(const std::uint8_t* data, std::size_t size) {
  const fs::path& folder = fresh_scratch_folder();
  const fs::path scene = folder / "scene.yaml";
  write_file(scene, study_scene_text());
  const std::string text(as_text(data, size));
  const fs::path path = folder / "study.yaml";
  write_file(path, text);
  refusing_with_our_errors([&] {
    const study::StudyFile s = study::load_study_file(path);
    check_study_cases(s, lists_cases(text));
    // Ids do not depend on where the file is.
    const study::StudyFile elsewhere = study::load_study_yaml(text, "elsewhere/other.yaml");
    check(elsewhere.cases.size() == s.cases.size(), "study: case count depends on the path");
    for (std::size_t i = 0; i < s.cases.size(); ++i) {
      check(elsewhere.cases[i].id == s.cases[i].id, "study: case ids depend on the path");
    }
    if (s.cases.size() > kStudyCheckedCases) return;
    // Only the scratch scene or a missing file: the runner caches a base scene per path for
    // the process, and another path could name any file on this machine (a FIFO would hang).
    std::error_code ec;
    if (s.scene_path != scene && fs::exists(s.scene_path, ec)) return;
    study::check_cases(s);
  });
}

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
      {"scene", &run_scene},
      {"dataset", &run_dataset},
      {"trajectory", &run_trajectory},
      {"study", &run_study},
  };
  return all;
}

}  // namespace wifislam::fuzz
