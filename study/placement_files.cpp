#include "study/placement_files.hpp"

#include <fmt/format.h>

#include "core/atomic_file.hpp"

namespace wifislam::study {

namespace {

std::string optional_m(const std::optional<double>& v) {
  return v ? fmt::format("{:.3f}", *v) : std::string();
}

std::string metres(const std::optional<double>& v) {
  return v ? fmt::format("{:.1f} m", *v) : std::string("none");
}

std::string placement_csv(const PlacementResult& result) {
  std::string csv =
      "count,x_m,y_m,z_m,error,resolution_m,near_similar_share,far_similar_share,"
      "aps_heard_per_pause,random_error,random_resolution_m,random_near_similar_share,"
      "random_far_similar_share\n";
  for (const PlacementStep& step : result.steps) {
    const Eigen::Vector3d& p = result.candidates[static_cast<std::size_t>(step.candidate)];
    csv += fmt::format(
        "{},{:.2f},{:.2f},{:.2f},{:.4f},{},{:.4f},{:.4f},{:.2f},{:.4f},{},{:.4f},{:.4f}\n",
        step.count, p.x(), p.y(), p.z(), step.greedy_error, optional_m(step.greedy.resolution_m),
        step.greedy.near_similar_share, step.greedy.far_similar_share,
        step.greedy.aps_heard_per_pause, step.random_error, optional_m(step.random_resolution_m),
        step.random_near_similar_share, step.random_far_similar_share);
  }
  return csv;
}

std::string access_points_yaml(const PlacementResult& result, const PlacementOptions& options,
                               const std::string& scene_path) {
  std::string yaml = fmt::format(
      "# {} access points placed greedily on {} by `wifislam study place` (candidates every {} "
      "m,\n# wifi_similarity {}); paste into the scene in place of its access_points block.\n"
      "access_points:\n  placement: explicit\n  list:\n",
      result.steps.size(), scene_path, options.candidate_spacing_m, options.wifi.similarity);
  for (const PlacementStep& step : result.steps) {
    const Eigen::Vector3d& p = result.candidates[static_cast<std::size_t>(step.candidate)];
    yaml += fmt::format("    - {{position_m: [{:.2f}, {:.2f}, {:.2f}]{}}}\n", p.x(), p.y(), p.z(),
                        result.level.empty() ? "" : ", level: " + result.level);
  }
  return yaml;
}

}  // namespace

void write_placement_files(const PlacementResult& result, const PlacementOptions& options,
                           const std::string& scene_path, const std::string& scene_name,
                           const std::filesystem::path& folder) {
  write_file_atomic(folder / "placement.csv", placement_csv(result));
  write_file_atomic(folder / "access_points.yaml", access_points_yaml(result, options, scene_path));
  plot_placement(result, scene_name, folder);
}

std::string placement_table(const PlacementResult& result) {
  std::string out = fmt::format("{:>5}  {:>16}  {:>7}  {:>10}  {:>6}  {:>6}  {:>12}  {:>12}\n",
                                "APs", "added at (x, y)", "error", "resolution", "near", "far",
                                "random error", "random res.");
  for (const PlacementStep& step : result.steps) {
    const Eigen::Vector3d& p = result.candidates[static_cast<std::size_t>(step.candidate)];
    out += fmt::format("{:>5}  {:>16}  {:>7.3f}  {:>10}  {:>6.3f}  {:>6.3f}  {:>12.3f}  {:>12}\n",
                       step.count, fmt::format("({:.1f}, {:.1f})", p.x(), p.y()), step.greedy_error,
                       metres(step.greedy.resolution_m), step.greedy.near_similar_share,
                       step.greedy.far_similar_share, step.random_error,
                       metres(step.random_resolution_m));
  }
  out += fmt::format(
      "the scene's own {} access points: error {:.3f}, resolution {}, near {:.3f}, far {:.3f}\n",
      result.scene_access_points, placement_error(result.scene_own),
      metres(result.scene_own.resolution_m), result.scene_own.near_similar_share,
      result.scene_own.far_similar_share);
  return out;
}

}  // namespace wifislam::study
