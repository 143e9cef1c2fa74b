#pragma once
// A scene's site: the world (floor plan, mesh, route), the robot's motion along the route, the
// access points and the radio propagation model over them. Built here, in one place, for every
// command that needs them (generate and the in-memory generator, world, radiomap, demo), so a
// radio map and a dataset of one scene see the same access points, walls and shadowing.
//
// Seeds, as datasets have always used them: the world, the motion and the radio model's
// shadowing draw from `scene.seed`'s named streams; the access points from
// `access_points.seed` when the scene sets it (sim/radio/ap_placement.hpp).

#include <memory>
#include <vector>

#include "sim/radio/access_point.hpp"
#include "sim/scene/scene.hpp"

namespace wifislam::sim {

struct World;
class MotionProfile;
namespace radio {
class PropagationModel;
}

class Site {
 public:
  /// Validates the scene and builds everything. Throws InvalidInputError for a scene whose world,
  /// route or access points cannot be built (each message names the part).
  explicit Site(const Scene& scene);
  ~Site();
  Site(Site&&) noexcept;
  Site& operator=(Site&&) noexcept;

  const Scene& scene() const { return scene_; }
  const World& world() const { return *world_; }
  const MotionProfile& motion() const { return *motion_; }
  const radio::PropagationModel& radio() const { return *radio_; }
  const std::vector<radio::AccessPoint>& access_points() const;
  /// Height of the Wi-Fi receiver above the floor. It rides with the camera: datasets scan there,
  /// and radio maps default to it.
  double receiver_height_m() const { return scene_.sensors.camera.height_m; }

 private:
  Scene scene_;
  std::unique_ptr<World> world_;
  std::unique_ptr<MotionProfile> motion_;
  std::unique_ptr<radio::PropagationModel> radio_;
};

}  // namespace wifislam::sim
