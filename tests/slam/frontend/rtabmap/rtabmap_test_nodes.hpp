#pragma once
// Synthetic RTAB-Map nodes for the front end's tests: each place is 150 random ORB descriptors of
// its own plus 50 drawn from a pool shared by every place (the wall and door texture any corridor
// repeats), so every node scores a little against every other and a revisited place scores much
// more. A revisit sees the place's own descriptors with a few bits flipped (sensor noise).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "slam/feature/frame_features.hpp"
#include "slam/frontend/rtabmap/rtabmap_front_end.hpp"

namespace wifislam::test {

/// Features of place `place` (32-byte ORB-like descriptors, keypoint responses decreasing).
slam::feature::FrameFeatures place_features(int place, std::uint64_t seed = 3,
                                            int flipped_bits = 3);

/// Drives an RtabmapFrontEnd over a chain of nodes the way the pipeline does: each node is a
/// keyframe tracked from the previous one (a visual edge), its candidates are "verified" (none
/// passes: these tests are about memory and hypotheses, not geometry), then on_verified.
class RtabmapDriver {
 public:
  explicit RtabmapDriver(slam::frontend::rtabmap::RtabmapOptions options = {}, bool wifi = false);

  /// Adds a node seeing `place`; returns its candidates. Node k stands at x = 0.5 k m (a straight
  /// corridor, looking along +x: no node comes back near an earlier one) unless `x_m` says where.
  std::vector<slam::frontend::Candidate> add_node(int place,
                                                  std::optional<double> x_m = std::nullopt);
  /// Adds a node and stops before verification (to look at the memory between the two).
  std::vector<slam::frontend::Candidate> select_only(int place,
                                                     std::optional<double> x_m = std::nullopt);
  void finish_node();

  slam::frontend::rtabmap::RtabmapFrontEnd& front_end() { return *front_end_; }
  slam::graph::KeyframeId last() const {
    return static_cast<slam::graph::KeyframeId>(graph_.node_count()) - 1;
  }

 private:
  slam::util::Instrumentation instrumentation_;
  slam::graph::PoseGraph graph_;
  slam::frontend::LoopRule rule_;
  std::unique_ptr<slam::frontend::rtabmap::RtabmapFrontEnd> front_end_;
  slam::feature::FrameFeatures features_;
  std::vector<slam::frontend::Candidate> pending_;
};

/// A one-second scan on channel 1 (tests/slam/wifi/synthetic_scans.hpp's scan_of).
WifiScan scan_at(double start_s, const std::vector<std::pair<std::uint64_t, int>>& aps);

}  // namespace wifislam::test
