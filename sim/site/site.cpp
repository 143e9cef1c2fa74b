#include "sim/site/site.hpp"

#include "sim/radio/ap_placement.hpp"
#include "sim/radio/propagation_model.hpp"
#include "sim/robot/motion_profile.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/world/world_generator.hpp"

namespace wifislam {

Site::Site(const Scene& scene) : scene_(scene) {
  validate_scene(scene_);
  world_ = std::make_unique<World>(generate_world(scene_));
  motion_ = std::make_unique<MotionProfile>(
      world_->route, RobotMotionOptions::from_route(scene_.route), scene_.seed);
  radio_ = std::make_unique<PropagationModel>(*world_, make_access_points(scene_, world_->plan),
                                              PropagationOptions::from_scene(scene_),
                                              scene_.seed);
}

Site::~Site() = default;
Site::Site(Site&&) noexcept = default;
Site& Site::operator=(Site&&) noexcept = default;

const std::vector<AccessPoint>& Site::access_points() const { return radio_->access_points(); }

}  // namespace wifislam
