#include "sim/site/site.hpp"

#include "sim/radio/ap_placement.hpp"
#include "sim/radio/propagation_model.hpp"
#include "sim/robot/motion_profile.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/world_generator.hpp"

namespace wifislam::sim {

Site::Site(const Scene& scene) : scene_(scene) {
  validate_scene(scene_);
  world_ = std::make_unique<World>(generate_world(scene_));
  motion_ = std::make_unique<MotionProfile>(
      world_->route, RobotMotionOptions::from_route(scene_.route), scene_.seed);
  radio_ = std::make_unique<radio::PropagationModel>(
      *world_, radio::make_access_points(scene_, world_->plan),
      radio::PropagationOptions::from_scene(scene_), scene_.seed);
}

Site::~Site() = default;
Site::Site(Site&&) noexcept = default;
Site& Site::operator=(Site&&) noexcept = default;

const std::vector<radio::AccessPoint>& Site::access_points() const {
  return radio_->access_points();
}

}  // namespace wifislam::sim
