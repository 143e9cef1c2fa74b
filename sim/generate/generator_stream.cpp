#include "sim/generate/generator_stream.hpp"

#include <fmt/format.h>

#include "sim/generate/as_stored.hpp"
#include "sim/generate/generation_pipeline.hpp"
#include "sim/render/depth_png.hpp"
#include "sim/robot/camera_mount.hpp"

namespace wifislam::sim::generate {

namespace {

/// `options` for a pipeline on a site whose scene has the seed and fps overrides applied.
GenerateOptions without_overrides(GenerateOptions options) {
  options.seed.reset();
  options.fps.reset();
  return options;
}

}  // namespace

GeneratorStream::GeneratorStream(const scene::Scene& scene, const GenerateOptions& options)
    : pipeline_(std::make_unique<GenerationPipeline>(resolve_scene(scene, options), options)),
      options_(without_overrides(options)) {}

GeneratorStream::GeneratorStream(std::shared_ptr<const site::Site> site,
                                 const GenerateOptions& options)
    : pipeline_(std::make_unique<GenerationPipeline>(std::move(site), options)),
      options_(options) {}

GeneratorStream::~GeneratorStream() = default;

void GeneratorStream::rewind() {
  pipeline_ = std::make_unique<GenerationPipeline>(pipeline_->shared_site(), options_);
  last_ground_truth_ = Pose::Identity();
}

bool GeneratorStream::has_wifi() const { return !pipeline_->radio().access_points().empty(); }

std::optional<SensorEvent> GeneratorStream::next() {
  auto generated = pipeline_->next();
  if (!generated) return std::nullopt;
  if (auto* frame = std::get_if<RgbdFrame>(&generated->event)) {
    last_ground_truth_ = generated->camera_to_world;
    if (!frame->depth_m.empty())
      frame->depth_m = depth_as_stored(depth_to_png_units(frame->depth_m));
  } else if (const auto* reading = std::get_if<OdometryReading>(&generated->event)) {
    return odometry_as_stored(*reading);
  }
  return std::move(generated->event);
}

const CameraIntrinsics& GeneratorStream::intrinsics() const {
  return pipeline_->scene().sensors.camera.intrinsics;
}

Pose GeneratorStream::camera_in_base() const { return pipeline_->mount().camera_in_base(); }

std::string GeneratorStream::description() const {
  const scene::Scene& s = pipeline_->scene();
  return fmt::format("generated scene {} (seed {}, {} frames at {} fps{}, {} Wi-Fi scans)", s.name,
                     s.seed, pipeline_->schedule().frame_count(), s.sensors.camera.fps,
                     pipeline_->images() ? "" : ", no images",
                     pipeline_->schedule().scans().size());
}

SensorStreamFacts generated_stream_facts(const site::Site& site, const std::string& description) {
  const scene::Scene& scene = site.scene();
  return {scene.sensors.camera.intrinsics,
          robot::CameraMount(scene.sensors.camera).camera_in_base(),
          !site.radio().access_points().empty(), /*has_odometry=*/true, description};
}

}  // namespace wifislam::sim::generate
