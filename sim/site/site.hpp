#pragma once
// A scene's site: the world (floor plan, mesh, route), the robot's motion along the route, the
// access points and the radio propagation model over them. Built here, in one place, for every
// command that needs them (generate and the in-memory generator, world, radiomap, demo, compare,
// studies, placement), so a radio map and a dataset of one scene see the same access points,
// walls and shadowing, and a caller that needs the site twice builds it once.
//
// Seeds, as datasets have always used them: the world, the motion and the radio model's
// shadowing draw from `scene.seed`'s named streams; the access points from
// `access_points.seed` when the scene sets it (sim/site/ap_placement.hpp).

#include <memory>
#include <vector>

#include "radio_model/access_point.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::radio_model {
class PropagationModel;
}

namespace wifislam::sim::world {
struct World;
}
namespace wifislam::sim::robot {
class MotionProfile;
}

namespace wifislam::sim::site {

class Site {
 public:
  /// Validates the scene and builds everything. Throws InvalidInputError for a scene whose world,
  /// route or access points cannot be built (each message names the part).
  explicit Site(const scene::Scene& scene);
  ~Site();
  Site(Site&&) noexcept;
  Site& operator=(Site&&) noexcept;

  /// The same building and route with other access points (`access_points` replaces the scene's
  /// block): the world and the motion are shared, not rebuilt; the radio model is built for the
  /// new access points exactly as Site(scene with that block) would build it.
  Site with_access_points(const scene::AccessPoints& access_points) const;

  const scene::Scene& scene() const { return scene_; }
  const world::World& world() const { return *world_; }
  const robot::MotionProfile& motion() const { return *motion_; }
  const radio_model::PropagationModel& radio() const { return *radio_; }
  const std::vector<radio_model::AccessPoint>& access_points() const;
  /// Height of the Wi-Fi receiver above the floor. It rides with the camera: datasets scan there,
  /// and radio maps default to it.
  double receiver_height_m() const { return scene_.sensors.camera.height_m; }

 private:
  Site(const scene::Scene& scene, std::shared_ptr<const world::World> world,
       std::shared_ptr<const robot::MotionProfile> motion);

  scene::Scene scene_;
  std::shared_ptr<const world::World> world_;
  std::shared_ptr<const robot::MotionProfile> motion_;
  std::unique_ptr<radio_model::PropagationModel> radio_;
};

}  // namespace wifislam::sim::site
