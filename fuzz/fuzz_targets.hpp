#pragma once
// The fuzz targets: one function per input the tool parses, shared by the libFuzzer drivers
// (fuzz/drivers, built by the `fuzz` preset; scripts/fuzz.sh) and the release suite's replay of
// the committed corpus and crash reproducers (tests/fuzz). Each takes arbitrary bytes and feeds
// them through the code the command line runs on that input. Returning normally means the input
// was accepted or refused with one of wifislam's own errors (what the CLI prints as a located
// message with exit 2 or 3). Anything else is a finding: another exception escaping, a broken
// round-trip invariant (InvariantBroken), a sanitizer report, a crash or a hang.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace wifislam::fuzz {

/// A property the target checks on accepted input did not hold (e.g. a scene's resolved YAML does
/// not load back to itself). Deliberately not a wifislam::Error, so it escapes like a crash.
class InvariantBroken : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

using TargetFunction = void (*)(const std::uint8_t* data, std::size_t size);

struct Target {
  std::string name;  // folder name under fuzz/corpus and fuzz/crashes, driver `<name>_fuzzer`
  TargetFunction run;
};

/// Every target, in a fixed order.
const std::vector<Target>& targets();

/// A scene file's text: load it as `wifislam world` and `generate` do; when it loads, check that
/// its resolved YAML loads back to the same scene, then build the world, the route's motion, the
/// access points, the radio model and the sensor schedule, and pull a few seconds of odometry and
/// Wi-Fi scans from the in-memory generator (no rendering).
void run_scene(const std::uint8_t* data, std::size_t size);

/// A dataset folder packed into one input (fuzz/dataset_bundle.hpp): unpacked into a scratch
/// folder and read as `slam` and `eval` read a dataset (every event with its images, with and
/// without checksum verification, and the ground truth).
void run_dataset(const std::uint8_t* data, std::size_t size);

/// A TUM trajectory file (`eval`'s RUN/trajectory.txt, groundtruth.txt, odometry.txt): read whole
/// and streamed, which must agree pose for pose and fail on the same inputs.
void run_trajectory(const std::uint8_t* data, std::size_t size);

/// A study file's text (study/study_file.hpp), written as study.yaml into a scratch folder
/// beside scene.yaml, a copy of fuzz/seed_dataset_scene.yaml, so `scene: scene.yaml` resolves.
/// Loaded as `wifislam study` loads it; when it loads, the cases must be the axes' product (or a
/// listed subset of it) with unique ids in study order that do not depend on the file's path,
/// and shards must partition them. Studies of at most kStudyCheckedCases cases whose scene is the
/// scratch copy (or a missing file) then have every case's scene and options checked
/// (check_cases).
void run_study(const std::uint8_t* data, std::size_t size);

/// The study target runs check_cases, which loads one scene per case, only up to this many cases:
/// one input stays well under a second under the sanitizers.
inline constexpr std::size_t kStudyCheckedCases = 12;

}  // namespace wifislam::fuzz
