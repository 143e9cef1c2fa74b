#include "sim/site/site.hpp"

#include "radio_model/propagation_model.hpp"
#include "sim/robot/motion_profile.hpp"
#include "sim/scene/scene_loader.hpp"
#include "sim/site/ap_placement.hpp"
#include "sim/site/radio_options.hpp"
#include "sim/world/radio_wall_mesh.hpp"
#include "sim/world/world_generator.hpp"

namespace wifislam::sim::site {

namespace {

std::unique_ptr<radio_model::PropagationModel> make_radio(const scene::Scene& scene,
                                                          const world::World& world) {
  Eigen::Vector2d bounds_min_m, bounds_max_m;
  world::building_bounds(world, bounds_min_m, bounds_max_m);
  return std::make_unique<radio_model::PropagationModel>(
      world::radio_wall_mesh(world), bounds_min_m, bounds_max_m, make_access_points(scene, world),
      propagation_options(scene), scene.seed);
}

}  // namespace

Site::Site(const scene::Scene& scene) : scene_(scene) {
  scene::validate_scene(scene_);
  world_ = std::make_shared<const world::World>(world::generate_world(scene_));
  motion_ = std::make_shared<const robot::MotionProfile>(
      world_->route, robot::RobotMotionOptions::from_route(scene_.route),
      scene::session_seed(scene_));
  radio_ = make_radio(scene_, *world_);
}

Site::Site(const scene::Scene& scene, std::shared_ptr<const world::World> world,
           std::shared_ptr<const robot::MotionProfile> motion)
    : scene_(scene), world_(std::move(world)), motion_(std::move(motion)) {
  scene::validate_scene(scene_);
  radio_ = make_radio(scene_, *world_);
}

Site::~Site() = default;
Site::Site(Site&&) noexcept = default;
Site& Site::operator=(Site&&) noexcept = default;

Site Site::with_access_points(const scene::AccessPoints& access_points) const {
  scene::Scene scene = scene_;
  scene.access_points = access_points;
  return Site(scene, world_, motion_);
}

const std::vector<radio_model::AccessPoint>& Site::access_points() const {
  return radio_->access_points();
}

}  // namespace wifislam::sim::site
