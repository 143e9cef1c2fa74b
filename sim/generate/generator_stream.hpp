#pragma once
// The in-memory SensorStream: frames, scans and odometry straight from the simulation, no disk
// (the fast path for sweeps). It gives SLAM exactly what reading the dataset written with the
// same scene and options would (sim/generate/as_stored.hpp: depth at the PNG's resolution,
// odometry rotations rebuilt from their stored quaternions). Frames carry no file paths.

#include <memory>

#include "core/sensor_stream.hpp"
#include "core/sensor_stream_fanout.hpp"
#include "sim/generate/generate_options.hpp"
#include "sim/scene/scene.hpp"
#include "sim/site/site.hpp"

namespace wifislam::sim::generate {

class GenerationPipeline;

class GeneratorStream final : public SensorStream {
 public:
  /// Builds the world, renderer and radio model (seconds for big scenes). The seed and fps
  /// overrides, max_frames and images of `options` apply; threads/overwrite do not.
  GeneratorStream(const scene::Scene& scene, const GenerateOptions& options = {});
  /// On a site built already (its scene used as given: the overrides belong in it).
  GeneratorStream(std::shared_ptr<const site::Site> site, const GenerateOptions& options = {});
  ~GeneratorStream() override;

  std::optional<SensorEvent> next() override;
  const CameraIntrinsics& intrinsics() const override;
  Pose camera_in_base() const override;
  /// False for a scene without access points: no scan can hear anything (as in a dataset whose
  /// wifi.csv holds no scan), so the Wi-Fi variant refuses it and vanilla runs.
  bool has_wifi() const override;
  bool has_odometry() const override { return true; }
  std::string description() const override;

  /// Starts the stream again from the first event: a new simulation on the same site (the world
  /// and radio are not built again), which gives the same events again.
  void rewind();

  /// The simulation behind the stream (ground truth, world, radio) for tests and evaluation.
  const GenerationPipeline& pipeline() const { return *pipeline_; }
  /// Ground truth of the last frame returned by next().
  const Pose& last_frame_ground_truth() const { return last_ground_truth_; }

 private:
  std::unique_ptr<GenerationPipeline> pipeline_;
  GenerateOptions options_;  // the pipeline's, without the overrides its site holds already
  Pose last_ground_truth_ = Pose::Identity();
};

/// What a stream of `site`'s events says of itself (camera, mount, Wi-Fi, odometry), as a
/// GeneratorStream on it would; for streams fed from a dataset's generation (on_event).
SensorStreamFacts generated_stream_facts(const site::Site& site, const std::string& description);

}  // namespace wifislam::sim::generate
