#pragma once
// What `wifislam paper` runs: the paper's experiments ("Evaluation") on the four twins, each a
// study (study/study_file.hpp) of one front end, twin and seed, so that a study database holds
// its runs (resumable, shardable, `wifislam study slurm` on any of them).
//
//   rgbdslam  C Hall: min_matches {50, 70, 100, 150} x inlier_distance {2, 3, 4}. The paper's
//             3 x 4 figure names neither set; these hold the values it does name (the table's 50
//             and 70, the bad maps' 100 and 150 at inlier distance 2) around our default 3 px.
//   rtabmap   the four twins x time_threshold_ms {inf, 70, 100, 200} (the paper's tables).
//   orbslam   B, C and J Hall x min_matches {10, 15, 20, 50, 100} (the paper's tables), and A Hall
//             at ORB-SLAM2's 20 alone: the paper got no result there ("very low number of
//             features"), and the report says whether ours does.
//   fabmap    the four twins: `localize`'s three methods (study/localisation_methods.hpp).
//
// Seeds: each twin's own seed, then seed + 1, ... (as `compare --seeds`).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sim/scene/scene.hpp"
#include "study/paper/paper_numbers.hpp"

namespace wifislam::study::paper {

/// The twins, in the paper's order of its datasets section (C, B, J, A).
const std::vector<std::string>& twin_names();
/// A twin's scene file as built into this program (scenes/<twin>.yaml at build time); throws
/// InvalidInputError naming the known twins otherwise.
const char* twin_scene_yaml(const std::string& twin);
sim::scene::Scene twin_scene(const std::string& twin);

/// One of the paper's SLAM experiments.
struct Experiment {
  Part part = Part::kRgbdslam;
  std::string frontend;
  std::vector<std::string> twins;
  /// Swept SLAM options (key, values), the first varying slowest.
  std::vector<std::pair<std::string, std::vector<std::string>>> axes;
};
/// rgbdslam, rtabmap, orbslam on B/C/J, orbslam on A (above).
const std::vector<Experiment>& experiments();
/// The parts `wifislam paper --parts` takes: rgbdslam, rtabmap, orbslam, fabmap.
const std::vector<Part>& runnable_parts();

/// What a paper folder is made with: its identity (a rerun with another must use another folder).
struct PaperSettings {
  double fps = 3.0;
  friend bool operator==(const PaperSettings&, const PaperSettings&) = default;
};

/// One study of the plan: its experiment, twin and seed.
struct PlannedStudy {
  const Experiment* experiment = nullptr;
  std::string twin;
  std::uint64_t seed = 0;
  /// "rtabmap-c_hall-seed1001": the study's name, and its file's and database's stem.
  std::string name() const;
};

/// The studies of `parts` on `twins` for the first `seeds` seeds, grouped by twin and seed (the
/// runs of one group share one rendering), in the order they run: seed by seed, twin by twin.
std::vector<PlannedStudy> planned_studies(const std::vector<Part>& parts,
                                          const std::vector<std::string>& twins, int seeds);

/// The study file of a planned study (YAML; its scene relative to a `studies/` folder beside
/// `scenes/`).
std::string study_file_text(const PlannedStudy& study, const PaperSettings& settings);

}  // namespace wifislam::study::paper
