#include "tests/slam/frontend/rtabmap/rtabmap_test_nodes.hpp"

#include "tests/slam/wifi/synthetic_scans.hpp"

namespace wifislam::test {

namespace {

cv::Mat random_descriptor(Rng& rng) {
  cv::Mat row(1, 32, CV_8U);
  for (int b = 0; b < 32; ++b)
    row.at<std::uint8_t>(0, b) = static_cast<std::uint8_t>(rng.next_u64());
  return row;
}

}  // namespace

slam::feature::FrameFeatures place_features(int place, std::uint64_t seed, int flipped_bits) {
  slam::feature::FrameFeatures f;
  Rng own = Rng::stream(seed, "place/" + std::to_string(place));
  Rng pick = Rng::stream(seed, "pick/" + std::to_string(place));
  static thread_local std::vector<cv::Mat> pool;
  if (pool.empty()) {
    Rng shared = Rng::stream(seed, "shared");
    for (int i = 0; i < 60; ++i) pool.push_back(random_descriptor(shared));
  }
  for (int i = 0; i < 150; ++i) f.descriptors.push_back(random_descriptor(own));
  for (int i = 0; i < 50; ++i) {
    f.descriptors.push_back(pool[static_cast<std::size_t>(pick.uniform_int(0, 59))]);
  }
  // Sensor noise: a few bits flipped in every descriptor, different on every visit.
  static thread_local std::uint64_t visit = 0;
  Rng noise = Rng::stream(seed, "noise/" + std::to_string(++visit));
  for (int r = 0; r < f.descriptors.rows; ++r) {
    for (int k = 0; k < flipped_bits; ++k) {
      const auto bit = noise.uniform_int(0, 255);
      f.descriptors.at<std::uint8_t>(r, static_cast<int>(bit / 8)) ^=
          static_cast<std::uint8_t>(1u << (bit % 8));
    }
    f.keypoints.emplace_back(cv::Point2f(static_cast<float>(r), 0.f), 31.f, -1.f,
                             static_cast<float>(1000 - r));
  }
  return f;
}

RtabmapDriver::RtabmapDriver(slam::frontend::rtabmap::RtabmapOptions options, bool wifi)
    : rule_(/*min_keyframe_gap=*/15, /*min_path_m=*/0.0) {
  front_end_ = std::make_unique<slam::frontend::rtabmap::RtabmapFrontEnd>(
      options, slam::optimize::PoseGraphOptions{});
  if (wifi) {
    slam::wifi::WifiOptions w;
    w.enabled = true;
    front_end_->attach_wifi(std::make_unique<slam::wifi::WifiModule>(w, instrumentation_));
  }
}

std::vector<slam::frontend::Candidate> RtabmapDriver::select_only(int place,
                                                                  std::optional<double> x_m) {
  // Camera looking along +x (its optical axis z is the world's x).
  Pose pose = Pose::Identity();
  pose.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  pose.translation() =
      Eigen::Vector3d(x_m.value_or(0.5 * static_cast<double>(graph_.node_count())), 0.0, 0.0);
  const slam::graph::KeyframeId id =
      graph_.add_node(Timestamp::from_ns(graph_.node_count()),
                      static_cast<std::int64_t>(graph_.node_count()), pose);
  if (id > 0) graph_.add_edge({id - 1, id, slam::graph::EdgeType::kVisual});
  rule_.add_keyframe(static_cast<double>(id));
  features_ = place_features(place);
  slam::frontend::SelectionQuery q;
  q.keyframe = id;
  q.features = &features_;
  q.graph = &graph_;
  q.loop_rule = &rule_;
  if (id > 0) q.already_compared = {id - 1};
  pending_ = front_end_->candidates_for(q);
  return pending_;
}

void RtabmapDriver::finish_node() {
  slam::frontend::VerificationReport report;
  report.keyframe = last();
  report.tracked_from = last() - 1;
  for (const slam::frontend::Candidate& c : pending_)
    report.comparisons.push_back({c, false, false, 0, slam::graph::EdgeType::kVisual});
  front_end_->on_verified(report);
}

std::vector<slam::frontend::Candidate> RtabmapDriver::add_node(int place,
                                                               std::optional<double> x_m) {
  std::vector<slam::frontend::Candidate> out = select_only(place, x_m);
  finish_node();
  return out;
}

WifiScan scan_at(double start_s, const std::vector<std::pair<std::uint64_t, int>>& aps) {
  return slam::test::scan_of(start_s, aps);
}

}  // namespace wifislam::test
