#include "slam/system/run_summary.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/run_format.hpp"
#include "slam/system/slam_system.hpp"

namespace wifislam::slam::system {

RunSummary summarize(const SlamSystem& system, const std::string& input, double wall_s) {
  RunSummary s;
  s.input = input;
  s.frontend = system.front_end().name();
  s.wifi = system.front_end().wifi() != nullptr;
  const util::Instrumentation& inst = system.instrumentation();
  s.frames = inst.counter(counter::kFrames);
  s.keyframes = static_cast<std::int64_t>(system.graph().node_count());
  for (const graph::GraphEdge& e : system.graph().edges()) {
    switch (e.type) {
      case graph::EdgeType::kVisual:
        ++s.visual_edges;
        break;
      case graph::EdgeType::kLoop:
        ++s.loop_edges;
        break;
      case graph::EdgeType::kOdometry:
        ++s.odometry_edges;
        break;
      case graph::EdgeType::kWeak:
        ++s.weak_edges;
        break;
    }
  }
  s.tracking_failures = inst.counter(counter::kTrackingFailures);
  s.keyframes_after_tracking_loss = inst.counter(counter::kKeyframesAfterTrackingLoss);
  s.candidate_comparisons = inst.counter(counter::kCandidateComparisons);
  s.ransac_runs = inst.counter(counter::kRansacRuns);
  s.wall_s = wall_s;
  s.processing_s = inst.seconds(module::kTotal);
  for (const auto& [name, m] : inst.modules()) s.module_s[name] = m.total_s;
  s.final_optimisation = system.final_optimisation();
  return s;
}

std::string RunSummary::BriefReport() const {
  return fmt::format(
      "{}: {} frames, {} keyframes, {} loop closures, {:.1f} fps (pipeline), {:.1f} s wall",
      label(), frames, keyframes, loop_edges, pipeline_fps(), wall_s);
}

std::string RunSummary::FullReport() const {
  std::string out;
  out += fmt::format("SLAM run ({})\n", label());
  out += fmt::format("  input                  {}\n", input);
  out += fmt::format("  frames                 {}\n", frames);
  out += fmt::format("  keyframes              {}\n", keyframes);
  out += fmt::format("  edges                  {} visual, {} loop, {} odometry, {} weak\n",
                     visual_edges, loop_edges, odometry_edges, weak_edges);
  out += fmt::format("  tracking failures      {} ({} keyframes made after them)\n",
                     tracking_failures, keyframes_after_tracking_loss);
  out += fmt::format("  candidate comparisons  {}\n", candidate_comparisons);
  out += fmt::format("  RANSAC runs            {}\n", ransac_runs);
  out += fmt::format("  wall-clock             {:.3f} s ({:.1f} fps)\n", wall_s, wall_fps());
  out +=
      fmt::format("  pipeline               {:.3f} s ({:.1f} fps)\n", processing_s, pipeline_fps());
  out += "  time per module:\n";
  for (const auto& [name, seconds] : module_s) {
    if (name == "total") continue;
    out += fmt::format("    {:<24} {:9.3f} s  {:5.1f} %\n", name, seconds,
                       processing_s > 0 ? 100.0 * seconds / processing_s : 0.0);
  }
  if (final_optimisation.ran) {
    out += fmt::format("  final optimisation     {}\n", final_optimisation.brief);
  }
  return out;
}

nlohmann::json RunSummary::to_json() const {
  return {{"input", input},
          {run_folder::run_key::kFrontend, frontend},
          {run_folder::run_key::kWifi, wifi},
          {"frames", frames},
          {"keyframes", keyframes},
          {"edges",
           {{"visual", visual_edges},
            {"loop", loop_edges},
            {"odometry", odometry_edges},
            {"weak", weak_edges}}},
          {"tracking_failures", tracking_failures},
          {"keyframes_after_tracking_loss", keyframes_after_tracking_loss},
          {"candidate_comparisons", candidate_comparisons},
          {"ransac_runs", ransac_runs},
          {"final_optimisation",
           {{"ran", final_optimisation.ran},
            {"iterations", final_optimisation.iterations},
            {"initial_cost", final_optimisation.initial_cost},
            {"final_cost", final_optimisation.final_cost}}}};
}

}  // namespace wifislam::slam::system
