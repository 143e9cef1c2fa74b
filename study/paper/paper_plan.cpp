#include "study/paper/paper_plan.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "sim/scene/scene_loader.hpp"
#include "study/paper/twin_scenes.hpp"

namespace wifislam::study::paper {

const std::vector<std::string>& twin_names() {
  static const std::vector<std::string> names = {"c_hall", "b_hall", "j_hall", "a_hall"};
  return names;
}

const char* twin_scene_yaml(const std::string& twin) {
  if (twin == "a_hall") return generated::kAHall;
  if (twin == "b_hall") return generated::kBHall;
  if (twin == "c_hall") return generated::kCHall;
  if (twin == "j_hall") return generated::kJHall;
  throw InvalidInputError(
      fmt::format("'{}' is not one of the paper's twins (c_hall, b_hall, j_hall, a_hall)", twin));
}

sim::scene::Scene twin_scene(const std::string& twin) {
  return sim::scene::load_scene_yaml(twin_scene_yaml(twin), "<" + twin + " twin>");
}

const std::vector<Experiment>& experiments() {
  static const std::vector<Experiment> all = {
      {Part::kRgbdslam,
       "rgbdslam",
       {"c_hall"},
       {{"min_matches", {"50", "70", "100", "150"}}, {"inlier_distance", {"2", "3", "4"}}}},
      {Part::kRtabmap,
       "rtabmap",
       {"c_hall", "b_hall", "j_hall", "a_hall"},
       {{"time_threshold_ms", {"inf", "70", "100", "200"}}}},
      {Part::kOrbslam,
       "orbslam",
       {"c_hall", "b_hall", "j_hall"},
       {{"min_matches", {"10", "15", "20", "50", "100"}}}},
      // The paper has no ORB-SLAM result on A Hall; one setting (ORB-SLAM2's 20) says whether
      // ours fails there too.
      {Part::kOrbslam, "orbslam", {"a_hall"}, {{"min_matches", {"20"}}}},
  };
  return all;
}

const std::vector<Part>& runnable_parts() {
  static const std::vector<Part> parts = {Part::kRgbdslam, Part::kRtabmap, Part::kOrbslam,
                                          Part::kFabmap};
  return parts;
}

std::string PlannedStudy::name() const {
  return fmt::format("{}-{}-seed{}", to_string(experiment->part), twin, seed);
}

std::vector<PlannedStudy> planned_studies(const std::vector<Part>& parts,
                                          const std::vector<std::string>& twins, int seeds) {
  std::vector<PlannedStudy> out;
  for (int k = 0; k < seeds; ++k) {
    for (const std::string& twin : twin_names()) {
      if (std::find(twins.begin(), twins.end(), twin) == twins.end()) continue;
      const std::uint64_t seed = twin_scene(twin).seed + static_cast<std::uint64_t>(k);
      for (const Experiment& e : experiments()) {
        if (std::find(parts.begin(), parts.end(), e.part) == parts.end()) continue;
        if (std::find(e.twins.begin(), e.twins.end(), twin) == e.twins.end()) continue;
        out.push_back({&e, twin, seed});
      }
    }
  }
  return out;
}

std::string study_file_text(const PlannedStudy& study, const PaperSettings& settings) {
  std::string axes;
  for (const auto& [key, values] : study.experiment->axes) {
    std::string list;
    for (const std::string& v : values) list += (list.empty() ? "" : ", ") + v;
    axes += fmt::format("  slam.{}: [{}]\n", key, list);
  }
  return fmt::format(
      "# Written by `wifislam paper`: its {part} experiment on the {twin} twin, seed {seed}.\n"
      "# `wifislam study run` or `study slurm` on this file gives the rows `paper` writes.\n"
      "version: 1\n"
      "name: {name}\n"
      "description: the paper's {part} experiment on {hall} (seed {seed})\n"
      "scene: ../scenes/{twin}.yaml\n"
      "level: slam\n"
      "set: {{seed: {seed}}}\n"
      "axes:\n"
      "{axes}"
      "slam: {{frontend: {frontend}, fps: {fps}}}\n",
      fmt::arg("part", to_string(study.experiment->part)), fmt::arg("twin", study.twin),
      fmt::arg("seed", study.seed), fmt::arg("name", study.name()),
      fmt::arg("hall", hall_name(study.twin)), fmt::arg("axes", axes),
      fmt::arg("frontend", study.experiment->frontend), fmt::arg("fps", settings.fps));
}

}  // namespace wifislam::study::paper
